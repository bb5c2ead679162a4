Option Strict On
Imports System.Globalization

''' <summary>A settling pile (hard case: many resting contacts): overlap left behind and time to rest.</summary>
Friend NotInheritable Class PileScene
    Implements IBenchScene

    Private Const Count As Integer = 40
    Private Const Restitution As Double = 0.3
    ''' <summary>Below this total kinetic energy (J) the pile counts as at rest: about 5 mm/s per body.</summary>
    Private Const RestEnergy As Double = 0.001
    ''' <summary>How often the pile's energy is looked at, s (rounded to whole sample steps).</summary>
    Private Const LookEvery As Double = 0.01

    Public ReadOnly Property Name As String = "pile" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Settling pile: overlap and time to rest" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "Scenarios.Pile(N = 40, e = 0.3): circles of mixed radius fall into a box and settle. There is no closed form for the " &
        "final heap, but two things are known: circles must not overlap (error = the deepest overlap at the end, circle–circle or " &
        "circle–wall, m) and the pile must come to rest (the note gives the time after which total KE stays below 1 mJ, and " &
        "how many of the bodies standing still at the end are not held there: their frictionless contact forces and weight " &
        "do not balance)." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "max overlap at the end (m)" Implements IBenchScene.ErrorMetric
    Public ReadOnly Property SimulatedSeconds As Double = 4.0 Implements IBenchScene.SimulatedSeconds

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.Pile(Count, Restitution)
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        Dim restSince = Double.NaN
        Dim finished = Sampling.Run(world, SimulatedSeconds, Sampling.SliceOf(sampleStep, LookEvery),
            Function(t)
                If world.KineticEnergy() >= RestEnergy Then
                    restSince = Double.NaN
                ElseIf Double.IsNaN(restSince) Then
                    restSince = t
                End If
                Return True
            End Function, budget)
        If Not finished Then Return SceneMeasurement.Stopped(world, budget)
        Dim note As String
        If Double.IsNaN(restSince) Then
            note = "not at rest after " & SimulatedSeconds.ToString("0.#", CultureInfo.InvariantCulture) & " s (KE " &
                   world.KineticEnergy().ToString("0.0e+0", CultureInfo.InvariantCulture) & " J)"
        Else
            note = "at rest from " & restSince.ToString("0.00", CultureInfo.InvariantCulture) & " s"
        End If
        note &= RestBalance.Note(world)
        Return New SceneMeasurement(Overlap.Deepest(world), note)
    End Function

End Class
