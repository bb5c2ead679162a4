Option Strict On
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>
''' Scenes of tests/cases in which a spring or a chain, not gravity, presses a ball onto what it touches in a scene
''' with links (see tests/cases/README.md): once refused, now held by the one rule of lasting contact.
''' </summary>
<Collection(FuzzRuns.Name)>
Public Class LinkedPressRegressionTests
    Private Const PressedOntoRectangle As String = "event-linked-spring-pressed-onto-rectangle.json"
    Private Const ChainOnWall As String = "event-linked-chain-pressed-onto-wall.json"
    Private Const PileOnFloor As String = "event-linked-ball-pile-on-floor.json"
    Private Const SlidesIntoBall As String = "event-linked-ball-slides-into-ball.json"
    ''' <summary>These runs are known to end quickly; the cap only stops a runaway, s.</summary>
    Private Const GenerousCap As Double = 300

    <Fact>
    Public Sub SpringPressed_BallC3NeverSinksIntoRectangleR0()
        ' g = 0: c3 slides along the top of r0 while a spring to c0, far below, pulls it down onto it. Each small
        ' bounce (e = 0.077) began a slop deeper than the one before: 6.4e-9 m deep by t = 0.05 s. Now the bounces
        ' end in a lasting contact that the spring presses, held exactly.
        Dim world = SceneFile.LoadFile(TestPaths.Case_(PressedOntoRectangle))
        world.Solver = SolverFactory.Create("event")
        AdvanceChecking(world, 0.5, Sub() Assert.Null(StateChecks.Overlap(world)))
    End Sub

    <Fact>
    Public Sub SpringPressed_BreaksNoInvariant_HoweverItIsSampled()
        Dim text = IO.File.ReadAllText(TestPaths.Case_(PressedOntoRectangle))
        Dim result = SceneCheck.Check(text, "event", New RunPlan(0.5, 0.05, 0.013, GenerousCap))
        Assert.True(result.Violations.Count = 0, String.Join("; ", result.Violations))
    End Sub

    <Fact>
    Public Sub ChainOnWall_BallC2NeverSinksIntoTheLeftWall()
        ' c2 hangs on a rod from c0, which hangs on a rod (and a string) from fixed points: the chain swings c2
        ' into the left wall, and the rods' pull, not gravity, presses it there. Its bounces (e = 0.2) came
        ' every 53 μs at the same speed, each a slop deeper: 3.7e-7 m out of the container by t = 0.75 s.
        Dim world = SceneFile.LoadFile(TestPaths.Case_(ChainOnWall))
        world.Solver = SolverFactory.Create("event")
        Dim ball = DirectCast(world.Find("c2"), Circle)
        AdvanceChecking(world, 0.75,
            Sub() Assert.True(ball.Position.X - ball.Radius >= -0.000000001, $"c2 is {-(ball.Position.X - ball.Radius)} m out of the left wall at t = {world.Time} s"))
    End Sub

    <Fact>
    Public Sub PileOnFloor_NoBallSinksIntoAnother_AndNothingIsBroken()
        ' A pyramid of six equal balls at rest on the floor (g = 100, e = 0.24) beside a ball on a string: the
        ' three above bounced on the three below for ever, each bounce a slop deeper: c1 and c5 2.9e-6 m into each
        ' other by t = 0.05 s. Frictionless, the pyramid spreads and falls; nothing sinks.
        Dim text = IO.File.ReadAllText(TestPaths.Case_(PileOnFloor))
        Dim result = SceneCheck.Check(text, "event", New RunPlan(0.5, 0.05, 0.013, GenerousCap))
        Assert.True(result.Violations.Count = 0, String.Join("; ", result.Violations))
    End Sub

    <Fact>
    Public Sub SlidesIntoBall_BallC2NeverSinksIntoC5()
        ' c5 rests at the bottom of the V of segments s0 and s1; c2 slides down s0 into it (e = 0, g = 16.8),
        ' stops dead, slides on and hits it again 12 μs later, each time a slop deeper: 2.3e-6 m by t = 0.7 s.
        Dim world = SceneFile.LoadFile(TestPaths.Case_(SlidesIntoBall))
        world.Solver = SolverFactory.Create("event")
        Dim c2 = DirectCast(world.Find("c2"), Circle), c5 = DirectCast(world.Find("c5"), Circle)
        AdvanceChecking(world, 0.7,
            Sub()
                Dim depth = c2.Radius + c5.Radius - (c2.Position - c5.Position).Length
                Assert.True(depth <= 0.000000001, $"c2 is {depth} m into c5 at t = {world.Time} s")
            End Sub)
    End Sub

    ''' <summary>Advances <paramref name="world"/> 0.05 s at a time up to <paramref name="endTime"/> (s), running <paramref name="check"/> after each step.</summary>
    Private Shared Sub AdvanceChecking(world As World, endTime As Double, check As Action)
        Do While world.Time < endTime - 0.000000001
            world.Advance(0.05)
            check()
        Loop
    End Sub
End Class
