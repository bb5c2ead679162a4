Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>Scenes with closed-form answers: 1D collisions, Newton's cradle, π from collisions, tunnelling.</summary>
Public Class ExactCollisionTests
    <Theory>
    <InlineData(1.0)>
    <InlineData(0.5)>
    Public Sub HeadOn_MassRatioOneToAMillion_MatchesTextbook(e As Double)
        Dim m1 = 1.0, u1 = 2.0, m2 = 1000000.0, u2 = -0.5
        Dim w = Scenarios.HeadOn(m1, u1, m2, u2, e)
        UseEventSolver(w)
        Dim count = 0
        w.CollisionListener = Sub(rec) count += 1
        w.Advance(2.0)
        Dim v1 = (m1 * u1 + m2 * u2 + m2 * e * (u2 - u1)) / (m1 + m2)
        Dim v2 = (m1 * u1 + m2 * u2 + m1 * e * (u1 - u2)) / (m1 + m2)
        Assert.Equal(1, count)
        Assert.True(Relative(w.Circles(0).Velocity.X, v1) < 1.0E-12, $"v1 {w.Circles(0).Velocity.X} vs {v1}")
        Assert.True(Relative(w.Circles(1).Velocity.X, v2) < 1.0E-12, $"v2 {w.Circles(1).Velocity.X} vs {v2}")
        Assert.Equal(0.0, w.Circles(0).Velocity.Y)
    End Sub

    <Fact>
    Public Sub HeadOn_CollidesAtThePredictedTime()
        ' Gap 4 − 0.2 = 3.8 m closing at 2.5 m/s.
        Dim w = Scenarios.HeadOn(1, 2.0, 3, -0.5, 1.0)
        UseEventSolver(w)
        Dim times As New List(Of Double)
        w.CollisionListener = Sub(rec) times.Add(rec.Time)
        w.Advance(0.7)
        w.Advance(1.0)
        Assert.Single(times)
        Assert.Equal(3.8 / 2.5, times(0), 12)
    End Sub

    <Fact>
    Public Sub NewtonsCradle_OneBallLeavesAtV0_TheRestStayStill()
        Dim v0 = 1.5
        Dim w = Scenarios.NewtonsCradle(v0)
        UseEventSolver(w)
        w.Advance(3.0)
        Dim last = DirectCast(w.Find("ball5"), Circle)
        Assert.True(Relative(last.Velocity.X, v0) < 1.0E-12, $"ball5 {last.Velocity.X}")
        For Each id In {"striker", "ball1", "ball2", "ball3", "ball4"}
            Dim c = DirectCast(w.Find(id), Circle)
            Assert.True(c.Velocity.Length < 1.0E-12 * v0, $"{id} moves at {c.Velocity}")
        Next
        Assert.Equal(5L, w.CollisionCount)
    End Sub

    ' Scenarios.PiCollisions(k) uses a mass ratio of 100^k, which gives the first k + 1 digits of π
    ' (k = 0 is two equal masses: 3 collisions). k = 4 (10⁸ : 1) gives 31415.
    <Theory>
    <InlineData(0, 3)>
    <InlineData(1, 31)>
    <InlineData(2, 314)>
    <InlineData(3, 3141)>
    <InlineData(4, 31415)>
    Public Sub PiFromCollisions_CountsTheDigitsOfPi(k As Integer, expected As Integer)
        Dim w = Scenarios.PiCollisions(k)
        UseEventSolver(w)
        ' Long enough for the heavy block to be well clear of everything (it ends slower than 1 m/s).
        w.Advance(100.0)
        w.Advance(100.0)
        Assert.Equal(CLng(expected), w.CollisionCount)
    End Sub

    <Fact>
    Public Sub Tunnelling_FastSmallCircle_BouncesOffAThinRectangle()
        Dim w As New World(10, 2, 0.0, 1.0, walls:=False)
        Dim ball As New Circle(New Vector(1, 1), 0.0005, 0.001, New Vector(10000.0, 0))
        w.Add(ball)
        w.Add(New Rectangle(New Vector(5, 0.5), 0.001, 1.0))
        UseEventSolver(w)
        w.Advance(0.001) ' 10 m of travel: straight through if it tunnelled
        Assert.Equal(-10000.0, ball.Velocity.X, 6)
        ' Hit at x = 5 − r after 3.9995e-4 s, then back for the rest of the millisecond.
        Dim tHit = (5 - 0.0005 - 1) / 10000.0
        Assert.Equal(5 - 0.0005 - 10000.0 * (0.001 - tHit), ball.Position.X, 9)
        Assert.Equal(1L, w.CollisionCount)
    End Sub

    <Fact>
    Public Sub Tunnelling_TwoFastCirclesCollide()
        Dim w As New World(10, 2, 0.0, 1.0, walls:=False)
        Dim a As New Circle(New Vector(1, 1), 0.001, 1.0, New Vector(10000.0, 0))
        Dim b As New Circle(New Vector(9, 1), 0.001, 1.0, New Vector(-10000.0, 0))
        w.Add(a)
        w.Add(b)
        UseEventSolver(w)
        w.Advance(0.001)
        Assert.Equal(1L, w.CollisionCount)
        Assert.Equal(-10000.0, a.Velocity.X, 6)
        Assert.Equal(10000.0, b.Velocity.X, 6)
        Assert.True(a.Position.X < b.Position.X)
    End Sub

    <Fact>
    Public Sub Collisions_AreReportedInTimeOrder_WithAbsoluteTimes()
        Dim w = Scenarios.ElasticGas(200, seed:=3)
        UseEventSolver(w)
        w.Advance(0.5)
        Dim times As New List(Of Double)
        w.CollisionListener = Sub(rec) times.Add(rec.Time)
        w.Advance(0.5)
        Assert.NotEmpty(times)
        For k = 1 To times.Count - 1
            Assert.True(times(k) >= times(k - 1))
        Next
        Assert.True(times(0) >= 0.5 AndAlso times(times.Count - 1) <= 1.0)
    End Sub
End Class
