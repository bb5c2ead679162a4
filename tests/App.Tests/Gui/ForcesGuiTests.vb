Option Strict On
Imports System.Text.RegularExpressions
Imports System.Threading
Imports Xunit

''' <summary>
''' The free-body diagram in the real window: on the inclined-plane lesson the Forces tab draws the forces on the
''' block at rest (its weight, the ramp's push and static friction, adding to zero beside m a = 0) on the canvas and
''' lists them in the tab; on the terminal-velocity lesson a body's linear drag b is typed into the tab and applied.
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

    <GuiFact>
    Public Sub TerminalVelocity_TheChosenBodysLinearDrag_IsTypedInTheForcesTab_AndApplied()
        Using app As New AppDriver(New XSessionOptions With {.Screen = "1024x768x24"}, IO.Path.Combine("scenes", "terminal-velocity.json"))
            app.WaitFor("^opened terminal-velocity.json: 2 bodies$")
            Dim from = app.Mark()
            app.Click("tab-forces")
            app.WaitFor("^tab Forces$", skip:=from)
            ' The tab shows the first body's drag: the scene gives both balls b = 0.5 N·s/m.
            app.WaitFor("^drag row: light \| 0 \| 0\.5$", skip:=from)
            ' Choose the second body with the keyboard in the opened list.
            from = app.Mark()
            app.Click("forces-body")
            For Each key In {"Down", "Return"}
                app.X.XDo("key", key)
                Thread.Sleep(300)
            Next
            app.WaitFor("^drag row: heavy \| 0 \| 0\.5$", skip:=from)
            from = app.Mark()
            app.TypeInto("forces-b", "2")
            app.Click("forces-set-drag")
            app.WaitFor("^drag of heavy cd 0\.000 b 2\.000$", skip:=from)
            app.WaitFor("^edit kept: the drag of heavy$", skip:=from)
            app.WaitFor("^drag row: heavy \| 0 \| 2$", skip:=from)
            ' Air on with the density typed (a comma for the decimal point works too), applied with Enter.
            from = app.Mark()
            app.TypeInto("forces-air-density", "1,5")
            app.X.XDo("key", "Return")
            app.WaitFor("^air 1\.500$", skip:=from)
            app.WaitFor("^air row: True \| 1\.5$", skip:=from)
            app.X.Shoot("forces-air-drag")
            ' With large fonts on the smallest screen the rows still fit: each piece across the window, its text whole, none on
            ' another; the page scrolls rather than squeeze the list below its header and two forces.
            from = app.Mark()
            app.Click("large-fonts")
            app.WaitFor("^large fonts on$", skip:=from)
            app.WaitFor("^ready$", skip:=from)
            Dim window = app.LastMatch("^window (-?\d+) (-?\d+) (\d+) (\d+)$")
            Dim wx = CInt(window.Groups(1).Value), wy = CInt(window.Groups(2).Value), ww = CInt(window.Groups(3).Value), wh = CInt(window.Groups(4).Value)
            app.X.Shoot("forces-air-drag-large")
            Dim pieces As New List(Of (Name As String, X As Integer, Y As Integer, W As Integer, H As Integer))
            For Each line In app.LastLayout()
                Dim m = Regex.Match(line, "^control (forces-(?:air|air-density-label|air-density|set-air|cd-label|cd|b-label|b|set-drag)) (-?\d+) (-?\d+) (\d+) (\d+) (fits|cut)$")
                If Not m.Success Then Continue For
                Dim r = (Name:=m.Groups(1).Value, X:=CInt(m.Groups(2).Value), Y:=CInt(m.Groups(3).Value), W:=CInt(m.Groups(4).Value), H:=CInt(m.Groups(5).Value))
                Assert.True(m.Groups(6).Value = "fits", $"{r.Name}'s text is cut off ({r.W} px wide)")
                Assert.True(r.X >= wx AndAlso r.X + r.W <= wx + ww, $"{r.Name} at ({r.X}, {r.Y}, {r.W} × {r.H}) is outside the window")
                pieces.Add(r)
            Next
            Assert.Contains(pieces, Function(p) p.Name = "forces-set-drag")
            Dim textLine = CInt(app.LastMatch("^text line (\d+) px").Groups(1).Value)
            Dim list = app.Control("forces-list")
            Assert.True(list.H >= 3 * textLine, $"the forces list is {list.H} px high, less than three lines ({textLine} px)")
            For i = 0 To pieces.Count - 1
                For j = i + 1 To pieces.Count - 1
                    Dim a = pieces(i), b = pieces(j)
                    Assert.True(a.X + a.W <= b.X OrElse b.X + b.W <= a.X OrElse a.Y + a.H <= b.Y OrElse b.Y + b.H <= a.Y, $"{a.Name} and {b.Name} overlap")
                Next
            Next
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub
End Class
