Option Strict On
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>
''' Scenes of tests/cases in which a spring, not gravity, presses a ball onto what it touches in a scene with
''' links (see tests/cases/README.md).
''' </summary>
<Collection(FuzzRuns.Name)>
Public Class LinkedPressRegressionTests
    Private Const PressedOntoRectangle As String = "event-linked-spring-pressed-onto-rectangle.json"
    ''' <summary>These runs are known to end quickly; the cap only stops a runaway, s.</summary>
    Private Const GenerousCap As Double = 300

    <Fact>
    Public Sub SpringPressed_BallC3NeverSinksIntoRectangleR0_ItIsRefusedWithTheWorldAsItWas()
        ' g = 0: c3 slides along the top of r0 while a spring to c0, far below, pulls it down onto it. Each
        ' small bounce (e = 0.077) began a slop deeper than the one before: 6.4e-9 m deep by t = 0.05 s.
        Dim world = SceneFile.LoadFile(TestPaths.Case_(PressedOntoRectangle))
        world.Solver = SolverFactory.Create("event")
        Dim ball = world.Find("c3")
        Dim start = ball.Position
        Dim ex = Assert.Throws(Of UnsupportedSceneException)(Sub() world.Advance(0.05))
        Assert.Contains("'c3' on a spring come to rest on a fixed rectangle 'r0'", ex.Message, StringComparison.Ordinal)
        Assert.Equal(0.0, world.Time)
        Assert.Equal(start, ball.Position)
        Assert.Null(StateChecks.Overlap(world))
    End Sub

    <Fact>
    Public Sub SpringPressed_IsUnsupported_AndBreaksNoInvariant()
        Dim text = IO.File.ReadAllText(TestPaths.Case_(PressedOntoRectangle))
        Dim result = SceneCheck.Check(text, "event", New RunPlan(0.05, 0.05, 0.013, GenerousCap))
        Dim broken = result.Violations.Where(Function(v) v.Invariant <> Invariants.Unsupported).ToList()
        Assert.True(broken.Count = 0, String.Join("; ", broken))
        Assert.True(result.Broke(Invariants.Unsupported))
    End Sub
End Class
