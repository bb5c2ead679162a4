Option Strict On
Imports System.Globalization

''' <summary>Newton's cradle: one ball in, one ball out at the same speed, the rest still.</summary>
Friend NotInheritable Class CradleScene
    Implements IBenchScene

    Private Const Speed As Double = 1.0
    Private Const Count As Integer = 5

    Public ReadOnly Property Name As String = "cradle" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Newton's cradle" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "Scenarios.NewtonsCradle(v0 = 1 m/s, 5 touching balls + striker, e = 1, g = 0). Closed form: the last ball leaves at v0 " &
        "and every other ball is at rest. Error = the largest |v − v_exact| over the six balls (m/s) at t = 3 s (impact at 1.8 s)." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "max velocity error (m/s)" Implements IBenchScene.ErrorMetric
    Public ReadOnly Property SimulatedSeconds As Double = 3.0 Implements IBenchScene.SimulatedSeconds

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.NewtonsCradle(Speed, Count)
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        If Not Sampling.Advance(world, SimulatedSeconds, sampleStep, budget) Then Return SceneMeasurement.Stopped(world, budget)
        Dim last = world.Find("ball" & Count.ToString(CultureInfo.InvariantCulture))
        Dim worst = 0.0
        Dim moving = 0
        For Each c In world.Circles
            Dim expected = If(c Is last, New Vector(Speed, 0), Vector.Zero)
            worst = Math.Max(worst, (c.Velocity - expected).Length)
            If c.Velocity.Length > 0.01 * Speed Then moving += 1
        Next
        Return New SceneMeasurement(worst, moving.ToString(CultureInfo.InvariantCulture) & " ball(s) moving")
    End Function
End Class
