Option Strict On
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Fuzzing.Generation
Imports PhysicsEngine.Fuzzing.Shrinking
Imports Xunit

''' <summary>Delta debugging and the scene shrinker, on failures made up for the test.</summary>
Public Class ShrinkerTests
    Private Shared ReadOnly Never As DateTime = DateTime.MaxValue

    <Fact>
    Public Sub DeltaDebugging_FindsExactlyTheItemsAFailureNeeds()
        Dim items = Enumerable.Range(0, 50).ToList()
        Dim asked = 0
        Dim result = DeltaDebugging.Minimize(items, Function(s)
                                                        asked += 1
                                                        Return s.Contains(7) AndAlso s.Contains(31)
                                                    End Function, Never)
        Assert.Equal("7,31", String.Join(",", result))
        ' ddmin needs O(k² log n) tests for k needed items; far fewer than the 2^50 subsets
        Assert.InRange(asked, 1, 150)
    End Sub

    <Fact>
    Public Sub DeltaDebugging_LeavesAListFromWhichNoSingleItemCanGo()
        Dim rng As New SplitMix(5)
        For trial = 1 To 40
            ' fails when the list holds all of any one of three random sets of items
            Dim sets = Enumerable.Range(0, 3).Select(Function(k) Enumerable.Range(0, 12).Where(Function(i) rng.Chance(0.3)).ToList()).Where(Function(s) s.Count > 0).ToList()
            If sets.Count = 0 Then Continue For
            Dim fails = Function(s As IReadOnlyList(Of Integer)) sets.Any(Function(needed) needed.All(Function(i) s.Contains(i)))
            Dim result = DeltaDebugging.Minimize(Enumerable.Range(0, 12).ToList(), fails, Never)
            Assert.True(fails(result))
            For Each item In result
                Assert.False(fails(result.Where(Function(i) i <> item).ToList()), $"trial {trial}: {item} could go from [{String.Join(",", result)}]")
            Next
        Next
    End Sub

    <Fact>
    Public Sub DeltaDebugging_PastItsDeadline_KeepsWhatItHas()
        Dim items = Enumerable.Range(0, 10).ToList()
        Assert.Equal(items, DeltaDebugging.Minimize(items, Function(s) True, DateTime.UtcNow.AddSeconds(-1)))
    End Sub

    <Fact>
    Public Sub TheSceneShrinker_CutsBodiesAndTheRun_ToWhatTheFailureNeeds()
        Dim doc = SceneGenerator.Generate(17, BodyKinds.Default, 40).ToDoc()
        Assert.True(doc.Bodies.Count >= 10)
        Dim needed = {doc.Bodies(2).Id, doc.Bodies(doc.Bodies.Count - 1).Id}
        Dim plan As New RunPlan(1.0, 0.05, 0.013, 10)
        ' a made-up failure: seen at t = 0.27 s whenever both bodies are there and the run is long enough
        Dim probe = Function(d As SceneDoc, p As RunPlan) As Violation
                        If Not needed.All(Function(id) d.Bodies.Any(Function(b) b.Id = id)) OrElse p.Time < 0.27 Then Return Nothing
                        Return New Violation(Invariants.Overlap, "event", p.Sample, 0.27, "made up")
                    End Function
        Dim first = probe(doc, plan)
        Dim result = SceneShrinker.Shrink(doc, plan, first, probe, Never)
        Assert.True(result.Reproduced)
        Assert.Equal(needed, result.Doc.Bodies.Select(Function(b) b.Id))
        ' the first sample at or after 0.27 s, as the sampling clock computes it: 6 × 0.05
        Assert.Equal(6 * 0.05, result.Plan.Time)
    End Sub

    <Fact>
    Public Sub AFailureThatDoesNotComeBack_IsNotShrunk()
        Dim doc = SceneGenerator.Generate(3, BodyKinds.Default, 40).ToDoc()
        Dim plan As New RunPlan(1.0, 0.05, 0.013, 10)
        Dim seen As New Violation(Invariants.WallTime, "event", 0.05, 0.5, "over the cap once")
        Dim result = SceneShrinker.Shrink(doc, plan, seen, Function(d, p) Nothing, Never)
        Assert.False(result.Reproduced)
        Assert.Same(doc, result.Doc)
        Assert.Equal(1, result.Probes)
    End Sub
End Class
