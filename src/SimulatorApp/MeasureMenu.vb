Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>The Measure menu: the tape measure, the pass timer and the stopwatch; what each does is the presenter's.</summary>
Friend NotInheritable Class MeasureMenu
    Implements IDisposable

    ''' <summary>The button's caption.</summary>
    Public Const Caption As String = "Measure ▾"

    Private ReadOnly _kit As WindowKit
    Private ReadOnly _button As Button
    Private ReadOnly _menu As New ContextMenuStrip()

    ''' <param name="button">the Measure button the menu drops down from</param>
    Public Sub New(kit As WindowKit, button As Button)
        _kit = kit
        _button = button
        AddHandler _menu.Closed, Sub(s, e) _kit.Emit("measure menu closed")
    End Sub

    ''' <summary>Drops the menu down under its button, kept on the screen.</summary>
    Public Sub Show()
        Dim p = _kit.Presenter
        Dim theme = p.Theme
        _kit.Prepare(_menu, theme)
        Dim back = ScenePainter.Rgb(theme.Panel), fore = ScenePainter.Rgb(theme.PanelText)
        Dim entries As (Name As String, Text As String, Tip As String, Checked As Boolean, Action As Action)() = {
            ("tape", "Tape measure (drag between two points)", "The distance and the angle to the horizontal between two points; Esc ends it", p.Tape.IsOn, Sub() p.ToggleTapeMeasure()),
            ("passes", "Time passes of a body…", "Click a body: each pass of its centre through the tape's line, or a vertical line where it is, is timed, and the period shown", p.PassTimer IsNot Nothing, Sub() p.BeginPassLine()),
            ("start-stop", If(p.LabStopwatch.IsRunning, "Stopwatch: stop", "Stopwatch: start"), "Counts simulated time: it stands still while paused and follows the Speed slider", p.LabStopwatch.IsRunning, Sub() p.StopwatchStartStop()),
            ("lap", "Stopwatch: lap", "Notes the time now; the stopwatch runs on", False, Sub() p.StopwatchLap()),
            ("reset", "Stopwatch: reset", "Back to zero, and the pass timer off", False, Sub() p.StopwatchReset())}
        For Each e In entries
            Dim act = e.Action
            Dim item As New ToolStripMenuItem(e.Text) With {.BackColor = back, .ForeColor = fore, .ToolTipText = e.Tip, .Checked = e.Checked}
            AddHandler item.Click, Sub(s, ev) _kit.Act(act)
            _menu.Items.Add(item)
        Next
        _menu.Show(_kit.OnScreen(_button, _menu.GetPreferredSize(Size.Empty)))
        If _kit.Trace IsNot Nothing Then
            For i = 0 To _menu.Items.Count - 1
                Dim b = _menu.Items(i).Bounds
                Dim at = _menu.PointToScreen(b.Location)
                _kit.Emit("measure item " & i & " " & at.X & " " & at.Y & " " & b.Width & " " & b.Height & " " & entries(i).Name)
            Next
            _kit.TraceMenuBounds("measure menu", _menu)
            _kit.Emit("measure menu shown " & _menu.Items.Count)
        End If
    End Sub

    Public Sub Dispose() Implements IDisposable.Dispose
        _menu.Dispose()
    End Sub
End Class
