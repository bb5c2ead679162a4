Option Strict On

''' <summary>
''' The classroom stopwatch: start, stop, lap and reset, counting simulated time. It reads the world's
''' clock, so it stands still while time is paused, runs faster or slower with the Speed slider, and
''' follows the clock when the run is taken back or forward in time (never reading less than it had
''' when it was last started).
''' </summary>
Public NotInheritable Class LabStopwatch
    Private ReadOnly _clock As Func(Of Double)
    Private ReadOnly _laps As New List(Of Double)
    ''' <summary>The time counted before the last start, s.</summary>
    Private _banked As Double
    ''' <summary>The clock's reading at the last start, s.</summary>
    Private _startedAt As Double

    ''' <param name="clock">the simulated time now, s</param>
    Public Sub New(clock As Func(Of Double))
        _clock = clock
    End Sub

    ''' <summary>Whether it is counting.</summary>
    Public ReadOnly Property IsRunning As Boolean

    ''' <summary>The time counted, s.</summary>
    Public ReadOnly Property Reading As Double
        Get
            If Not _IsRunning Then Return _banked
            Return _banked + Math.Max(0.0, _clock() - _startedAt)
        End Get
    End Property

    ''' <summary>The readings at each press of Lap since the last reset, s.</summary>
    Public ReadOnly Property Laps As IReadOnlyList(Of Double)
        Get
            Return _laps
        End Get
    End Property

    ''' <summary>Starts counting from the reading it has.</summary>
    Public Sub Start()
        If _IsRunning Then Return
        _startedAt = _clock()
        _IsRunning = True
    End Sub

    ''' <summary>Stops counting; the reading stays.</summary>
    Public Sub [Stop]()
        If Not _IsRunning Then Return
        _banked = Reading
        _IsRunning = False
    End Sub

    ''' <summary>Notes the reading now as a lap (it goes on counting).</summary>
    Public Sub Lap()
        _laps.Add(Reading)
    End Sub

    ''' <summary>Back to zero, stopped, with no laps.</summary>
    Public Sub Reset()
        _IsRunning = False
        _banked = 0
        _laps.Clear()
    End Sub

    ''' <summary>"1.234 s", or "1.234 s (lap 2: 0.617 s)" after a lap.</summary>
    Public ReadOnly Property Text As String
        Get
            Dim t = Units.Num(Reading, 3) & " s"
            If _laps.Count = 0 Then Return t
            Dim previous = If(_laps.Count > 1, _laps(_laps.Count - 2), 0.0)
            Return t & " (lap " & _laps.Count & ": " & Units.Num(_laps(_laps.Count - 1) - previous, 3) & " s)"
        End Get
    End Property
End Class
