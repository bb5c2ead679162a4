Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace EventDriven
    ''' <summary>
    ''' A cluster of touching bodies resolved at once (ClusterResponse: a ball wedged in a narrow V is hit by
    ''' both sides too often at one instant) counts every change of energy it makes in World.Dissipated:
    ''' what the blow takes, and all of a wedged body's motion when it is stopped. It never adds energy.
    ''' </summary>
    Public Class ClusterLedgerTests
        Private Const G As Double = 9.81
        Private Const Radius As Double = 0.05     ' m
        Private Const HalfGap As Double = 0.02    ' m: half the V's opening at its foot, narrower than the ball
        Private Const Foot As Double = 0.2        ' m: height of the V's foot

        ''' <summary>
        ''' A V of two fixed segments whose sides lean <paramref name="halfAngleDegrees"/> from the vertical, open
        ''' 4 cm at the foot, and a 5 cm ball dropped into it from 0.6 m, off its axis by 1.3 cm.
        ''' </summary>
        Private Shared Function BallIntoV(halfAngleDegrees As Double, e As Double) As World
            Dim w As New World(1.0, 2.0, G, e)
            Dim a = halfAngleDegrees * Math.PI / 180
            Const h = 0.8
            w.Add(New Segment(New Vector(0.5 - HalfGap - h * Math.Tan(a), Foot + h), New Vector(0.5 - HalfGap, Foot), "left"))
            w.Add(New Segment(New Vector(0.5 + HalfGap, Foot), New Vector(0.5 + HalfGap + h * Math.Tan(a), Foot + h), "right"))
            w.Add(New Circle(New Vector(0.487, 0.6), Radius, 0.1, id:="ball"))
            Return w
        End Function

        ''' <summary>
        ''' e = 0: the ball ends wedged where it touches both sides, and at every sample energy plus dissipated is
        ''' the starting energy to 10⁻⁹ (relative: neither lost uncounted nor gained), and dissipated never falls.
        ''' Without the cluster's books, 5 % (10°) and 9·10⁻⁵ (20°) of the energy went missing.
        ''' </summary>
        <Theory>
        <InlineData(10.0)>
        <InlineData(20.0)>
        Public Sub BallWedgedInAV_EnergyPlusDissipatedKept(halfAngleDegrees As Double)
            Dim w = BallIntoV(halfAngleDegrees, 0.0)
            Dim previous = 0.0
            EventSolverTestKit.RunEventSolverChecked(w, 2, 0.05, EnergyLaw.PlusDissipatedKept(0.000000001),
                eachStep:=Sub(x)
                              Assert.True(x.Dissipated >= previous, $"t = {x.Time} s: dissipated fell from {previous} to {x.Dissipated} J")
                              previous = x.Dissipated
                          End Sub)
            ' Where a ball touches both sides: on the axis, (r − HalfGap cos a) / sin a above the foot.
            Dim a = halfAngleDegrees * Math.PI / 180
            Dim ball = w.Find("ball")
            Assert.Equal(0.5, ball.Position.X, 6)
            Assert.Equal(Foot + (Radius - HalfGap * Math.Cos(a)) / Math.Sin(a), ball.Position.Y, 6)
            Assert.Equal(0.0, ball.Velocity.Length, 12)
        End Sub

        ''' <summary>e = 1: the ball bounces about in the V for ever and nothing is lost, wedged or not.</summary>
        <Theory>
        <InlineData(10.0)>
        <InlineData(20.0)>
        Public Sub BallInAV_Elastic_LosesNothing(halfAngleDegrees As Double)
            Dim w = BallIntoV(halfAngleDegrees, 1.0)
            EventSolverTestKit.RunEventSolverChecked(w, 2, 0.05, EnergyLaw.PlusDissipatedKept(0.000000001))
            Assert.Equal(0.0, w.Dissipated, 12)
        End Sub
    End Class
End Namespace
