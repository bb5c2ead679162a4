Option Strict On

''' <summary>A box bobbing undamped on water: its height against simple harmonic motion about the floating depth.</summary>
Friend NotInheritable Class FloatingBoxScene
    Implements IBenchScene

    Private Const Mass As Double = 40.0
    Private Const Width As Double = 0.4
    Private Const Water As Double = 1000.0
    Private Const Displacement As Double = 0.03
    Private Const Gravity As Double = 9.81

    Public ReadOnly Property Name As String = "floating-box" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Box bobbing on water" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "Scenarios.FloatingBox(m = 40 kg, w = 0.4 m, ρ_l = 1000 kg/m²), released 3 cm above its floating depth m/(ρ_l w) = 0.1 m: " &
        "buoyancy ρ_l g w (depth) makes it bob with T = 2π √(m/(ρ_l g w)) = 0.634 s. Closed form: y(t) = y_eq + 0.03 cos(2π t/T). " &
        "Error = the largest |height − closed form| at the sample times over 3 s." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "max height error (m)" Implements IBenchScene.ErrorMetric
    Public ReadOnly Property SimulatedSeconds As Double = 3.0 Implements IBenchScene.SimulatedSeconds

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.FloatingBox(Mass, Width, Water, Displacement, Gravity)
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim box = world.Rectangles(0)
        Dim equilibrium = 1.5 - Buoyancy.FloatingDepth(Mass, Width, Water)
        Dim omega = 2 * Math.PI / Buoyancy.BobbingPeriod(Mass, Width, Water, Gravity)
        Dim worst = 0.0
        Dim finished = Sampling.Run(world, SimulatedSeconds, Sampling.SliceOf(sampleStep, 0.01),
                                    Function(t)
                                        worst = Math.Max(worst, Math.Abs(box.Position.Y - (equilibrium + Displacement * Math.Cos(omega * t))))
                                        Return True
                                    End Function, budget)
        If Not finished Then Return SceneMeasurement.Stopped(world, budget)
        Return New SceneMeasurement(worst)
    End Function
End Class
