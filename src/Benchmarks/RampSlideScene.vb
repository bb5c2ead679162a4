Option Strict On
Imports System.Globalization

''' <summary>A ball released at rest on a frictionless 30° ramp: its path, against s(t) = ½ g sin θ t² along the slope.</summary>
Friend NotInheritable Class RampSlideScene
    Implements IBenchScene

    Private Const Angle As Double = Math.PI / 6
    Private Const Gravity As Double = 9.81

    Public ReadOnly Property Name As String = "ramp-slide" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Ball sliding down a ramp" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "Scenarios.RampSlide(θ = 30°, g = 9.81 m/s²): a 0.1 m ball released at rest touching a fixed segment. With no friction " &
        "the only force along the slope is g sin θ, so the centre moves s(t) = ½ g sin θ t² down the slope and stays r from it. " &
        "Error = the largest distance between the centre and that closed form at the sample times over 1 s (it has slid 2.45 m " &
        "and is still on the 4 m ramp)." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "max position error (m)" Implements IBenchScene.ErrorMetric
    Public ReadOnly Property SimulatedSeconds As Double = 1.0 Implements IBenchScene.SimulatedSeconds

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.RampSlide(Angle, Gravity)
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim ball = world.Circles(0)
        Dim start = ball.Position
        Dim down = New Vector(Math.Cos(Angle), -Math.Sin(Angle))
        Dim worst = 0.0
        Dim finished = Sampling.Run(world, SimulatedSeconds, Sampling.SliceOf(sampleStep, 0.01),
                                    Function(t)
                                        Dim expected = start + (0.5 * Gravity * Math.Sin(Angle) * t * t) * down
                                        worst = Math.Max(worst, (ball.Position - expected).Length)
                                        Return True
                                    End Function, budget)
        If Not finished Then Return SceneMeasurement.Stopped(world, budget)
        Return New SceneMeasurement(worst, "slid " & (ball.Position - start).Length.ToString("0.000", CultureInfo.InvariantCulture) & " m")
    End Function
End Class
