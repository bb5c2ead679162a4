Option Strict On
Imports System.IO
Imports PhysicsEngine.Fuzzing
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Fuzzing.Generation
Imports Xunit
Imports Xunit.Abstractions

''' <summary>
''' The quick pass: a few hundred generated scenes with fixed seeds, each run with every solver in worker
''' processes (so that a run that never returns is killed at the cap), and not one invariant may break
''' beyond the open defects listed in <see cref="QuickPass.KnownFailures"/>.
''' </summary>
<Collection(FuzzRuns.Name)>
Public Class QuickPassTests
    Private ReadOnly _output As ITestOutputHelper

    Public Sub New(output As ITestOutputHelper)
        _output = output
    End Sub

    <Fact>
    Public Sub RandomScenes_BreakNoInvariant_WithAnySolver()
        Dim options As New FuzzOptions With {
            .Scenes = QuickPass.Scenes, .Seed = QuickPass.FirstSeed, .Time = QuickPass.Time, .Cap = QuickPass.Cap,
            .MaxBodies = QuickPass.MaxBodies, .Kinds = BodyKinds.Default, .Shrink = False}
        AssertNoNewFailures(options, QuickPass.KnownFailures)
    End Sub

    ''' <summary>
    ''' The same with every kind of body and link the format has, with the event solver: no refusal, the energy
    ''' laws, no overlap deeper than 1e-9 m, the sampling interval never changing a run, and the wall-time cap,
    ''' beyond the open defects listed in <see cref="QuickPass.AllKindsKnownFailures"/>.
    ''' </summary>
    <Fact>
    Public Sub RandomScenesOfEveryKind_BreakNoInvariant_WithTheEventSolver()
        Dim options As New FuzzOptions With {
            .Scenes = QuickPass.AllKindsScenes, .Seed = QuickPass.FirstSeed, .Time = QuickPass.Time, .Cap = QuickPass.Cap,
            .MaxBodies = QuickPass.AllKindsMaxBodies, .Kinds = BodyKinds.All, .Rough = QuickPass.AllKindsRough,
            .Solvers = {"event"}, .Shrink = False}
        AssertNoNewFailures(options, QuickPass.AllKindsKnownFailures)
    End Sub

    ''' <summary>Runs the campaign of <paramref name="options"/> and fails on any broken invariant not in <paramref name="knownFailures"/>.</summary>
    Private Sub AssertNoNewFailures(options As FuzzOptions, knownFailures As IReadOnlyList(Of (Seed As Integer, Invariant As String)))
        Dim log As New StringWriter()
        Dim result = Campaign.Run(options, log)
        _output.WriteLine(log.ToString())
        Dim isKnown = Function(f As (Outcome As SceneOutcome, Violation As Violation)) knownFailures.Any(Function(k) k.Seed.ToString(Globalization.CultureInfo.InvariantCulture) = f.Outcome.Label AndAlso k.Invariant = f.Violation.Invariant)
        Dim known = result.Failures().Where(isKnown).ToList()
        For Each f In known
            _output.WriteLine("known, still open: seed " & f.Outcome.Label & ": " & f.Violation.ToString())
        Next
        Dim failures = result.Failures().Where(Function(f) Not isKnown(f)).ToList()
        Dim lines = failures.Select(Function(f) "seed " & f.Outcome.Label & ": " & f.Violation.ToString())
        Assert.True(failures.Count = 0,
            failures.Count & " invariants broken in " & failures.Select(Function(f) f.Outcome.Label).Distinct().Count() & " of " & options.Scenes & " scenes (seeds " &
            options.Seed & " to " & (options.Seed + options.Scenes - 1) & "):" & vbLf & String.Join(vbLf, lines) & vbLf &
            "To shrink one and get the command that shows it: bash scripts/fuzz.sh 1 --seed N" &
            If(options.Kinds = BodyKinds.All, $" --kinds all --bodies {options.MaxBodies} --rough {options.Rough.ToString(Globalization.CultureInfo.InvariantCulture)} --solvers event", ""))
    End Sub
End Class
