Option Strict On
Imports System.Text.RegularExpressions
Imports System.Threading
Imports Xunit

''' <summary>
''' "Add by corners" in the real window under Xvfb: a teacher clicks a polygon's corners on the
''' canvas and finishes it by clicking the first corner again, by a double click or with Enter, or
''' gives it up with Esc. Checked in the app's --trace output and in screenshots' pixels.
''' </summary>
<Collection(RealWindow.Name)>
Public Class CornersGuiTests
    Private Const Background As Integer = &HFAFAFA
    Private Const FixedColour As Integer = &H78909C

    ''' <summary>Clicks a corner at (x, y) m and waits until the app has taken it as corner <paramref name="number"/>.</summary>
    Private Shared Sub ClickCorner(app As AppDriver, number As Integer, x As Double, y As Double)
        Dim p = app.Screen(x, y)
        Dim from = app.Mark()
        app.ClickAt(p.X, p.Y)
        app.WaitFor("^corner " & number & " at ", TimeSpan.FromSeconds(15), from)
    End Sub

    ''' <summary>
    ''' Clicks a named control until the trace shows its effect: a click can be lost while the window
    ''' is busy on a loaded machine (at most three tries).
    ''' </summary>
    Private Shared Sub ClickUntil(app As AppDriver, name As String, pattern As String)
        For attempt = 1 To 3
            Dim from = app.Mark()
            app.Click(name)
            Try
                app.WaitFor(pattern, TimeSpan.FromSeconds(If(attempt < 3, 5, 10)), from)
                Return
            Catch ex As TimeoutException When attempt < 3
            End Try
        Next
    End Sub

    ''' <summary>The corners on a "placed polygon" trace line, m.</summary>
    Private Shared Function CornersOf(m As Match) As List(Of (X As Double, Y As Double))
        Return Regex.Matches(m.Groups(4).Value, "\((\S+), (\S+)\)").Cast(Of Match)().
            Select(Function(c) (AppDriver.Dbl(c.Groups(1).Value), AppDriver.Dbl(c.Groups(2).Value))).ToList()
    End Function

    ''' <summary>Each expected corner has a placed corner within <paramref name="tolerance"/> m, and there are as many.</summary>
    Private Shared Sub SameCorners(expected As (X As Double, Y As Double)(), placed As List(Of (X As Double, Y As Double)), tolerance As Double)
        Assert.Equal(expected.Length, placed.Count)
        For Each e In expected
            Assert.True(placed.Any(Function(p) Math.Abs(p.X - e.X) <= tolerance AndAlso Math.Abs(p.Y - e.Y) <= tolerance),
                        $"no corner near ({e.X}, {e.Y}) among {String.Join(" ", placed)}")
        Next
    End Sub

    <GuiFact>
    Public Sub ClickingCorners_AndTheFirstAgain_AddsThatPolygon_DrawnWhereClicked()
        Using app As New AppDriver()
            app.PauseAndClear()
            app.TypeInto("mass", "2")
            ClickUntil(app, "add-corners", "^mode corners m 2.000 kg$")
            Dim corners = {(X:=2.0, Y:=1.0), (X:=5.0, Y:=1.0), (X:=5.5, Y:=3.0), (X:=3.0, Y:=3.8)}
            For i = 0 To corners.Length - 1
                ClickCorner(app, i + 1, corners(i).X, corners(i).Y)
            Next
            ' The outline so far, with its next side following the cursor: a screenshot of the preview.
            Dim cursor = app.Screen(1.5, 2.5)
            app.MoveTo(cursor.X, cursor.Y)
            Thread.Sleep(300)
            Dim drawing = app.X.Shoot("corners-drawing")
            Dim inside = app.Screen(4.5, 1.5) ' away from the id written at its centroid
            Assert.True(drawing.Fraction(inside.X - 3, inside.Y - 3, inside.X + 4, inside.Y + 4, Function(c) c <> Background) > 0.9, "the preview is filled")
            Dim from = app.Mark()
            Dim first = app.Screen(corners(0).X, corners(0).Y)
            app.ClickAt(first.X + 2, first.Y - 2)
            Dim m = app.WaitFor("^placed polygon (\S+) at \((\S+), (\S+)\) corners (.*)$", skip:=from)
            ' A click lands on a whole pixel: each corner is where it was clicked to a pixel or two.
            Dim px = 2.5 / app.Scale
            SameCorners(corners, CornersOf(m), px)
            ' The centroid of the quadrilateral, by the shoelace formulas.
            Dim a = 0.0, cx = 0.0, cy = 0.0
            For i = 0 To corners.Length - 1
                Dim p = corners(i), q = corners((i + 1) Mod corners.Length)
                Dim cross = p.X * q.Y - q.X * p.Y
                a += cross / 2
                cx += (p.X + q.X) * cross
                cy += (p.Y + q.Y) * cross
            Next
            Assert.Equal(cx / (6 * a), AppDriver.Dbl(m.Groups(2).Value), 2)
            Assert.Equal(cy / (6 * a), AppDriver.Dbl(m.Groups(3).Value), 2)
            Thread.Sleep(300)
            Dim shot = app.X.Shoot("corners-placed")
            Assert.True(ColouredAround(shot, inside.X, inside.Y, 3) > 0.8, "the polygon is filled in its colour")
            Dim outside = app.Screen(1.6, 1.6)
            Assert.True(shot.Fraction(outside.X - 3, outside.Y - 3, outside.X + 4, outside.Y + 4, Function(c) c = Background) > 0.95, "nothing outside its left side")
            ' The Bodies tab lists it: a 4-sided polygon of 2 kg.
            from = app.Mark()
            app.Click("tab-bodies")
            app.WaitFor("^row Bodies 0: " & m.Groups(1).Value & " \| #[0-9a-f]{6} \| quadrilateral \| \S+ \| \S+ \| 0 \| 0 \| 0 \| 2.00 \| \S+ × \S+ \| ", skip:=from)
        End Using
    End Sub

    <GuiFact>
    Public Sub ADoubleClick_Enter_AndEsc_FinishOrCancel_AndADentIsLeftOut()
        Using app As New AppDriver()
            app.PauseAndClear()
            app.TypeInto("mass", "1")
            ' A double click on the last corner finishes; corner 4 is pushed in, so it is left out.
            ClickUntil(app, "add-corners", "^mode corners m 1.000 kg$")
            ClickCorner(app, 1, 1.0, 1.0)
            ClickCorner(app, 2, 3.0, 1.0)
            ClickCorner(app, 3, 3.0, 3.0)
            ClickCorner(app, 4, 2.2, 2.0)
            Dim last = app.Screen(1.0, 3.0)
            Dim from = app.Mark()
            app.MoveTo(last.X, last.Y)
            app.X.XDo("click", "--repeat", "2", "--delay", "80", "1")
            Dim m = app.WaitFor("^placed polygon (\S+) at \((\S+), (\S+)\) corners (.*)$", skip:=from)
            Dim px = 2.5 / app.Scale
            SameCorners({(1.0, 1.0), (3.0, 1.0), (3.0, 3.0), (1.0, 3.0)}, CornersOf(m), px)
            app.WaitFor("^message: The corners you clicked do not make a convex shape, .*corner 4 lies inside it or on a side, and was left out\.$", skip:=from)

            ' Enter finishes a fixed triangle, with the focus still on the Add by corners button.
            ClickUntil(app, "fixed", "^fixed on$")
            ClickUntil(app, "add-corners", "^mode corners fixed$")
            ClickCorner(app, 1, 4.5, 0.5)
            ClickCorner(app, 2, 7.0, 0.5)
            ClickCorner(app, 3, 6.0, 2.5)
            from = app.Mark()
            app.X.XDo("key", "Return")
            app.WaitFor("^key finish corners$", skip:=from)
            Dim tri = app.WaitFor("^placed polygon (\S+) at \((\S+), (\S+)\) corners (.*)$", skip:=from)
            SameCorners({(4.5, 0.5), (7.0, 0.5), (6.0, 2.5)}, CornersOf(tri), px)

            ' Esc gives up a polygon half drawn: nothing is added.
            ClickUntil(app, "fixed", "^fixed off$")
            ClickUntil(app, "add-corners", "^mode corners m ")
            ClickCorner(app, 1, 1.0, 4.0)
            ClickCorner(app, 2, 2.0, 4.2)
            from = app.Mark()
            app.X.XDo("key", "Escape")
            app.WaitFor("^tool cancelled$", skip:=from)
            ' The next click is the normal mode's again: no corner, no polygon.
            Dim empty = app.Screen(1.5, 4.5)
            app.ClickAt(empty.X, empty.Y)
            Thread.Sleep(300)
            Assert.DoesNotContain(app.Lines().Skip(from), Function(l) l.StartsWith("corner ", StringComparison.Ordinal) OrElse l.StartsWith("placed ", StringComparison.Ordinal))
            Dim shot = app.X.Shoot("corners-square-and-triangle")
            Dim square = app.Screen(1.5, 1.5)
            Assert.True(ColouredAround(shot, square.X, square.Y, 3) > 0.8, "the square is drawn")
            Dim triangle = app.Screen(5.0, 0.8)
            Assert.True(shot.Fraction(triangle.X - 2, triangle.Y - 2, triangle.X + 3, triangle.Y + 3, Function(c) c = FixedColour) > 0.8, "the fixed triangle is drawn in the fixed colour")
            Dim halfDrawn = app.Screen(1.5, 4.1)
            Assert.True(shot.Fraction(halfDrawn.X - 3, halfDrawn.Y - 3, halfDrawn.X + 4, halfDrawn.Y + 4, Function(c) c = Background) > 0.95, "nothing is left of the cancelled polygon")
        End Using
    End Sub
End Class
