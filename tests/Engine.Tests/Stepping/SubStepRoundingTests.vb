Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' Advancing to sample times k·S − t, as the command line does, leaves rounding-sized remainders. They
''' must not turn into sliver steps of ~1e-15 s: Verlet would divide position rounding by them and the
''' ball would leave the floor at a wild speed.
''' </summary>
Public Class SubStepRoundingTests
    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub AdvancingToSampleTimes_KeepsTheBouncingBallBelowItsDropHeight(solver As String)
        Const dt = 1.0 / 4000
        Dim w = TestSolvers.Run(Scenarios.BouncingBall(1.0, 0.9), solver, dt)
        Dim ball = w.Circles(0)
        Dim top = ball.Position.Y
        Dim walls As New List(Of CollisionRecord)
        w.CollisionListener = Sub(r) If r.Kind = CollisionKind.CircleWall AndAlso r.Wall <> WallSide.Bottom Then walls.Add(r)
        For k = 1 To 4 * 4000
            w.Advance(k * dt - w.Time)
            Assert.True(ball.Position.Y <= top + 1.0E-6, $"t = {w.Time}: y = {ball.Position.Y} m above the drop height {top} m")
        Next
        Assert.Empty(walls)
    End Sub
End Class
