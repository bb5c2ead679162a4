Option Strict On
Imports System.Drawing
Imports System.Drawing.Drawing2D
Imports PhysicsEngine.Presentation

''' <summary>
''' Draws the presenter's scene with GDI+: the window's canvas and the frame benchmark's offscreen
''' bitmap use this same code. Pens, brushes and fonts are cached, and nothing is allocated per body
''' per frame except what GDI+ itself needs.
''' </summary>
Partial Friend NotInheritable Class ScenePainter
    Implements IDisposable

    ''' <summary>Shorter arrows (px at 96 dpi) are not drawn: they would be a blob on the ball.</summary>
    Private Const MinArrowPx As Single = 8
    ''' <summary>With more balls than this, drawing turns off anti-aliasing, labels and arrows to keep the frame rate.</summary>
    Private Const BusyScene As Integer = 80
    ''' <summary>The smallest radius a ball is drawn with, px at 96 dpi, so a 1 cm ball in a 100 m box still shows.</summary>
    Private Const MinBallPx As Single = 2

    Private ReadOnly _fontScale As Double
    Private ReadOnly _brushes As New Dictionary(Of String, SolidBrush)(StringComparer.Ordinal)
    Private ReadOnly _solid As New Dictionary(Of Integer, SolidBrush)
    Private ReadOnly _pens As New Dictionary(Of Long, Pen)
    Private _font As Font
    Private _bigFont As Font
    Private _fontsLarge As Boolean = True ' forces the first build
    Private ReadOnly _arrowPoints(2) As PointF
    Private ReadOnly _pullPen As New Pen(Color.Gray, 2) With {.DashStyle = DashStyle.Dash}
    Private ReadOnly _openPen As New Pen(Color.Gray, 1) With {.DashStyle = DashStyle.Dash}

    ''' <param name="fontScale">how much point sizes grow to be drawn at the screen's DPI (see <see cref="ScreenDpi"/>)</param>
    Public Sub New(Optional fontScale As Double = 1.0)
        _fontScale = If(fontScale > 0, fontScale, 1.0)
    End Sub

    ''' <summary>Paints the whole canvas of <paramref name="width"/> × <paramref name="height"/> px.</summary>
    Public Sub Paint(g As Graphics, p As SimulationPresenter, width As Integer, height As Integer)
        Dim theme = p.Theme
        Dim view = p.View
        Dim world = p.World
        Dim k = CSng(p.ScreenScale)
        Dim busy = world.Circles.Count > BusyScene
        EnsureFonts(p.LargeFonts)
        g.SmoothingMode = If(busy, SmoothingMode.HighSpeed, SmoothingMode.AntiAlias)
        g.TextRenderingHint = Text.TextRenderingHint.AntiAlias
        g.Clear(Rgb(theme.Background))
        Dim thick = k * If(theme.IsHighContrast, 3.0F, 2.0F)
        Dim ink = PenOf(theme.Ink, thick)
        Dim outline = PenOf(theme.Ink, k * If(theme.IsHighContrast, 2.0F, 1.0F))
        Dim strip = p.ScaleStripPixels
        ' Nothing of the scene is drawn over the strip that holds the scale bar and the arrows' key.
        g.SetClip(New RectangleF(0, 0, width, Math.Max(1, height - strip)))

        ' The grid under everything else, the metre lines stronger than the 10 cm ones.
        If p.ShowGrid Then DrawGrid(g, p, view, theme, k)

        ' The container: solid walls, or a faint dashed outline when balls may leave it.
        Dim tl = view.ToScreen(New Vector(0, world.Height))
        Dim cw = CSng(view.ToPixels(world.Width)), ch = CSng(view.ToPixels(world.Height))
        If p.HasWalls Then
            g.DrawRectangle(ink, CSng(tl.X), CSng(tl.Y), cw, ch)
        Else
            ' Dashed in the cue's colour and as thick as a wall, so the open sides read on a projector.
            _openPen.Color = Rgb(theme.Cue)
            _openPen.Width = 2 * k
            g.DrawRectangle(_openPen, CSng(tl.X), CSng(tl.Y), cw, ch)
        End If
        If p.ShowTraces Then DrawTraces(g, p, view, theme, k)
        ' Liquids under the bodies: a body in one shows through its fill.
        DrawLiquids(g, world, view, theme, k)

        ' Fixed bodies first (the fixed colour says they never move), then movable ones over them.
        Dim fixedFill = SolidOf(theme.Fixed)
        For Each r In world.Rectangles
            Dim c = view.ToScreen(New Vector(r.Min.X, r.Max.Y))
            Dim w = CSng(view.ToPixels(r.Width)), h = CSng(view.ToPixels(r.Height))
            g.FillRectangle(If(r.IsFixed, fixedFill, BrushOf(r.Color)), CSng(c.X), CSng(c.Y), w, h)
            g.DrawRectangle(outline, CSng(c.X), CSng(c.Y), w, h)
        Next
        For Each poly In world.Polygons
            Dim pts = Corners(poly.Vertices, view)
            g.FillPolygon(If(poly.IsFixed, fixedFill, BrushOf(poly.Color)), pts)
            g.DrawPolygon(outline, pts)
        Next
        ' A ramp is a line of no thickness: drawn as a thick bar in the fixed colour, edged in ink, so it reads from the back of the room.
        Dim rampEdge = PenOf(theme.Ink, k * 7)
        Dim rampFill = PenOf(theme.Fixed, k * 4)
        rampEdge.StartCap = LineCap.Round
        rampEdge.EndCap = LineCap.Round
        rampFill.StartCap = LineCap.Round
        rampFill.EndCap = LineCap.Round
        For Each seg In world.Segments
            Dim a = view.ToScreen(seg.StartPoint), b = view.ToScreen(seg.EndPoint)
            g.DrawLine(rampEdge, CSng(a.X), CSng(a.Y), CSng(b.X), CSng(b.Y))
            g.DrawLine(rampFill, CSng(a.X), CSng(a.Y), CSng(b.X), CSng(b.Y))
        Next

        For Each c In world.Circles
            Dim s = view.ToScreen(c.Position)
            Dim rad = Math.Max(MinBallPx * k, CSng(view.ToPixels(c.Radius)))
            Dim x = CSng(s.X) - rad, y = CSng(s.Y) - rad, d = 2 * rad
            g.FillEllipse(BrushOf(c.Color), x, y, d, d)
            If Not busy OrElse rad >= 3 Then g.DrawEllipse(outline, x, y, d, d)
            If c.IsFixed AndAlso rad > 6 * k Then
                ' A cross marks a fixed ball: it is pinned where it is.
                Dim arm = rad * 0.5F
                g.DrawLine(ink, CSng(s.X) - arm, CSng(s.Y) - arm, CSng(s.X) + arm, CSng(s.Y) + arm)
                g.DrawLine(ink, CSng(s.X) - arm, CSng(s.Y) + arm, CSng(s.X) + arm, CSng(s.Y) - arm)
            End If
        Next

        DrawLinks(g, world, view, theme, k)
        If p.ShowArrows AndAlso Not busy Then DrawArrows(g, p, view, theme, k)
        DrawForces(g, p, view, theme, k)
        DrawMomentumViews(g, p, view, theme, k, width, height)
        ' Every label last, where the layout put it: over the links and arrows, never over a body or another label.
        If Not busy Then DrawLabels(g, p, theme, width, height)

        Dim carried = p.DraggedBody
        If carried IsNot Nothing Then
            Dim ring = PenOf(theme.Cue, 3 * k)
            Dim circle = TryCast(carried, Circle)
            If circle IsNot Nothing Then
                Dim s = view.ToScreen(circle.Position)
                Dim rad = CSng(view.ToPixels(circle.Radius)) + 5 * k
                g.DrawEllipse(ring, CSng(s.X) - rad, CSng(s.Y) - rad, 2 * rad, 2 * rad)
            Else
                Dim lo = view.ToScreen(New Vector(carried.BoundsMin.X, carried.BoundsMax.Y))
                Dim w = CSng(view.ToPixels(carried.BoundsMax.X - carried.BoundsMin.X)), h = CSng(view.ToPixels(carried.BoundsMax.Y - carried.BoundsMin.Y))
                g.DrawRectangle(ring, CSng(lo.X) - 5 * k, CSng(lo.Y) - 5 * k, w + 10 * k, h + 10 * k)
            End If
        End If

        DrawToolPreview(g, p, view, theme, k)
        DrawLiquidPreview(g, p, view, k)
        DrawCornerDraft(g, p, view, outline, theme, k)

        DrawDraft(g, p, view, outline, theme, k)
        DrawCue(g, p, view, theme, k)
        DrawArrowDrag(g, p, view, theme, k)
        DrawMeasures(g, p, view, theme, k)
        g.ResetClip()
        Dim keyEnd = DrawScaleBar(g, p, view, theme, height, k)
        DrawBanner(g, p, theme, width, height, keyEnd, k)
    End Sub

    ''' <summary>The grid's lines (see <see cref="CanvasGrid"/>): metre lines in the grid colour, 10 cm lines fainter.</summary>
    Private Sub DrawGrid(g As Graphics, p As SimulationPresenter, view As ViewTransform, theme As Theme, k As Single)
        Dim major = PenOf(theme.Grid, k * If(theme.IsHighContrast, 1.5F, 1.0F))
        ' The minor lines halfway between the grid colour and the canvas: there, but quieter than the metres.
        Dim minor = PenOf(Blend(theme.Grid, theme.Background), k)
        For Each line In p.GridLines()
            Dim a = view.ToScreen(line.Start), b = view.ToScreen(line.End)
            g.DrawLine(If(line.Major, major, minor), CSng(a.X), CSng(a.Y), CSng(b.X), CSng(b.Y))
        Next
    End Sub

    ''' <summary>The colour halfway between two &amp;HRRGGBB colours.</summary>
    Private Shared Function Blend(a As Integer, b As Integer) As Integer
        Dim r = (((a >> 16) And &HFF) + ((b >> 16) And &HFF)) \ 2
        Dim gr = (((a >> 8) And &HFF) + ((b >> 8) And &HFF)) \ 2
        Dim bl = ((a And &HFF) + (b And &HFF)) \ 2
        Return (r << 16) Or (gr << 8) Or bl
    End Function

    ''' <summary>
    ''' The labels where the layout placed them (see <see cref="CanvasLabelLayout"/>): an id inside its
    ''' ball in white (the canvas colour on the fixed grey), every other label on a backing of the
    ''' canvas colour, in ink, Σp in the momentum colour.
    ''' </summary>
    Private Sub DrawLabels(g As Graphics, p As SimulationPresenter, theme As Theme, width As Integer, height As Integer)
        Dim measure = Function(text As String) As (Width As Double, Height As Double)
                          Dim sz = g.MeasureString(text, _font)
                          Return (sz.Width, sz.Height)
                      End Function
        For Each placed In p.LayOutLabels(measure, width, height)
            Dim b = placed.Box
            If placed.Inside Then
                ' Dark or light by the colour under it, so an id reads on a yellow ball as on a blue one.
                Dim onFixed = placed.Body IsNot Nothing AndAlso placed.Body.IsFixed AndAlso placed.Body.Kind <> ShapeKind.Circle
                Dim under = If(onFixed, theme.Fixed, BodyColours.Parse(placed.Body?.Color, &H808080))
                g.DrawString(placed.Text, _font, SolidOf(If(BodyColours.Luminance(under) > 0.45, &H101010, &HFFFFFF)), CSng(b.X), CSng(b.Y))
                Continue For
            End If
            Dim colour = If(placed.Kind = CanvasLabelKind.TotalMomentum, MomentumColour(theme), theme.Ink)
            g.FillRectangle(SolidOf(theme.Background, 220), CSng(b.X), CSng(b.Y), CSng(b.Width), CSng(b.Height))
            g.DrawString(placed.Text, _font, SolidOf(colour), CSng(b.X), CSng(b.Y))
        Next
    End Sub

    ''' <summary>A list of model points as canvas points.</summary>
    Private Shared Function Corners(points As IReadOnlyList(Of Vector), view As ViewTransform) As PointF()
        Dim pts(points.Count - 1) As PointF
        For i = 0 To points.Count - 1
            Dim s = view.ToScreen(points(i))
            pts(i) = New PointF(CSng(s.X), CSng(s.Y))
        Next
        Return pts
    End Function

    ''' <summary>Number of zigs in a drawn spring: fixed, so a stretched spring's coils open out and a compressed one's close up.</summary>
    Private Const SpringZigs As Integer = 12

    ''' <summary>
    ''' Every link between the centres of its bodies (or to its anchor): a string as a thin line, a
    ''' rod as a bar, a spring as a zig-zag; an anchor as a small block in the fixed colour.
    ''' </summary>
    Private Sub DrawLinks(g As Graphics, world As World, view As ViewTransform, theme As Theme, k As Single)
        Dim links = world.Links
        If links.Count = 0 Then Return
        Dim thin = PenOf(theme.Ink, 1.5F * k)
        Dim barEdge = PenOf(theme.Ink, 7 * k)
        Dim barFill = PenOf(theme.Fixed, 4 * k)
        Dim coil = PenOf(theme.Ink, 2 * k)
        For Each l In links
            Dim a = view.ToScreen(l.EndA), b = view.ToScreen(l.EndB)
            Dim ax = CSng(a.X), ay = CSng(a.Y), bx = CSng(b.X), by = CSng(b.Y)
            Select Case l.Kind
                Case LinkKind.String
                    g.DrawLine(thin, ax, ay, bx, by)
                Case LinkKind.Rod
                    g.DrawLine(barEdge, ax, ay, bx, by)
                    g.DrawLine(barFill, ax, ay, bx, by)
                Case Else
                    g.DrawLines(coil, Zigzag(ax, ay, bx, by, 6 * k))
            End Select
            If l.B Is Nothing Then
                Dim half = 6 * k
                g.FillRectangle(SolidOf(theme.Fixed), bx - half, by - half, 2 * half, 2 * half)
                g.DrawRectangle(PenOf(theme.Ink, 1.5F * k), bx - half, by - half, 2 * half, 2 * half)
            End If
            ' A dot where the link holds each body: at its centre of mass.
            Dim dot = 2.5F * k
            g.FillEllipse(SolidOf(theme.Ink), ax - dot, ay - dot, 2 * dot, 2 * dot)
            If l.B IsNot Nothing Then g.FillEllipse(SolidOf(theme.Ink), bx - dot, by - dot, 2 * dot, 2 * dot)
        Next
    End Sub

    ''' <summary>A zig-zag from (x0, y0) to (x1, y1) px: short straight ends, <see cref="SpringZigs"/> zigs of half-width <paramref name="amplitude"/> px between.</summary>
    Private Shared Function Zigzag(x0 As Single, y0 As Single, x1 As Single, y1 As Single, amplitude As Single) As PointF()
        Dim dx = x1 - x0, dy = y1 - y0
        Dim len = CSng(Math.Sqrt(dx * dx + dy * dy))
        If len < 1 Then Return {New PointF(x0, y0), New PointF(x1, y1)}
        Dim ux = dx / len, uy = dy / len
        Dim nx = -uy * amplitude, ny = ux * amplitude
        Dim pts(SpringZigs + 2) As PointF
        pts(0) = New PointF(x0, y0)
        ' The zigs fill the middle 80 %: the ends stay straight so the spring is seen to hold the body.
        For i = 0 To SpringZigs
            Dim t = 0.1F + 0.8F * i / SpringZigs
            Dim side = If(i = 0 OrElse i = SpringZigs, 0.0F, If(i Mod 2 = 1, 1.0F, -1.0F))
            pts(i + 1) = New PointF(x0 + dx * t + nx * side, y0 + dy * t + ny * side)
        Next
        pts(SpringZigs + 2) = New PointF(x1, y1)
        Return pts
    End Function

    ''' <summary>While a ramp is dragged or a link's second end is sought: a dashed line from the first end to the cursor.</summary>
    Private Sub DrawToolPreview(g As Graphics, p As SimulationPresenter, view As ViewTransform, theme As Theme, k As Single)
        If Not p.ToolCursor.HasValue Then Return
        Dim start As Vector
        If p.Mode = ClickMode.Ramp AndAlso p.RampStart.HasValue Then
            start = p.RampStart.Value
        ElseIf p.Mode = ClickMode.Link AndAlso p.LinkStart IsNot Nothing Then
            start = p.LinkStart.CentreOfMass
        Else
            Return
        End If
        Dim a = view.ToScreen(start), b = view.ToScreen(p.ToolCursor.Value)
        _pullPen.Color = Rgb(theme.Cue)
        _pullPen.Width = If(p.Mode = ClickMode.Ramp, 5, 3) * k
        g.DrawLine(_pullPen, CSng(a.X), CSng(a.Y), CSng(b.X), CSng(b.Y))
    End Sub

    ''' <summary>Each moving body's velocity (and its components), from its centre of mass, as far as it would go in the arrows' time; clipped to the canvas.</summary>
    Private Sub DrawArrows(g As Graphics, p As SimulationPresenter, view As ViewTransform, theme As Theme, k As Single)
        Dim scale = view.ToPixels(p.Arrows.Seconds) ' px per m/s
        Dim main = PenOf(theme.Arrow, 3 * k)
        Dim xPen = PenOf(theme.ArrowX, 2 * k)
        Dim yPen = PenOf(theme.ArrowY, 2 * k)
        Dim least = MinArrowPx * k
        For Each c In p.World.Movables
            Dim s = view.ToScreen(c.CentreOfMass)
            Dim vx = CSng(c.Velocity.X * scale), vy = CSng(-c.Velocity.Y * scale)
            If vx * vx + vy * vy < least * least OrElse Single.IsInfinity(vx) OrElse Single.IsInfinity(vy) Then Continue For
            Dim sx = CSng(s.X), sy = CSng(s.Y)
            If Math.Abs(vx) >= least Then Arrow(g, xPen, sx, sy, sx + vx, sy, k)
            If Math.Abs(vy) >= least Then Arrow(g, yPen, sx, sy, sx, sy + vy, k)
            Arrow(g, main, sx, sy, sx + vx, sy + vy, k)
        Next
    End Sub

    Private Sub DrawDraft(g As Graphics, p As SimulationPresenter, view As ViewTransform, outline As Pen, theme As Theme, k As Single)
        Dim d = p.Draft
        If d Is Nothing OrElse Not d.HasCentre Then Return
        Dim s = view.ToScreen(d.Centre)
        Dim w = CSng(view.ToPixels(d.Width)), h = CSng(view.ToPixels(d.Height))
        Dim ghost = SolidOf(BodyColours.Parse(d.Colour, &H808080), 140)
        ' A preview that would overlap something is outlined in red: a click there moves it to the nearest free place.
        Dim edge = If(p.DraftFits, outline, PenOf(theme.Alert, 3 * k))
        If d.IsCircle Then
            g.FillEllipse(ghost, CSng(s.X) - w / 2, CSng(s.Y) - h / 2, w, h)
            g.DrawEllipse(edge, CSng(s.X) - w / 2, CSng(s.Y) - h / 2, w, h)
        ElseIf d.Kind = ShapeKind.Polygon Then
            Dim pts = Corners(DirectCast(d.Build(d.Centre), Polygon).Vertices, view)
            g.FillPolygon(ghost, pts)
            g.DrawPolygon(edge, pts)
        Else
            g.FillRectangle(ghost, CSng(s.X) - w / 2, CSng(s.Y) - h / 2, w, h)
            g.DrawRectangle(edge, CSng(s.X) - w / 2, CSng(s.Y) - h / 2, w, h)
        End If
    End Sub

    Private Sub DrawCue(g As Graphics, p As SimulationPresenter, view As ViewTransform, theme As Theme, k As Single)
        Dim c = p.AimedBody
        If c Is Nothing Then Return
        Dim centre = view.ToScreen(c.CentreOfMass)
        Dim cursor = view.ToScreen(p.AimCursor)
        _pullPen.Color = Rgb(theme.Ink)
        _pullPen.Width = 2 * k
        g.DrawLine(_pullPen, CSng(cursor.X), CSng(cursor.Y), CSng(centre.X), CSng(centre.Y))
        ' The shot: from the ball's centre along the impulse, as long as the pull.
        Dim j = p.CueImpulse
        If j.Length > 0 Then
            Dim tip = view.ToScreen(c.CentreOfMass + j / CueShot.ImpulsePerMetre)
            Arrow(g, PenOf(theme.Cue, 4 * k), CSng(centre.X), CSng(centre.Y), CSng(tip.X), CSng(tip.Y), k)
        End If
        Dim label = p.CueLabel
        Dim sz = g.MeasureString(label, _font)
        ' Under the ball, so that the label never hides it or the cue; kept on the canvas.
        Dim lx = CSng(centre.X) - sz.Width / 2, ly = CSng(centre.Y + view.ToPixels(c.BoundsMax.Y - c.CentreOfMass.Y)) + 8 * k
        Dim bounds = g.VisibleClipBounds
        lx = Math.Max(bounds.Left + 2, Math.Min(lx, bounds.Right - sz.Width - 2))
        ly = Math.Max(bounds.Top + 2, Math.Min(ly, bounds.Bottom - sz.Height - 2))
        g.FillRectangle(SolidOf(theme.Background, 220), lx - 2, ly - 2, sz.Width + 4, sz.Height + 4)
        g.DrawString(label, _font, SolidOf(theme.Ink), lx, ly)
    End Sub

    ''' <summary>While a velocity arrow is dragged by its tip: a ring on the tip, and the velocity it sets beside it.</summary>
    Private Sub DrawArrowDrag(g As Graphics, p As SimulationPresenter, view As ViewTransform, theme As Theme, k As Single)
        Dim b = p.ArrowBody
        If b Is Nothing Then Return
        Dim tip = view.ToScreen(b.CentreOfMass + b.Velocity * p.Arrows.Seconds)
        Dim r = 7 * k
        g.DrawEllipse(PenOf(theme.Cue, 2 * k), CSng(tip.X) - r, CSng(tip.Y) - r, 2 * r, 2 * r)
        Dim label = p.ArrowLabel
        Dim sz = g.MeasureString(label, _font)
        ' Beside the tip, kept on the canvas.
        Dim bounds = g.VisibleClipBounds
        Dim lx = Math.Max(bounds.Left + 2, Math.Min(CSng(tip.X) + 12 * k, bounds.Right - sz.Width - 2))
        Dim ly = Math.Max(bounds.Top + 2, Math.Min(CSng(tip.Y) + 10 * k, bounds.Bottom - sz.Height - 2))
        g.FillRectangle(SolidOf(theme.Background, 220), lx - 2, ly - 2, sz.Width + 4, sz.Height + 4)
        g.DrawString(label, _font, SolidOf(theme.Ink), lx, ly)
    End Sub

    ''' <summary>In the strip under the container: the scale bar, then the arrows' key (a round speed drawn at the arrows' scale); returns where they end on the right, px (0 when nothing was drawn).</summary>
    Private Function DrawScaleBar(g As Graphics, p As SimulationPresenter, view As ViewTransform, theme As Theme, height As Integer, k As Single) As Single
        Dim bar = ScaleBar.Choose(view.Scale, 160 * k)
        If bar.Pixels <= 0 Then Return 0
        ' Under the container's left edge, or the canvas's left margin when that edge is off to one side (zoomed in).
        Dim x0 = CSng(If(view.OffsetX >= 16 * k AndAlso view.OffsetX <= g.VisibleClipBounds.Width / 3, view.OffsetX, 16 * k)), y0 = height - p.ScaleStripPixels / 2.0F
        Dim x1 = x0 + CSng(bar.Pixels)
        Dim pen = PenOf(theme.Ink, 3 * k)
        g.DrawLine(pen, x0, y0, x1, y0)
        g.DrawLine(pen, x0, y0 - 6 * k, x0, y0 + 6 * k)
        g.DrawLine(pen, x1, y0 - 6 * k, x1, y0 + 6 * k)
        Dim label = bar.Label
        g.DrawString(label, _font, SolidOf(theme.Ink), x1 + 8 * k, y0 - _font.Height / 2.0F)
        Dim barEnd = x1 + 8 * k + g.MeasureString(label, _font).Width
        If Not p.ShowArrows Then Return barEnd
        ' The key: "→ 2 m/s", the arrow as long as a 2 m/s ball's.
        Dim keyX = barEnd + 24 * k
        Dim pxPerMps = view.ToPixels(p.Arrows.Seconds)
        Dim speed = p.Arrows.LegendSpeed(view.Scale, 90 * k)
        If speed <= 0 Then Return barEnd
        Dim len = CSng(speed * pxPerMps)
        Arrow(g, PenOf(theme.Arrow, 3 * k), keyX, y0, keyX + len, y0, k)
        Dim keyText = "velocity " & Units.Quantity(speed, "m/s")
        g.DrawString(keyText, _font, SolidOf(theme.Ink), keyX + len + 6 * k, y0 - _font.Height / 2.0F)
        Return keyX + len + 6 * k + g.MeasureString(keyText, _font).Width
    End Function

    ''' <summary>The state in words (PAUSED, a tool's hint) in the strip, right of the scale bar and the key (which end at <paramref name="keyEnd"/> px): in the big font when it fits there, else the normal one, else on the canvas's top left.</summary>
    Private Sub DrawBanner(g As Graphics, p As SimulationPresenter, theme As Theme, width As Integer, height As Integer, keyEnd As Single, k As Single)
        Dim text As String = Nothing
        Dim colour = theme.Ink
        If p.Mode = ClickMode.Delete Then
            text = "DELETE MODE: click a body or a link to remove it"
            colour = theme.Alert
        ElseIf p.Mode = ClickMode.Ramp Then
            text = "Drag from one end of the ramp to the other  (Esc cancels)"
        ElseIf p.Mode = ClickMode.Link Then
            text = "Click two bodies, or a body and an empty place  (Esc cancels)"
        ElseIf p.Mode = ClickMode.Corners Then
            ' Short, to fit beside the scale bar: the message box says the rest.
            text = If(p.CornerDraft IsNot Nothing AndAlso p.CornerDraft.Count >= 3,
                      "Enter or the first corner finishes",
                      "Click the corners  (Esc cancels)")
        ElseIf p.Draft IsNot Nothing Then
            text = "Click to place the " & p.Draft.KindName & "  (Esc cancels)"
        ElseIf p.IsPaused Then
            text = "PAUSED"
            colour = theme.Alert
        ElseIf Not p.HasWalls Then
            text = "no walls: balls can leave the box"
        End If
        If text Is Nothing Then Return
        ' In the strip under the container, on the right (the scale bar and the arrows' key are on the left),
        ' never over the key nor cut by the canvas's edge.
        For Each font In {_bigFont, _font}
            Dim sz = g.MeasureString(text, font)
            Dim x = width - sz.Width - 16 * k
            If x >= keyEnd + 12 * k Then
                g.DrawString(text, font, SolidOf(colour), x, height - p.ScaleStripPixels / 2.0F - sz.Height / 2)
                Return
            End If
        Next
        ' No room in the strip: on a backing at the canvas's top left.
        Dim small = g.MeasureString(text, _font)
        g.FillRectangle(SolidOf(theme.Background, 220), 6 * k, 6 * k, small.Width, small.Height)
        g.DrawString(text, _font, SolidOf(colour), 6 * k, 6 * k)
    End Sub

    ''' <summary>An arrow as one polyline (shaft, then the two strokes of the head), so GDI+ strokes it in one call.</summary>
    Private Sub Arrow(g As Graphics, pen As Pen, x0 As Single, y0 As Single, x1 As Single, y1 As Single, k As Single)
        Dim dx = x1 - x0, dy = y1 - y0
        Dim len = CSng(Math.Sqrt(dx * dx + dy * dy))
        If len < 1 Then Return
        Dim head = Math.Min(10.0F * k, len * 0.4F)
        Dim ux = dx / len, uy = dy / len
        ' Wings at ±30° back from the tip; the path goes wing → tip → start, then tip → other wing.
        Dim pts = _arrowPoints
        pts(0) = New PointF(x1 - head * (ux * 0.866F - uy * 0.5F), y1 - head * (uy * 0.866F + ux * 0.5F))
        pts(1) = New PointF(x1, y1)
        pts(2) = New PointF(x1 - head * (ux * 0.866F + uy * 0.5F), y1 - head * (uy * 0.866F - ux * 0.5F))
        g.DrawLines(pen, pts)
        g.DrawLine(pen, x0, y0, x1, y1)
    End Sub

    Private Sub EnsureFonts(large As Boolean)
        If _font IsNot Nothing AndAlso large = _fontsLarge Then Return
        _font?.Dispose()
        _bigFont?.Dispose()
        _font = New Font(FontFamily.GenericSansSerif, CSng(If(large, 14.0, 10.0) * _fontScale), FontStyle.Bold)
        _bigFont = New Font(FontFamily.GenericSansSerif, CSng(If(large, 20.0, 14.0) * _fontScale), FontStyle.Bold)
        _fontsLarge = large
    End Sub

    Private Function BrushOf(hex As String) As SolidBrush
        Dim key = If(hex, "")
        Dim b As SolidBrush = Nothing
        If _brushes.TryGetValue(key, b) Then Return b
        b = New SolidBrush(Rgb(BodyColours.Parse(hex, &H808080)))
        _brushes(key) = b
        Return b
    End Function

    Private Function SolidOf(colour As Integer, Optional alpha As Integer = 255) As SolidBrush
        Dim key = (alpha << 24) Or (colour And &HFFFFFF)
        Dim b As SolidBrush = Nothing
        If _solid.TryGetValue(key, b) Then Return b
        b = New SolidBrush(Color.FromArgb(alpha, Rgb(colour)))
        _solid(key) = b
        Return b
    End Function

    Private Function PenOf(colour As Integer, width As Single) As Pen
        Dim key = (CLng(colour And &HFFFFFF) << 16) Or CLng(width * 16)
        Dim p As Pen = Nothing
        If _pens.TryGetValue(key, p) Then Return p
        p = New Pen(Rgb(colour), width)
        _pens(key) = p
        Return p
    End Function

    ''' <summary>&amp;HRRGGBB to an opaque GDI+ colour.</summary>
    Public Shared Function Rgb(value As Integer) As Color
        Return Color.FromArgb(255, (value >> 16) And 255, (value >> 8) And 255, value And 255)
    End Function

    Public Sub Dispose() Implements IDisposable.Dispose
        For Each b In _brushes.Values
            b.Dispose()
        Next
        For Each b In _solid.Values
            b.Dispose()
        Next
        For Each p In _pens.Values
            p.Dispose()
        Next
        _brushes.Clear()
        _solid.Clear()
        _pens.Clear()
        _pullPen.Dispose()
        _openPen.Dispose()
        DisposeMomentumPens()
        _font?.Dispose()
        _bigFont?.Dispose()
    End Sub
End Class
