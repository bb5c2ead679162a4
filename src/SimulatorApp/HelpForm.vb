Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>A help window: the list of pages on the left, the chosen page on the right, in the main window's theme.</summary>
Friend NotInheritable Class HelpForm
    Inherits Form

    Private ReadOnly _pages As New ListBox()
    Private ReadOnly _text As New TextBox()
    Private ReadOnly _topics As IReadOnlyList(Of HelpTopic)
    Private ReadOnly _trace As Action(Of String)

    ''' <param name="scale">screen pixels per 96-dpi pixel</param>
    ''' <param name="trace">with --trace, told each page shown (GUI tests read the text through it)</param>
    Public Sub New(title As String, topics As IReadOnlyList(Of HelpTopic), font As Font, theme As Theme, scale As Double, trace As Action(Of String))
        _topics = topics
        _trace = trace
        Text = title
        AutoScaleMode = AutoScaleMode.None
        StartPosition = FormStartPosition.Manual
        ' Over the canvas, leaving the side panel's buttons free; as large as designed, but never larger than the screen.
        Dim area = Screen.FromPoint(Control.MousePosition).WorkingArea
        Dim w = Math.Min(CInt(1000 * scale), CInt(area.Width * 0.6))
        Dim h = Math.Min(CInt(640 * scale), area.Height - CInt(80 * scale))
        Bounds = New Drawing.Rectangle(area.X + CInt(10 * scale), area.Y + CInt(40 * scale), w, h)
        ' Never smaller than 12 pt at 96 dpi: this window is read from the back of a classroom.
        Dim least = CSng(12 * scale)
        Me.Font = If(font IsNot Nothing AndAlso font.SizeInPoints >= least, font, New Font(FontFamily.GenericSansSerif, least))
        _pages.Dock = DockStyle.Left
        _pages.Width = CInt(w * 0.3)
        _pages.IntegralHeight = False
        For Each t In topics
            _pages.Items.Add(t.Title)
        Next
        _text.Dock = DockStyle.Fill
        _text.Multiline = True
        _text.ReadOnly = True
        _text.ScrollBars = ScrollBars.Vertical
        If theme IsNot Nothing Then
            For Each c As Control In {CType(_text, Control), _pages, Me}
                c.BackColor = ScenePainter.Rgb(If(theme.IsHighContrast, theme.Panel, &HFFFFFF))
                c.ForeColor = ScenePainter.Rgb(theme.PanelText)
            Next
        End If
        AddHandler _pages.SelectedIndexChanged, AddressOf OnPageChosen
        Controls.Add(_text)
        Controls.Add(_pages)
        If topics.Count > 0 Then _pages.SelectedIndex = 0
        AddHandler Shown, Sub(s, e) ShowEveryPage()
    End Sub

    ''' <summary>With --trace: every page, once, so tests can read them all; then back to the first.</summary>
    Private Sub ShowEveryPage()
        If _trace Is Nothing Then Return
        For i = 1 To _topics.Count - 1
            _pages.SelectedIndex = i
        Next
        If _topics.Count > 0 Then _pages.SelectedIndex = 0
    End Sub

    Private Sub OnPageChosen(sender As Object, e As EventArgs)
        Dim i = _pages.SelectedIndex
        If i < 0 OrElse i >= _topics.Count Then Return
        _text.Text = _topics(i).Title & Environment.NewLine & Environment.NewLine & _topics(i).Text.Replace(vbLf, Environment.NewLine)
        _text.SelectionStart = 0
        _text.SelectionLength = 0
        _trace?.Invoke("help page " & _topics(i).Title & ": " & _text.Text.Replace(Environment.NewLine, " "))
    End Sub
End Class
