Option Strict On

''' <summary>A projectile with linear drag: its position against the exponential approach to the terminal velocity.</summary>
Friend NotInheritable Class DragProjectileScene
    Implements IBenchScene

    Private Const Speed As Double = 10.0
    Private Const Angle As Double = Math.PI / 4
    Private Const Drag As Double = 0.2
    Private Const Mass As Double = 0.5
    Private Const Gravity As Double = 9.81

    Public ReadOnly Property Name As String = "drag-projectile" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Projectile with linear drag" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "Scenarios.DragProjectile(v0 = 10 m/s, θ = 45°, b = 0.2 N·s/m, m = 0.5 kg): τ = m/b = 2.5 s, terminal velocity m g/b = 24.5 m/s. " &
        "Closed form: x(t) = x0 + v_t t + (v0 − v_t) τ (1 − e^(−t/τ)). Error = the largest |position − closed form| at the sample " &
        "times over 1.2 s of flight (it lands at 1.43 s)." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "max position error (m)" Implements IBenchScene.ErrorMetric
    Public ReadOnly Property SimulatedSeconds As Double = 1.2 Implements IBenchScene.SimulatedSeconds

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.DragProjectile(Speed, Angle, Drag, Mass, Gravity)
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim ball = world.Circles(0)
        Dim x0 = ball.Position, v0 = ball.Velocity
        Dim tau = LinearDrag.TimeConstant(Mass, Drag), vt = LinearDrag.TerminalVelocity(Mass, Drag, Gravity)
        Dim worst = 0.0
        Dim finished = Sampling.Run(world, SimulatedSeconds, Sampling.SliceOf(sampleStep, 0.01),
                                    Function(t)
                                        worst = Math.Max(worst, (ball.Position - LinearDrag.Position(x0, v0, vt, tau, t)).Length)
                                        Return True
                                    End Function, budget)
        If Not finished Then Return SceneMeasurement.Stopped(world, budget)
        Return New SceneMeasurement(worst)
    End Function
End Class
