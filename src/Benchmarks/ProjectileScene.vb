Option Strict On

''' <summary>A projectile (10 m/s at 45°): where it is at the closed-form landing time.</summary>
Friend NotInheritable Class ProjectileScene
    Implements IBenchScene

    Private Const Speed As Double = 10.0
    Private Const Angle As Double = Math.PI / 4
    Private Const Gravity As Double = 9.81

    Public ReadOnly Property Name As String = "projectile" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Projectile: position at landing" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "Scenarios.Projectile(v0 = 10 m/s, θ = 45°, g = 9.81 m/s²), launched from the floor. Closed form (suvat): " &
        "it lands after T = 2 v0 sin θ / g = 1.4416 s at x0 + v0 cos θ T. Error = |position at T − closed form| (m)." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "position error at landing (m)" Implements IBenchScene.ErrorMetric

    Public ReadOnly Property SimulatedSeconds As Double = ClosedForms.ProjectileFlightTime(Speed, Angle, Gravity) Implements IBenchScene.SimulatedSeconds

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.Projectile(Speed, Angle, Gravity)
    End Function

    Public Function Measure(world As World, sampleStep As Double) As SceneMeasurement Implements IBenchScene.Measure
        Dim ball = world.Circles(0)
        Dim expected = ClosedForms.ProjectilePosition(ball.Position, ball.Velocity, Gravity, SimulatedSeconds)
        world.Advance(SimulatedSeconds)
        Return New SceneMeasurement((ball.Position - expected).Length)
    End Function
End Class
