Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>
''' A help window: the list of pages on the left, the chosen page on the right, in the main window's
''' theme. A page's title wraps in the list rather than being cut; Esc closes the window.
''' </summary>
Friend NotInheritable Class HelpForm
    Inherits Form

    Private ReadOnly _pages As New ListBox()
    Private ReadOnly _text As New TextBox()
    Private ReadOnly _topics As IReadOnlyList(Of HelpTopic)
    Private ReadOnly _trace As Action(Of String)
    Private ReadOnly _theme As Theme
    Private ReadOnly _scale As Double

    ''' <param name="scale">screen pixels per 96-dpi pixel</param>
    ''' <param name="trace">with --trace, told each page shown (GUI tests read the text through it)</param>
    Public Sub New(title As String, topics As IReadOnlyList(Of HelpTopic), font As Font, theme As Theme, scale As Double, trace As Action(Of String))
        _topics = topics
        _trace = trace
        _theme = theme
        _scale = scale
        Text = title
        AutoScaleMode = AutoScaleMode.None
        StartPosition = FormStartPosition.Manual
        KeyPreview = True
        ' Over the canvas, leaving the side panel's buttons free; as large as designed, but never larger than the screen.
        Dim area = Screen.FromPoint(Control.MousePosition).WorkingArea
        Dim w = Math.Min(CInt(1000 * scale), CInt(area.Width * 0.6))
        Dim h = Math.Min(CInt(640 * scale), area.Height - CInt(80 * scale))
        Bounds = New Drawing.Rectangle(area.X + CInt(10 * scale), area.Y + CInt(40 * scale), w, h)
        ' Never smaller than 12 pt at 96 dpi: this window is read from the back of a classroom.
        Dim least = CSng(12 * scale)
        Me.Font = If(font IsNot Nothing AndAlso font.SizeInPoints >= least, font, New Font(FontFamily.GenericSansSerif, least))
        _pages.Dock = DockStyle.Left
        _pages.Width = CInt(w * 0.32)
        _pages.IntegralHeight = False
        ' Each title as many lines tall as it needs at the list's width: a long title wraps, never cut.
        _pages.DrawMode = DrawMode.OwnerDrawVariable
        AddHandler _pages.MeasureItem, AddressOf OnMeasureTitle
        AddHandler _pages.DrawItem, AddressOf OnDrawTitle
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
        AddHandler FormClosed, Sub(s, e) _trace?.Invoke("help closed " & title)
    End Sub

    ''' <summary>Room inside the list around a title, px.</summary>
    Private ReadOnly Property Margin96 As Integer
        Get
            Return CInt(Math.Round(6 * _scale))
        End Get
    End Property

    ''' <summary>The width a title wraps at, px.</summary>
    Private ReadOnly Property TitleWidth As Integer
        Get
            ' Leave room for the list's own scroll bar.
            Return Math.Max(20, _pages.ClientSize.Width - 2 * Margin96 - CInt(18 * _scale))
        End Get
    End Property

    Private Sub OnMeasureTitle(sender As Object, e As MeasureItemEventArgs)
        If e.Index < 0 OrElse e.Index >= _topics.Count Then Return
        Dim size = e.Graphics.MeasureString(_topics(e.Index).Title, Font, TitleWidth)
        e.ItemHeight = Math.Min(255, CInt(Math.Ceiling(size.Height)) + 2 * Margin96)
    End Sub

    Private Sub OnDrawTitle(sender As Object, e As DrawItemEventArgs)
        If e.Index < 0 OrElse e.Index >= _topics.Count Then Return
        Dim chosen = (e.State And DrawItemState.Selected) = DrawItemState.Selected
        Dim back = If(chosen, If(_theme IsNot Nothing AndAlso _theme.IsHighContrast, Color.FromArgb(&H15, &H65, &HC0), SystemColors.Highlight), _pages.BackColor)
        Dim fore = If(chosen, Color.White, _pages.ForeColor)
        Using b As New SolidBrush(back), ink As New SolidBrush(fore)
            e.Graphics.FillRectangle(b, e.Bounds)
            e.Graphics.DrawString(_topics(e.Index).Title, Font, ink, New RectangleF(e.Bounds.X + Margin96, e.Bounds.Y + Margin96, TitleWidth, e.Bounds.Height - Margin96))
        End Using
    End Sub

    ''' <summary>Esc closes the window, as it closes every other secondary window.</summary>
    Protected Overrides Function ProcessCmdKey(ByRef msg As Message, keyData As Keys) As Boolean
        If keyData = Keys.Escape Then
            Close()
            Return True
        End If
        Return MyBase.ProcessCmdKey(msg, keyData)
    End Function

    ''' <summary>With --trace: every page, once, so tests can read them all; then back to the first.</summary>
    Private Sub ShowEveryPage()
        If _trace Is Nothing Then Return
        ' Whether each title shows whole in the list: its wrapped height fits the row it was given.
        Using g = _pages.CreateGraphics()
            For i = 0 To _topics.Count - 1
                Dim needs = CInt(Math.Ceiling(g.MeasureString(_topics(i).Title, Font, TitleWidth).Height))
                Dim row = _pages.GetItemRectangle(i)
                _trace("help title " & i & " row " & row.Height & " needs " & (needs + Margin96) & " width " & TitleWidth & " " & _topics(i).Title)
            Next
        End Using
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
