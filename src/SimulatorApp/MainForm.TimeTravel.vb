Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

' The time controls' part of the window: step back and forward a frame or a collision, and the
' timeline slider. What they do is the presenter's (SimulationPresenter.TimeTravel).
Partial Friend NotInheritable Class MainForm
    Private ReadOnly _stepBack As New Button()
    Private ReadOnly _step As New Button()
    Private ReadOnly _previousCollision As New Button()
    Private ReadOnly _nextCollision As New Button()
    Private ReadOnly _timeline As New ScaledSlider()
    Private _timelineTip As String = ""

    Private Sub BuildTimeControls()
        AddButton(_previousCollision, SimulationPresenter.PreviousCollisionCaption, Sub() _presenter.StepToPreviousCollision())
        AddButton(_stepBack, SimulationPresenter.StepBackCaption, Sub() _presenter.StepBackFrame())
        AddButton(_step, SimulationPresenter.StepCaption, Sub() _presenter.StepFrame())
        AddButton(_nextCollision, SimulationPresenter.NextCollisionCaption, Sub() _presenter.StepToNextCollision())
        SetUpSlider(_timeline, SimulationPresenter.TimelineSteps, SimulationPresenter.TimelineSteps \ 10, Sub() _presenter.TimelineSliderMoved(_timeline.Value))
        _timeline.SmallChange = 1
        _timeline.LargeChange = SimulationPresenter.TimelineSteps \ 20
        _tips.SetToolTip(_previousCollision, "Back to the last collision (" & SimulationPresenter.PreviousCollisionKey & ")")
        _tips.SetToolTip(_stepBack, "One frame back (" & SimulationPresenter.StepBackKey & ")")
        _tips.SetToolTip(_step, "One frame on (" & SimulationPresenter.StepKey & ")")
        _tips.SetToolTip(_nextCollision, "On to the next collision (" & SimulationPresenter.NextCollisionKey & ")")
        ' Every control of the side panel says when it takes the focus, so a test can follow Tab.
        For Each c As Control In _side.Controls
            Dim control = c
            AddHandler control.GotFocus,
                Sub(s, e)
                    ' Tab to a control below the panel's visible part scrolls it into view.
                    _sideView.EnsureVisible(control)
                    If _trace Is Nothing Then Return
                    Dim p = control.PointToScreen(Point.Empty)
                    Dim name = NamedControls().FirstOrDefault(Function(n) n.Control Is control).Name
                    _trace("focus " & p.X & " " & p.Y & " " & control.GetType().Name & " " & If(name, "-"))
                End Sub
        Next
    End Sub

    ''' <summary>
    ''' The time controls' row, after the Tutorial/Open/Save rows: the timeline between the steps back
    ''' and the steps on, like a player's. One row, so the panel still fits a 1280 × 720 screen; the
    ''' time is on the totals line, and the stretch kept in the slider's tip and the messages.
    ''' </summary>
    Private Sub ArrangeTimeControls(line As Integer)
        ' A line of text and a margin: at 192 dpi Mono's buttons ask for more (see ArrangeControls), which
        ' the panel has no room for; these captions are single symbols, centred in what there is.
        Row(Math.Max(S(26), line + S(9)), (_previousCollision, 0.11), (_stepBack, 0.1), (_timeline, 0.58), (_step, 0.1), (_nextCollision, 0.11))
    End Sub

    ''' <summary>Tab goes through the side panel as it reads: row by row, left to right (the order the controls were made in is not that).</summary>
    Private Sub OrderTabsByPlace()
        ' A text box sits a few pixels lower than the buttons of its row (it is centred in it): controls
        ' whose tops are that close are one row.
        Dim byTop = _side.Controls.Cast(Of Control)().OrderBy(Function(c) c.Top).ToList()
        Dim index = 0, first = 0
        Do While first < byTop.Count
            Dim last = first
            Do While last + 1 < byTop.Count AndAlso byTop(last + 1).Top < byTop(first).Top + S(12)
                last += 1
            Loop
            For Each c In byTop.Skip(first).Take(last - first + 1).OrderBy(Function(x) x.Left)
                c.TabIndex = index
                index += 1
            Next
            first = last + 1
        Loop
    End Sub

    ''' <summary>The timeline's label and thumb follow the time on show.</summary>
    Private Sub ShowTimeline()
        Dim tip = _presenter.TimelineText
        If tip <> _timelineTip Then
            _timelineTip = tip
            _tips.SetToolTip(_timeline, tip)
        End If
        Dim wanted = _presenter.TimelinePosition
        If _timeline.Value <> wanted AndAlso Not _timeline.Capture Then
            Dim was = _updating
            _updating = True
            _timeline.Value = wanted
            _updating = was
        End If
    End Sub

    ''' <summary>The time controls, by the names the --trace layout gives them.</summary>
    Private Function TimeControls() As IEnumerable(Of (Name As String, Control As Control))
        Return {("timeline", CType(_timeline, Control)),
                ("previous-collision", CType(_previousCollision, Control)), ("step-back", CType(_stepBack, Control)),
                ("step", CType(_step, Control)), ("next-collision", CType(_nextCollision, Control))}
    End Function

    ''' <summary>
    ''' The time controls' keys: . and → a frame on, , and ← a frame back, Ctrl+→ and Ctrl+← a
    ''' collision on and back. Not while a text box has the focus (it keeps its keys), and the arrows
    ''' not while a slider has it (they move it).
    ''' </summary>
    Private Function ProcessTimeKey(keyData As Keys) As Boolean
        Dim focused = ActiveControl
        If TypeOf focused Is TextBox Then Return False
        Dim onSlider = TypeOf focused Is ScaledSlider
        Dim action As Action = Nothing
        Dim name As String = Nothing
        Select Case keyData
            Case Keys.OemPeriod : action = AddressOf _presenter.StepFrame : name = "step"
            Case Keys.Oemcomma : action = AddressOf _presenter.StepBackFrame : name = "step back"
            Case Keys.Right : If Not onSlider Then action = AddressOf _presenter.StepFrame : name = "step"
            Case Keys.Left : If Not onSlider Then action = AddressOf _presenter.StepBackFrame : name = "step back"
            Case Keys.Control Or Keys.Right : action = AddressOf _presenter.StepToNextCollision : name = "next collision"
            Case Keys.Control Or Keys.Left : action = AddressOf _presenter.StepToPreviousCollision : name = "previous collision"
        End Select
        If action Is Nothing Then Return False
        _trace?.Invoke("key " & name)
        Act(action)
        Return True
    End Function
End Class
