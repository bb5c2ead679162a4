Option Strict On
Imports Xunit

''' <summary>The grid in the real window: the Grid box draws a line every metre and every 10 cm under the bodies.</summary>
<Collection(RealWindow.Name)>
Public Class GridGuiTests
    <GuiFact>
    Public Sub TheGridBox_DrawsMetreAnd10cmLinesOnTheCanvas()
        Using app As New AppDriver(New XSessionOptions(), IO.Path.Combine("scenes", "inclined-plane.json"))
            app.WaitFor("^opened inclined-plane.json: 4 bodies$")
            app.ClickAndWait("pause", "^paused t=")
            app.WaitFor("^canvas grid 0 lines$")
            Dim window = app.WaitFor("^window (-?\d+) (-?\d+) \d+ \d+$")
            Dim wx = CInt(window.Groups(1).Value), wy = CInt(window.Groups(2).Value)
            ' An empty place of the canvas, on the 1 m line across, halfway between two 10 cm lines up (above the ramps).
            Dim metre = app.Screen(1.0, 4.45)
            Dim before = app.X.Shoot("grid-off")
            Dim from = app.Mark()
            app.Click("grid")
            app.WaitFor("^grid on$", skip:=from)
            ' 10 m × 5 m: 101 lines across and 51 up, the box being drawn large enough for the 10 cm ones.
            app.WaitFor("^canvas grid 152 lines$", skip:=from)
            ' A frame later the painted canvas is on the screen.
            from = app.Mark()
            app.Click("step")
            app.WaitFor("^step t=", skip:=from)
            Dim after = app.X.Shoot("grid-on")
            Dim darkest = Function(shot As Screenshot) Enumerable.Range(-2, 5).Min(Function(d) Pixels.Luma(shot.Pixel(metre.X - wx + d, metre.Y - wy)))
            Assert.True(darkest(before) >= 245, $"the canvas is blank there without the grid: {darkest(before)}")
            Assert.True(darkest(after) < 236, $"no metre line at x = 1 m: {darkest(after)}")
            ' Between two 10 cm lines each way (1.05 m, 4.45 m) the canvas stays blank.
            Dim between = app.Screen(1.05, 4.45)
            Assert.True(Pixels.Luma(after.Pixel(between.X - wx, between.Y - wy)) >= 245, "a line between the 10 cm lines")
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub
End Class
