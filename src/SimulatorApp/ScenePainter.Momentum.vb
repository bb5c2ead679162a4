Option Strict On
Imports System.Drawing
Imports System.Drawing.Drawing2D
Imports PhysicsEngine.Presentation

' The momentum views on the canvas: fading path traces (under the bodies), and over them the
' impulses Δp at the last collisions, the centre of mass with its velocity, the total momentum Σp,
' and the momenta diagram with the momentum arrows' key in the top-right corner.
Partial Friend NotInheritable Class ScenePainter
    ''' <summary>Steps of fading a trace is drawn in (one polyline per step, so a trace costs a few calls, not one per segment).</summary>
    Private Const TraceBands As Integer = 6
    ''' <summary>The colour of total momentum (Σp arrows), apart from every body's and the velocity arrows'.</summary>
    Private Const MomentumLight As Integer = &H6A1B9A
    Private Const MomentumDark As Integer = &HEA80FC

    Private ReadOnly _fadedPens As New Dictionary(Of Long, Pen)

    Private Shared Function MomentumColour(theme As Theme) As Integer
        Return If(theme.IsHighContrast, MomentumDark, MomentumLight)
    End Function

    ''' <summary>A pen of a colour at an opacity (0 to 255), cached.</summary>
    Private Function FadedPen(colour As Integer, alpha As Integer, width As Single) As Pen
        Dim key = (CLng(alpha And 255) << 40) Or (CLng(colour And &HFFFFFF) << 16) Or CLng(width * 16)
        Dim pen As Pen = Nothing
        If _fadedPens.TryGetValue(key, pen) Then Return pen
        pen = New Pen(Color.FromArgb(alpha, Rgb(colour)), width) With {.LineJoin = LineJoin.Round}
        _fadedPens(key) = pen
        Return pen
    End Function

    ''' <summary>
    ''' Each traced body's path, in its colour, faint where it is old and strong where it is new. The
    ''' fading is a mix towards the canvas colour, drawn opaque: cheaper in software (libgdiplus) than
    ''' see-through lines, and a gas is traced every frame.
    ''' </summary>
    Private Sub DrawTraces(g As Graphics, p As SimulationPresenter, view As ViewTransform, theme As Theme, k As Single)
        Dim traces = p.Traces
        For Each body In traces.Bodies
            Dim pts = traces.Points(body)
            If pts.Count < 2 Then Continue For
            Dim colour = BodyColours.Parse(body.Color, &H808080)
            Dim screen(pts.Count - 1) As PointF
            For i = 0 To pts.Count - 1
                Dim s = view.ToScreen(pts(i))
                screen(i) = New PointF(CSng(s.X), CSng(s.Y))
            Next
            ' Band b holds the segments of its share of the trace's age, sharing end points with the next band.
            For b = 0 To TraceBands - 1
                Dim first = b * (screen.Length - 1) \ TraceBands
                Dim last = (b + 1) * (screen.Length - 1) \ TraceBands
                If last <= first Then Continue For
                Dim part(last - first) As PointF
                Array.Copy(screen, first, part, 0, part.Length)
                Dim strength = 0.15 + 0.85 * (b + 1) / TraceBands
                g.DrawLines(PenOf(Mix(colour, theme.Background, strength), 2 * k), part)
            Next
        Next
    End Sub

    ''' <summary>&amp;HRRGGBB of <paramref name="share"/> (0 to 1) of <paramref name="colour"/> and the rest of <paramref name="background"/>.</summary>
    Private Shared Function Mix(colour As Integer, background As Integer, share As Double) As Integer
        Dim result = 0
        For shift = 0 To 16 Step 8
            Dim c = (colour >> shift) And 255, bg = (background >> shift) And 255
            result = result Or (CInt(Math.Round(bg + (c - bg) * share)) << shift)
        Next
        Return result
    End Function

    ''' <summary>The views over the bodies: impulses, centre of mass, Σp, and the corner panel.</summary>
    Private Sub DrawMomentumViews(g As Graphics, p As SimulationPresenter, view As ViewTransform, theme As Theme, k As Single, width As Integer, height As Integer)
        Dim ppu = CSng(p.MomentumArrows.PixelsPerUnit) ' px per kg·m/s
        If p.ShowImpulses Then
            For Each m In p.Impulses.Marks
                If Not m.IsLocated Then Continue For
                Dim alpha = CInt(255 * ImpulseMarks.Opacity(m))
                If alpha <= 0 Then Continue For
                Dim a = view.ToScreen(m.At)
                Dim ax = CSng(a.X), ay = CSng(a.Y)
                Dim colour = BodyColours.Parse(m.Body.Color, theme.Ink)
                ' An outline in ink under the body's colour, so a pale ball's impulse still reads.
                Arrow(g, FadedPen(theme.Ink, alpha, 6 * k), ax, ay, ax + CSng(m.Impulse.X) * ppu, ay - CSng(m.Impulse.Y) * ppu, k)
                Arrow(g, FadedPen(colour, alpha, 3 * k), ax, ay, ax + CSng(m.Impulse.X) * ppu, ay - CSng(m.Impulse.Y) * ppu, k)
            Next
        End If
        Dim summary = p.Momentum
        If summary.HasBodies AndAlso (p.ShowCentreOfMass OrElse p.ShowTotalMomentum) Then
            Dim c = view.ToScreen(summary.CentreOfMass)
            Dim cx = CSng(c.X), cy = CSng(c.Y)
            If p.ShowTotalMomentum Then
                Dim pm = summary.Momentum
                Dim tipX = cx + CSng(pm.X) * ppu, tipY = cy - CSng(pm.Y) * ppu
                Arrow(g, PenOf(MomentumColour(theme), 5 * k), cx, cy, tipX, tipY, k)
            End If
            If p.ShowCentreOfMass Then
                ' Its velocity at the velocity arrows' scale, so it compares with theirs.
                Dim scale = CSng(view.ToPixels(p.Arrows.Seconds))
                Dim v = summary.Velocity
                Arrow(g, PenOf(theme.Arrow, 3 * k), cx, cy, cx + CSng(v.X) * scale, cy - CSng(v.Y) * scale, k)
                ' The marker: a ring with a cross, quartered like a target, in ink on the canvas colour.
                Dim r = 8 * k
                g.FillEllipse(SolidOf(theme.Background), cx - r, cy - r, 2 * r, 2 * r)
                g.FillPie(SolidOf(theme.Ink), cx - r, cy - r, 2 * r, 2 * r, 0, 90)
                g.FillPie(SolidOf(theme.Ink), cx - r, cy - r, 2 * r, 2 * r, 180, 90)
                g.DrawEllipse(PenOf(theme.Ink, 2 * k), cx - r, cy - r, 2 * r, 2 * r)
            End If
        End If
        If p.ShowsMomentumArrows Then DrawMomentumPanel(g, p, theme, k, width, height)
    End Sub

    ''' <summary>
    ''' The top-right panel: the momenta diagram (each body's p tip to tail in its colour, Σp from the
    ''' first tail to the last tip) when it is on, and always the momentum arrows' key.
    ''' </summary>
    Private Sub DrawMomentumPanel(g As Graphics, p As SimulationPresenter, theme As Theme, k As Single, width As Integer, height As Integer)
        Dim ppu = p.MomentumArrows.PixelsPerUnit
        Dim room = CSng(p.MomentumRoomPixels)
        Dim pad = 8 * k
        Dim line = CSng(_font.GetHeight(g))
        Dim keyValue = p.MomentumArrows.LegendMomentum(room * 0.6)
        Dim keyText = Units.Quantity(keyValue, "kg·m/s")
        Dim title = If(p.ShowMomentaDiagram, "Momenta", "Momentum")
        ' In its own column right of the container (see MomentumPanelPixels), as wide as the column.
        Dim column = CSng(p.MomentumPanelPixels)
        Dim w = Math.Max(20 * k, column - 12 * k)
        Dim diagramSide = If(p.ShowMomentaDiagram, Math.Min(1.25F * room, w - 2 * pad), 0.0F)
        Dim h = line + diagramSide + line + 3 * pad
        Dim x0 = width - column + 6 * k, y0 = 6 * k
        ' Opaque: a see-through panel costs a gas about a millisecond a frame in software (libgdiplus).
        g.FillRectangle(SolidOf(theme.Background), x0, y0, w, h)
        g.DrawRectangle(PenOf(theme.Grid, k), x0, y0, w, h)
        g.DrawString(title, _font, SolidOf(theme.Ink), x0 + pad, y0 + pad / 2)
        If p.ShowMomentaDiagram Then
            Dim d = p.Momenta()
            ' The chain's box is centred in the square below the title.
            Dim minX = Math.Min(0.0, d.Sum.X), maxX = Math.Max(0.0, d.Sum.X), minY = Math.Min(0.0, d.Sum.Y), maxY = Math.Max(0.0, d.Sum.Y)
            For i = 0 To d.Count - 1
                Dim t = d.Tail(i) + d.Momentum(i)
                minX = Math.Min(minX, t.X) : maxX = Math.Max(maxX, t.X)
                minY = Math.Min(minY, t.Y) : maxY = Math.Max(maxY, t.Y)
            Next
            Dim boxX = x0 + (w - diagramSide) / 2, boxY = y0 + pad + line
            Dim ox = boxX + diagramSide / 2 - CSng((minX + maxX) / 2 * ppu)
            Dim oy = boxY + diagramSide / 2 + CSng((minY + maxY) / 2 * ppu)
            Dim clip = g.Clip
            g.SetClip(New RectangleF(x0, boxY, w, diagramSide))
            ' The sum first, wide, and the chain over it: where they lie along one line (a head-on
            ' collision) the sum still shows round the chain.
            Arrow(g, PenOf(MomentumColour(theme), 7 * k), ox, oy, ox + CSng(d.Sum.X * ppu), oy - CSng(d.Sum.Y * ppu), k)
            Dim tail = New PointF(ox, oy)
            For i = 0 To d.Count - 1
                Dim pm = d.Momentum(i)
                Dim tip = New PointF(tail.X + CSng(pm.X * ppu), tail.Y - CSng(pm.Y * ppu))
                Arrow(g, PenOf(BodyColours.Parse(d.Colour(i), theme.Ink), 3 * k), tail.X, tail.Y, tip.X, tip.Y, k)
                tail = tip
            Next
            g.Clip = clip
            clip.Dispose()
            If Not d.ShowsEachBody Then
                g.DrawString(d.BodyCount & " bodies: Σp only", _font, SolidOf(theme.Ink), x0 + pad, boxY + diagramSide - line)
            End If
        End If
        ' The key: a round momentum at the same scale as every momentum arrow.
        Dim ky = y0 + h - pad - line / 2
        If keyValue > 0 Then
            Dim len = CSng(keyValue * ppu)
            Arrow(g, PenOf(MomentumColour(theme), 3 * k), x0 + pad, ky, x0 + pad + len, ky, k)
            g.DrawString(keyText, _font, SolidOf(theme.Ink), x0 + pad + len + 6 * k, ky - line / 2)
        End If
    End Sub

    Private Sub DisposeMomentumPens()
        For Each pen In _fadedPens.Values
            pen.Dispose()
        Next
        _fadedPens.Clear()
    End Sub
End Class
