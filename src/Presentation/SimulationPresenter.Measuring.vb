Option Strict On

' The measuring tools: the tape measure, the protractor's reading on a ramp or face under the cursor,
' the stopwatch, and the timing of a body's passes through a line.
Partial Public NotInheritable Class SimulationPresenter
    ''' <summary>How near the cursor must be to a ramp or a polygon's face for the protractor to read it, in canvas pixels at 96 dpi.</summary>
    Public Const ProtractorPixels As Double = 8

    ''' <summary>The tutorial's page on the measuring tools.</summary>
    Public Shared ReadOnly Property MeasuringHelp As New HelpTopic("11. Measuring: tape, protractor, stopwatch",
        "Measure ▾ (in the row above the tables) holds the measuring tools." & vbLf & "" & vbLf &
        "Tape measure: press at one point of the canvas, drag to another and let go. The line shows its length in metres (three figures, more when the view is zoomed in far enough to resolve them) and its angle to the horizontal. It stays while time runs; a new drag replaces it; Esc, or Tape measure again, takes it away." & vbLf & "" & vbLf &
        "Protractor: hold the cursor over a ramp or a face of a polygon. An arc at its lower end gives its angle to the horizontal, for example 30.0°." & vbLf & "" & vbLf &
        "Stopwatch: start, stop, lap and reset. It counts simulated time: it stands still while paused, runs 4 times as fast at 4× speed, and follows the clock when you step or scrub back (never below where it was started). It reads in the canvas's top left corner." & vbLf & "" & vbLf &
        "Time passes of a body…, then a click on the body: each time its centre crosses a line, in the direction of its first crossing, the time is noted and the period (the time since the last crossing) shown. The line is the tape's, when one is drawn (drag it down from a pendulum's pivot), otherwise the vertical line where the body is. The instant of a crossing is found between frames on the body's motion, not at the end of a frame, so a pendulum's period comes out to a part in 10⁵. Going back in time forgets the crossings after the moment shown; the stopwatch's Reset turns the timing off.")

    Private ReadOnly _tape As New TapeMeasure()
    Private _stopwatch As LabStopwatch
    ''' <summary>Whether the next left click on a body chooses it for the pass timer.</summary>
    Private _choosingPassBody As Boolean

    ''' <summary>The tape measure: its line and whether it is on.</summary>
    Public ReadOnly Property Tape As TapeMeasure
        Get
            Return _tape
        End Get
    End Property

    ''' <summary>The stopwatch, counting simulated time.</summary>
    Public ReadOnly Property LabStopwatch As LabStopwatch
        Get
            If _stopwatch Is Nothing Then _stopwatch = New LabStopwatch(Function() World.Time)
            Return _stopwatch
        End Get
    End Property

    ''' <summary>The timing of a body's passes through a line, or Nothing when none is set.</summary>
    Public ReadOnly Property PassTimer As PassTimer

    ''' <summary>The protractor's reading on the ramp or polygon face under the cursor, or Nothing.</summary>
    Public ReadOnly Property Protractor As ProtractorReading

    ''' <summary>"1.23 m at 30.0°": the tape's reading at the zoom on show ("" without a line).</summary>
    Public ReadOnly Property TapeLabel As String
        Get
            Return _tape.Label(1.0 / View.Scale)
        End Get
    End Property

    ''' <summary>Whether the pass line's next click chooses a body.</summary>
    Public ReadOnly Property IsChoosingPassBody As Boolean
        Get
            Return _choosingPassBody
        End Get
    End Property

    ''' <summary>
    ''' The stopwatch's readout on the canvas: "Stopwatch 1.234 s", then the passes and period when a
    ''' pass line is set; "" while the stopwatch is at zero, stopped, with no pass line.
    ''' </summary>
    Public ReadOnly Property StopwatchText As String
        Get
            Dim lines As New List(Of String)
            If LabStopwatch.IsRunning OrElse LabStopwatch.Reading > 0 OrElse LabStopwatch.Laps.Count > 0 Then lines.Add("Stopwatch " & LabStopwatch.Text & If(LabStopwatch.IsRunning, "", " (stopped)"))
            If PassTimer IsNot Nothing Then
                Dim passes = PassTimer.Passes
                Dim text = "Passes of " & PassTimer.BodyId & ": " & passes.Count
                If passes.Count > 0 Then text &= ", last at " & Units.Num(passes(passes.Count - 1), 4) & " s"
                If passes.Count > 1 Then text &= ", period " & Units.Num(PassTimer.Period, 4) & " s"
                lines.Add(text)
            End If
            Return String.Join(vbLf, lines)
        End Get
    End Property

    ''' <summary>The tape measure's entry: switches it on, or, when on, off with its line taken away.</summary>
    Public Sub ToggleTapeMeasure()
        Guarded(
            Sub()
                If _tape.IsOn Then
                    _tape.Clear()
                    Emit("tape off")
                    ShowMessage("")
                Else
                    _pointer.CancelPlacement()
                    _pointer.EndGestures()
                    _choosingPassBody = False
                    _tape.TurnOn()
                    Emit("tape on")
                    ShowMessage("Tape measure: press at one point, drag to another and let go; a new drag measures again (Esc or Tape measure again ends it).")
                End If
                _window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>The stopwatch's Start/Stop.</summary>
    Public Sub StopwatchStartStop()
        If LabStopwatch.IsRunning Then
            LabStopwatch.Stop()
            Emit("stopwatch stopped " & Exact(LabStopwatch.Reading) & " s")
        Else
            LabStopwatch.Start()
            Emit("stopwatch started at t=" & Exact(World.Time) & " s")
        End If
        _window.ShowSettings()
    End Sub

    ''' <summary>The stopwatch's Lap: notes the reading now.</summary>
    Public Sub StopwatchLap()
        LabStopwatch.Lap()
        Emit("stopwatch lap " & LabStopwatch.Laps.Count & " " & Exact(LabStopwatch.Laps(LabStopwatch.Laps.Count - 1)) & " s")
        _window.ShowSettings()
    End Sub

    ''' <summary>The stopwatch's Reset: zero, stopped, no laps, and no pass line.</summary>
    Public Sub StopwatchReset()
        LabStopwatch.Reset()
        _PassTimer = Nothing
        _choosingPassBody = False
        Emit("stopwatch reset")
        _window.ShowSettings()
    End Sub

    ''' <summary>
    ''' The pass line's entry: the next left click on a movable body times its passes through the tape's
    ''' line when one is drawn, otherwise through the vertical line through its centre now.
    ''' </summary>
    Public Sub BeginPassLine()
        Guarded(
            Sub()
                _pointer.CancelPlacement()
                _pointer.EndGestures()
                _choosingPassBody = True
                Emit("pass line choosing")
                ShowMessage("Pass timer: click the body to time" & If(_tape.HasLine, " through the tape's line", " through a vertical line where it is now") & " (Esc cancels).")
                _window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>Times <paramref name="body"/>'s passes through the line through <paramref name="through"/> (m) along <paramref name="direction"/>.</summary>
    Public Sub SetPassLine(body As Shape, through As Vector, direction As Vector)
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        _PassTimer = New PassTimer(body.Id, through, direction)
        _PassTimer.Observe(World.Time, body.CentreOfMass, body.Velocity)
        _choosingPassBody = False
        Emit("pass line " & body.Id & " through " & Units.Pair(through, 3) & " along " & Units.Pair(_PassTimer.Direction, 3))
        ShowMessage("Timing each pass of " & body.Id & " through the line, in the direction of its first pass.")
        _window.ShowSettings()
    End Sub

    ''' <summary>A mouse button went down at (x, y) px: True when a measuring tool took it.</summary>
    Private Function MeasurePointerDown(button As PointerButton, x As Double, y As Double) As Boolean
        Dim p = View.ToWorld(x, y)
        If Not p.IsFinite OrElse button <> PointerButton.Left Then Return False
        If _choosingPassBody Then
            Dim body = BodyAt(p)
            If body Is Nothing OrElse body.IsFixed Then
                ShowMessage("Pass timer: click a body that moves (Esc cancels).")
            ElseIf _tape.HasLine Then
                SetPassLine(body, _tape.Start.Value, _tape.Finish.Value - _tape.Start.Value)
            Else
                SetPassLine(body, body.CentreOfMass, New Vector(0, 1))
            End If
            Return True
        End If
        If Not _tape.IsOn OrElse Mode <> ClickMode.Move Then Return False
        _tape.Press(p)
        Return True
    End Function

    ''' <summary>The cursor moved to (x, y) px: the tape follows it, the protractor reads what is under it. True while the tape is dragged.</summary>
    Private Function MeasurePointerMove(x As Double, y As Double) As Boolean
        Dim p = View.ToWorld(x, y)
        If Not p.IsFinite Then Return False
        Dim before = _Protractor
        _Protractor = ProtractorReading.Near(World, p, ProtractorPixels * ScreenScale / View.Scale)
        ' The trace says when the reading changes (not at every move).
        If _Protractor Is Nothing Then
            If before IsNot Nothing Then Emit("protractor none")
        ElseIf before Is Nothing OrElse before.Lower <> _Protractor.Lower OrElse before.Upper <> _Protractor.Upper Then
            Emit("protractor " & Units.Num(_Protractor.Degrees, 3) & " deg from " & Units.Pair(_Protractor.Lower, 3))
        End If
        If Not _tape.IsDragging Then Return False
        _tape.MoveTo(p)
        Return True
    End Function

    ''' <summary>A mouse button came up at (x, y) px: True when the tape took it.</summary>
    Private Function MeasurePointerUp(button As PointerButton, x As Double, y As Double) As Boolean
        If Not _tape.IsDragging OrElse button <> PointerButton.Left Then Return False
        Dim p = View.ToWorld(x, y)
        _tape.Release(If(p.IsFinite, p, _tape.Finish.Value))
        Emit("tape " & Exact(_tape.Length) & " m at " & Units.Num(_tape.AngleDegrees, 3) & " deg from " & Units.Pair(_tape.Start.Value, 3) & " to " & Units.Pair(_tape.Finish.Value, 3))
        Return True
    End Function

    ''' <summary>Esc: ends choosing a body, or the tape measure; True when it did.</summary>
    Private Function CancelMeasure() As Boolean
        If _choosingPassBody Then
            _choosingPassBody = False
            Emit("pass line cancelled")
            ShowMessage("")
            Return True
        End If
        If _tape.IsOn Then
            _tape.Clear()
            Emit("tape off")
            ShowMessage("")
            Return True
        End If
        Return False
    End Function

    ''' <summary>After a frame: the pass timer sees where its body is now.</summary>
    Private Sub FollowMeasures()
        Dim timer = PassTimer
        If timer Is Nothing Then Return
        Dim body = World.Find(timer.BodyId)
        If body Is Nothing Then Return
        Dim pass = timer.Observe(World.Time, body.CentreOfMass, body.Velocity)
        If pass.HasValue Then
            Emit("pass " & timer.BodyId & " " & timer.Passes.Count & " t=" & Exact(pass.Value) & " s" &
                 If(timer.Passes.Count > 1, " period " & Exact(timer.Period) & " s", ""))
        End If
    End Sub

    ''' <summary>A new scene: no tape line, no pass line, the stopwatch at zero.</summary>
    Private Sub ForgetMeasures()
        _tape.Clear()
        _PassTimer = Nothing
        _choosingPassBody = False
        _Protractor = Nothing
        _stopwatch?.Reset()
    End Sub

    ''' <summary>A time or length with every digit, for the trace.</summary>
    Private Shared Function Exact(value As Double) As String
        Return value.ToString("R", Globalization.CultureInfo.InvariantCulture)
    End Function
End Class
