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
        ' On the tabs' header row, right of the tabs, where there is room at every screen size: the
        ' side panel has no row to spare on a 1024 × 768 projector.
        AddHeaderButton(_scenes, SimulationPresenter.ScenesCaption, AddressOf ShowLessonMenu)
        AddHeaderButton(_restart, SimulationPresenter.RestartCaption, Sub() _presenter.Restart())
        _tips.SetToolTip(_scenes, "Ready-made lesson scenes (" & SimulationPresenter.ScenesKey & ")")
        _tips.SetToolTip(_restart, "Back to the scene as it was opened or last built (" & SimulationPresenter.RestartKey & ")")
        _tips.SetToolTip(_pause, "Pause or resume (" & SimulationPresenter.PauseKey & ")")
        _tips.SetToolTip(_reset, "Remove every body (" & SimulationPresenter.ResetKey & ")")
        AddHandler _lessonMenu.Closed, Sub(s, e) _trace?.Invoke("lesson menu closed")
    End Sub

    Private Sub AddHeaderButton(button As Button, text As String, action As Action)
        button.Text = text
        button.UseMnemonic = False
        AddHandler button.Click, Sub(s, e) Act(action)
        Controls.Add(button)
        button.BringToFront()
    End Sub

    ''' <summary>
    ''' Scenes and Restart at the right end of the tabs' header row (<paramref name="top"/> px down,
    ''' ending <paramref name="right"/> px across), each as wide as its caption, in the theme's
    ''' colours (they are not on the side panel, which colours its own).
    ''' </summary>
    Private Sub PlaceLessonButtons(top As Integer, right As Integer)
        Dim header = If(_tabs.TabCount > 0, _tabs.GetTabRect(0).Height, LineHeight(Font) + S(8))
        ' As tall as the side panel's buttons (Mono centres a caption by the font height it reports,
        ' and clips it in a shorter button). Where the tabs are shorter (Mono does not scale them with
        ' the DPI) the tabs move down, so the buttons end level with them and cover no text.
        Dim height = Math.Max(S(26), Math.Max(LineHeight(Font) + S(9), Font.Height + S(4)))
        Dim extra = Math.Max(0, height - header)
        If extra > 0 Then _tabs.SetBounds(_tabs.Left, top + extra, _tabs.Width, Math.Max(1, _tabs.Height - extra))
        Dim x = right - S(6)
        For Each b In {_restart, _scenes}
            Dim width = Math.Max(S(90), Measure(b.Text, Font).Width + S(24))
            x -= width
            b.SetBounds(x, top, width, height)
            x -= S(6)
            b.BringToFront()
        Next
        Dim theme = _presenter.Theme
        For Each b In {_scenes, _restart}
            b.ForeColor = ScenePainter.Rgb(theme.PanelText)
            b.BackColor = ScenePainter.Rgb(theme.Button)
            b.FlatStyle = If(theme.IsHighContrast, FlatStyle.Flat, FlatStyle.Standard)
            b.FlatAppearance.BorderColor = ScenePainter.Rgb(theme.PanelText)
            b.FlatAppearance.BorderSize = If(theme.IsHighContrast, 2, 1)
            b.UseVisualStyleBackColor = Not theme.IsHighContrast
        Next
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
        _lessonMenu.Renderer = If(theme.IsHighContrast, New ToolStripProfessionalRenderer(New LessonMenuColours()), New ToolStripProfessionalRenderer())
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
        If ProcessTimeKey(keyData) Then Return True
        If ProcessCornerKey(keyData) Then Return True
        Return MyBase.ProcessCmdKey(msg, keyData)
    End Function
End Class
