Option Strict On
Imports Xunit

''' <summary>
''' The free-body diagram in the real window: on the inclined-plane lesson the Forces tab draws the forces on the
''' block at rest (its weight, the ramp's push and static friction, adding to zero beside m a = 0) on the canvas and
''' lists them in the tab.
''' </summary>
<Collection(RealWindow.Name)>
Public Class ForcesGuiTests
    <GuiFact>
    Public Sub InclinedPlane_TheForcesOnTheBlockAtRest_AreDrawnAndListed_AndAddToZero()
        Using app As New AppDriver(New XSessionOptions With {.Screen = "1280x800x24"}, IO.Path.Combine("scenes", "inclined-plane.json"))
            app.WaitFor("^opened inclined-plane.json: 4 bodies$")
            Dim start = app.Mark()
            Dim from = start
            app.Click("tab-forces")
            app.WaitFor("^tab Forces$", skip:=from)
            from = app.Mark()
            app.Click("forces-show")
            app.WaitFor("^forces on$", skip:=from)
            ' The block at rest on the gentle ramp (tan θ below μs): weight, the ramp's push and friction, ΣF = m a = 0.
            Dim shown = app.WaitFor("^forces of stays: W Earth 9\.810 N 270\.0°; N gentle (\S+) N (\S+)°; F gentle (\S+) N (\S+)° \| sum \(0\.000, 0\.000\) N ma \(0\.000, 0\.000\) N$", skip:=from)
            Dim normal = AppDriver.Dbl(shown.Groups(1).Value), friction = AppDriver.Dbl(shown.Groups(3).Value)
            ' N = m g cos θ and F = m g sin θ: together they hold up the weight.
            Assert.Equal(9.81, Math.Sqrt(normal * normal + friction * friction), 2)
            Assert.Equal(90 + AppDriver.Dbl(shown.Groups(4).Value), AppDriver.Dbl(shown.Groups(2).Value), 1)
            ' The tab lists the same forces and the sum.
            app.WaitFor("^forces tab: weight Earth 9\.81 270\.0 \| normal gentle \S+ \S+ \| friction gentle \S+ \S+ \| ΣF = \(0, 0\) N    m·a = \(0, 0\) N$", skip:=start)
            app.X.Shoot("forces-inclined-plane")
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub
End Class
