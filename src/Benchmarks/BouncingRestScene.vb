Option Strict On
Imports System.Globalization

''' <summary>A dropped ball (h0 = 1 m, e = 0.9): when it stops bouncing, against t0 (1 + e) / (1 − e).</summary>
Friend NotInheritable Class BouncingRestScene
    Implements IBenchScene

    Private Const DropHeight As Double = 1.0
    Private Const Restitution As Double = 0.9
    Private Const Gravity As Double = 9.81
    Private Const Radius As Double = 0.05

    Public ReadOnly Property Name As String = "bouncing-rest" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Bouncing ball: time to rest" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "Scenarios.BouncingBall(h0 = 1 m, e = 0.9). Closed form: the bounces form a geometric series that ends at " &
        "T = t0 (1 + e) / (1 − e), t0 = √(2 h0 / g) (T = 8.579 s). Error = |time of the last reported floor bounce − T|; " &
        "a solver that stops bouncing early or late shows it here. Every solver ends the infinite series with a resting rule, " &
        "so the bounces it no longer reports (below its threshold) are part of this error." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "rest-time error (s)" Implements IBenchScene.ErrorMetric

    ''' <summary>The closed-form rest time T, s.</summary>
    Public Shared ReadOnly Property RestTime As Double = ClosedForms.BounceRestTime(DropHeight, Restitution, Gravity)

    ''' <summary>A quarter past T, so a late last bounce is seen.</summary>
    Public ReadOnly Property SimulatedSeconds As Double = 1.25 * RestTime Implements IBenchScene.SimulatedSeconds

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.BouncingBall(DropHeight, Restitution, Gravity, Radius)
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        Dim ball = world.Circles(0)
        Dim lastBounce = Double.NaN
        Dim bounces = 0
        world.CollisionListener = Sub(r)
                                      If r.Kind = CollisionKind.CircleWall AndAlso r.Wall = WallSide.Bottom Then
                                          lastBounce = r.Time
                                          bounces += 1
                                      End If
                                  End Sub
        Dim finished = Sampling.Advance(world, SimulatedSeconds, sampleStep, budget)
        world.CollisionListener = Nothing
        If Not finished Then Return SceneMeasurement.Stopped(world, budget)
        Dim height = ball.Position.Y - Radius
        Dim note = bounces.ToString(CultureInfo.InvariantCulture) & " bounces, last at " &
                   lastBounce.ToString("0.000", CultureInfo.InvariantCulture) & " s"
        If height > 0.001 OrElse ball.Velocity.Length > 0.01 Then note &= "; still moving at the end"
        ' The event solver knows when the ball came to rest: the end of the geometric series of bounces
        ' that its resting rule sums exactly. A stepping solver only shows its last reported bounce.
        Dim eventSolver = TryCast(world.Solver, EventDrivenSolver)
        Dim rest = If(eventSolver Is Nothing, Nothing, eventSolver.RestTime(ball))
        If rest.HasValue Then
            note &= "; at rest from " & rest.Value.ToString("0.000000", CultureInfo.InvariantCulture) & " s"
            Return New SceneMeasurement(Math.Abs(rest.Value - RestTime), note)
        End If
        If bounces = 0 Then Return New SceneMeasurement(RestTime, "no bounce reported")
        Return New SceneMeasurement(Math.Abs(lastBounce - RestTime), note)
    End Function
End Class
