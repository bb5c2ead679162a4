Option Strict On
Imports System.Globalization
Imports System.Text.RegularExpressions
Imports System.Threading
Imports Xunit

''' <summary>
''' The momentum views, the walls toggle and typing into the tables, in the real window: each
''' toggle is clicked, its number in the trace is checked against the bodies' state the engine
''' reports, and the canvas is photographed.
''' </summary>
<Collection(RealWindow.Name)>
Public Class MomentumViewsGuiTests
    Private Const MomentumPurple As Integer = &H6A1B9A

    Private Shared Function D(text As String) As Double
        Return Double.Parse(text, CultureInfo.InvariantCulture)
    End Function

    ''' <summary>Each movable body's last reported state on pausing: id → (x, y, vx, vy).</summary>
    Private Shared Function Bodies(app As AppDriver, fromLine As Integer) As Dictionary(Of String, (X As Double, Y As Double, Vx As Double, Vy As Double))
        Dim result As New Dictionary(Of String, (X As Double, Y As Double, Vx As Double, Vy As Double))(StringComparer.Ordinal)
        For Each line In app.Lines().Skip(fromLine)
            Dim m = Regex.Match(line, "^body (\S+) at \((\S+), (\S+)\) m v \((\S+), (\S+)\) m/s$")
            If m.Success Then result(m.Groups(1).Value) = (D(m.Groups(2).Value), D(m.Groups(3).Value), D(m.Groups(4).Value), D(m.Groups(5).Value))
        Next
        Return result
    End Function

    Private Shared Sub Near(expected As Double, actual As Double, tolerance As Double)
        Assert.True(Math.Abs(expected - actual) <= tolerance, $"{actual} is not within {tolerance} of {expected}")
    End Sub

    Private Shared Function NearColour(p As Integer, target As Integer) As Boolean
        Dim dr = ((p >> 16) And 255) - ((target >> 16) And 255), dg = ((p >> 8) And 255) - ((target >> 8) And 255), db = (p And 255) - (target And 255)
        Return Math.Abs(dr) < 40 AndAlso Math.Abs(dg) < 40 AndAlso Math.Abs(db) < 40
    End Function

    <GuiFact>
    Public Sub CentreOfMass_TotalMomentum_Diagram_AndTraces_ShowTheEnginesNumbers()
        Using app As New AppDriver()
            app.PauseAndClear()
            Dim a = app.PlaceCircle("0.3", "1", 2.0, 3.0)
            Dim b = app.PlaceCircle("0.4", "3", 6.0, 2.0)
            app.ClickAndWait("centre-of-mass", "^centre of mass on$")
            app.ClickAndWait("total-momentum", "^total momentum on$")
            app.ClickAndWait("momenta-diagram", "^momenta diagram on$")
            app.ClickAndWait("traces", "^traces on$")
            ' Let them fall a little, then stop time: the pause lists every body and the views' numbers.
            app.ClickAndWait("pause", "^resumed$")
            Thread.Sleep(600)
            Dim from = app.Mark()
            app.Click("pause")
            Dim com = app.WaitFor("^centre of mass at \((\S+), (\S+)\) m v \((\S+), (\S+)\) m/s total mass (\S+) kg Σp \((\S+), (\S+)\) kg·m/s$", skip:=from)
            Dim state = Bodies(app, from)
            Assert.True(state.ContainsKey(a) AndAlso state.ContainsKey(b), app.X.AppOutput())
            Dim sa = state(a), sb = state(b)
            ' Σm·x / Σm and Σm·v, worked out here from the engine's report of each body (masses 1 and 3 kg).
            Assert.Equal(4.0, D(com.Groups(5).Value), 6)
            ' The bodies are reported to 3 decimals: the sums agree to within what that rounding allows.
            Near((1 * sa.X + 3 * sb.X) / 4, D(com.Groups(1).Value), 0.001)
            Near((1 * sa.Y + 3 * sb.Y) / 4, D(com.Groups(2).Value), 0.001)
            Near(1 * sa.Vx + 3 * sb.Vx, D(com.Groups(6).Value), 0.003)
            Near(1 * sa.Vy + 3 * sb.Vy, D(com.Groups(7).Value), 0.003)
            Near(D(com.Groups(7).Value) / 4, D(com.Groups(4).Value), 0.0002)
            Assert.True(Math.Abs(D(com.Groups(7).Value)) > 1, "they have been falling (or bouncing): Σp is not zero")
            ' The trace of each ball ends where the ball is: its newest sample is at most a sample (1/30 s) and a
            ' frame old, so within |v| · 0.06 s of the ball.
            Dim trace = app.WaitFor("^trace " & Regex.Escape(a) & " (\d+) points, newest \((\S+), (\S+)\) m$", skip:=from)
            Assert.True(CInt(trace.Groups(1).Value) >= 5, trace.Value)
            Dim lag = Math.Sqrt(sa.Vx * sa.Vx + sa.Vy * sa.Vy) * 0.06 + 0.01
            Assert.InRange(D(trace.Groups(2).Value), sa.X - lag, sa.X + lag)
            Assert.InRange(D(trace.Groups(3).Value), sa.Y - lag, sa.Y + lag)
            Thread.Sleep(300)
            Dim shot = app.X.Shoot("momentum-views")
            Dim canvas = app.Control("canvas")
            Dim window = app.Control("totals")
            Dim purple = shot.Fraction(0, 0, canvas.W, canvas.H, Function(p) NearColour(p, MomentumPurple))
            Assert.True(purple > 0.0005, $"no Σp arrows drawn ({purple:P3} of the canvas is their colour)")
            ' The momenta panel is in the top-right corner of the canvas.
            Dim corner = shot.Fraction(canvas.W * 2 \ 3, 0, canvas.W, canvas.H \ 2, Function(p) NearColour(p, MomentumPurple))
            Assert.True(corner > 0.0005, $"no momenta diagram in the corner ({corner:P3})")
            Assert.True(window.Y > 0)
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub

    <GuiFact>
    Public Sub EveryView_WithLargeFontsOnA1280x800Projector_IsDrawn_AndItsBoxesAreReachable()
        Using app As New AppDriver(New XSessionOptions With {.Screen = "1280x800x24"})
            Dim relaid = app.Mark()
            app.ClickAndWait("large-fonts", "^large fonts on$")
            ' The layout with large fonts, not the first one: the boxes are found where they are now.
            app.WaitFor("^ready$", skip:=relaid)
            ' With large fonts the side panel scrolls: each box is scrolled to and clicked as a teacher would.
            For Each view In {("centre-of-mass", "centre of mass"), ("total-momentum", "total momentum"), ("momenta-diagram", "momenta diagram"),
                              ("impulses", "impulses"), ("traces", "traces")}
                app.ClickAndWait(view.Item1, "^" & view.Item2 & " on$")
            Next
            Thread.Sleep(2500)
            Dim from = app.Mark()
            app.ClickAndWait("pause", "^paused t=")
            Dim com = app.WaitFor("^centre of mass at \((\S+), (\S+)\) m", skip:=from)
            Assert.True(D(com.Groups(1).Value) > 0 AndAlso D(com.Groups(2).Value) > 0, com.Value)
            Thread.Sleep(300)
            Dim shot = app.X.Shoot("momentum-views-large")
            Dim canvas = app.Control("canvas")
            Dim purple = shot.Fraction(0, 0, canvas.W, canvas.H, Function(p) NearColour(p, MomentumPurple))
            Assert.True(purple > 0.0005, $"no Σp arrows drawn ({purple:P3} of the canvas is their colour)")
            ' High contrast: the momentum arrows turn a light violet that shows on black.
            app.ClickAndWait("high-contrast", "^high contrast on$")
            Thread.Sleep(500)
            Dim dark = app.X.Shoot("momentum-views-dark")
            Dim violet = dark.Fraction(0, 0, canvas.W, canvas.H, Function(p) NearColour(p, &HEA80FC))
            Assert.True(violet > 0.0005, $"no Σp arrows drawn in high contrast ({violet:P3})")
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub

    <GuiFact>
    Public Sub Impulses_AtAFloorBounce_AreTwiceTheMomentumOfImpact()
        Using app As New AppDriver()
            app.PauseAndClear()
            ' A 2 kg ball of radius 0.3 m dropped from 2.3 m: it meets the floor at v = √(2 g · 2.0 m), e = 1 after Reset.
            Dim id = app.PlaceCircle("0.3", "2", 3.0, 2.3)
            Dim placed = app.LastMatch("^placed circle " & Regex.Escape(id) & " at \((\S+), (\S+)\)")
            Dim drop = D(placed.Groups(2).Value) - 0.3
            app.ClickAndWait("impulses", "^impulses on$")
            app.ClickAndWait("pause", "^resumed$")
            Dim m = app.WaitFor("^impulse " & Regex.Escape(id) & " Δp \((\S+), (\S+)\) kg·m/s at \((\S+), (\S+)\) m against wall:bottom", TimeSpan.FromSeconds(20))
            app.Click("pause")
            Dim expected = 2 * 2 * Math.Sqrt(2 * 9.81 * drop)
            Assert.Equal(0.0, D(m.Groups(1).Value), 6)
            Assert.Equal(expected, D(m.Groups(2).Value), 1)
            Assert.Equal(0.0, D(m.Groups(4).Value), 6) ' drawn from the floor, where the ball touched it
            Thread.Sleep(300)
            app.X.Shoot("impulse")
        End Using
    End Sub

    <GuiFact>
    Public Sub WallsOff_LetsBallsLeaveTheBox_AndOnAgainBringsThemBack()
        Using app As New AppDriver()
            app.ClickAndWait("walls", "^walls off$")
            Thread.Sleep(1500)
            Dim from = app.Mark()
            app.ClickAndWait("pause", "^paused t=")
            Dim state = Bodies(app, from)
            Assert.NotEmpty(state)
            ' Gravity pulls every ball down through where the floor was.
            Assert.True(state.Values.Any(Function(s) s.Y < 0), "a ball has left through the floor: " & String.Join("; ", state.Select(Function(s) s.Key & " y " & s.Value.Y)))
            Thread.Sleep(300)
            app.X.Shoot("walls-off")
            app.ClickAndWait("walls", "^walls on$")
            from = app.Mark()
            app.ClickAndWait("pause", "^resumed$")
            app.ClickAndWait("pause", "^paused t=")
            state = Bodies(app, from)
            Assert.True(state.Values.All(Function(s) s.Y > 0), "every ball is back inside: " & String.Join("; ", state.Select(Function(s) s.Key & " y " & s.Value.Y)))
            app.X.Shoot("walls-on")
        End Using
    End Sub

    <GuiFact>
    Public Sub TypingVxIntoTheTable_SetsItExactly_AndABadMassIsRefused()
        Using app As New AppDriver()
            Dim cell = app.Control("cell-circles-0-vx")
            Dim massCell = app.Control("cell-circles-0-mass")
            app.PauseAndClear()
            Dim id = app.PlaceCircle("0.3", "2", 2.0, 2.5)
            Dim from = app.Mark()
            app.MoveTo(cell.X + cell.W \ 2, cell.Y + cell.H \ 2)
            app.X.XDo("click", "--repeat", "2", "--delay", "80", "1")
            app.WaitFor("^edit open Circles 0 vx \(m/s\) \[0\]", skip:=from)
            Thread.Sleep(200)
            app.X.Shoot("edit-cell")
            app.TypeAndEnter("2.345")
            app.WaitFor("^edited " & Regex.Escape(id) & " vx \(m/s\) = 2.345$", skip:=from)
            ' The engine has it: resume for a moment and pause, and the body reports that velocity.
            app.ClickAndWait("pause", "^resumed$")
            from = app.Mark()
            app.ClickAndWait("pause", "^paused t=")
            Dim state = Bodies(app, from)
            Assert.Equal(2.345, state(id).Vx, 6)
            ' F2 on the selected row opens the quantity typed last; Esc closes it and changes nothing.
            Dim idCell = app.Control("cell-circles-0-x")
            from = app.Mark()
            app.ClickAt(idCell.X - 20, idCell.Y + idCell.H \ 2)
            app.X.XDo("key", "F2")
            app.WaitFor("^edit open Circles 0 vx \(m/s\) \[2.345\]", skip:=from)
            app.X.XDo("type", "--delay", "30", "--", "9")
            app.X.XDo("key", "Escape")
            app.WaitFor("^edit cancelled$", skip:=from)
            from = app.Mark()
            app.ClickAndWait("pause", "^resumed$")
            app.ClickAndWait("pause", "^paused t=")
            Assert.Equal(2.345, Bodies(app, from)(id).Vx, 6)
            ' A mass that is not a number: the Add panel's message, and nothing changes.
            from = app.Mark()
            app.MoveTo(massCell.X + massCell.W \ 2, massCell.Y + massCell.H \ 2)
            app.X.XDo("click", "--repeat", "2", "--delay", "80", "1")
            app.WaitFor("^edit open Circles 0 m \(kg\) \[2\]", skip:=from)
            app.X.XDo("key", "ctrl+a")
            app.TypeAndEnter("abc")
            app.WaitFor("^message: Please enter a suitable value for the mass and radius! mass \(kg\) 'abc' is not a number\.$", skip:=from)
            Assert.DoesNotContain(app.Lines().Skip(from), Function(l) l.StartsWith("edited ", StringComparison.Ordinal))
            Thread.Sleep(300)
            app.X.Shoot("edit-refused")
        End Using
    End Sub
End Class
