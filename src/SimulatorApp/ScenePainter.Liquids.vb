Option Strict On
Imports System.Drawing
Imports PhysicsEngine.Presentation

' The liquid regions, under the bodies: a translucent fill in the liquid's colour (see LiquidLook), its
' surface as a clear line across the top, and its density written inside, near the bottom left, when
' the region is big enough on screen to hold it without crowding.
Partial Friend NotInheritable Class ScenePainter
    Private Sub DrawLiquids(g As Graphics, world As World, view As ViewTransform, theme As Theme, k As Single)
        For Each liquid In world.Liquids
            Dim colour = LiquidLook.ColourOf(liquid)
            Dim c = view.ToScreen(New Vector(liquid.Min.X, liquid.Max.Y))
            Dim w = CSng(view.ToPixels(liquid.Width)), h = CSng(view.ToPixels(liquid.Height))
            Dim x = CSng(c.X), y = CSng(c.Y)
            g.FillRectangle(SolidOf(colour, If(theme.IsHighContrast, LiquidLook.HighContrastFillAlpha, LiquidLook.FillAlpha)), x, y, w, h)
            g.DrawLine(PenOf(colour, k * If(theme.IsHighContrast, 4.0F, 3.0F)), x, y, x + w, y)
            Dim label = LiquidLook.Label(liquid)
            Dim size = g.MeasureString(label, _font)
            Dim margin = 4 * k
            If size.Width + 2 * margin <= w AndAlso size.Height * 2 + 2 * margin <= h Then
                g.DrawString(label, _font, SolidOf(theme.Ink), x + margin, y + h - size.Height - margin)
            End If
        Next
    End Sub

    ''' <summary>While a liquid is dragged out: the region it would fill, translucent, edged in its colour.</summary>
    Private Sub DrawLiquidPreview(g As Graphics, p As SimulationPresenter, view As ViewTransform, k As Single)
        If Not p.LiquidStart.HasValue OrElse Not p.ToolCursor.HasValue Then Return
        Dim a = view.ToScreen(p.LiquidStart.Value), b = view.ToScreen(p.ToolCursor.Value)
        Dim colour = If(p.LiquidToolDensity < LiquidLook.OilBelow, LiquidLook.Oil, LiquidLook.Water)
        Dim x = CSng(Math.Min(a.X, b.X)), y = CSng(Math.Min(a.Y, b.Y)), w = CSng(Math.Abs(b.X - a.X)), h = CSng(Math.Abs(b.Y - a.Y))
        g.FillRectangle(SolidOf(colour, LiquidLook.FillAlpha), x, y, w, h)
        g.DrawRectangle(PenOf(colour, 2 * k), x, y, w, h)
    End Sub
End Class
