Option Strict On
Imports System.Globalization

''' <summary>
''' A hard mixed scene (Scenarios.MixedSizes): what every solver leaves behind in overlaps and
''' penetrations, and what the exact solver pays per collision when fast small balls bounce among
''' large slow ones.
''' </summary>
Friend NotInheritable Class MixedScene
    Implements IBenchScene

    Private ReadOnly _seconds As Double

    ''' <param name="seconds">simulated seconds per run</param>
    Public Sub New(seconds As Double)
        _seconds = seconds
    End Sub

    ''' <summary>How often the overlaps are looked at, s (rounded to whole sample steps).</summary>
    Private Const LookEvery As Double = 0.001

    Public ReadOnly Property Name As String = "mixed" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Mixed sizes and speeds: penetration and cost" Implements IBenchScene.Title

    Public ReadOnly Property Description As String Implements IBenchScene.Description
        Get
            Return "Scenarios.MixedSizes(60 balls, seed 1): radii from 1 mm to 0.5 m, masses over 10¹², speeds up to 10⁴ m/s, " &
                   "four fixed rectangles (two partly outside the box) and three fixed circles, g = 9.81, e = 1. No closed form, but " &
                   "nothing may sink into anything: error = the deepest penetration seen every millisecond over " &
                   _seconds.ToString("0.##", CultureInfo.InvariantCulture) & " s (ball into ball, fixed body or wall, m). " &
                   "The note gives the energy drift (e = 1: it is conserved) and whether a centre was ever inside a fixed body."
        End Get
    End Property

    Public ReadOnly Property ErrorMetric As String = "deepest penetration (m)" Implements IBenchScene.ErrorMetric

    Public ReadOnly Property SimulatedSeconds As Double Implements IBenchScene.SimulatedSeconds
        Get
            Return _seconds
        End Get
    End Property

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.MixedSizes()
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        Dim before = world.KineticEnergy() + world.PotentialEnergy()
        Dim worst = 0.0
        Dim centresInside = 0
        Dim finished = Sampling.Run(world, _seconds, Sampling.SliceOf(sampleStep, LookEvery),
            Function(t)
                worst = Math.Max(worst, Overlap.Deepest(world))
                centresInside += Overlap.CentresInsideFixedBodies(world)
                Return True
            End Function, budget)
        If Not finished Then Return SceneMeasurement.Stopped(world, budget)
        Dim after = world.KineticEnergy() + world.PotentialEnergy()
        Dim note = "energy drift " & NumberText.Sci(Math.Abs(after - before) / before)
        If centresInside > 0 Then note &= "; a centre inside a fixed body at " & centresInside.ToString(CultureInfo.InvariantCulture) & " sample(s)"
        Return New SceneMeasurement(worst, note)
    End Function
End Class
