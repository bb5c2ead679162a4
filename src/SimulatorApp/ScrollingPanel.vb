Option Strict On
Imports System.Drawing
Imports System.Windows.Forms

''' <summary>
''' A panel that shows part of a taller content panel, with a scroll bar as wide as the screen's
''' scale asks (Mono's own is the same thin strip at every DPI). It scrolls with its bar, with the
''' mouse wheel anywhere over it (see <see cref="WheelRouter"/>: Mono sends the wheel to the focused
''' control, wherever the pointer is), and to a control that takes the focus (Tab). The content's
''' controls keep their places within the content, so nothing moves under the mouse except by a
''' scroll the teacher asked for.
''' </summary>
Friend NotInheritable Class ScrollingPanel
    Inherits Panel

    Private ReadOnly _bar As New VScrollBar()
    Private _contentHeight As Integer

    Public Sub New()
        Content = New Panel()
        Controls.Add(Content)
        Controls.Add(_bar)
        _bar.Visible = False
        AddHandler _bar.ValueChanged, Sub(s, e) Place()
    End Sub

    ''' <summary>The panel that holds the controls: as tall as they need, moved up as the panel scrolls.</summary>
    Public ReadOnly Property Content As Panel

    ''' <summary>Raised after every scroll (by the bar, the wheel or a focus), once the content is in its new place.</summary>
    Public Event Scrolled As EventHandler

    ''' <summary>The scroll bar's width, px (it is shown only when the content is taller than the panel).</summary>
    Public Property BarWidth As Integer = 16

    ''' <summary>How far the content is scrolled, px (0 at the top).</summary>
    Public ReadOnly Property Offset As Integer
        Get
            Return If(_bar.Visible, _bar.Value, 0)
        End Get
    End Property

    ''' <summary>How much of the content is below the visible part when scrolled to the top, px (0 when it all shows).</summary>
    Public ReadOnly Property Overflow As Integer
        Get
            Return Math.Max(0, _contentHeight - ClientSize.Height)
        End Get
    End Property

    ''' <summary>Whether the content is taller than the panel (the bar shows).</summary>
    Public ReadOnly Property Scrolls As Boolean
        Get
            Return Overflow > 0
        End Get
    End Property

    ''' <summary>The width the content has for its controls, px (leaving room for the bar when it shows).</summary>
    Public Function ContentWidthFor(contentHeight As Integer) As Integer
        Return ClientSize.Width - If(contentHeight > ClientSize.Height, BarWidth, 0)
    End Function

    ''' <summary>Sets the content's height (after a layout), keeping the scroll where it was as far as it can.</summary>
    Public Sub SetContentHeight(height As Integer)
        _contentHeight = Math.Max(0, height)
        Dim was = _bar.Value
        Dim over = Overflow
        _bar.Visible = over > 0
        _bar.SetBounds(ClientSize.Width - BarWidth, 0, BarWidth, ClientSize.Height)
        If over > 0 Then
            _bar.Minimum = 0
            _bar.LargeChange = Math.Max(1, ClientSize.Height - BarWidth)
            _bar.SmallChange = Math.Max(1, BarWidth * 2)
            ' A scroll bar's largest value is Maximum − LargeChange + 1.
            _bar.Maximum = over + _bar.LargeChange - 1
            _bar.Value = Math.Max(0, Math.Min(over, was))
        Else
            _bar.Value = 0
        End If
        Place()
    End Sub

    ''' <summary>Scrolls by <paramref name="pixels"/> (down when positive), within the content.</summary>
    Public Sub ScrollBy(pixels As Integer)
        ScrollTo(Offset + pixels)
    End Sub

    ''' <summary>Scrolls so that the content's <paramref name="y"/> (px) is at the top, within the content.</summary>
    Public Sub ScrollTo(y As Integer)
        If Not _bar.Visible Then Return
        Dim wanted = Math.Max(0, Math.Min(Overflow, y))
        If wanted = _bar.Value Then Return
        _bar.Value = wanted ' ValueChanged places the content
    End Sub

    ''' <summary>Scrolls as little as shows the whole of <paramref name="c"/> (a control of the content).</summary>
    Public Sub EnsureVisible(c As Control)
        If c Is Nothing OrElse Not _bar.Visible Then Return
        Dim top = c.Top, bottom = c.Bottom
        Dim margin = BarWidth \ 2
        If top - margin < Offset Then
            ScrollTo(top - margin)
        ElseIf bottom + margin > Offset + ClientSize.Height Then
            ScrollTo(bottom + margin - ClientSize.Height)
        End If
    End Sub

    Private _placedAt As Integer = Integer.MinValue

    Private Sub Place()
        Dim w = ClientSize.Width - If(_bar.Visible, BarWidth, 0)
        Content.SetBounds(0, -Offset, Math.Max(1, w), Math.Max(_contentHeight, ClientSize.Height))
        If _placedAt <> Offset Then
            _placedAt = Offset
            RaiseEvent Scrolled(Me, EventArgs.Empty)
        End If
    End Sub

    Protected Overrides Sub OnResize(eventargs As EventArgs)
        MyBase.OnResize(eventargs)
        SetContentHeight(_contentHeight)
    End Sub
End Class
