Option Strict On
Imports System.Globalization
Imports Xunit

''' <summary>Liquids in the real window: the floating-and-sinking lesson run until the boxes settle, drawn translucent blue with its surface.</summary>
<Collection(RealWindow.Name)>
Public Class LiquidsGuiTests
    <GuiFact>
    Public Sub FloatingAndSinking_TheLightBoxFloatsAtItsDepth_TheDenseOneLiesOnTheBottom_InBlueWater()
        Using app As New AppDriver(New XSessionOptions(), IO.Path.Combine("scenes", "floating-sinking.json"))
            app.WaitFor("^opened floating-sinking.json: 3 bodies$")
            ' Lightly damped, the boxes settle within a few seconds of simulated time.
            app.WaitFor("^clock 9 s$", TimeSpan.FromSeconds(60))
            app.ClickAndWait("pause", "^paused t=")
            Dim from = app.Mark()
            app.Click("step")
            app.WaitFor("^step t=", skip:=from)
            ' A box's position is its lower-left corner: its depth is the surface (2 m) less its bottom.
            Dim bottom = Function(id As String) Double.Parse(app.WaitFor("^state " & id & " \S+ (\S+) ", skip:=from).Groups(1).Value, CultureInfo.InvariantCulture)
            ' 90 kg, 0.6 m wide, in water of 1000 kg/m²: m/(ρ_l w) = 0.15 m; 270 kg: 0.45 m.
            Assert.True(Math.Abs(2.0 - bottom("cork") - 0.15) < 0.001, $"cork's depth {2.0 - bottom("cork")} m")
            Assert.True(Math.Abs(2.0 - bottom("oak") - 0.45) < 0.001, $"oak's depth {2.0 - bottom("oak")} m")
            Assert.True(Math.Abs(bottom("brick")) < 0.000001, $"brick's bottom at {bottom("brick")} m")
            Dim window = app.WaitFor("^window (-?\d+) (-?\d+) \d+ \d+$")
            Dim wx = CInt(window.Groups(1).Value), wy = CInt(window.Groups(2).Value)
            Dim shot = app.X.Shoot("floating-sinking")
            ' In the water between the boxes: blue; above it: the canvas.
            Dim wet = app.Screen(2.6, 1.0), dry = app.Screen(2.6, 3.0)
            Dim p = shot.Pixel(wet.X - wx, wet.Y - wy)
            Assert.True((p And &HFF) > ((p >> 16) And &HFF) + 40, $"water is not blue: {p:X6}")
            Assert.True(Pixels.Luma(shot.Pixel(dry.X - wx, dry.Y - wy)) >= 245, "the air above the water is not the canvas")
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub

    <GuiFact>
    Public Sub TheLiquidMenu_OilDraggedOutOnTheCanvas_IsAddedAndDrawnAmber()
        Using app As New AppDriver(New XSessionOptions(), IO.Path.Combine("scenes", "floating-sinking.json"))
            app.WaitFor("^opened floating-sinking.json: 3 bodies$")
            app.ClickAndWait("pause", "^paused t=")
            Dim from = app.Mark()
            app.Click("add-liquid")
            Dim oil = app.WaitFor("^liquid item 1 (-?\d+) (-?\d+) (\d+) (\d+)$", skip:=from)
            app.ClickAt(CInt(oil.Groups(1).Value) + CInt(oil.Groups(3).Value) \ 2, CInt(oil.Groups(2).Value) + CInt(oil.Groups(4).Value) \ 2)
            app.WaitFor("^mode liquid density 900 kg/m²$", skip:=from)
            ' Above the water and clear of the boxes: a second liquid may not overlap the first.
            Dim a = app.Screen(2.0, 2.6), b = app.Screen(3.4, 3.6)
            app.Drag(1, a.X, a.Y, b.X, b.Y)
            app.WaitFor("^placed liquid \S+ density 900 from ", skip:=from)
            from = app.Mark()
            app.Click("step")
            app.WaitFor("^step t=", skip:=from)
            Dim window = app.WaitFor("^window (-?\d+) (-?\d+) \d+ \d+$")
            Dim wx = CInt(window.Groups(1).Value), wy = CInt(window.Groups(2).Value)
            Dim shot = app.X.Shoot("oil-drawn")
            Dim inOil = app.Screen(2.7, 3.1)
            Dim p = shot.Pixel(inOil.X - wx, inOil.Y - wy)
            ' Amber: red above blue.
            Assert.True(((p >> 16) And &HFF) > (p And &HFF) + 40, $"oil is not amber: {p:X6}")
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub
End Class
