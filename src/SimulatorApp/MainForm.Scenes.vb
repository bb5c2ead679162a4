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
    ''' Drops the Scenes menu down under its button: one item per topic, each opening its lessons
    ''' (their titles; what each shows is in its tip and, once opened, the message box), read from
    ''' the scenes folder now, so a file added there since is listed. The menu is kept on the screen,
    ''' and its lists open towards the side with room.
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
        _lessonMenu.ShowItemToolTips = True
        Dim menu = _presenter.LessonMenu()
        Dim count = 0
        For k = 0 To menu.Count - 1
            Dim topicIndex = k
            Dim topic As New ToolStripMenuItem(menu(k).Topic.Replace("&", "&&")) With {.BackColor = back, .ForeColor = fore}
            topic.DropDown.Font = Font
            topic.DropDown.BackColor = back
            topic.DropDown.ForeColor = fore
            If TypeOf topic.DropDown Is ToolStripDropDownMenu Then DirectCast(topic.DropDown, ToolStripDropDownMenu).ShowItemToolTips = True
            Dim lessons = menu(k).Lessons
            For Each lesson In lessons
                Dim chosen = lesson
                ' "&" would underline the next letter of a title; doubled it is shown as itself.
                Dim item As New ToolStripMenuItem(chosen.Title.Replace("&", "&&")) With {.BackColor = back, .ForeColor = fore, .ToolTipText = chosen.Summary}
                AddHandler item.Click, Sub(s, e) Act(Sub() _presenter.OpenLesson(chosen))
                topic.DropDownItems.Add(item)
                count += 1
            Next
            AddHandler topic.DropDownOpened, Sub(s, e) TraceLessonList(topicIndex, topic, lessons)
            _lessonMenu.Items.Add(topic)
        Next
        If menu.Count = 0 Then
            _lessonMenu.Items.Add(New ToolStripMenuItem("No scene files in " & If(_presenter.LessonFolder, "the scenes folder")) With {.Enabled = False, .BackColor = back, .ForeColor = fore})
        End If
        ' Under the button, moved left as far as it takes to stay on the screen; the lists open to the
        ' right when there is room for the widest of them there, else to the left.
        Dim area = Screen.FromControl(Me).WorkingArea
        Dim menuSize = _lessonMenu.GetPreferredSize(Drawing.Size.Empty)
        Dim widestList = _lessonMenu.Items.OfType(Of ToolStripMenuItem)().Select(Function(t) t.DropDown.GetPreferredSize(Drawing.Size.Empty).Width).DefaultIfEmpty(0).Max()
        Dim at = _scenes.PointToScreen(New Point(0, _scenes.Height))
        at.X = Math.Max(area.Left, Math.Min(at.X, area.Right - menuSize.Width))
        at.Y = Math.Max(area.Top, Math.Min(at.Y, area.Bottom - menuSize.Height))
        Dim direction = If(at.X + menuSize.Width + widestList <= area.Right, ToolStripDropDownDirection.Right, ToolStripDropDownDirection.Left)
        For Each t In _lessonMenu.Items.OfType(Of ToolStripMenuItem)()
            t.DropDownDirection = direction
        Next
        _lessonMenu.Show(at)
        TraceLessonMenu(menu, count)
    End Sub

    ''' <summary>With --trace: where each topic of the open menu is on the screen, and which topic holds each lesson (GUI tests click them there).</summary>
    Private Sub TraceLessonMenu(menu As IReadOnlyList(Of (Topic As String, Lessons As IReadOnlyList(Of Lesson))), count As Integer)
        If _trace Is Nothing Then Return
        For k = 0 To Math.Min(menu.Count, _lessonMenu.Items.Count) - 1
            Dim b = _lessonMenu.Items(k).Bounds
            Dim p = _lessonMenu.PointToScreen(b.Location)
            _trace("lesson topic " & k & " " & p.X & " " & p.Y & " " & b.Width & " " & b.Height & " " & menu(k).Topic)
            For Each lesson In menu(k).Lessons
                _trace("lesson in " & k & " " & lesson.FileName)
            Next
        Next
        TraceMenuBounds("lesson menu", _lessonMenu)
        _trace("lesson menu shown " & count)
    End Sub

    ''' <summary>With --trace: where each lesson of a topic's list is on the screen, once it has opened.</summary>
    Private Sub TraceLessonList(topic As Integer, item As ToolStripMenuItem, lessons As IReadOnlyList(Of Lesson))
        If _trace Is Nothing Then Return
        Dim list = item.DropDown
        For i = 0 To Math.Min(lessons.Count, list.Items.Count) - 1
            Dim b = list.Items(i).Bounds
            Dim p = list.PointToScreen(b.Location)
            _trace("lesson item " & i & " " & p.X & " " & p.Y & " " & b.Width & " " & b.Height & " " & lessons(i).FileName)
        Next
        TraceMenuBounds("lesson list " & topic, list)
        _trace("lesson list shown " & topic)
    End Sub

    ''' <summary>With --trace: a drop-down's rectangle on the screen and the screen's, and whether every item's text fits ("menu … on screen").</summary>
    Private Sub TraceMenuBounds(name As String, menu As ToolStrip)
        Dim r = New Drawing.Rectangle(menu.PointToScreen(Point.Empty), menu.Size)
        Dim area = Screen.FromControl(Me).Bounds
        Dim fits = menu.Items.Cast(Of ToolStripItem)().All(Function(i) Measure(i.Text, menu.Font).Width <= i.Bounds.Width)
        _trace(name & " at " & r.X & " " & r.Y & " " & r.Width & " " & r.Height & " screen " & area.Width & " " & area.Height & If(fits, " fits", " cut"))
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
        If keyData = (Keys.Control Or Keys.D0) OrElse keyData = (Keys.Control Or Keys.NumPad0) Then
            _trace?.Invoke("key whole view")
            Act(Sub() _presenter.ResetView())
            Return True
        End If
        ' Undo and redo, except in a text box, which undoes its own typing.
        If Not TypeOf ActiveControl Is TextBox Then
            Select Case keyData
                Case Keys.Control Or Keys.Z
                    _trace?.Invoke("key undo")
                    Act(Sub() _presenter.Undo())
                    Return True
                Case Keys.Control Or Keys.Y, Keys.Control Or Keys.Shift Or Keys.Z
                    _trace?.Invoke("key redo")
                    Act(Sub() _presenter.Redo())
                    Return True
            End Select
        End If
        If ProcessTimeKey(keyData) Then Return True
        If ProcessCornerKey(keyData) Then Return True
        Return MyBase.ProcessCmdKey(msg, keyData)
    End Function
End Class
