Option Strict On
Imports System.Drawing
Imports System.Drawing.Drawing2D
Imports System.Windows.Forms

''' <summary>
''' A check box whose box is as tall as its text. Mono draws a check box's box 13 px square at every
''' DPI: at 192 dpi it is a speck beside the caption, too small to hit or to see ticked from the
''' back of a room. This one draws the box and the tick from its font's height, in the control's
''' colours (so the high-contrast theme reaches it too). It stays a CheckBox: clicks, Space and
''' CheckedChanged work as before.
''' </summary>
Friend NotInheritable Class ScaledCheckBox
    Inherits CheckBox

    Public Sub New()
        SetStyle(ControlStyles.UserPaint Or ControlStyles.AllPaintingInWmPaint Or ControlStyles.OptimizedDoubleBuffer Or ControlStyles.ResizeRedraw, True)
    End Sub

    ''' <summary>Screen pixels per 96-dpi pixel.</summary>
    Public Property ScreenScale As Double = 1.0

    ''' <summary>The box's side, px: the text's height, at least 13 px at 96 dpi.</summary>
    Public ReadOnly Property BoxSize As Integer
        Get
            Dim text = CInt(Math.Ceiling(Font.GetHeight(96.0F) * 0.8))
            Return Math.Min(Math.Max(4, Height - 2), Math.Max(CInt(Math.Round(13 * ScreenScale)), text))
        End Get
    End Property

    ''' <summary>Room the box and its gap take before the caption, px.</summary>
    Public ReadOnly Property CaptionOffset As Integer
        Get
            Return BoxSize + CInt(Math.Round(6 * ScreenScale))
        End Get
    End Property

    Protected Overrides Sub OnPaint(e As PaintEventArgs)
        Dim g = e.Graphics
        g.Clear(BackColor)
        Dim size = BoxSize
        Dim box As New Drawing.Rectangle(CInt(Math.Round(1 * ScreenScale)), (Height - size) \ 2, size, size)
        Dim line = CSng(Math.Max(1.0, 1.5 * ScreenScale))
        Dim dark = BackColor.GetBrightness() < 0.3
        Using fill As New SolidBrush(If(Enabled, If(dark, Color.Black, Color.White), SystemColors.Control)), edge As New Pen(ForeColor, line)
            g.FillRectangle(fill, box)
            g.DrawRectangle(edge, box.X, box.Y, box.Width, box.Height)
        End Using
        If Checked Then
            g.SmoothingMode = SmoothingMode.AntiAlias
            Using tick As New Pen(ForeColor, CSng(Math.Max(1.5, size / 6.0))) With {.StartCap = LineCap.Round, .EndCap = LineCap.Round, .LineJoin = LineJoin.Round}
                g.DrawLines(tick, {New PointF(box.X + size * 0.2F, box.Y + size * 0.52F),
                                   New PointF(box.X + size * 0.42F, box.Y + size * 0.75F),
                                   New PointF(box.X + size * 0.8F, box.Y + size * 0.25F)})
            End Using
            g.SmoothingMode = SmoothingMode.Default
        End If
        Dim textArea As New Drawing.Rectangle(box.Right + CInt(Math.Round(5 * ScreenScale)), 0, Math.Max(1, Width - box.Right - CInt(Math.Round(5 * ScreenScale))), Height)
        TextRenderer.DrawText(g, Text, Font, textArea, If(Enabled, ForeColor, SystemColors.GrayText), TextFormatFlags.VerticalCenter Or TextFormatFlags.Left Or TextFormatFlags.NoPrefix Or TextFormatFlags.SingleLine)
        If Focused AndAlso ShowFocusCues Then
            ControlPaint.DrawFocusRectangle(g, New Drawing.Rectangle(textArea.X - 2, 1, Math.Min(textArea.Width, TextRenderer.MeasureText(g, Text, Font).Width + 4), Height - 2), ForeColor, BackColor)
        End If
    End Sub
End Class
