Option Strict On
Imports System.Diagnostics
Imports System.Globalization

''' <summary>
''' A wall-clock budget for one run. Scenes look at it between slices of simulated time, so a solver
''' that grinds on a hard case (a collapsing pile) is stopped and reported instead of stalling the run.
''' </summary>
Friend NotInheritable Class RunBudget
    Private ReadOnly _clock As Stopwatch = Stopwatch.StartNew()

    ''' <param name="seconds">wall-clock seconds allowed</param>
    Public Sub New(seconds As Double)
        Me.Seconds = seconds
    End Sub

    ''' <summary>Wall-clock seconds allowed.</summary>
    Public ReadOnly Property Seconds As Double

    ''' <summary>True once the budget is spent.</summary>
    Public ReadOnly Property Expired As Boolean
        Get
            Return _clock.Elapsed.TotalSeconds > Seconds
        End Get
    End Property

    ''' <summary>"stopped at 0.73 s simulated: over the 60 s wall-clock budget".</summary>
    Public Function StoppedNote(world As World) As String
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Return "stopped at " & world.Time.ToString("0.###", CultureInfo.InvariantCulture) & " s simulated: over the " &
               Seconds.ToString("0.#", CultureInfo.InvariantCulture) & " s wall-clock budget"
    End Function
End Class
