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
    Private Const ChainOnWall As String = "event-linked-chain-pressed-onto-wall.json"
    Private Const PileOnFloor As String = "event-linked-ball-pile-on-floor.json"
    Private Const SlidesIntoBall As String = "event-linked-ball-slides-into-ball.json"
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

    <Fact>
    Public Sub ChainOnWall_BallC2NeverSinksIntoTheLeftWall_ItIsRefusedWithTheWorldAsItWas()
        ' c2 hangs on a rod from c0, which hangs on a rod (and a string) from fixed points: the chain swings c2
        ' into the left wall, and the rods' pull, not gravity, presses it there. Its bounces (e = 0.2) came
        ' every 53 μs at the same speed, each a slop deeper: 3.7e-7 m out of the container by t = 0.75 s.
        Dim world = SceneFile.LoadFile(TestPaths.Case_(ChainOnWall))
        world.Solver = SolverFactory.Create("event")
        Dim ball = DirectCast(world.Find("c2"), Circle)
        Dim refused = AdvanceUntilRefused(world, ball, 0.75,
            Sub() Assert.True(ball.Position.X - ball.Radius >= -0.000000001, $"c2 is {-(ball.Position.X - ball.Radius)} m out of the left wall at t = {world.Time} s"))
        Assert.NotNull(refused)
        Assert.Contains("'c2' on links come to rest on the left wall", refused.Message, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub PileOnFloor_NoBallSinksIntoAnother_ItIsRefusedWithTheWorldAsItWas()
        ' A pyramid of six equal balls at rest on the floor (g = 100, e = 0.24) beside a ball on a string: the
        ' three on the floor rest there, the three above them bounced on them for ever, each bounce a slop
        ' deeper: c1 and c5 2.9e-6 m into each other by t = 0.05 s.
        Dim world = SceneFile.LoadFile(TestPaths.Case_(PileOnFloor))
        world.Solver = SolverFactory.Create("event")
        Dim start = world.Movables.Select(Function(b) b.Position).ToArray()
        Dim ex = Assert.Throws(Of UnsupportedSceneException)(Sub() world.Advance(0.05))
        Assert.Contains("come to rest on a ball", ex.Message, StringComparison.Ordinal)
        Assert.Equal(0.0, world.Time)
        Assert.Equal(start, world.Movables.Select(Function(b) b.Position).ToArray())
        Dim text = IO.File.ReadAllText(TestPaths.Case_(PileOnFloor))
        Dim result = SceneCheck.Check(text, "event", New RunPlan(0.05, 0.05, 0.013, GenerousCap))
        Dim broken = result.Violations.Where(Function(v) v.Invariant <> Invariants.Unsupported).ToList()
        Assert.True(broken.Count = 0, String.Join("; ", broken))
    End Sub

    <Fact>
    Public Sub SlidesIntoBall_BallC2NeverSinksIntoC5_ItIsRefusedWithTheWorldAsItWas()
        ' c5 rests at the bottom of the V of segments s0 and s1; c2 slides down s0 into it (e = 0, g = 16.8),
        ' stops dead, slides on and hits it again 12 μs later, each time a slop deeper: 2.3e-6 m by t = 0.7 s.
        Dim world = SceneFile.LoadFile(TestPaths.Case_(SlidesIntoBall))
        world.Solver = SolverFactory.Create("event")
        Dim c2 = DirectCast(world.Find("c2"), Circle), c5 = DirectCast(world.Find("c5"), Circle)
        Dim refused = AdvanceUntilRefused(world, c2, 0.7,
            Sub()
                Dim depth = c2.Radius + c5.Radius - (c2.Position - c5.Position).Length
                Assert.True(depth <= 0.000000001, $"c2 is {depth} m into c5 at t = {world.Time} s")
            End Sub)
        Assert.NotNull(refused)
        Assert.Contains("'c2' come to rest on a ball 'c5'", refused.Message, StringComparison.Ordinal)
    End Sub

    ''' <summary>
    ''' Advances <paramref name="world"/> 0.05 s at a time up to <paramref name="endTime"/> (s), running
    ''' <paramref name="check"/> after each step, until the event solver refuses; a refusal must leave the
    ''' world as it was (its clock, and <paramref name="body"/> where it was). Returns the refusal, or Nothing.
    ''' </summary>
    Private Shared Function AdvanceUntilRefused(world As World, body As Shape, endTime As Double, check As Action) As UnsupportedSceneException
        Do While world.Time < endTime - 0.000000001
            Dim before = body.Position
            Dim beforeTime = world.Time
            Try
                world.Advance(0.05)
            Catch ex As UnsupportedSceneException
                Assert.Equal(beforeTime, world.Time)
                Assert.Equal(before, body.Position)
                Return ex
            End Try
            check()
        Loop
        Return Nothing
    End Function
End Class
