Option Strict On
Imports System.Drawing
Imports System.Drawing.Drawing2D
Imports System.Windows.Forms

''' <summary>
''' A horizontal slider drawn at the screen's scale. Mono's TrackBar draws its thumb the same few
''' pixels at every DPI, so at 192 dpi it is a sliver beside text twice as tall; this one sizes its
''' thumb, track and ticks from the control's height and the screen's scale. It behaves as a
''' TrackBar does: drag the thumb, click the track to move a large step towards the click, arrows
''' and Page Up/Down from the keyboard, Home and End.
''' </summary>
Friend NotInheritable Class ScaledSlider
    Inherits Control

    Private _minimum As Integer
    Private _maximum As Integer = 10
    Private _value As Integer
    Private _dragging As Boolean
    Private _grab As Integer ' cursor x minus the thumb's middle when the drag began, px

    Public Sub New()
        SetStyle(ControlStyles.UserPaint Or ControlStyles.AllPaintingInWmPaint Or ControlStyles.OptimizedDoubleBuffer Or
                 ControlStyles.ResizeRedraw Or ControlStyles.Selectable, True)
        TabStop = True
    End Sub

    ''' <summary>Screen pixels per 96-dpi pixel: the thumb's width and the lines grow with it.</summary>
    Public Property ScreenScale As Double = 1.0

    ''' <summary>Raised when <see cref="Value"/> changes, by the mouse, the keyboard or code.</summary>
    Public Event ValueChanged As EventHandler

    ''' <summary>The least value (the left end).</summary>
    Public Property Minimum As Integer
        Get
            Return _minimum
        End Get
        Set(v As Integer)
            _minimum = v
            If _maximum < v Then _maximum = v
            Value = _value
            Invalidate()
        End Set
    End Property

    ''' <summary>The greatest value (the right end).</summary>
    Public Property Maximum As Integer
        Get
            Return _maximum
        End Get
        Set(v As Integer)
            _maximum = Math.Max(v, _minimum)
            Value = _value
            Invalidate()
        End Set
    End Property

    ''' <summary>What an arrow key moves.</summary>
    Public Property SmallChange As Integer = 1

    ''' <summary>What Page Up/Down and a click on the track move.</summary>
    Public Property LargeChange As Integer = 5

    ''' <summary>Values between two tick marks.</summary>
    Public Property TickFrequency As Integer = 1

    ''' <summary>Where the thumb is, from <see cref="Minimum"/> to <see cref="Maximum"/>.</summary>
    Public Property Value As Integer
        Get
            Return _value
        End Get
        Set(v As Integer)
            Dim clamped = Math.Max(_minimum, Math.Min(_maximum, v))
            If clamped = _value Then Return
            _value = clamped
            Invalidate()
            RaiseEvent ValueChanged(Me, EventArgs.Empty)
        End Set
    End Property

    ''' <summary>The thumb's width, px: a finger's width at any DPI, and never less than a third of the control's height.</summary>
    Public ReadOnly Property ThumbWidth As Integer
        Get
            Return Math.Max(CInt(Math.Round(16 * ScreenScale)), Height \ 3)
        End Get
    End Property

    ''' <summary>The thumb's height, px.</summary>
    Public ReadOnly Property ThumbHeight As Integer
        Get
            Return ThumbRectangle().Height
        End Get
    End Property

    ''' <summary>How far in from each end the thumb's middle can go, px.</summary>
    Public ReadOnly Property Inset As Integer
        Get
            Return ThumbWidth \ 2 + CInt(Math.Round(4 * ScreenScale))
        End Get
    End Property

    ''' <summary>The thumb's middle for <paramref name="v"/>, px from the control's left.</summary>
    Public Function ThumbCentre(v As Integer) As Integer
        Dim span = Math.Max(1, _maximum - _minimum)
        Return Inset + CInt(Math.Round((Width - 2 * Inset) * CDbl(v - _minimum) / span))
    End Function

    ''' <summary>The value whose thumb would be centred at <paramref name="x"/> px.</summary>
    Private Function ValueAt(x As Integer) As Integer
        Dim usable = Math.Max(1, Width - 2 * Inset)
        Return _minimum + CInt(Math.Round((_maximum - _minimum) * CDbl(x - Inset) / usable))
    End Function

    ''' <summary>The thumb: the control's height less the ticks' strip under it, and a margin.</summary>
    Private Function ThumbRectangle() As Drawing.Rectangle
        Dim w = ThumbWidth
        Dim top = CInt(Math.Round(2 * ScreenScale))
        Return New Drawing.Rectangle(ThumbCentre(_value) - w \ 2, top, w, Math.Max(4, Height - TickRoom() - top - CInt(ScreenScale)))
    End Function

    ''' <summary>The track's line, px from the top: through the thumb's middle.</summary>
    Private Function TrackY() As Integer
        Dim top = CInt(Math.Round(2 * ScreenScale))
        Return top + Math.Max(4, Height - TickRoom() - top - CInt(ScreenScale)) \ 2
    End Function

    Private Function TickRoom() As Integer
        Return Math.Max(3, CInt(Math.Round(7 * ScreenScale)))
    End Function

    Protected Overrides Sub OnPaint(e As PaintEventArgs)
        Dim g = e.Graphics
        g.Clear(BackColor)
        g.SmoothingMode = SmoothingMode.AntiAlias
        Dim ink = ForeColor
        Dim y = TrackY()
        Dim line = CSng(Math.Max(1.0, 2 * ScreenScale))
        Using track As New Pen(Color.FromArgb(160, ink), line), tick As New Pen(Color.FromArgb(140, ink), CSng(Math.Max(1.0, ScreenScale)))
            g.DrawLine(track, Inset, y, Width - Inset, y)
            Dim every = Math.Max(1, TickFrequency)
            Dim tickTop = ThumbRectangle().Bottom + CInt(ScreenScale)
            For v = _minimum To _maximum Step every
                Dim x = ThumbCentre(v)
                g.DrawLine(tick, x, tickTop, x, Math.Min(Height - 1, tickTop + TickRoom() - CInt(2 * ScreenScale)))
            Next
        End Using
        Dim thumb = ThumbRectangle()
        Dim fill = If(Enabled, If(_dragging OrElse Focused, SystemColors.Highlight, Color.FromArgb(255, 200, 200, 200)), SystemColors.Control)
        If BackColor.GetBrightness() < 0.3 Then fill = If(_dragging OrElse Focused, Color.FromArgb(&H15, &H65, &HC0), Color.FromArgb(&H60, &H60, &H60))
        Using brush As New SolidBrush(fill), edge As New Pen(ink, line)
            g.FillRectangle(brush, thumb)
            g.DrawRectangle(edge, thumb.X, thumb.Y, thumb.Width, thumb.Height)
        End Using
        If Focused Then ControlPaint.DrawFocusRectangle(g, ClientRectangle, ink, BackColor)
    End Sub

    Protected Overrides Sub OnMouseDown(e As MouseEventArgs)
        MyBase.OnMouseDown(e)
        If e.Button <> MouseButtons.Left Then Return
        If CanFocus Then Focus()
        Dim thumb = ThumbRectangle()
        thumb.Inflate(CInt(2 * ScreenScale), 0)
        If e.X >= thumb.Left AndAlso e.X <= thumb.Right Then
            _dragging = True
            _grab = e.X - ThumbCentre(_value)
            Capture = True
            Invalidate()
        ElseIf e.X < ThumbCentre(_value) Then
            Value = _value - LargeChange
        Else
            Value = _value + LargeChange
        End If
    End Sub

    Protected Overrides Sub OnMouseMove(e As MouseEventArgs)
        MyBase.OnMouseMove(e)
        If _dragging Then Value = ValueAt(e.X - _grab)
    End Sub

    Protected Overrides Sub OnMouseUp(e As MouseEventArgs)
        MyBase.OnMouseUp(e)
        If Not _dragging Then Return
        Value = ValueAt(e.X - _grab)
        _dragging = False
        Capture = False
        Invalidate()
    End Sub

    Protected Overrides Function IsInputKey(keyData As Keys) As Boolean
        Select Case keyData
            Case Keys.Left, Keys.Right, Keys.Up, Keys.Down, Keys.PageUp, Keys.PageDown, Keys.Home, Keys.End
                Return True
        End Select
        Return MyBase.IsInputKey(keyData)
    End Function

    Protected Overrides Sub OnKeyDown(e As KeyEventArgs)
        MyBase.OnKeyDown(e)
        Select Case e.KeyCode
            Case Keys.Left, Keys.Down : Value = _value - SmallChange
            Case Keys.Right, Keys.Up : Value = _value + SmallChange
            Case Keys.PageDown : Value = _value - LargeChange
            Case Keys.PageUp : Value = _value + LargeChange
            Case Keys.Home : Value = _minimum
            Case Keys.End : Value = _maximum
            Case Else : Return
        End Select
        e.Handled = True
    End Sub

    Protected Overrides Sub OnGotFocus(e As EventArgs)
        MyBase.OnGotFocus(e)
        Invalidate()
    End Sub

    Protected Overrides Sub OnLostFocus(e As EventArgs)
        MyBase.OnLostFocus(e)
        Invalidate()
    End Sub
End Class
