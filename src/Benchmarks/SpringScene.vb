Option Strict On

''' <summary>A mass on a vertical spring released unstretched: its height, against y0 − (mg/k)(1 − cos ωt).</summary>
Friend NotInheritable Class SpringScene
    Implements IBenchScene

    Private Const Stiffness As Double = 20.0
    Private Const Mass As Double = 0.5
    Private Const Gravity As Double = 9.81

    Public ReadOnly Property Name As String = "spring" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Mass on a spring" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "Scenarios.SpringMass(k = 20 N/m, m = 0.5 kg): released at rest with the spring at its rest length, the mass oscillates " &
        "about mg/k = 0.245 m below with ω = √(k/m) = 6.32 rad/s: y(t) = y0 − (mg/k)(1 − cos ωt). Error = the largest |y − " &
        "closed form| at the sample times over 5 s (five periods)." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "max height error (m)" Implements IBenchScene.ErrorMetric
    Public ReadOnly Property SimulatedSeconds As Double = 5.0 Implements IBenchScene.SimulatedSeconds

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.SpringMass(Stiffness, Mass, Gravity)
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim body = world.Circles(0)
        Dim y0 = body.Position.Y
        Dim worst = 0.0
        Dim finished = Sampling.Run(world, SimulatedSeconds, Sampling.SliceOf(sampleStep, 0.01),
                                    Function(t)
                                        worst = Math.Max(worst, Math.Abs(body.Position.Y - ClosedForms.SpringHeight(y0, Stiffness, Mass, Gravity, t)))
                                        Return True
                                    End Function, budget)
        If Not finished Then Return SceneMeasurement.Stopped(world, budget)
        Return New SceneMeasurement(worst)
    End Function
End Class
