Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>Changes made while running (g, e, velocity, impulse, drag, size, add, remove) keep every prediction valid.</summary>
Public Class MidRunChangeTests
    <Fact>
    Public Sub GravityChange_MidFlight_FollowsTheNewParabola()
        Dim w = Scenarios.Projectile(speed:=10, angle:=Math.PI / 4)
        UseEventSolver(w)
        Dim ball = w.Circles(0)
        Dim p0 = ball.Position, v0 = ball.Velocity
        w.Advance(0.3)
        w.Gravity = 0
        w.Advance(0.3)
        ' 0.3 s under g, then 0.3 s in a straight line at the velocity it had.
        Dim vy1 = v0.Y - 9.81 * 0.3
        Dim y1 = p0.Y + v0.Y * 0.3 - 0.5 * 9.81 * 0.09
        Assert.Equal(y1 + vy1 * 0.3, ball.Position.Y, 12)
        Assert.Equal(p0.X + v0.X * 0.6, ball.Position.X, 12)
    End Sub

    <Fact>
    Public Sub RestitutionChange_MidFlight_AppliesToTheNextBounce()
        Dim w = Scenarios.BouncingBall(1.0, 0.9)
        UseEventSolver(w)
        Dim after As New List(Of Double)
        w.CollisionListener = Sub(rec) after.Add(rec.AVelocityAfter.Y)
        w.Advance(0.2)
        w.Restitution = 0.5
        w.Advance(0.5)
        Assert.Single(after)
        Assert.Equal(0.5 * Math.Sqrt(2 * 9.81 * 1.0), after(0), 12)
    End Sub

    <Fact>
    Public Sub SetVelocity_MidRun_ChangesTheCollisionTime()
        Dim w = Scenarios.HeadOn(1, 1.0, 1, 0.0, 1.0)
        UseEventSolver(w)
        Dim times As New List(Of Double)
        w.CollisionListener = Sub(rec) times.Add(rec.Time)
        w.Advance(1.0) ' gap now 3.8 − 1 = 2.8 m
        w.SetVelocity(w.Circles(1), New Vector(-1.8, 0))
        w.Advance(3.0)
        Assert.Single(times)
        Assert.Equal(1.0 + 2.8 / 2.8, times(0), 12)
    End Sub

    <Fact>
    Public Sub ApplyImpulse_MidRun_ChangesTheCollisionTime()
        Dim w = Scenarios.HeadOn(2, 1.0, 1, 0.0, 1.0)
        UseEventSolver(w)
        Dim times As New List(Of Double)
        w.CollisionListener = Sub(rec) times.Add(rec.Time)
        w.Advance(1.0)
        w.ApplyImpulse(w.Circles(0), New Vector(2.0, 0)) ' Δv = J/m = 1 m/s: now 2 m/s
        w.Advance(3.0)
        Assert.Single(times)
        Assert.Equal(1.0 + 2.8 / 2.0, times(0), 12)
    End Sub

    <Fact>
    Public Sub Remove_TheTarget_MeansNoCollision_Add_OverlappingIsPushedApart()
        Dim w = Scenarios.HeadOn(1, 1.0, 1, 0.0, 1.0)
        UseEventSolver(w)
        w.Advance(1.0)
        w.Remove(w.Circles(1))
        w.Advance(5.0)
        Assert.Equal(0L, w.CollisionCount)
        Dim newcomer As New Circle(w.Circles(0).Position + New Vector(0.05, 0), 0.1, 1.0)
        w.Add(newcomer)
        w.Advance(0.01)
        Assert.True(DeepestOverlap(w) <= 1.0E-9)
        Assert.True(newcomer.Position.IsFinite)
    End Sub

    <Fact>
    Public Sub Drag_PushesWhatItMeets_AndReachesItsTarget()
        Dim w As New World(4, 2, 0.0, 1.0)
        Dim hand As New Circle(New Vector(1, 1), 0.1, 1.0, id:="hand")
        Dim ball As New Circle(New Vector(2, 1), 0.1, 1.0, id:="ball")
        w.Add(hand)
        w.Add(ball)
        UseEventSolver(w)
        w.BeginDrag(hand)
        w.DragTo(New Vector(1.9, 1))
        w.Advance(0.5) ' hand at 1.8 m/s; touches the ball when it has moved 0.8 m
        Assert.Equal(New Vector(1.9, 1), hand.Position)
        ' The hand acts as infinitely heavy: the ball leaves at 2 × 1.8 m/s (e = 1).
        Assert.Equal(3.6, ball.Velocity.X, 12)
        Assert.True(DeepestOverlap(w) <= 1.0E-9)
        w.EndDrag(Vector.Zero)
        w.Advance(1.0)
        Assert.True(DeepestOverlap(w) <= 1.0E-9)
    End Sub

    <Fact>
    Public Sub Resize_MidRun_KeepsTheGasInside_AndBouncesOffTheNewWalls()
        Dim w = Scenarios.ElasticGas(300, seed:=5)
        UseEventSolver(w)
        w.Advance(1.0)
        Dim e = w.KineticEnergy()
        w.Resize(w.Width * 0.8, w.Height * 0.8)
        For k = 1 To 10
            w.Advance(0.2)
            Assert.True(DeepestOverlap(w) <= 1.0E-9, $"overlap {DeepestOverlap(w)}")
        Next
        Assert.True(Relative(w.KineticEnergy(), e) < 1.0E-9)
    End Sub

    <Fact>
    Public Sub MidRunVelocityChange_MatchesTheSameChangeMadeAtTheStart()
        ' Run A: launch at t = 0. Run B: the ball sits still for 0.5 s, then gets the same velocity.
        ' After the change both follow the same path, so B at 0.5 + t must equal A at t.
        Dim a = Scenarios.ElasticGas(50, seed:=7)
        Dim b = Scenarios.ElasticGas(50, seed:=7)
        For Each c In b.Circles
            c.Velocity = Vector.Zero
        Next
        UseEventSolver(a)
        UseEventSolver(b)
        b.Advance(0.5)
        For k = 0 To a.Circles.Count - 1
            b.SetVelocity(b.Circles(k), a.Circles(k).Velocity)
        Next
        ' A gas is chaotic (rounding differences grow with every collision), so compare over a
        ' stretch with a few dozen collisions.
        a.Advance(0.3)
        b.Advance(0.3)
        Assert.True(a.CollisionCount > 10, $"{a.CollisionCount} collisions")
        Assert.Equal(a.CollisionCount, b.CollisionCount)
        For k = 0 To a.Circles.Count - 1
            Dim d = (a.Circles(k).Position - b.Circles(k).Position).Length
            Assert.True(d < 1.0E-6, $"circle {k} differs by {d} m")
        Next
    End Sub
End Class
