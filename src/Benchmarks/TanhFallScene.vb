Option Strict On

''' <summary>A ball falling from rest in air with quadratic drag: its speed against v_t tanh(g t/v_t).</summary>
Friend NotInheritable Class TanhFallScene
    Implements IBenchScene

    Private Const Mass As Double = 0.2
    Private Const Radius As Double = 0.15
    Private Const Air As Double = 1.2
    Private Const Cd As Double = 0.8
    Private Const Gravity As Double = 9.81

    Public ReadOnly Property Name As String = "tanh-fall" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Fall with quadratic drag" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "Scenarios.AirFall(m = 0.2 kg, r = 0.15 m, ρ = 1.2 kg/m², C_d = 0.8): quadratic drag ½ ρ C_d (2r) v², terminal speed " &
        "v_t = √(2 m g/(ρ C_d 2r)) = 3.69 m/s. Closed form: v(t) = v_t tanh(g t/v_t). Error = the largest |speed − closed form| " &
        "at the sample times over 3 s." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "max speed error (m/s)" Implements IBenchScene.ErrorMetric
    Public ReadOnly Property SimulatedSeconds As Double = 3.0 Implements IBenchScene.SimulatedSeconds

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.AirFall(Mass, Radius, Air, Cd, Gravity)
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim ball = world.Circles(0)
        Dim vt = QuadraticDrag.TerminalSpeed(Mass, Gravity, Air, Cd, 2 * Radius)
        Dim worst = 0.0
        Dim finished = Sampling.Run(world, SimulatedSeconds, Sampling.SliceOf(sampleStep, 0.01),
                                    Function(t)
                                        worst = Math.Max(worst, Math.Abs(-ball.Velocity.Y - QuadraticDrag.FallSpeed(vt, Gravity, t)))
                                        Return True
                                    End Function, budget)
        If Not finished Then Return SceneMeasurement.Stopped(world, budget)
        Return New SceneMeasurement(worst)
    End Function
End Class
