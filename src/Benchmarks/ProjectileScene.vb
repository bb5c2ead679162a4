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

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim ball = world.Circles(0)
        Dim flight = ClosedForms.ProjectileFlightTime(Speed, Angle, Gravity)
        Dim expected = ClosedForms.ProjectilePosition(ball.Position, ball.Velocity, Gravity, flight)

        ' First run: when does the solver report the landing? (Bodies are only guaranteed to be up to
        ' date at the end of an Advance, so the position is not read inside the listener.)
        Dim landedTime = Double.NaN
        world.CollisionListener = Sub(r)
                                      If Double.IsNaN(landedTime) AndAlso r.Kind = CollisionKind.CircleWall AndAlso r.Wall = WallSide.Bottom Then landedTime = r.Time
                                  End Sub
        Dim finished = Sampling.Advance(world, SimulatedSeconds, sampleStep, budget)
        world.CollisionListener = Nothing
        If Not finished Then Return SceneMeasurement.Stopped(world, budget)
        If Double.IsNaN(landedTime) Then Return New SceneMeasurement(Double.NaN, "no landing reported")

        ' Second run, same solver from the start: stop exactly at that moment and look. A stepping
        ' solver reports at the end of a step, so this replays the same steps.
        Dim again = Build()
        again.Solver = SolverFactory.Create(world.Solver.Name, world.Solver.TimeStep)
        again.Advance(landedTime)
        Return New SceneMeasurement((again.Circles(0).Position - expected).Length,
                                    "landed at " & landedTime.ToString("0.0000", CultureInfo.InvariantCulture) & " s (closed form " &
                                    flight.ToString("0.0000", CultureInfo.InvariantCulture) & " s)")
    End Function
End Class
