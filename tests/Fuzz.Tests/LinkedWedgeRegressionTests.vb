Option Strict On
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>
''' Scenes of tests/cases with bodies wedged among contacts in a scene with links, which pairwise blows
''' passed back and forth at one instant until the event solver gave up (see tests/cases/README.md).
''' </summary>
<Collection(FuzzRuns.Name)>
Public Class LinkedWedgeRegressionTests
    Private Const CagedBall As String = "event-linked-caged-ball.json"
    ''' <summary>These runs are known to end quickly; the cap only stops a runaway, s.</summary>
    Private Const GenerousCap As Double = 300

    <Fact>
    Public Sub CagedBall_KeepsEveryEventSolverInvariant()
        ' c2 sits between c1 and c3 with no room, and a rod holds c1 and c3 apart: c1, moving right, hits c2,
        ' which hits c3, which pulls c1 back through the rod, which hits c2 again, for ever at t = 0 (e = 1).
        Dim text = IO.File.ReadAllText(TestPaths.Case_(CagedBall))
        Dim result = SceneCheck.Check(text, "event", New RunPlan(0.05, 0.05, 0.013, GenerousCap))
        Assert.True(result.Violations.Count = 0, String.Join("; ", result.Violations))
    End Sub

    <Fact>
    Public Sub CagedBall_MovesWithTheRodAsOneBody_AtAThirdOfTheSpeed()
        ' The cage leaves c2 no room, so the three balls can only move together; the horizontal momentum m v0
        ' (gravity acts straight down) is shared by three equal masses: each moves at v0 / 3.
        Dim world = SceneFile.LoadFile(TestPaths.Case_(CagedBall))
        world.Solver = SolverFactory.Create("event")
        Dim c1 = world.Find("c1"), c2 = world.Find("c2"), c3 = world.Find("c3")
        Dim v0 = c1.Velocity.X
        Dim radius = DirectCast(c1, Circle).Radius
        world.Advance(0.05)
        For Each c In {c1, c2, c3}
            Assert.Equal(v0 / 3, c.Velocity.X, 1.0E-12 * v0)
            Assert.Equal(-world.Gravity * 0.05, c.Velocity.Y, 1.0E-9)
        Next
        Assert.InRange((c2.Position - c1.Position).Length - 2 * radius, -0.000000001, 0.000000001)
        Assert.InRange((c3.Position - c2.Position).Length - 2 * radius, -0.000000001, 0.000000001)
    End Sub
End Class
