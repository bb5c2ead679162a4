Option Strict On
Imports System.Drawing
Imports System.Windows.Forms

''' <summary>
''' The message box at the top of the side panel: a fixed height, whatever the message, so the
''' controls under it never move when a message grows from two lines to three. A message longer
''' than the box scrolls within it (the wheel over it, or the arrow keys when it has the focus),
''' and a bar at its right edge shows that there is more and where the view is. It draws its text
''' itself, wrapped at its width and measured at the DPI GDI+ draws at: Mono's TextBox spaces its
''' lines by the DPI it reports, twice the drawn text's at 192 dpi.
''' </summary>
Friend NotInheritable Class MessageArea
    Inherits Control

    Private _offset As Integer ' px scrolled down
    Private _measure As Func(Of String, Font, Integer, Size)

    Public Sub New()
        SetStyle(ControlStyles.UserPaint Or ControlStyles.AllPaintingInWmPaint Or ControlStyles.OptimizedDoubleBuffer Or ControlStyles.ResizeRedraw, True)
        TabStop = False
    End Sub

    ''' <summary>Screen pixels per 96-dpi pixel: the margins and the bar grow with it.</summary>
    Public Property ScreenScale As Double = 1.0

    ''' <summary>How the text's size is measured, wrapped at a width (the window's measure, at the DPI GDI+ draws at).</summary>
    Public Sub SetMeasure(measure As Func(Of String, Font, Integer, Size))
        _measure = measure
    End Sub

    Private Function Px(v As Double) As Integer
        Return CInt(Math.Round(v * ScreenScale))
    End Function

    ''' <summary>The rectangle the text is wrapped in, px (inside the border, left of the bar).</summary>
    Private ReadOnly Property TextBounds As Drawing.Rectangle
        Get
            Return New Drawing.Rectangle(Px(4), Px(3), Math.Max(1, Width - Px(8) - Px(6)), Math.Max(1, Height - Px(6)))
        End Get
    End Property

    ''' <summary>The height the whole text needs, px.</summary>
    Public ReadOnly Property Needs As Integer
        Get
            If _measure Is Nothing Then Return 0
            Return _measure(Text, Font, TextBounds.Width).Height
        End Get
    End Property

    ''' <summary>Whether the text is longer than the box (it scrolls).</summary>
    Public ReadOnly Property Scrolls As Boolean
        Get
            Return Needs > TextBounds.Height
        End Get
    End Property

    ''' <summary>How far down the text is scrolled, px.</summary>
    Public ReadOnly Property Offset As Integer
        Get
            Return _offset
        End Get
    End Property

    Protected Overrides Sub OnTextChanged(e As EventArgs)
        MyBase.OnTextChanged(e)
        _offset = 0 ' a new message shows from its start
        Invalidate()
    End Sub

    ''' <summary>Scrolls the text by <paramref name="pixels"/> (down when positive); returns whether it moved.</summary>
    Public Function ScrollBy(pixels As Integer) As Boolean
        Dim most = Math.Max(0, Needs - TextBounds.Height)
        Dim wanted = Math.Max(0, Math.Min(most, _offset + pixels))
        If wanted = _offset Then Return False
        _offset = wanted
        Invalidate()
        Return True
    End Function

    Protected Overrides Sub OnPaint(e As PaintEventArgs)
        Dim g = e.Graphics
        g.Clear(BackColor)
        Dim area = TextBounds
        Dim clip = g.Clip
        g.SetClip(area)
        Using brush As New SolidBrush(ForeColor)
            g.DrawString(Text, Font, brush, New RectangleF(area.X, area.Y - _offset, area.Width, Math.Max(area.Height, Needs) + Px(4)))
        End Using
        g.Clip = clip
        Using edge As New Pen(ForeColor, CSng(Math.Max(1.0, ScreenScale)))
            g.DrawRectangle(edge, 0, 0, Width - 1, Height - 1)
        End Using
        If Scrolls Then
            ' A bar at the right edge: how much of the message shows, and where.
            Dim needs = Me.Needs
            Dim track As New Drawing.Rectangle(Width - Px(7), Px(3), Px(4), Height - Px(6))
            Dim top = track.Y + CInt(track.Height * CDbl(_offset) / needs)
            Dim length = Math.Max(Px(6), CInt(track.Height * CDbl(area.Height) / needs))
            Using faint As New SolidBrush(Color.FromArgb(60, ForeColor)), thumb As New SolidBrush(ForeColor)
                g.FillRectangle(faint, track)
                g.FillRectangle(thumb, track.X, Math.Min(top, track.Bottom - length), track.Width, length)
            End Using
        End If
    End Sub
End Class
