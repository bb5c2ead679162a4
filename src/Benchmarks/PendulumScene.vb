Option Strict On
Imports System.Globalization

''' <summary>A pendulum on a string released from 60°: where it is after one period, against where it started.</summary>
Friend NotInheritable Class PendulumScene
    Implements IBenchScene

    Private Const Length As Double = 1.5
    Private Const Angle As Double = Math.PI / 3
    Private Const Gravity As Double = 9.81

    Public ReadOnly Property Name As String = "pendulum" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Pendulum: return after one period" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "Scenarios.Pendulum(L = 1.5 m, θ0 = 60°, a string): the large-angle period is T = 4 √(L/g) K(sin 30°) = 2.6368 s " &
        "(K by Gauss's arithmetic–geometric mean), 7 % longer than 2π √(L/g). After exactly one period the bob is back where it " &
        "was released. Error = |position at T − release point| (m); the note gives the bob's distance from the pivot then " &
        "(1.5 m for a taut string)." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "position error after one period (m)" Implements IBenchScene.ErrorMetric

    Private Shared ReadOnly Period As Double = ClosedForms.PendulumPeriod(Length, Angle, Gravity)

    Public ReadOnly Property SimulatedSeconds As Double = Period Implements IBenchScene.SimulatedSeconds

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.Pendulum(Length, Angle, Gravity)
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim bob = world.Circles(0)
        Dim start = bob.Position
        Dim pivot = world.Links(0).Anchor
        If Not Sampling.Advance(world, SimulatedSeconds, sampleStep, budget) Then Return SceneMeasurement.Stopped(world, budget)
        Return New SceneMeasurement((bob.Position - start).Length,
                                    "after T = " & Period.ToString("0.0000", CultureInfo.InvariantCulture) & " s; string " &
                                    (bob.Position - pivot).Length.ToString("0.000000", CultureInfo.InvariantCulture) & " m")
    End Function
End Class
