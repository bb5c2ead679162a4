Option Strict On
Imports System.Globalization

''' <summary>A projectile (10 m/s at 45°): where it first touches the floor, against the suvat landing point.</summary>
Friend NotInheritable Class ProjectileScene
    Implements IBenchScene

    Private Const Speed As Double = 10.0
    Private Const Angle As Double = Math.PI / 4
    Private Const Gravity As Double = 9.81

    Public ReadOnly Property Name As String = "projectile" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Projectile: position at landing" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "Scenarios.Projectile(v0 = 10 m/s, θ = 45°, g = 9.81 m/s²), launched from the floor. Closed form (suvat): it lands after " &
        "T = 2 v0 sin θ / g = 1.4416 s at x0 + v0 cos θ T = 11.19 m. Error = |centre when the solver reports the first floor " &
        "collision − centre at the closed-form landing| (m); a stepping solver finds the floor only at the end of a step." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "position error at landing (m)" Implements IBenchScene.ErrorMetric

    ''' <summary>The flight, plus a little so that a late landing is still seen.</summary>
    Public ReadOnly Property SimulatedSeconds As Double = ClosedForms.ProjectileFlightTime(Speed, Angle, Gravity) + 0.2 Implements IBenchScene.SimulatedSeconds

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.Projectile(Speed, Angle, Gravity)
    End Function

    Public Function Measure(world As World, sampleStep As Double) As SceneMeasurement Implements IBenchScene.Measure
        Dim ball = world.Circles(0)
        Dim flight = ClosedForms.ProjectileFlightTime(Speed, Angle, Gravity)
        Dim expected = ClosedForms.ProjectilePosition(ball.Position, ball.Velocity, Gravity, flight)
        Dim landedAt = Double.NaN
        Dim landedTime = Double.NaN
        ' The listener only reads the state the solver has at the moment it reports the collision.
        world.CollisionListener = Sub(r)
                                      If Double.IsNaN(landedTime) AndAlso r.Kind = CollisionKind.CircleWall AndAlso r.Wall = WallSide.Bottom Then
                                          landedTime = r.Time
                                          landedAt = (ball.Position - expected).Length
                                      End If
                                  End Sub
        world.Advance(SimulatedSeconds)
        world.CollisionListener = Nothing
        If Double.IsNaN(landedTime) Then Return New SceneMeasurement(Double.NaN, "no landing reported")
        Return New SceneMeasurement(landedAt, "landed at " & landedTime.ToString("0.0000", CultureInfo.InvariantCulture) & " s (closed form " &
                                    flight.ToString("0.0000", CultureInfo.InvariantCulture) & " s)")
    End Function
End Class
