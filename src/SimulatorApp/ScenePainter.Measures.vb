Option Strict On
Imports System.Drawing
Imports PhysicsEngine.Presentation

' The measuring tools on the canvas: the tape's line with a tick at each end and its reading, the
' protractor's arc at the lower end of the ramp or face under the cursor, the pass line, and the
' stopwatch's readout in the canvas's top left corner (drawn over the scene: it moves no control).
Partial Friend NotInheritable Class ScenePainter
    Private Sub DrawMeasures(g As Graphics, p As SimulationPresenter, view As ViewTransform, theme As Theme, k As Single)
        Dim ink = SolidOf(theme.Ink)
        Dim tape = p.Tape
        If tape.HasLine Then
            Dim a = view.ToScreen(tape.Start.Value), b = view.ToScreen(tape.Finish.Value)
            Dim pen = PenOf(theme.Cue, 2 * k)
            g.DrawLine(pen, CSng(a.X), CSng(a.Y), CSng(b.X), CSng(b.Y))
            ' A tick across each end, so the ends read as the points measured.
            Dim along = New Vector(b.X - a.X, b.Y - a.Y).Normalized(New Vector(1, 0))
            Dim across = along.Perpendicular() * (6 * k)
            For Each e In {a, b}
                g.DrawLine(pen, CSng(e.X - across.X), CSng(e.Y - across.Y), CSng(e.X + across.X), CSng(e.Y + across.Y))
            Next
            Dim label = p.TapeLabel
            Dim size = g.MeasureString(label, _font)
            Dim mx = CSng((a.X + b.X) / 2 + across.X * 2), my = CSng((a.Y + b.Y) / 2 + across.Y * 2)
            g.FillRectangle(SolidOf(theme.Background, 210), mx - size.Width / 2, my - size.Height / 2, size.Width, size.Height)
            g.DrawString(label, _font, ink, mx - size.Width / 2, my - size.Height / 2)
        End If

        Dim reading = p.Protractor
        If reading IsNot Nothing Then
            Dim lower = view.ToScreen(reading.Lower)
            Dim radius = 40 * k
            Dim sweep = CSng(reading.Degrees)
            ' Screen angles run clockwise from +x: a face rising to the right is at −θ, to the left at 180 + θ.
            Dim startAngle = If(reading.RisesRight, -sweep, 180.0F)
            g.DrawArc(PenOf(theme.Cue, 2 * k), CSng(lower.X) - radius, CSng(lower.Y) - radius, 2 * radius, 2 * radius, startAngle, sweep)
            Dim levelEnd = CSng(lower.X) + If(reading.RisesRight, 1, -1) * (radius + 8 * k)
            g.DrawLine(PenOf(theme.Cue, k), CSng(lower.X), CSng(lower.Y), levelEnd, CSng(lower.Y))
            Dim size = g.MeasureString(reading.Label, _font)
            Dim lx = If(reading.RisesRight, levelEnd + 2 * k, levelEnd - size.Width - 2 * k)
            g.FillRectangle(SolidOf(theme.Background, 210), lx, CSng(lower.Y) - size.Height, size.Width, size.Height)
            g.DrawString(reading.Label, _font, ink, lx, CSng(lower.Y) - size.Height)
        End If

        Dim timer = p.PassTimer
        If timer IsNot Nothing Then
            ' The pass line across the whole container.
            Dim reach = p.World.Width + p.World.Height
            Dim a = view.ToScreen(timer.Through - reach * timer.Direction), b = view.ToScreen(timer.Through + reach * timer.Direction)
            Dim dashed = PenOf(theme.Cue, 1.5F * k)
            g.DrawLine(dashed, CSng(a.X), CSng(a.Y), CSng(b.X), CSng(b.Y))
        End If

        Dim text = p.StopwatchText
        If text.Length > 0 Then
            Dim size = g.MeasureString(text, _font)
            Dim pad = 4 * k
            g.FillRectangle(SolidOf(theme.Background, 230), pad, pad, size.Width + 2 * pad, size.Height + 2 * pad)
            g.DrawRectangle(PenOf(theme.Ink, k), pad, pad, size.Width + 2 * pad, size.Height + 2 * pad)
            g.DrawString(text, _font, ink, 2 * pad, 2 * pad)
        End If
    End Sub
End Class
