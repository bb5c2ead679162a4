Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' A ball at rest on the floor or on a rectangle, with e &lt; 1: it must not jitter, sink, or flood the log,
''' and it must still slide when pushed (a classic bug of contact resolution: a ball resting on a rectangle could not be pushed
''' sideways, because every resting contact multiplied its velocity by e).
''' </summary>
Public Class RestingContactTests
    ''' <summary>A 4 m × 3 m box, e = 0.5, with a 3 m wide table (top at 0.5 m) on the right, and a ball dropped on the floor or on the table.</summary>
    Private Shared Function Scene(onTable As Boolean, solver As String) As (World As World, Ball As Circle, RestY As Double)
        Dim w As New World(4.0, 3.0, 9.81, 0.5)
        w.Add(New Rectangle(New Vector(1.0, 0.0), 3.0, 0.5, "table"))
        Const r = 0.1
        Dim ball = If(onTable, New Circle(New Vector(1.5, 0.7), r, 2.0, id:="ball"), New Circle(New Vector(0.3, 0.2), r, 2.0, id:="ball"))
        w.Add(ball)
        TestSolvers.Run(w, solver)
        Return (w, ball, If(onTable, 0.5 + r, r))
    End Function

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub BallAtRestOnTheFloor_NeitherJittersNorSinks_NorFloodsTheLog(solver As String)
        AssertRestsQuietly(Scene(False, solver))
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub BallAtRestOnARectangle_NeitherJittersNorSinks_NorFloodsTheLog(solver As String)
        AssertRestsQuietly(Scene(True, solver))
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub BallAtRestOnTheFloor_SlidesWhenPushed(solver As String)
        AssertSlidesWhenPushed(Scene(False, solver))
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub BallAtRestOnARectangle_SlidesWhenPushed(solver As String)
        AssertSlidesWhenPushed(Scene(True, solver))
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub BallSlidingAlongTheFloor_CarriesOnAcrossTwoTouchingRectangles(solver As String)
        ' Two boxes side by side make one table top: the seam must not catch the ball.
        Dim w As New World(4.0, 3.0, 9.81, 0.5)
        w.Add(New Rectangle(New Vector(0.0, 0.0), 2.0, 0.5, "left"))
        w.Add(New Rectangle(New Vector(2.0, 0.0), 2.0, 0.5, "right"))
        Dim ball As New Circle(New Vector(1.0, 0.6), 0.1, 1.0)
        w.Add(ball)
        TestSolvers.Run(w, solver)
        TestSolvers.Frames(w, 1.0, 1.0 / 60)
        w.SetVelocity(ball, New Vector(1.0, 0.0))
        TestSolvers.Frames(w, 1.5, 1.0 / 60)
        ' Crossing the seam the ball (sunk by up to one step's fall, g dt²) meets the right box's corner at a
        ' slant, which costs it a few µm/s; a catching seam would stop it dead.
        Assert.Equal(2.5, ball.Position.X, 3)
        Assert.InRange(Math.Abs(ball.Velocity.Y), 0.0, 1.0E-6)
        Assert.Equal(1.0, ball.Velocity.X, 4)
    End Sub

    Private Shared Sub AssertRestsQuietly(scene As (World As World, Ball As Circle, RestY As Double))
        Dim w = scene.World, ball = scene.Ball
        TestSolvers.Frames(w, 2.0, 1.0 / 60) ' the drop and its bounces die out well within 2 s at e = 0.5
        Dim collisionsBefore = w.CollisionCount
        Dim fastest = 0.0, deepest = 0.0
        TestSolvers.Frames(w, 2.0, 1.0 / 60, Sub()
                                                  fastest = Math.Max(fastest, ball.Velocity.Length)
                                                  deepest = Math.Max(deepest, scene.RestY - ball.Position.Y)
                                              End Sub)
        Assert.InRange(fastest, 0.0, 1.0E-9)
        Assert.InRange(deepest, -1.0E-9, 1.0E-9)
        Assert.Equal(collisionsBefore, w.CollisionCount)
        Assert.True(collisionsBefore > 0, "the ball never landed")
    End Sub

    Private Shared Sub AssertSlidesWhenPushed(scene As (World As World, Ball As Circle, RestY As Double))
        Dim w = scene.World, ball = scene.Ball
        TestSolvers.Frames(w, 2.0, 1.0 / 60)
        Dim x0 = ball.Position.X
        w.ApplyImpulse(ball, New Vector(ball.Mass * 1.0, 0)) ' Δv = J/m = 1 m/s along the surface
        TestSolvers.Frames(w, 0.5, 1.0 / 60, Sub() Assert.InRange(scene.RestY - ball.Position.Y, -1.0E-9, 1.0E-9))
        ' No friction: the resting contact must leave the tangential velocity alone, whatever e is.
        Assert.Equal(1.0, ball.Velocity.X, 9)
        Assert.InRange(Math.Abs(ball.Velocity.Y), 0.0, 1.0E-9)
        Assert.Equal(x0 + 0.5, ball.Position.X, 6)
    End Sub
End Class
