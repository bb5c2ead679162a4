Option Strict On
Imports System.IO
Imports PhysicsEngine.Fuzzing
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
        Dim log As New StringWriter()
        Dim result = Campaign.Run(options, log)
        _output.WriteLine(log.ToString())
        Dim known = result.Failures().Where(Function(f) IsKnown(f.Outcome.Label, f.Violation.Invariant)).ToList()
        For Each f In known
            _output.WriteLine("known, still open: seed " & f.Outcome.Label & ": " & f.Violation.ToString())
        Next
        Dim failures = result.Failures().Where(Function(f) Not IsKnown(f.Outcome.Label, f.Violation.Invariant)).ToList()
        Dim lines = failures.Select(Function(f) "seed " & f.Outcome.Label & ": " & f.Violation.ToString())
        Assert.True(failures.Count = 0,
            failures.Count & " invariants broken in " & failures.Select(Function(f) f.Outcome.Label).Distinct().Count() & " of " & options.Scenes & " scenes (seeds " &
            options.Seed & " to " & (options.Seed + options.Scenes - 1) & "):" & vbLf & String.Join(vbLf, lines) & vbLf &
            "To shrink one and get the command that shows it: bash scripts/fuzz.sh 1 --seed N")
    End Sub

    Private Shared Function IsKnown(label As String, invariant As String) As Boolean
        Return QuickPass.KnownFailures.Any(Function(k) k.Seed.ToString(Globalization.CultureInfo.InvariantCulture) = label AndAlso k.Invariant = invariant)
    End Function
End Class
