Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>
''' The Scenes menu: one item per topic, each opening its lessons (their titles; what each shows is
''' in its tip and, once opened, the message box), read from the scenes folder each time it opens, so
''' a file added there since is listed. The menu is kept on the screen, and its lists open towards
''' the side with room.
''' </summary>
Friend NotInheritable Class LessonMenu
    Inherits DropDownMenu

    ''' <param name="button">the Scenes button the menu drops down from</param>
    Public Sub New(kit As WindowKit, button As Button)
        MyBase.New(kit, button, "lesson")
    End Sub

    ''' <summary>Drops the menu down under its button.</summary>
    Public Sub Show()
        Begin()
        Dim p = Kit.Presenter
        Dim menu = p.LessonMenu()
        Dim count = 0
        For k = 0 To menu.Count - 1
            Dim topicIndex = k
            Dim topic As New ToolStripMenuItem(menu(k).Topic.Replace("&", "&&")) With {.BackColor = Back, .ForeColor = Fore}
            topic.DropDown.Font = Kit.Font
            topic.DropDown.BackColor = Back
            topic.DropDown.ForeColor = Fore
            If TypeOf topic.DropDown Is ToolStripDropDownMenu Then DirectCast(topic.DropDown, ToolStripDropDownMenu).ShowItemToolTips = True
            Dim lessons = menu(k).Lessons
            For Each lesson In lessons
                Dim chosen = lesson
                ' "&" would underline the next letter of a title; doubled it is shown as itself.
                Dim item As New ToolStripMenuItem(chosen.Title.Replace("&", "&&")) With {.BackColor = Back, .ForeColor = Fore, .ToolTipText = chosen.Summary}
                AddHandler item.Click, Sub(s, e) Kit.Act(Sub() Kit.Presenter.OpenLesson(chosen))
                topic.DropDownItems.Add(item)
                count += 1
            Next
            AddHandler topic.DropDownOpened, Sub(s, e) TraceList(topicIndex, topic, lessons)
            Strip.Items.Add(topic)
        Next
        If menu.Count = 0 Then
            Strip.Items.Add(New ToolStripMenuItem("No scene files in " & If(p.LessonFolder, "the scenes folder")) With {.Enabled = False, .BackColor = Back, .ForeColor = Fore})
        End If
        ' Under the button, moved as far as it takes to stay on the screen; the lists open to the
        ' right when there is room for the widest of them there, else to the left.
        Dim area = Screen.FromControl(Kit.Window).WorkingArea
        Dim size = Strip.GetPreferredSize(Drawing.Size.Empty)
        Dim widestList = Strip.Items.OfType(Of ToolStripMenuItem)().Select(Function(t) t.DropDown.GetPreferredSize(Drawing.Size.Empty).Width).DefaultIfEmpty(0).Max()
        Dim at = Kit.OnScreen(Owner, size)
        Dim direction = If(at.X + size.Width + widestList <= area.Right, ToolStripDropDownDirection.Right, ToolStripDropDownDirection.Left)
        For Each t In Strip.Items.OfType(Of ToolStripMenuItem)()
            t.DropDownDirection = direction
        Next
        Strip.Show(at)
        TraceMenu(menu, count)
    End Sub

    ''' <summary>With --trace: where each topic of the open menu is on the screen, and which topic holds each lesson (GUI tests click them there).</summary>
    Private Sub TraceMenu(menu As IReadOnlyList(Of (Topic As String, Lessons As IReadOnlyList(Of Lesson))), count As Integer)
        If Kit.Trace Is Nothing Then Return
        For k = 0 To Math.Min(menu.Count, Strip.Items.Count) - 1
            Dim b = Strip.Items(k).Bounds
            Dim p = Strip.PointToScreen(b.Location)
            Kit.Emit("lesson topic " & k & " " & p.X & " " & p.Y & " " & b.Width & " " & b.Height & " " & menu(k).Topic)
            For Each lesson In menu(k).Lessons
                Kit.Emit("lesson in " & k & " " & lesson.FileName)
            Next
        Next
        Kit.TraceMenuBounds("lesson menu", Strip)
        Kit.Emit("lesson menu shown " & count)
    End Sub

    ''' <summary>With --trace: where each lesson of a topic's list is on the screen, once it has opened.</summary>
    Private Sub TraceList(topic As Integer, item As ToolStripMenuItem, lessons As IReadOnlyList(Of Lesson))
        If Kit.Trace Is Nothing Then Return
        Dim list = item.DropDown
        For i = 0 To Math.Min(lessons.Count, list.Items.Count) - 1
            Dim b = list.Items(i).Bounds
            Dim p = list.PointToScreen(b.Location)
            Kit.Emit("lesson item " & i & " " & p.X & " " & p.Y & " " & b.Width & " " & b.Height & " " & lessons(i).FileName)
        Next
        Kit.TraceMenuBounds("lesson list " & topic, list)
        Kit.Emit("lesson list shown " & topic)
    End Sub
End Class
