Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

' The lesson toolkit's part of the window: the Scenes menu, the Restart button and the keys of
' pause, restart, reset and the menu. What they do is the presenter's (SimulationPresenter.Lessons).
Partial Friend NotInheritable Class MainForm
    Private ReadOnly _scenes As New Button()
    Private ReadOnly _restart As New Button()
    Private ReadOnly _lessonMenu As New ContextMenuStrip()
    Private ReadOnly _tips As New ToolTip()

    Private Sub BuildLessonControls()
        AddButton(_scenes, SimulationPresenter.ScenesCaption, AddressOf ShowLessonMenu)
        AddButton(_restart, SimulationPresenter.RestartCaption, Sub() _presenter.Restart())
        _tips.SetToolTip(_scenes, "Ready-made lesson scenes (" & SimulationPresenter.ScenesKey & ")")
        _tips.SetToolTip(_restart, "Back to the scene as it was opened or last built (" & SimulationPresenter.RestartKey & ")")
        _tips.SetToolTip(_pause, "Pause or resume (" & SimulationPresenter.PauseKey & ")")
        _tips.SetToolTip(_reset, "Remove every body (" & SimulationPresenter.ResetKey & ")")
        AddHandler _lessonMenu.Closed, Sub(s, e) _trace?.Invoke("lesson menu closed")
    End Sub

    Private Sub DisposeLessonControls()
        _lessonMenu.Dispose()
        _tips.Dispose()
    End Sub

    ''' <summary>The lesson toolkit's controls, by the names the --trace layout gives them.</summary>
    Private Function LessonControls() As IEnumerable(Of (Name As String, Control As Control))
        Return {("scenes", CType(_scenes, Control)), ("restart", CType(_restart, Control))}
    End Function

    ''' <summary>
    ''' Drops the Scenes menu down under its button: one item per lesson, its title and what it shows,
    ''' read from the scenes folder now, so a file added there since is listed.
    ''' </summary>
    Private Sub ShowLessonMenu()
        For Each old In _lessonMenu.Items.Cast(Of ToolStripItem)().ToList()
            old.Dispose()
        Next
        _lessonMenu.Items.Clear()
        Dim theme = _presenter.Theme
        Dim back = ScenePainter.Rgb(theme.Panel), fore = ScenePainter.Rgb(theme.PanelText)
        _lessonMenu.Font = Font
        _lessonMenu.BackColor = back
        _lessonMenu.ForeColor = fore
        Dim lessons = _presenter.Lessons()
        For Each lesson In lessons
            Dim chosen = lesson
            ' "&" would underline the next letter of a title; doubled it is shown as itself.
            Dim item As New ToolStripMenuItem(chosen.MenuText.Replace("&", "&&")) With {.BackColor = back, .ForeColor = fore}
            AddHandler item.Click, Sub(s, e) Act(Sub() _presenter.OpenLesson(chosen))
            _lessonMenu.Items.Add(item)
        Next
        If lessons.Count = 0 Then
            _lessonMenu.Items.Add(New ToolStripMenuItem("No scene files in " & If(_presenter.LessonFolder, "the scenes folder")) With {.Enabled = False, .BackColor = back, .ForeColor = fore})
        End If
        _lessonMenu.Show(_scenes, New Point(0, _scenes.Height))
        TraceLessonMenu(lessons)
    End Sub

    ''' <summary>With --trace: where each item of the open menu is on the screen (GUI tests click them there).</summary>
    Private Sub TraceLessonMenu(lessons As IReadOnlyList(Of Lesson))
        If _trace Is Nothing Then Return
        For i = 0 To Math.Min(lessons.Count, _lessonMenu.Items.Count) - 1
            Dim b = _lessonMenu.Items(i).Bounds
            Dim p = _lessonMenu.PointToScreen(b.Location)
            _trace("lesson item " & i & " " & p.X & " " & p.Y & " " & b.Width & " " & b.Height & " " & lessons(i).FileName)
        Next
        _trace("lesson menu shown " & lessons.Count)
    End Sub

    ''' <summary>The keys of the lesson toolkit, wherever the focus is (a text box keeps every other key).</summary>
    Protected Overrides Function ProcessCmdKey(ByRef msg As Message, keyData As Keys) As Boolean
        Select Case keyData
            Case Keys.Control Or Keys.P
                _trace?.Invoke("key pause")
                Act(Sub() _presenter.TogglePause())
                Return True
            Case Keys.Control Or Keys.R
                _trace?.Invoke("key restart")
                Act(Sub() _presenter.Restart())
                Return True
            Case Keys.Control Or Keys.Shift Or Keys.R
                _trace?.Invoke("key reset")
                Act(Sub() _presenter.Reset())
                Return True
            Case Keys.Control Or Keys.L
                _trace?.Invoke("key scenes")
                ShowLessonMenu()
                Return True
        End Select
        Return MyBase.ProcessCmdKey(msg, keyData)
    End Function
End Class
