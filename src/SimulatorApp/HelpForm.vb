Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>A help window: the list of pages on the left, the chosen page on the right.</summary>
Friend NotInheritable Class HelpForm
    Inherits Form

    Private ReadOnly _pages As New ListBox()
    Private ReadOnly _text As New TextBox()
    Private ReadOnly _topics As IReadOnlyList(Of HelpTopic)

    Public Sub New(title As String, topics As IReadOnlyList(Of HelpTopic), font As Font)
        _topics = topics
        Text = title
        AutoScaleMode = AutoScaleMode.Dpi
        StartPosition = FormStartPosition.Manual
        Location = New Point(120, 60)
        ClientSize = New Size(1000, 640)
        ' Never smaller than 12 pt: this window is read from the back of a classroom.
        Me.Font = If(font IsNot Nothing AndAlso font.SizeInPoints >= 12, font, New Font(FontFamily.GenericSansSerif, 12.0F))
        _pages.Dock = DockStyle.Left
        _pages.Width = 300
        _pages.IntegralHeight = False
        For Each t In topics
            _pages.Items.Add(t.Title)
        Next
        _text.Dock = DockStyle.Fill
        _text.Multiline = True
        _text.ReadOnly = True
        _text.ScrollBars = ScrollBars.Vertical
        _text.BackColor = SystemColors.Window
        AddHandler _pages.SelectedIndexChanged, AddressOf OnPageChosen
        Controls.Add(_text)
        Controls.Add(_pages)
        If topics.Count > 0 Then _pages.SelectedIndex = 0
    End Sub

    Private Sub OnPageChosen(sender As Object, e As EventArgs)
        Dim i = _pages.SelectedIndex
        If i < 0 OrElse i >= _topics.Count Then Return
        _text.Text = _topics(i).Title & Environment.NewLine & Environment.NewLine & _topics(i).Text.Replace(vbLf, Environment.NewLine)
        _text.SelectionStart = 0
        _text.SelectionLength = 0
    End Sub
End Class
