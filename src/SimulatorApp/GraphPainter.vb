Option Strict On
Imports System.Drawing
Imports System.Drawing.Drawing2D
Imports PhysicsEngine.Presentation

''' <summary>
''' Draws a <see cref="GraphPlot"/> with GDI+: title, notes and key at the top, then the axes with
''' round ticks (<see cref="AxisTicks"/>) and their labels with units, the histogram's bars, and the
''' curves. Text is in the window's font (large fonts make it larger), lines are thick enough for a
''' projector, and the colours follow the theme.
''' </summary>
Friend NotInheritable Class GraphPainter
    Private Sub New()
    End Sub

    ''' <summary>Draws <paramref name="plot"/> into a <paramref name="width"/> × <paramref name="height"/> px area.</summary>
    Public Shared Sub Paint(g As Graphics, plot As GraphPlot, theme As Theme, font As Font, width As Integer, height As Integer, scale As Double)
        g.SmoothingMode = SmoothingMode.AntiAlias
        g.TextRenderingHint = Text.TextRenderingHint.AntiAliasGridFit
        Dim back = ScenePainter.Rgb(theme.Background), ink = ScenePainter.Rgb(theme.Ink), grid = ScenePainter.Rgb(theme.Grid)
        g.Clear(back)
        Dim px = Function(v As Double) CSng(v * scale)
        Using inkBrush As New SolidBrush(ink), bold As New Font(font, FontStyle.Bold), inkPen As New Pen(ink, px(1.5)), gridPen As New Pen(grid, px(1))
            Dim line = g.MeasureString("Ag", font).Height
            ' Short of room (the tab under the canvas, large fonts): no title (the lit button names the
            ' graph), and the notes go in a box in the plot's top right corner instead of above it.
            Dim compact = height < 14 * line
            Dim y = px(4)
            Dim x = px(8)
            If Not compact Then
                g.DrawString(plot.Title, bold, inkBrush, px(8), y)
                x += g.MeasureString(plot.Title, bold).Width + px(24)
            End If
            ' The key beside the title when there is room, else under it: a short stroke of each
            ' curve's colour and its name.
            Dim keyWidth = plot.Lines.Sum(Function(l) g.MeasureString(l.Name, font).Width + px(40))
            If x + keyWidth > width - px(8) AndAlso x > px(8) Then
                x = px(8)
                y += g.MeasureString("Ag", bold).Height
            End If
            For Each l In plot.Lines
                Dim w = g.MeasureString(l.Name, font).Width + px(40)
                If x + w > width - px(8) AndAlso x > px(8) Then
                    x = px(8)
                    y += line
                End If
                Using pen = CurvePen(l, px(3))
                    g.DrawLine(pen, x, y + line / 2, x + px(24), y + line / 2)
                End Using
                g.DrawString(l.Name, font, inkBrush, x + px(28), y)
                x += w
            Next
            y = If(compact, y + line, Math.Max(y + line, px(4) + g.MeasureString("Ag", bold).Height))
            If Not compact Then
                For Each note In plot.Notes
                    g.DrawString(note, font, inkBrush, px(8), y)
                    y += line
                Next
            End If
            y += px(2)

            Dim b = plot.Bounds()
            Dim hasData = Not Double.IsInfinity(b.XMin) AndAlso Not Double.IsInfinity(b.YMin)
            If Not hasData Then
                b = (0, 1, If(Double.IsNaN(plot.YFloor), 0, plot.YFloor), 1)
            End If
            Dim maxTicksY = Math.Max(2, CInt((height - y - 3 * line) / (line * 2.2)))
            Dim yTicks = AxisTicks.Ticks(b.YMin, b.YMax, Math.Min(8, maxTicksY))
            Dim yLabels = yTicks.Select(AddressOf TickText).ToList()
            Dim left = px(8) + line + px(6) + yLabels.Max(Function(s) g.MeasureString(s, font).Width) + px(6)
            Dim right = CSng(width) - px(16)
            Dim bottom = CSng(height) - 2 * line - px(10)
            Dim top = y + line / 2
            If right - left < px(40) OrElse bottom - top < px(30) Then
                g.DrawString("No room for the graph here: press ⤢ Window.", font, inkBrush, px(8), y)
                Return
            End If
            Dim xLabelWidth = g.MeasureString(TickText(b.XMax) & "000", font).Width
            Dim xTicks = AxisTicks.Ticks(b.XMin, b.XMax, Math.Max(2, Math.Min(10, CInt((right - left) / xLabelWidth))))
            Dim x0 = xTicks(0), x1 = xTicks(xTicks.Count - 1), y0 = yTicks(0), y1 = yTicks(yTicks.Count - 1)
            Dim toX = Function(v As Double) CSng(left + (v - x0) / (x1 - x0) * (right - left))
            Dim toY = Function(v As Double) CSng(bottom - (v - y0) / (y1 - y0) * (bottom - top))

            Dim yLabelAcross = False
            ' Grid and tick labels.
            Using centred As New StringFormat With {.Alignment = StringAlignment.Center}, rightAligned As New StringFormat With {.Alignment = StringAlignment.Far, .LineAlignment = StringAlignment.Center}
                For i = 0 To yTicks.Count - 1
                    Dim ty = toY(yTicks(i))
                    g.DrawLine(gridPen, left, ty, right, ty)
                    g.DrawString(yLabels(i), font, inkBrush, left - px(6), ty, rightAligned)
                Next
                For Each t In xTicks
                    Dim tx = toX(t)
                    g.DrawLine(gridPen, tx, top, tx, bottom)
                    g.DrawString(TickText(t), font, inkBrush, tx, bottom + px(4), centred)
                Next
                ' Axis labels with units: x under the ticks, y turned up the left side.
                g.DrawString(plot.XLabel, font, inkBrush, (left + right) / 2, bottom + line + px(6), centred)
                If g.MeasureString(plot.YLabel, font).Width <= bottom - top Then
                    Dim state = g.Save()
                    g.TranslateTransform(px(8), (top + bottom) / 2)
                    g.RotateTransform(-90)
                    g.DrawString(plot.YLabel, font, inkBrush, 0, 0, centred)
                    g.Restore(state)
                Else
                    yLabelAcross = True
                End If
            End Using
            ' Text over the plot (a label or notes that had no room elsewhere), on a box of the background.
            Dim boxes As New List(Of (Text As String, X As Single, Y As Single, Right As Boolean))
            If yLabelAcross Then boxes.Add((plot.YLabel, left + px(6), top + px(2), False))
            If compact Then
                Dim ny = top + px(2)
                For Each note In plot.Notes
                    boxes.Add((note, right - px(6), ny, True))
                    ny += line
                Next
            End If
            g.DrawLine(inkPen, left, bottom, right, bottom)
            g.DrawLine(inkPen, left, top, left, bottom)

            If plot.Bars IsNot Nothing Then
                Using fill As New SolidBrush(ScenePainter.Rgb(plot.BarColour)), edge As New Pen(ink, px(1))
                    For i = 0 To plot.Bars.Counts.Count - 1
                        Dim bx0 = toX(plot.Bars.Edges(i)), bx1 = toX(plot.Bars.Edges(i + 1)), by = toY(plot.Bars.Counts(i))
                        If plot.Bars.Counts(i) = 0 Then Continue For
                        g.FillRectangle(fill, bx0, by, bx1 - bx0, bottom - by)
                        g.DrawRectangle(edge, bx0, by, bx1 - bx0, bottom - by)
                    Next
                End Using
            End If
            g.SetClip(New RectangleF(left, top - px(2), right - left + px(2), bottom - top + px(4)))
            For Each l In plot.Lines
                Dim pts = l.Points.Where(Function(p) Not Double.IsNaN(p.Y) AndAlso Not Double.IsInfinity(p.Y)).Select(Function(p) New PointF(toX(p.X), toY(p.Y))).ToArray()
                If pts.Length = 0 Then Continue For
                Using pen = CurvePen(l, px(2.5))
                    If pts.Length = 1 Then
                        g.DrawEllipse(pen, pts(0).X - px(2), pts(0).Y - px(2), px(4), px(4))
                    Else
                        g.DrawLines(pen, pts)
                    End If
                End Using
            Next
            g.ResetClip()
            Using backBrush As New SolidBrush(Color.FromArgb(215, back))
                For Each box In boxes
                    Dim size = g.MeasureString(box.Text, font)
                    Dim bx = If(box.Right, box.X - size.Width, box.X)
                    g.FillRectangle(backBrush, bx - px(2), box.Y, size.Width + px(4), size.Height)
                    g.DrawString(box.Text, font, inkBrush, bx, box.Y)
                Next
            End Using
            If Not String.IsNullOrEmpty(plot.EmptyText) Then
                Using centred As New StringFormat With {.Alignment = StringAlignment.Center, .LineAlignment = StringAlignment.Center}
                    g.DrawString(plot.EmptyText, font, inkBrush, (left + right) / 2, (top + bottom) / 2, centred)
                End Using
            End If
        End Using
    End Sub

    ''' <summary>A tick's label: as few digits as the round value needs ("0.5", "250", "−2"), a power of ten when very large or small.</summary>
    Private Shared Function TickText(v As Double) As String
        If v = 0 Then Return "0"
        Dim size = Math.Abs(v)
        If size >= 100000 OrElse size < 0.001 Then Return Units.Sig(v, 3)
        Return Math.Round(v, 9).ToString("0.#########", Globalization.CultureInfo.InvariantCulture).Replace("-", "−")
    End Function

    Private Shared Function CurvePen(l As GraphLine, width As Single) As Pen
        Dim pen As New Pen(ScenePainter.Rgb(l.Colour), width) With {.LineJoin = LineJoin.Round}
        If l.Dashed Then pen.DashStyle = DashStyle.Dash
        Return pen
    End Function
End Class
