Option Strict On
Imports System.Globalization

''' <summary>A dropped ball (h0 = 1 m, e = 0.9): the heights of its first five apexes against e^(2n) h0.</summary>
Friend NotInheritable Class BouncingApexScene
    Implements IBenchScene

    Private Const DropHeight As Double = 1.0
    Private Const Restitution As Double = 0.9
    Private Const Gravity As Double = 9.81
    Private Const Radius As Double = 0.05
    Private Const Apexes As Integer = 5

    Public ReadOnly Property Name As String = "bouncing-apex" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Bouncing ball: apex heights" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "Scenarios.BouncingBall(h0 = 1 m, e = 0.9, g = 9.81 m/s², r = 0.05 m). Closed form: apex n = e^(2n) h0. " &
        "Error = the largest |apex − e^(2n) h0| over the first five apexes; each apex is the vertex of the parabola " &
        "through the three highest samples (samples every step for a stepping solver, every 1 ms for the event solver)." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "max apex error (m)" Implements IBenchScene.ErrorMetric

    ''' <summary>Just past the fifth apex (impact 5 plus the rise e^5 t0), s.</summary>
    Public ReadOnly Property SimulatedSeconds As Double Implements IBenchScene.SimulatedSeconds
        Get
            Dim t0 = Math.Sqrt(2 * DropHeight / Gravity)
            Return ClosedForms.BounceImpactTime(DropHeight, Restitution, Gravity, Apexes) + Math.Pow(Restitution, Apexes) * t0 + 0.15
        End Get
    End Property

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.BouncingBall(DropHeight, Restitution, Gravity, Radius)
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        Dim ball = world.Circles(0)
        Dim found As New List(Of Double)
        Dim y0 = Double.NaN, y1 = Double.NaN
        Dim finished = Sampling.Run(world, SimulatedSeconds, sampleStep,
            Function(t)
                Dim y2 = ball.Position.Y - Radius
                ' A local maximum well above the floor is an apex; low ones would be contact jitter.
                If y1 >= y0 AndAlso y1 > y2 AndAlso y1 > 0.05 Then found.Add(Sampling.ParabolaPeak(y0, y1, y2))
                y0 = y1
                y1 = y2
                Return found.Count < Apexes
            End Function, budget)
        If Not finished Then Return SceneMeasurement.Stopped(world, budget)
        If found.Count = 0 Then Return New SceneMeasurement(DropHeight, "no apex found")
        Dim worst = 0.0
        For n = 1 To found.Count
            worst = Math.Max(worst, Math.Abs(found(n - 1) - ClosedForms.BounceApex(DropHeight, Restitution, n)))
        Next
        Dim note = If(found.Count < Apexes, "only " & found.Count.ToString(CultureInfo.InvariantCulture) & " apexes", "")
        Return New SceneMeasurement(worst, note)
    End Function
End Class
