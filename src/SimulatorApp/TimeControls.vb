Option Strict On
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>
''' The player row of the side panel: step back and forward a frame or a collision, and the timeline
''' slider between them, with their keys. What they do is the presenter's (its TimeMachine).
''' </summary>
Friend NotInheritable Class TimeControls
    Implements IDisposable

    Private ReadOnly _kit As WindowKit
    Private ReadOnly _stepBack As New Button()
    Private ReadOnly _step As New Button()
    Private ReadOnly _previousCollision As New Button()
    Private ReadOnly _nextCollision As New Button()
    Private ReadOnly _timeline As New ScaledSlider()
    Private _timelineTip As String = ""
    ''' <summary>True while the thumb is put where the presenter says: the slider's own change is not the teacher's.</summary>
    Private _showing As Boolean

    ''' <param name="panel">the side panel's content, where the row goes</param>
    Public Sub New(kit As WindowKit, panel As Control)
        _kit = kit
        For Each b In {(_previousCollision, SimulationPresenter.PreviousCollisionCaption, CType(Sub() _kit.Presenter.StepToPreviousCollision(), Action), "Back to the last collision (" & SimulationPresenter.PreviousCollisionKey & ")"),
                       (_stepBack, SimulationPresenter.StepBackCaption, CType(Sub() _kit.Presenter.StepBackFrame(), Action), "One frame back (" & SimulationPresenter.StepBackKey & ")"),
                       (_step, SimulationPresenter.StepCaption, CType(Sub() _kit.Presenter.StepFrame(), Action), "One frame on (" & SimulationPresenter.StepKey & ")"),
                       (_nextCollision, SimulationPresenter.NextCollisionCaption, CType(Sub() _kit.Presenter.StepToNextCollision(), Action), "On to the next collision (" & SimulationPresenter.NextCollisionKey & ")")}
            Dim action = b.Item3
            b.Item1.Text = b.Item2
            b.Item1.UseMnemonic = False
            AddHandler b.Item1.Click, Sub(s, e) _kit.Act(action)
            _kit.Tips.SetToolTip(b.Item1, b.Item4)
            panel.Controls.Add(b.Item1)
        Next
        _timeline.ScreenScale = kit.Dpi.Scale
        _timeline.Minimum = 0
        _timeline.Maximum = SimulationPresenter.TimelineSteps
        _timeline.TickFrequency = SimulationPresenter.TimelineSteps \ 10
        _timeline.SmallChange = 1
        _timeline.LargeChange = SimulationPresenter.TimelineSteps \ 20
        AddHandler _timeline.ValueChanged, Sub(s, e) If Not _showing Then _kit.Act(Sub() _kit.Presenter.TimelineSliderMoved(_timeline.Value))
        panel.Controls.Add(_timeline)
    End Sub

    ''' <summary>
    ''' The row, after the Tutorial/Open/Save rows: the timeline between the steps back and the steps
    ''' on, like a player's. One row, so the panel still fits a 1280 × 720 screen; the time is on the
    ''' totals line, and the stretch kept in the slider's tip and the messages.
    ''' </summary>
    Public Sub Arrange(rows As PanelRows, line As Integer)
        ' A line of text and a margin: these captions are single symbols, centred in what there is.
        ' Where a share is too narrow for its symbol (large fonts on a small screen) the button widens and the timeline gives way.
        rows.CaptionRow(Math.Max(_kit.S(26), line + _kit.S(9)), (_previousCollision, 0.11, {_previousCollision.Text}), (_stepBack, 0.1, {_stepBack.Text}),
                        (_timeline, 0.58, Nothing), (_step, 0.1, {_step.Text}), (_nextCollision, 0.11, {_nextCollision.Text}))
    End Sub

    ''' <summary>The timeline's tip and thumb follow the time on show (not while the teacher holds the thumb).</summary>
    Public Sub Show()
        Dim p = _kit.Presenter
        Dim tip = p.TimelineText
        If tip <> _timelineTip Then
            _timelineTip = tip
            _kit.Tips.SetToolTip(_timeline, tip)
        End If
        Dim wanted = p.TimelinePosition
        If _timeline.Value <> wanted AndAlso Not _timeline.Capture Then
            _showing = True
            Try
                _timeline.Value = wanted
            Finally
                _showing = False
            End Try
        End If
    End Sub

    ''' <summary>The controls, by the names the --trace layout gives them.</summary>
    Public Function Controls() As IEnumerable(Of (Name As String, Control As Control))
        Return {("timeline", CType(_timeline, Control)),
                ("previous-collision", CType(_previousCollision, Control)), ("step-back", CType(_stepBack, Control)),
                ("step", CType(_step, Control)), ("next-collision", CType(_nextCollision, Control))}
    End Function

    ''' <summary>
    ''' The keys: . and → a frame on, , and ← a frame back, Ctrl+→ and Ctrl+← a collision on and back.
    ''' Not while a text box has the focus (it keeps its keys), and the arrows not while a slider has
    ''' it (they move it). Returns whether the key was one of them.
    ''' </summary>
    Public Function ProcessKey(keyData As Keys, focused As Control) As Boolean
        If TypeOf focused Is TextBox Then Return False
        Dim onSlider = TypeOf focused Is ScaledSlider
        Dim p = _kit.Presenter
        Dim action As Action = Nothing
        Dim name As String = Nothing
        Select Case keyData
            Case Keys.OemPeriod : action = AddressOf p.StepFrame : name = "step"
            Case Keys.Oemcomma : action = AddressOf p.StepBackFrame : name = "step back"
            Case Keys.Right : If Not onSlider Then action = AddressOf p.StepFrame : name = "step"
            Case Keys.Left : If Not onSlider Then action = AddressOf p.StepBackFrame : name = "step back"
            Case Keys.Control Or Keys.Right : action = AddressOf p.StepToNextCollision : name = "next collision"
            Case Keys.Control Or Keys.Left : action = AddressOf p.StepToPreviousCollision : name = "previous collision"
        End Select
        If action Is Nothing Then Return False
        _kit.Emit("key " & name)
        _kit.Act(action)
        Return True
    End Function

    ''' <summary>Its controls (the window disposes them too, with the panel; a second time does nothing).</summary>
    Public Sub Dispose() Implements IDisposable.Dispose
        _stepBack.Dispose()
        _step.Dispose()
        _previousCollision.Dispose()
        _nextCollision.Dispose()
        _timeline.Dispose()
    End Sub
End Class
