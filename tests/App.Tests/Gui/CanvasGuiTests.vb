Option Strict On
Imports System.Globalization
Imports System.Text.RegularExpressions
Imports System.Threading
Imports Xunit

''' <summary>The canvas in the real window: the wheel zooms about the pointer (and scrolls the side panel over it, never zooming), Ctrl+0 shows the whole box.</summary>
<Collection(RealWindow.Name)>
Public Class CanvasGuiTests
    Private Shared Function D(text As String) As Double
        Return Double.Parse(text, CultureInfo.InvariantCulture)
    End Function

    <GuiFact>
    Public Sub TheWheelOverTheCanvas_ZoomsAboutThePointer_AndCtrl0ShowsTheWholeBox()
        Using app As New AppDriver(New XSessionOptions With {.Screen = "1280x720x24"})
            app.ClickAndWait("pause", "^paused t=")
            Dim fitted = app.Scale
            Dim c = app.Control("canvas")
            Dim px = c.X + c.W \ 3, py = c.Y + c.H \ 3
            ' The point of the scene under the pointer, before.
            Dim under = app.ToWorld(px, py)
            Dim from = app.Mark()
            app.MoveTo(px, py)
            For k = 1 To 4
                app.X.XDo("click", "4")
            Next
            app.WaitFor("^zoom 2\.441$", skip:=from)
            app.WaitFor("^view scale ", skip:=from)
            app.ReadLayout()
            Assert.Equal(fitted * Math.Pow(1.25, 4), app.Scale, 1)
            Dim still = app.ToWorld(px, py)
            Assert.True(Math.Abs(still.X - under.X) < 2 / app.Scale AndAlso Math.Abs(still.Y - under.Y) < 2 / app.Scale, $"the point under the pointer moved from {under} to {still}")
            app.X.Shoot("canvas-zoomed")
            ' The wheel over the side panel is the panel's, not the canvas's.
            Dim side = app.Control("side")
            from = app.Mark()
            app.MoveTo(side.X + side.W \ 2, side.Y + side.H \ 2)
            app.X.XDo("click", "4")
            app.WaitFor("^wheel side ", skip:=from)
            app.X.XDo("key", "ctrl+0")
            app.WaitFor("^key whole view$", skip:=from)
            app.WaitFor("^zoom 1\.000$", skip:=from)
            Assert.Equal(1, app.Lines().Skip(from).Count(Function(l) l.StartsWith("zoom ", StringComparison.Ordinal)))
            app.ReadLayout()
            Assert.Equal(fitted, app.Scale, 3)
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub
End Class
