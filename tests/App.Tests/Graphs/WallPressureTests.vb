Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>The wall pressure gauge against closed forms.</summary>
Public Class WallPressureTests
    ''' <summary>
    ''' One ball of mass m and radius r moving at v along x between the walls of a W × H box (g = 0,
    ''' e = 1). Its centre goes W − 2r between bounces, so it hits a wall every (W − 2r)/v, each time
    ''' with |Δp| = 2mv: the walls take 2mv² / (W − 2r) N·s per second, spread over the perimeter
    ''' 2(W + H): P = m v² / ((W − 2r)(W + H)). Started in the middle and run a whole number of
    ''' round trips, the count of bounces is exact.
    ''' </summary>
    <Theory>
    <InlineData(4.0, 2.0, 0.25, 3.0, 1.5)>
    <InlineData(1.0, 5.0, 0.1, 0.5, 7.0)>
    Public Sub OneBallBetweenTwoWalls_MatchesTheClosedForm(w As Double, h As Double, r As Double, m As Double, v As Double)
        Dim world As New World(w, h, 0.0, 1.0)
        world.Solver = SolverFactory.Create("event")
        world.Add(New Circle(New Vector(w / 2, h / 2), r, m, New Vector(v, 0)))
        Dim gauge As New WallPressure(0, 2 * (w + h), readingSeconds:=1.0E+100)
        world.CollisionListener = Sub(c) gauge.Collided(c)
        Dim roundTrip = 2 * (w - 2 * r) / v
        Const Trips As Integer = 25
        world.Advance(Trips * roundTrip)
        gauge.Advance(world.Time, 0, 0)
        Assert.Equal(2 * Trips * 2 * m * v, gauge.TotalImpulse, 9)
        Dim closedForm = m * v * v / ((w - 2 * r) * (w + h))
        Dim measured = gauge.TotalImpulse / (gauge.Perimeter * world.Time)
        Assert.Equal(closedForm, measured, 9)
    End Sub

    <Fact>
    Public Sub Readings_AverageAndStandardError_FromTheIntervals()
        Dim ball As New Circle(New Vector(1, 1), 0.1, 2.0)
        Dim gauge As New WallPressure(0, 10.0, readingSeconds:=1.0)
        ' 1 s with one hit of |Δp| = 2 × 2 = 4 N·s, then 1 s with two: readings 0.4 and 0.8 N/m.
        gauge.Collided(New CollisionRecord(0.5, ball, Nothing, WallSide.Left, CollisionKind.CircleWall, New Vector(-1, 0), New Vector(1, 0), Vector.Zero, Vector.Zero))
        Assert.True(gauge.Advance(1.0, 1.0, 0.5))
        gauge.Collided(New CollisionRecord(1.2, ball, Nothing, WallSide.Right, CollisionKind.CircleWall, New Vector(1, 0), New Vector(-1, 0), Vector.Zero, Vector.Zero))
        gauge.Collided(New CollisionRecord(1.7, ball, Nothing, WallSide.Top, CollisionKind.CircleWall, New Vector(0, 1), New Vector(0, -1), Vector.Zero, Vector.Zero))
        ' A collision with another body is not the wall's.
        gauge.Collided(New CollisionRecord(1.8, ball, New Circle(New Vector(3, 3), 0.1, 1.0), WallSide.None, CollisionKind.CircleCircle, New Vector(0, 1), New Vector(0, -1), Vector.Zero, Vector.Zero))
        Assert.False(gauge.Advance(1.5, 1.0, 0.5))
        Assert.True(gauge.Advance(2.0, 1.0, 0.7))
        Assert.Equal(2, gauge.ReadingCount)
        Assert.Equal(0.4, gauge.Readings(0).Measured, 12)
        Assert.Equal(0.8, gauge.Readings(1).Measured, 12)
        Assert.Equal(12.0 / (10.0 * 2.0), gauge.Average, 12)
        ' Sample standard deviation of {0.4, 0.8} is 0.2828; over √2 readings: 0.2.
        Assert.Equal(0.2, gauge.StandardError, 12)
        Assert.Equal(0.6, gauge.AverageIdeal, 12)
    End Sub
End Class
