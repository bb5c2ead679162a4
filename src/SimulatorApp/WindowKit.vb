Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>
''' What the window's parts share, and all they see of one another: the presenter, the trace, the
''' screen's scale and the measure of text at the DPI GDI+ draws at, the tooltips, the window's font,
''' and how a teacher's action is run (then the canvas redrawn). Each part (the lesson, solver and
''' export menus, the Graphs tab, the player row, the momentum boxes, the table's edit box, the side
''' panel's rows) keeps its own controls and state and is handed this; <see cref="MainForm"/> builds them.
''' </summary>
Friend NotInheritable Class WindowKit
    Implements IDisposable

    Private ReadOnly _window As Form
    Private ReadOnly _act As Action(Of Action)
    Private _measureBitmap As Bitmap
    Private _measure As Graphics

    ''' <param name="window">the main window (its font, its screen)</param>
    ''' <param name="act">runs a teacher's action and redraws the canvas</param>
    Public Sub New(window As Form, dpi As ScreenDpi, trace As Action(Of String), act As Action(Of Action))
        _window = window
        Me.Dpi = dpi
        Me.Trace = trace
        _act = act
    End Sub

    ''' <summary>The presenter (set once it exists: it is made after the controls).</summary>
    Public Property Presenter As SimulationPresenter

    ''' <summary>The screen's DPI and scale.</summary>
    Public ReadOnly Property Dpi As ScreenDpi

    ''' <summary>Receives one line per action with --trace; Nothing otherwise.</summary>
    Public ReadOnly Property Trace As Action(Of String)

    ''' <summary>The tooltips of every control.</summary>
    Public ReadOnly Property Tips As New ToolTip()

    ''' <summary>The window's font now (large fonts change it).</summary>
    Public ReadOnly Property Font As Font
        Get
            Return _window.Font
        End Get
    End Property

    ''' <summary>The window (menus and dialogs open over it).</summary>
    Public ReadOnly Property Window As Form
        Get
            Return _window
        End Get
    End Property

    ''' <summary>Writes a line to the trace, if there is one.</summary>
    Public Sub Emit(line As String)
        Trace?.Invoke(line)
    End Sub

    ''' <summary>Runs a teacher's action, then redraws the canvas. The presenter turns failures into messages.</summary>
    Public Sub Act(action As Action)
        _act(action)
    End Sub

    ''' <summary>Pixels at 96 dpi to pixels on this screen.</summary>
    Public Function S(px As Double) As Integer
        Dim f = If(Dpi IsNot Nothing, Dpi.Scale, 1.0)
        Return CInt(Math.Round(px * f))
    End Function

    ''' <summary>
    ''' The size of text as it will be drawn, wrapped at <paramref name="width"/> px when given. It is
    ''' measured at the DPI GDI+ draws points at: Mono's own measures (Font.Height, TextRenderer) use
    ''' the DPI it reports, which under a desktop's Xft.dpi is not the one it draws with.
    ''' </summary>
    Public Function Measure(text As String, font As Font, Optional width As Integer = 0) As Size
        If _measure Is Nothing Then
            _measureBitmap = New Bitmap(1, 1)
            _measureBitmap.SetResolution(CSng(Dpi.Graphics), CSng(Dpi.Graphics))
            _measure = Graphics.FromImage(_measureBitmap)
        End If
        Dim sz = If(width > 0, _measure.MeasureString(If(text, ""), font, width), _measure.MeasureString(If(text, ""), font))
        Return New Size(CInt(Math.Ceiling(sz.Width)), CInt(Math.Ceiling(sz.Height)))
    End Function

    ''' <summary>The height of one line of text in <paramref name="font"/>, px.</summary>
    Public Function LineHeight(font As Font) As Integer
        Return Measure("Ag", font).Height
    End Function

    ''' <summary>Height of a row of buttons: a line of text as drawn and a margin (see <see cref="CentreCaption"/>).</summary>
    Public Function ButtonRowHeight() As Integer
        Return Math.Max(S(26), LineHeight(Font) + S(9))
    End Function

    ''' <summary>
    ''' Puts a button's one-line caption in its middle by the measured height of the text. Mono centres
    ''' a caption by the font height it reports, which a desktop's Xft.dpi inflates (95 px for a 44-px
    ''' line at 192 dpi with large fonts): a button no taller than the text needs would show its caption
    ''' low and cut. Aligned to the top with a measured top padding, the caption sits in the middle on
    ''' Mono and on Windows alike.
    ''' </summary>
    Public Sub CentreCaption(b As Button)
        If b Is Nothing Then Throw New ArgumentNullException(NameOf(b))
        ' The button's edge: 2 px of bevel and 1 of focus margin inside it, on both.
        Const edge = 3
        Dim top = Math.Max(0, (b.Height - LineHeight(b.Font)) \ 2 - edge)
        b.TextAlign = ContentAlignment.TopCenter
        If b.Padding.Top <> top Then b.Padding = New Padding(0, top, 0, 0)
    End Sub

    ''' <summary>Mono's vertical scroll bar of a text box (an internal field; Nothing on Windows, which has none to fight).</summary>
    Private Shared ReadOnly MonoVerticalScroll As Reflection.FieldInfo =
        GetType(TextBoxBase).GetField("vscroll", Reflection.BindingFlags.Instance Or Reflection.BindingFlags.NonPublic)

    ''' <summary>
    ''' How far down <paramref name="box"/>'s view of its text is scrolled, px (0: its line shows from its
    ''' top). Mono keeps this in its own scroll bar, hidden in a box without scroll bars; 0 where there is none.
    ''' </summary>
    Public Shared Function ViewTop(box As TextBox) As Integer
        If box Is Nothing Then Throw New ArgumentNullException(NameOf(box))
        Dim bar = TryCast(MonoVerticalScroll?.GetValue(box), ScrollBar)
        Return If(bar Is Nothing, 0, bar.Value)
    End Function

    ''' <summary>
    ''' Puts <paramref name="box"/>'s one line back at the top of its view. Mono lays out a line as tall
    ''' as the font height it reports (under a desktop's Xft.dpi twice the text drawn: 48 px for 24 px of
    ''' figures at 192 dpi) and, each time the caret moves (text set or typed, a click), scrolls a
    ''' multiline box until that whole line is in view: in a box a line of text high only the bottom edge
    ''' of the figures then shows. The figures are drawn in the line's top half, so a view at the top shows them whole.
    ''' </summary>
    Private Shared Sub ScrollToTop(box As TextBox)
        Dim bar = TryCast(MonoVerticalScroll?.GetValue(box), ScrollBar)
        If bar IsNot Nothing AndAlso bar.Value <> bar.Minimum Then bar.Value = bar.Minimum
    End Sub

    ''' <summary>The characters a one-line text box never keeps.</summary>
    Private Shared ReadOnly LineBreaks As Char() = {Convert.ToChar(13), Convert.ToChar(10)}

    ''' <summary>
    ''' Makes <paramref name="box"/> a box of one line that takes the height the layout gives it (see
    ''' <see cref="OneLineHeight"/>), its text in its middle at every DPI. It is multiline to the toolkit:
    ''' Mono keeps a single-line box as tall as the font height it reports (under a desktop's Xft.dpi
    ''' about twice the text drawn) and writes the text at its top; a multiline box takes the height it is
    ''' given. It never wraps, and Enter or a pasted line break adds no line. Its view is kept at the top
    ''' of its line (see <see cref="ScrollToTop"/>) after every change, click, key and resize; with
    ''' <paramref name="trace"/>, each time it is, "box <paramref name="name"/> view top N px [text]".
    ''' </summary>
    Public Shared Sub KeepToOneLine(box As TextBox, Optional trace As Action(Of String) = Nothing, Optional name As String = Nothing)
        If box Is Nothing Then Throw New ArgumentNullException(NameOf(box))
        ' Mono scrolls after the event that moved the caret has been handled: put the view back once it has.
        Dim pending = False
        Dim settle =
            Sub()
                If pending OrElse Not box.IsHandleCreated OrElse box.IsDisposed Then Return
                pending = True
                box.BeginInvoke(New Action(
                    Sub()
                        pending = False
                        If box.IsDisposed Then Return
                        ScrollToTop(box)
                        trace?.Invoke("box " & If(name, box.Name) & " view top " & ViewTop(box) & " px [" & box.Text & "]")
                    End Sub))
            End Sub
        AddHandler box.TextChanged, Sub(s, e) settle()
        AddHandler box.KeyUp, Sub(s, e) settle()
        AddHandler box.MouseUp, Sub(s, e) settle()
        AddHandler box.GotFocus, Sub(s, e) settle()
        AddHandler box.SizeChanged, Sub(s, e) settle()
        box.AutoSize = False
        box.Multiline = True
        box.WordWrap = False
        box.AcceptsReturn = False
        AddHandler box.KeyDown,
            Sub(s, e)
                If e.KeyCode = Keys.Enter Then e.SuppressKeyPress = True
            End Sub
        AddHandler box.KeyPress,
            Sub(s, e)
                If Array.IndexOf(LineBreaks, e.KeyChar) >= 0 Then e.Handled = True
            End Sub
        AddHandler box.TextChanged,
            Sub(s, e)
                If box.Text.IndexOfAny(LineBreaks) >= 0 Then box.Text = String.Concat(box.Text.Where(Function(ch) Array.IndexOf(LineBreaks, ch) < 0))
            End Sub
    End Sub

    ''' <summary>The height of a one-line text box or drop-down in <paramref name="font"/>: a line of text and a margin, px.</summary>
    Public Function OneLineHeight(font As Font) As Integer
        Return LineHeight(font) + S(6)
    End Function

    ''' <summary>A button in the theme's colours (flat with a thick edge in high contrast).</summary>
    Public Shared Sub Style(b As Button, theme As Theme)
        If b Is Nothing Then Throw New ArgumentNullException(NameOf(b))
        If theme Is Nothing Then Throw New ArgumentNullException(NameOf(theme))
        b.ForeColor = ScenePainter.Rgb(theme.PanelText)
        b.BackColor = ScenePainter.Rgb(theme.Button)
        b.FlatStyle = If(theme.IsHighContrast, FlatStyle.Flat, FlatStyle.Standard)
        b.FlatAppearance.BorderColor = ScenePainter.Rgb(theme.PanelText)
        b.FlatAppearance.BorderSize = If(theme.IsHighContrast, 2, 1)
        b.UseVisualStyleBackColor = Not theme.IsHighContrast
    End Sub

    ''' <summary>A drop-down menu in the theme's colours and the window's font, emptied to be filled again.</summary>
    Public Sub Prepare(menu As ContextMenuStrip, theme As Theme)
        For Each old In menu.Items.Cast(Of ToolStripItem)().ToList()
            old.Dispose()
        Next
        menu.Items.Clear()
        menu.Font = Font
        menu.Renderer = If(theme.IsHighContrast, New ToolStripProfessionalRenderer(New LessonMenuColours()), New ToolStripProfessionalRenderer())
        menu.BackColor = ScenePainter.Rgb(theme.Panel)
        menu.ForeColor = ScenePainter.Rgb(theme.PanelText)
        menu.ShowItemToolTips = True
    End Sub

    ''' <summary>Where a menu of <paramref name="size"/> opens under <paramref name="button"/>, moved left and up as far as it takes to stay on the screen.</summary>
    Public Function OnScreen(button As Control, size As Size) As Point
        Dim area = Screen.FromControl(_window).WorkingArea
        Dim at = button.PointToScreen(New Point(0, button.Height))
        at.X = Math.Max(area.Left, Math.Min(at.X, area.Right - size.Width))
        at.Y = Math.Max(area.Top, Math.Min(at.Y, area.Bottom - size.Height))
        Return at
    End Function

    ''' <summary>With --trace: a drop-down's rectangle on the screen and the screen's, and whether every item's text fits ("menu … on screen").</summary>
    Public Sub TraceMenuBounds(name As String, menu As ToolStrip)
        If Trace Is Nothing Then Return
        Dim r = New Drawing.Rectangle(menu.PointToScreen(Point.Empty), menu.Size)
        Dim area = Screen.FromControl(_window).Bounds
        Dim fits = menu.Items.Cast(Of ToolStripItem)().All(Function(i) Measure(i.Text, menu.Font).Width <= i.Bounds.Width)
        Trace.Invoke(name & " at " & r.X & " " & r.Y & " " & r.Width & " " & r.Height & " screen " & area.Width & " " & area.Height & If(fits, " fits", " cut"))
    End Sub

    Public Sub Dispose() Implements IDisposable.Dispose
        Tips.Dispose()
        _measure?.Dispose()
        _measureBitmap?.Dispose()
    End Sub
End Class
