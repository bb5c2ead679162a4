Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' The end of the Zeno series: bounce heights, the rest time t0 (1 + e)/(1 − e), resting on a
''' rectangle, sliding off its edge, and a resting ball that is hit.
''' </summary>
Public Class RestingTests
    Private Const G As Double = 9.81

    <Fact>
    Public Sub BouncingBall_EveryApexIsEToThe2nTimesH0_UntilItRests()
        Dim h0 = 1.0, e = 0.9
        Dim w = Scenarios.BouncingBall(h0, e)
        Dim solver = UseEventSolver(w)
        Dim ball = w.Circles(0)
        Dim upSpeeds As New List(Of Double)
        Dim times As New List(Of Double)
        w.CollisionListener = Sub(rec)
                                  upSpeeds.Add(rec.AVelocityAfter.Y)
                                  times.Add(rec.Time)
                              End Sub
        w.Advance(30.0)
        Assert.True(upSpeeds.Count > 50, $"only {upSpeeds.Count} bounces")
        Dim t0 = Math.Sqrt(2 * h0 / G)
        For n = 1 To upSpeeds.Count
            ' Apex of the flight after bounce n: v²/(2g) = e^(2n) h0 (energy: the rebound speed is e^n √(2 g h0)).
            ' Times are absolute, so a flight of τ s at t ≈ 8 s is known to ulp(t) ≈ 2e-15 s, and the
            ' landing speed to g ulp(t): the apex v²/2g carries an absolute error of about v ulp(t),
            ' below 1e-18 m for the last hops (apexes of 1e-10 m), where 1e-9 of the apex is not reachable.
            Dim apex = upSpeeds(n - 1) ^ 2 / (2 * G)
            Dim expectedApex = e ^ (2 * n) * h0
            Dim timeRounding = Math.Abs(upSpeeds(n - 1)) * 4 * Math.Pow(2, -52) * times(n - 1)
            Assert.True(Math.Abs(apex - expectedApex) < 1.0E-9 * expectedApex + timeRounding, $"apex {n}: {apex} vs {expectedApex}")
            ' Bounce n happens at t0 (1 + 2e + … + 2e^(n−1)).
            Dim expectedTime = t0 * (1 + 2 * e * (1 - e ^ (n - 1)) / (1 - e))
            Assert.True(Math.Abs(times(n - 1) - expectedTime) < 1.0E-9, $"bounce {n} at {times(n - 1)} vs {expectedTime}")
        Next
        Dim rest = solver.RestTime(ball)
        Assert.True(rest.HasValue)
        Dim expectedRest = t0 * (1 + e) / (1 - e)
        Assert.True(Math.Abs(rest.Value - expectedRest) < 0.001, $"rest at {rest.Value} vs {expectedRest}")
        ' The bounces are followed until less than the rest window of the series is left.
        Assert.True(times(times.Count - 1) > expectedRest - RestRules.RestWindow, $"last bounce at {times(times.Count - 1)}, rest at {expectedRest}")
        Assert.Equal(ball.Radius, ball.Position.Y)
        Assert.Equal(0.0, ball.Velocity.Y)
    End Sub

    <Fact>
    Public Sub RestingBall_CostsNoEvents()
        Dim w = Scenarios.BouncingBall(1.0, 0.5)
        Dim solver = UseEventSolver(w)
        w.Advance(10.0)
        Dim collisions = w.CollisionCount
        Dim events = solver.EventCount
        w.Advance(1000.0)
        Assert.Equal(collisions, w.CollisionCount)
        Assert.Equal(events, solver.EventCount)
        Assert.Equal(w.Circles(0).Radius, w.Circles(0).Position.Y)
    End Sub

    <Fact>
    Public Sub BallDroppedOnARectangle_RestsOnItsTop_AtTheGeometricSeriesTime()
        Dim e = 0.5, r = 0.05
        Dim w As New World(4, 4, G, e)
        w.Add(New Rectangle(New Vector(1, 0), 2, 1, "table"))
        Dim ball As New Circle(New Vector(2, 1 + r + 0.8), r, 1.0, id:="ball")
        w.Add(ball)
        Dim solver = UseEventSolver(w)
        w.Advance(5.0)
        Dim t0 = Math.Sqrt(2 * 0.8 / G)
        Assert.Equal(1 + r, ball.Position.Y)
        Assert.Equal(0.0, ball.Velocity.Y)
        Assert.True(Math.Abs(solver.RestTime(ball).Value - t0 * (1 + e) / (1 - e)) < 0.001)
    End Sub

    ''' <summary>
    ''' A ball of radius r resting at x on a table 2 m wide and <paramref name="top"/> m high (e = 0),
    ''' rolling towards its right edge at vx m/s: every collision in the next 3 s.
    ''' </summary>
    Private Shared Function CollisionsOffTable(x As Double, vx As Double, r As Double, top As Double) As List(Of CollisionRecord)
        Dim w As New World(6, 4, G, 0.0)
        w.Add(New Rectangle(New Vector(0, 0), 2, top, "table"))
        w.Add(New Circle(New Vector(x, top + r), r, 1.0, New Vector(vx, 0), "ball"))
        UseEventSolver(w)
        Dim collisions As New List(Of CollisionRecord)
        w.CollisionListener = Sub(rec) collisions.Add(rec)
        w.Advance(3.0)
        Return collisions
    End Function

    <Fact>
    Public Sub RestingBall_FastEnough_FliesOffTheEdgeOnAParabola()
        Dim r = 0.05, top = 1.0
        Dim vx = 1.5 * Math.Sqrt(G * r)
        Dim landings = CollisionsOffTable(1, vx, r, top)
        Assert.NotEmpty(landings)
        Dim land = landings(0)
        Assert.Equal(WallSide.Bottom, land.Wall)
        ' Reaches the edge after 1/vx, then falls `top` metres: t = √(2 top / g).
        Dim fall = Math.Sqrt(2 * top / G)
        Assert.Equal(1 / vx + fall, land.Time, 9)
        Assert.Equal(-G * fall, land.AVelocityBefore.Y, 9)
    End Sub

    <Fact>
    Public Sub RestingBall_TooSlow_SlidesRoundTheCorner_ThenFalls()
        Dim r = 0.05, top = 1.0
        Dim vx = 0.5 * Math.Sqrt(G * r)
        Dim landings = CollisionsOffTable(1.9, vx, r, top)
        Assert.NotEmpty(landings)
        ' Leaves the corner where g cos θ = v²/r with v² = vx² + 2 g r (1 − cos θ).
        Dim cosT = (vx * vx + 2 * G * r) / (3 * G * r)
        Dim sinT = Math.Sqrt(1 - cosT * cosT)
        Dim speed = Math.Sqrt(G * r * cosT)
        Dim x0 = 2 + r * sinT, y0 = top + r * cosT
        Dim ux = speed * cosT, uy = -speed * sinT
        ' Then a parabola down to y = r.
        Dim tFall = (uy + Math.Sqrt(uy * uy + 2 * G * (y0 - r))) / G
        Dim land = landings(0)
        Dim ball = land.A
        Assert.Equal(WallSide.Bottom, land.Wall)
        Assert.Equal(ux, land.AVelocityBefore.X, 9)
        Assert.Equal(uy - G * tFall, land.AVelocityBefore.Y, 9)
        ' With e = 0 it then slides along the floor at ux, so its landing point is where it is now, ux·(3 − t_land) back.
        Assert.Equal(x0 + ux * tFall, ball.Position.X - ux * (3.0 - land.Time), 9)
        Assert.Equal(r, ball.Position.Y)
    End Sub

    <Fact>
    Public Sub RestingBall_ThatIsHit_Reacts()
        Dim e = 0.9, r = 0.05
        Dim w As New World(6, 2, G, e)
        Dim target As New Circle(New Vector(3, r), r, 1.0, id:="target")
        Dim striker As New Circle(New Vector(1, r), r, 1.0, New Vector(1.0, 0), "striker")
        w.Add(target)
        w.Add(striker)
        Dim solver = UseEventSolver(w)
        w.Advance(1.0)
        Assert.True(solver.IsAsleep(target) OrElse target.Velocity.X = 0)
        w.Advance(2.0) ' hit after (2 − 0.1) / 1 = 1.9 s
        ' Equal masses: the target leaves at (1 + e)/2 u, the striker keeps (1 − e)/2 u; both stay on the floor.
        Assert.Equal((1 + e) / 2, target.Velocity.X, 12)
        Assert.Equal((1 - e) / 2, striker.Velocity.X, 12)
        Assert.Equal(r, target.Position.Y)
        Assert.Equal(0.0, target.Velocity.Y)
        Assert.False(solver.IsAsleep(target))
    End Sub

    <Fact>
    Public Sub BallOnAFixedCircle_ExactlyAbove_Rests_OffCentre_SlidesOff()
        Dim r = 0.05
        Dim w As New World(4, 4, G, 0.3)
        w.Add(Circle.CreateFixed(New Vector(2, 1), 0.2, "peg"))
        Dim above As New Circle(New Vector(2, 1.6), r, 1.0, id:="above")
        w.Add(above)
        UseEventSolver(w)
        w.Advance(5.0)
        Assert.Equal(1 + 0.2 + r, above.Position.Y, 9)
        Assert.Equal(2.0, above.Position.X)

        Dim w2 As New World(4, 4, G, 0.3)
        w2.Add(Circle.CreateFixed(New Vector(2, 1), 0.2, "peg"))
        Dim off As New Circle(New Vector(2.01, 1.6), r, 1.0, id:="off")
        w2.Add(off)
        UseEventSolver(w2)
        w2.Advance(5.0)
        ' It ends on the floor, not on the peg.
        Assert.True(off.Position.Y < 0.5, $"still at {off.Position}")
        Assert.True(DeepestOverlap(w2) < 1.0E-9)
    End Sub
End Class
