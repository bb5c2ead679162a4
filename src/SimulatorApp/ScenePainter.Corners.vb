Option Strict On
Imports System.Drawing
Imports PhysicsEngine.Presentation

' A polygon being drawn by its corners: the polygon it would make now (filled faintly, outlined in
' red where it would overlap something), the sides clicked so far, the next side following the
' cursor, and a ring round the first corner once the polygon can be finished there.
Partial Friend NotInheritable Class ScenePainter
    Private Sub DrawCornerDraft(g As Graphics, p As SimulationPresenter, view As ViewTransform, outline As Pen, theme As Theme, k As Single)
        Dim d = p.CornerDraft
        If d Is Nothing OrElse p.Mode <> ClickMode.Corners Then Return
        Dim preview = p.CornerPreview
        If preview.Count >= 3 Then
            Dim pts = Corners(preview, view)
            g.FillPolygon(SolidOf(BodyColours.Parse(d.Colour, &H808080), 110), pts)
            g.DrawPolygon(If(p.CornerPreviewFits, outline, PenOf(theme.Alert, 3 * k)), pts)
        End If
        If d.Count = 0 Then Return
        Dim clicked = Corners(d.Corners, view)
        If clicked.Length >= 2 Then g.DrawLines(PenOf(theme.Ink, 2 * k), clicked)
        Dim last = clicked(clicked.Length - 1), first = clicked(0)
        If p.ToolCursor.HasValue Then
            Dim c = view.ToScreen(p.ToolCursor.Value)
            Dim cx = CSng(c.X), cy = CSng(c.Y)
            ' The side the next click makes, and (faint) the side that closes the polygon.
            _pullPen.Color = Rgb(theme.Cue)
            _pullPen.Width = 3 * k
            g.DrawLine(_pullPen, last.X, last.Y, cx, cy)
            If clicked.Length >= 2 Then
                _pullPen.Width = 1.5F * k
                g.DrawLine(_pullPen, cx, cy, first.X, first.Y)
            End If
        End If
        Dim dot = 4 * k
        For Each pt In clicked
            g.FillEllipse(SolidOf(theme.Ink), pt.X - dot, pt.Y - dot, 2 * dot, 2 * dot)
        Next
        If d.Count >= 3 Then
            ' Where a click finishes the polygon: as far out as the presenter takes a click to be on the first corner.
            Dim ring = CSng(SimulationPresenter.CornerSnapPixels) * k
            g.DrawEllipse(PenOf(theme.Cue, 2 * k), first.X - ring, first.Y - ring, 2 * ring, 2 * ring)
        End If
    End Sub
End Class
