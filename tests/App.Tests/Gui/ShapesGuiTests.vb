Option Strict On
Imports System.Threading
Imports Xunit

''' <summary>
''' The ramp, polygon, box and link tools in the real window under Xvfb, used with the mouse as a
''' teacher would: each checked in the app's --trace output and in a screenshot's pixels.
''' </summary>
<Collection(RealWindow.Name)>
Public Class ShapesGuiTests
    ''' <summary>The light theme's canvas and its fixed colour (&amp;HRRGGBB).</summary>
    Private Const Background As Integer = &HFAFAFA
    Private Const FixedColour As Integer = &H78909C

    <GuiFact>
    Public Sub AddRamp_ByDragging_IsDrawnFromEndToEnd()
        Using app As New AppDriver()
            app.PauseAndClear()
            app.ClickAndWait("add-ramp", "^mode ramp$")
            Dim a = app.Screen(1.0, 1.0), b = app.Screen(5.0, 3.0)
            Dim from = app.Mark()
            app.Drag(1, a.X, a.Y, b.X, b.Y)
            Dim m = app.WaitFor("^placed ramp (\S+) from \((\S+), (\S+)\) to \((\S+), (\S+)\)", skip:=from)
            ' One pixel is 1/scale m: the ends are where the drag began and ended, to a pixel or two.
            Dim px = 2.5 / app.Scale
            Assert.Equal(1.0, AppDriver.Dbl(m.Groups(2).Value), px)
            Assert.Equal(1.0, AppDriver.Dbl(m.Groups(3).Value), px)
            Assert.Equal(5.0, AppDriver.Dbl(m.Groups(4).Value), px)
            Assert.Equal(3.0, AppDriver.Dbl(m.Groups(5).Value), px)
            Thread.Sleep(300)
            Dim shot = app.X.Shoot("shapes-ramp")
            ' Along the line: the bar in the fixed colour; half a metre off it: the empty canvas.
            For Each t In {0.2, 0.5, 0.8}
                Dim p = app.Screen(1 + 4 * t, 1 + 2 * t)
                Assert.True(shot.Fraction(p.X - 1, p.Y - 1, p.X + 2, p.Y + 2, Function(c) c = FixedColour) > 0.3, $"no ramp drawn at {t:P0} of its length")
            Next
            Dim off = app.Screen(3.0, 2.5)
            Assert.True(shot.Fraction(off.X - 3, off.Y - 3, off.X + 4, off.Y + 4, Function(c) c = Background) > 0.95, "the ramp is a line, not a block")
        End Using
    End Sub

    <GuiFact>
    Public Sub AddPolygon_FromTheTypedValues_IsPlacedWhereClicked()
        Using app As New AppDriver()
            app.PauseAndClear()
            app.TypeInto("sides", "6")
            app.TypeInto("radius", "0.6")
            app.TypeInto("angle", "30")
            app.TypeInto("mass", "2")
            app.ClickAndWait("add-polygon", "^adding polygon n 6 r 0.600 m angle 30.0 m 2.000 kg$")
            Dim target = app.Screen(4.0, 2.5)
            Dim from = app.Mark()
            app.MoveTo(target.X - 20, target.Y)
            app.MoveTo(target.X, target.Y)
            app.ClickAt(target.X, target.Y)
            Dim m = app.WaitFor("^placed polygon (\S+) at \((\S+), (\S+)\)", skip:=from)
            Assert.Equal(4.0, AppDriver.Dbl(m.Groups(2).Value), 1)
            Assert.Equal(2.5, AppDriver.Dbl(m.Groups(3).Value), 1)
            Thread.Sleep(300)
            Dim shot = app.X.Shoot("shapes-polygon")
            Dim r = 0.6 * app.Scale
            ' Turned 30° from a corner straight up, a hexagon has corners left and right at r and flat
            ' sides above and below at 0.866 r: filled towards a corner past the flat sides' distance,
            ' empty just beyond the flat top.
            Assert.True(ColouredAround(shot, target.X + CInt(0.9 * r), target.Y, 2) > 0.8, "the polygon is filled towards its right corner")
            Assert.True(ColouredAround(shot, target.X, target.Y - CInt(0.78 * r), 2) > 0.8, "the polygon is filled up to its flat top")
            Assert.True(ColouredAround(shot, target.X, target.Y - CInt(0.95 * r), 2) < 0.1, "nothing beyond its flat top")
            ' The Bodies tab lists it with its kind, centre, mass and size.
            from = app.Mark()
            app.Click("tab-bodies")
            app.WaitFor("^row Bodies 0: " & m.Groups(1).Value & " \| #[0-9a-f]{6} \| hexagon \| 4.00 \| 2.50 \| 0 \| 0 \| 0 \| 2.00 \| \S+ × \S+ \| ", skip:=from)
            Thread.Sleep(300)
            app.X.Shoot("shapes-polygon-table")
        End Using
    End Sub

    <GuiFact>
    Public Sub AddBox_WithFixedCleared_FallsToTheFloor()
        Using app As New AppDriver()
            app.PauseAndClear()
            app.TypeInto("rect-width", "1")
            app.TypeInto("rect-height", "0.6")
            app.TypeInto("mass", "3")
            app.ClickAndWait("rect-fixed", "^rectangle fixed off$")
            app.ClickAndWait("add-rectangle", "^adding box 1.000 x 0.600 m m 3.000 kg$")
            Dim target = app.Screen(5.0, 3.0)
            Dim from = app.Mark()
            app.MoveTo(target.X - 20, target.Y)
            app.MoveTo(target.X, target.Y)
            app.ClickAt(target.X, target.Y)
            Dim placedAt = app.WaitFor("^placed box (\S+) at \((\S+), (\S+)\)", skip:=from)
            Dim id = placedAt.Groups(1).Value
            Dim x0 = AppDriver.Dbl(placedAt.Groups(2).Value), y0 = AppDriver.Dbl(placedAt.Groups(3).Value)
            Thread.Sleep(300)
            Dim placed = app.X.Shoot("shapes-box-placed")
            Assert.True(ColouredAround(placed, target.X + CInt(0.3 * app.Scale), target.Y, 3) > 0.8, "the box is drawn where it was placed")
            ' Time on until it has hit the floor: with e = 1 it bounces back up, and with its lower side
            ' starting h = y0 − 0.3 m up its centre follows y = y0 − ½ g τ², τ the time since the last top
            ' of a bounce (a period of 2 √(2 h / g)). A busy machine runs fewer frames, so the test waits
            ' for simulated time, not real time.
            Dim t = 0.0, y = 0.0
            For attempt = 1 To 20
                app.ClickAndWait("pause", "^resumed$")
                Thread.Sleep(700)
                from = app.Mark()
                app.Click("pause")
                t = AppDriver.Dbl(app.WaitFor("^paused t=(\S+) s$", skip:=from).Groups(1).Value)
                Dim m = app.WaitFor("^body " & id & " at \((\S+), (\S+)\) m", skip:=from)
                Assert.Equal(x0, AppDriver.Dbl(m.Groups(1).Value), 3)
                y = AppDriver.Dbl(m.Groups(2).Value)
                If t > 0.9 Then Exit For
            Next
            Assert.True(t > 0.9, $"time reached only {t} s")
            Const g As Double = 9.81
            Dim fall = Math.Sqrt(2 * (y0 - 0.3) / g)
            Dim tau = t Mod (2 * fall)
            If tau > fall Then tau = 2 * fall - tau
            ' The trace gives t to 1 ms, in which the box moves at most √(2 g h) × 0.5 ms ≈ 4 mm.
            Assert.InRange(y - (y0 - 0.5 * g * tau * tau), -0.006, 0.006)
            Thread.Sleep(300)
            Dim fallen = app.X.Shoot("shapes-box-fallen")
            Dim now = app.Screen(x0, y)
            Assert.True(ColouredAround(fallen, now.X + CInt(0.3 * app.Scale), now.Y, 3) > 0.8, "the box is drawn where it has got to")
        End Using
    End Sub

    <GuiFact>
    Public Sub Links_SpringRodAndString_AreDrawnListedAndDeleted()
        Using app As New AppDriver()
            app.PauseAndClear()
            Dim left = app.PlaceCircle("0.3", "1", 2.0, 3.0)
            Dim right = app.PlaceCircle("0.3", "1", 5.0, 3.0)
            app.TypeInto("stiffness", "30")
            app.ClickAndWait("add-spring", "^mode link spring k 30.000 N/m$")
            Dim spring = Link(app, 2.0, 3.0, 5.0, 3.0, "spring " & left & " to " & right & " length 3.000 m")
            app.ClickAndWait("add-string", "^mode link string$")
            Dim strand = Link(app, 2.0, 3.0, 2.0, 4.6, "string " & left & " to anchor \(")
            app.ClickAndWait("add-rod", "^mode link rod$")
            Link(app, 5.0, 3.0, 6.5, 4.6, "rod " & right & " to anchor \(")
            Thread.Sleep(300)
            Dim shot = app.X.Shoot("shapes-links")
            ' The spring's zig-zag crosses the straight line between the balls again and again: ink
            ' above and below it; the rod is a bar in the fixed colour; the string a thin dark line.
            Dim mid = app.Screen(3.5, 3.0)
            Assert.True(shot.Fraction(mid.X - 40, mid.Y - 8, mid.X + 40, mid.Y - 2, AddressOf IsInk) > 0.02, "no zig-zag above the spring's line")
            Assert.True(shot.Fraction(mid.X - 40, mid.Y + 2, mid.X + 40, mid.Y + 8, AddressOf IsInk) > 0.02, "no zig-zag below the spring's line")
            Dim rod = app.Screen(5.75, 3.8)
            Assert.True(shot.Fraction(rod.X - 2, rod.Y - 2, rod.X + 3, rod.Y + 3, Function(c) c = FixedColour) > 0.3, "no rod drawn")
            Dim str = app.Screen(2.0, 3.8)
            Assert.True(shot.Fraction(str.X - 3, str.Y, str.X + 4, str.Y + 1, AddressOf IsInk) > 0, "no string drawn")
            Dim anchor = app.Screen(6.5, 4.6)
            Assert.True(shot.Fraction(anchor.X - 3, anchor.Y - 3, anchor.X + 4, anchor.Y + 4, Function(c) c = FixedColour) > 0.3, "no anchor drawn")

            ' The Links tab lists the three, the spring with its stiffness and its rest length.
            Dim from = app.Mark()
            app.Click("tab-links")
            app.WaitFor("^row Links 0: " & spring & " \| spring, k 30.0.N/m \| " & left & " \| " & right & " \| 3.00 \| ", skip:=from)
            app.WaitFor("^row Links 2: \S+ \| rod \| " & right & " \| anchor \(", skip:=from)
            Thread.Sleep(300)
            app.X.Shoot("shapes-links-table")

            ' Delete mode: a click on the string (not on a ball) removes just the string.
            app.ClickAndWait("delete-mode", "^mode delete$")
            from = app.Mark()
            app.ClickAt(str.X, str.Y)
            app.WaitFor("^deleted link " & strand & "$", skip:=from)
            Thread.Sleep(300)
            Dim after = app.X.Shoot("shapes-link-deleted")
            Assert.True(after.Fraction(str.X - 3, str.Y, str.X + 4, str.Y + 1, AddressOf IsInk) = 0, "the string is still drawn")
            Assert.True(after.Fraction(mid.X - 40, mid.Y - 8, mid.X + 40, mid.Y - 2, AddressOf IsInk) > 0.02, "the spring went too")
        End Using
    End Sub

    <GuiFact>
    Public Sub ASceneOfEveryKind_ReadsInBothThemes()
        Using app As New AppDriver()
            app.PauseAndClear()
            ' A ramp, a fixed triangle, a box, a pendulum on a string and two balls on a spring.
            app.ClickAndWait("add-ramp", "^mode ramp$")
            Dim a = app.Screen(0.4, 2.2), b = app.Screen(3.2, 0.6)
            Dim from = app.Mark()
            app.Drag(1, a.X, a.Y, b.X, b.Y)
            app.WaitFor("^placed ramp ", skip:=from)
            app.TypeInto("sides", "3")
            app.TypeInto("angle", "0")
            app.TypeInto("radius", "0.5")
            app.ClickAndWait("fixed", "^inputs ")
            app.ClickAndWait("add-polygon", "^adding fixed polygon n 3 ")
            Place(app, 4.2, 0.6, "polygon")
            app.ClickAndWait("fixed", "^inputs ")
            app.TypeInto("rect-width", "0.8")
            app.TypeInto("rect-height", "0.5")
            app.TypeInto("mass", "2")
            app.ClickAndWait("rect-fixed", "^rectangle fixed off$")
            app.ClickAndWait("add-rectangle", "^adding box ")
            Place(app, 6.8, 0.3, "box")
            app.PlaceCircle("0.25", "1", 2.5, 3.0)
            app.ClickAndWait("add-string", "^mode link string$")
            Link(app, 2.5, 3.0, 2.0, 4.7, "string ")
            app.PlaceCircle("0.2", "1", 4.6, 3.2)
            app.PlaceCircle("0.3", "3", 6.6, 3.2)
            app.TypeInto("stiffness", "40")
            app.ClickAndWait("add-spring", "^mode link spring ")
            Link(app, 4.6, 3.2, 6.6, 3.2, "spring ")
            app.ClickAndWait("add-rod", "^mode link rod$")
            Link(app, 6.6, 3.2, 7.4, 4.7, "rod ")
            ' A push on the box, so its velocity arrow shows too.
            Dim box = app.Screen(6.8, 0.3)
            from = app.Mark()
            app.Drag(1, box.X, box.Y, box.X + CInt(app.Scale * 0.4), box.Y, 4)
            app.WaitFor("^fired ", skip:=from)
            Thread.Sleep(300)
            Dim light = app.X.Shoot("shapes-scene")
            Dim canvas = app.Control("canvas")
            Assert.True(light.DistinctColours(canvas.X, canvas.Y, canvas.X + canvas.W, canvas.Y + canvas.H) > 8, "the scene is drawn")
            app.ClickAndWait("high-contrast", "^high contrast on$")
            Thread.Sleep(300)
            Dim dark = app.X.Shoot("shapes-scene-dark")
            ' The ramp still shows against the black canvas: its bar is the dark theme's fixed colour.
            Dim mid = app.Screen(1.8, 1.4)
            Assert.True(dark.Fraction(mid.X - 1, mid.Y - 1, mid.X + 2, mid.Y + 2, Function(c) c = &HB0BEC5) > 0.3, "no ramp on the dark canvas")
        End Using
    End Sub

    ''' <summary>Moves onto a model point and clicks to place the body waiting there; waits for the trace.</summary>
    Private Shared Sub Place(app As AppDriver, x As Double, y As Double, kind As String)
        Dim p = app.Screen(x, y)
        Dim from = app.Mark()
        app.MoveTo(p.X - 20, p.Y)
        app.MoveTo(p.X, p.Y)
        app.ClickAt(p.X, p.Y)
        app.WaitFor("^placed " & kind & " ", skip:=from)
    End Sub

    ''' <summary>Clicks a body at (x0, y0) m, then a body or empty place at (x1, y1) m, with the link tool on; returns the new link's id.</summary>
    Private Shared Function Link(app As AppDriver, x0 As Double, y0 As Double, x1 As Double, y1 As Double, made As String) As String
        Dim a = app.Screen(x0, y0), b = app.Screen(x1, y1)
        Dim from = app.Mark()
        app.ClickAt(a.X, a.Y)
        app.WaitFor("^link from ", skip:=from)
        app.ClickAt(b.X, b.Y)
        Return app.WaitFor("^linked (\S+) " & made, skip:=from).Groups(1).Value
    End Function

    ''' <summary>The light theme's ink and the dark edges of drawn lines.</summary>
    Private Shared Function IsInk(c As Integer) As Boolean
        Return Luma(c) < 90
    End Function
End Class
