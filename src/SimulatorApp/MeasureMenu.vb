Option Strict On
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>The Measure menu: the tape measure, the pass timer and the stopwatch; what each does is the presenter's.</summary>
Friend NotInheritable Class MeasureMenu
    Inherits DropDownMenu

    ''' <summary>The button's caption.</summary>
    Public Const Caption As String = "Measure ▾"

    ''' <param name="button">the Measure button the menu drops down from</param>
    Public Sub New(kit As WindowKit, button As Button)
        MyBase.New(kit, button, "measure")
    End Sub

    ''' <summary>Drops the menu down under its button, kept on the screen.</summary>
    Public Sub Show()
        Begin()
        Dim p = Kit.Presenter
        Dim entries As (Name As String, Text As String, Tip As String, Checked As Boolean, Action As Action)() = {
            ("tape", "Tape measure (drag between two points)", "The distance and the angle to the horizontal between two points; Esc ends it", p.Tape.IsOn, Sub() p.ToggleTapeMeasure()),
            ("passes", "Time passes of a body…", "Click a body: each pass of its centre through the tape's line, or a vertical line where it is, is timed, and the period shown", p.PassTimer IsNot Nothing, Sub() p.BeginPassLine()),
            ("start-stop", If(p.LabStopwatch.IsRunning, "Stopwatch: stop", "Stopwatch: start"), "Counts simulated time: it stands still while paused and follows the Speed slider", p.LabStopwatch.IsRunning, Sub() p.StopwatchStartStop()),
            ("lap", "Stopwatch: lap", "Notes the time now; the stopwatch runs on", False, Sub() p.StopwatchLap()),
            ("reset", "Stopwatch: reset", "Back to zero, and the pass timer off", False, Sub() p.StopwatchReset())}
        For Each e In entries
            Strip.Items.Add(NewItem(e.Text, e.Tip, e.Action, e.Checked))
        Next
        Drop(entries.Select(Function(e) e.Name).ToList())
    End Sub
End Class
