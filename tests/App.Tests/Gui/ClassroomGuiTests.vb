Option Strict On
Imports System.Text.RegularExpressions
Imports System.Threading
Imports Xunit

''' <summary>
''' The real window under Xvfb, driven with the mouse and keyboard as a teacher would: every test
''' checks the effect twice, in the app's --trace output and in a screenshot's pixels.
''' </summary>
<Collection(RealWindow.Name)>
Public Class ClassroomGuiTests
    <GuiFact>
    Public Sub AddCircle_FollowsTheCursor_AndIsPlacedWhereClicked()
        Using app As New AppDriver()
            app.PauseAndClear()
            Dim target = app.Screen(3.0, 2.5)
            Dim before = app.X.Shoot("add-before")
            Assert.True(ColouredAround(before, target.X, target.Y) < 0.1, "the canvas is empty there at first")
            app.TypeInto("radius", "0.5")
            app.TypeInto("mass", "2")
            app.ClickAndWait("add-circle", "^adding circle r 0.500 m m 2.000 kg$")
            ' Before the click, a see-through preview follows the cursor.
            Dim hover = app.Screen(5.5, 3.5)
            app.MoveTo(hover.X - 20, hover.Y)
            app.MoveTo(hover.X, hover.Y)
            Thread.Sleep(300)
            Dim preview = app.X.Shoot("add-preview")
            Dim covered = preview.Fraction(hover.X + 10, hover.Y + 10, hover.X + 20, hover.Y + 20, Function(p) p <> &HFAFAFA)
            Assert.True(covered > 0.8, $"no preview under the cursor ({covered:P0} of the spot is not background)")
            Dim from = app.Mark()
            app.MoveTo(target.X - 15, target.Y)
            app.ClickAt(target.X, target.Y)
            Dim m = app.WaitFor("^placed circle (\S+) at \((\S+), (\S+)\)", skip:=from)
            Assert.Equal(3.0, AppDriver.Dbl(m.Groups(2).Value), 1)
            Assert.Equal(2.5, AppDriver.Dbl(m.Groups(3).Value), 1)
            Thread.Sleep(300)
            Dim after = app.X.Shoot("add-after")
            ' Beside the centre, where the id label is not.
            Assert.True(ColouredAround(after, target.X + 14, target.Y + 14) > 0.8, "the new circle is drawn where it was placed" & vbLf & app.X.AppOutput())
            Assert.True(after.Fraction(hover.X + 10, hover.Y + 10, hover.X + 20, hover.Y + 20, Function(p) p <> &HFAFAFA) < 0.1, "the preview is gone")
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub

    <GuiFact>
    Public Sub AddCircle_EmptyRadius_AndAddingTwice_GiveTheSeedsMessages()
        Using app As New AppDriver()
            app.PauseAndClear()
            app.TypeInto("radius", "")
            Dim from = app.Mark()
            app.Click("add-circle")
            app.WaitFor("^message: Please enter a suitable value for the mass and radius! radius \(m\) is empty", skip:=from)
            app.TypeInto("radius", "0.3")
            app.ClickAndWait("add-circle", "^adding circle r 0.300 m")
            app.ClickAndWait("add-rectangle", "^message: Please spawn your current object first!$")
            Dim shot = app.X.Shoot("validation")
            ' The message is shown in the yellow box at the top of the side panel.
            Dim box = app.Control("canvas")
            Dim yellow = shot.Fraction(box.W + 10, 8, shot.Width - 30, 50, Function(p) p = &HFFF8C4)
            Assert.True(yellow > 0.2, $"no message box on screen ({yellow:P0} yellow)")
        End Using
    End Sub

    <GuiFact>
    Public Sub RightDrag_CarriesTheCircleToWhereItIsDropped()
        Using app As New AppDriver()
            app.PauseAndClear()
            Dim id = app.PlaceCircle("0.4", "1", 2.0, 2.0)
            Dim a = app.Screen(2.0, 2.0), b = app.Screen(5.0, 3.0)
            Dim from = app.Mark()
            app.Drag(3, a.X, a.Y, b.X, b.Y)
            Dim m = app.WaitFor("^drag end " & id & " at \((\S+), (\S+)\)", skip:=from)
            Assert.Equal(5.0, AppDriver.Dbl(m.Groups(1).Value), 1)
            Assert.Equal(3.0, AppDriver.Dbl(m.Groups(2).Value), 1)
            Thread.Sleep(300)
            Dim shot = app.X.Shoot("drag")
            Assert.True(ColouredAround(shot, b.X + 12, b.Y + 12) > 0.8, "the circle is drawn where it was dropped")
            Assert.True(ColouredAround(shot, a.X, a.Y) < 0.1, "and no longer where it was")
        End Using
    End Sub

    <GuiFact>
    Public Sub Cue_PullBackAndRelease_FiresTheCircle_AndItMoves()
        Using app As New AppDriver()
            app.PauseAndClear()
            Dim id = app.PlaceCircle("0.3", "1", 2.0, 2.5)
            Dim a = app.Screen(2.0, 2.5), back = app.Screen(1.0, 2.5)
            Dim from = app.Mark()
            app.Press(1, a.X, a.Y)
            For k = 1 To 8
                app.MoveTo(a.X + (back.X - a.X) * k \ 8, a.Y)
            Next
            Thread.Sleep(300)
            ' While aiming, the cue's shot arrow (orange) points forward from the ball.
            Dim aiming = app.X.Shoot("cue-aiming")
            Dim cue = aiming.Fraction(a.X + 20, a.Y - 6, a.X + CInt(app.Scale * 0.9), a.Y + 7, Function(p) p = &HF57F17)
            Assert.True(cue > 0.05, $"no cue arrow ahead of the ball while aiming ({cue:P1} orange)")
            app.Release(1)
            Dim fired = app.WaitFor("^fired " & id & " J \((\S+), (\S+)\) N·s dv \((\S+), (\S+)\) m/s", skip:=from)
            Dim dvx = AppDriver.Dbl(fired.Groups(3).Value)
            Assert.True(dvx > 2.0, "a 1 m pull on a 1 kg ball gives about 4 m/s to the right: " & fired.Value)
            Assert.Equal(0.0, AppDriver.Dbl(fired.Groups(4).Value), 1)
            app.ClickAndWait("pause", "^resumed")
            Thread.Sleep(700)
            Dim mark = app.Mark()
            app.Click("pause")
            Dim m = app.WaitFor("^body " & id & " at \((\S+), (\S+)\)", skip:=mark)
            Dim x = AppDriver.Dbl(m.Groups(1).Value)
            Assert.True(x > 2.5, $"the ball moved right, to x = {x} m")
            Thread.Sleep(300)
            Dim shot = app.X.Shoot("cue")
            Dim now = app.Screen(x, AppDriver.Dbl(m.Groups(2).Value))
            Assert.True(ColouredAround(shot, now.X + 10, now.Y + 10, 3) > 0.5, "the ball is drawn where the trace says")
            Assert.True(ColouredAround(shot, a.X, a.Y) < 0.1, "and has left its starting place")
        End Using
    End Sub

    <GuiFact>
    Public Sub DeleteMode_ClickRemovesTheCircle()
        Using app As New AppDriver()
            app.PauseAndClear()
            Dim id = app.PlaceCircle("0.4", "1", 4.0, 2.0)
            app.ClickAndWait("delete-mode", "^mode delete$")
            Dim p = app.Screen(4.0, 2.0)
            Dim from = app.Mark()
            app.ClickAt(p.X, p.Y)
            app.WaitFor("^deleted " & id & "$", skip:=from)
            Thread.Sleep(300)
            Dim shot = app.X.Shoot("delete")
            Assert.True(ColouredAround(shot, p.X, p.Y) < 0.1, "the circle is gone from the canvas")
        End Using
    End Sub

    <GuiFact>
    Public Sub PauseAndResume_StopAndRestartTime()
        Using app As New AppDriver()
            Dim t1 = AppDriver.Dbl(app.ClickAndWait("pause", "^paused t=(\S+) s").Groups(1).Value)
            Thread.Sleep(300)
            Dim shotA = app.X.Shoot("paused-a")
            Thread.Sleep(600)
            Dim shotB = app.X.Shoot("paused-b")
            Dim c = app.Control("canvas")
            For y = c.Y To c.Y + c.H - 1 Step 3
                For x = c.X To c.X + c.W - 1 Step 3
                    If shotA.Pixel(x, y) <> shotB.Pixel(x, y) Then Assert.Fail($"the canvas changed at ({x}, {y}) while paused")
                Next
            Next
            app.ClickAndWait("pause", "^resumed$")
            Thread.Sleep(800)
            Dim t2 = AppDriver.Dbl(app.ClickAndWait("pause", "^paused t=(\S+) s").Groups(1).Value)
            Assert.True(t2 > t1 + 0.1, $"time ran again after resuming: {t1} → {t2} s")
        End Using
    End Sub

    <GuiFact>
    Public Sub Sliders_GravityRestitutionAndSpeed_MoveWithTheMouse()
        Using app As New AppDriver()
            ' Gravity: a click on the track right of the thumb moves it one large step (1 m/s²) up.
            Dim g = app.Control("gravity")
            Dim from = app.Mark()
            app.ClickAt(g.X + g.W * 3 \ 4, g.Y + 12)
            Dim gm = app.WaitFor("^gravity (\S+)$", skip:=from)
            Assert.True(AppDriver.Dbl(gm.Groups(1).Value) > 9.81, gm.Value)
            ' The Moon mark.
            app.ClickAndWait("moon", "^gravity 1.62$")
            ' Restitution: from e = 1 after a reset, a click on the track left of the thumb takes one large step (0.1) down.
            app.ClickAndWait("reset", "^reset:")
            Dim e = app.Control("restitution")
            from = app.Mark()
            app.ClickAt(e.X + e.W \ 3, e.Y + 12)
            app.WaitFor("^restitution 0.90$", skip:=from)
            ' Speed: drag the thumb from 1× to the far right (4× faster).
            Dim s = app.Control("speed")
            Dim thumbX = s.X + 12 + CInt((s.W - 24) * 8 / 12.0)
            from = app.Mark()
            app.Drag(1, thumbX, s.Y + 10, s.X + s.W + 20, s.Y + 10)
            app.WaitFor("^speed 4× faster$", skip:=from)
            ' And to the far left (20× slower).
            thumbX = s.X + s.W - 12
            from = app.Mark()
            app.Drag(1, thumbX, s.Y + 10, s.X - 20, s.Y + 10)
            app.WaitFor("^speed 20× slower$", skip:=from)
            Thread.Sleep(200)
            app.X.Shoot("sliders")
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub

    <GuiFact>
    Public Sub Reset_RemovesEveryBody_AndRestoresTheDefaults()
        Using app As New AppDriver()
            app.ClickAndWait("jupiter", "^gravity 24.79$")
            Dim m = app.ClickAndWait("reset", "^reset: (\d+) bodies, g (\S+), e (\S+), speed (.+)$")
            Assert.Equal("0", m.Groups(1).Value)
            Assert.Equal("9.81", m.Groups(2).Value)
            Assert.Equal("1.00", m.Groups(3).Value)
            Assert.Equal("1× (real time)", m.Groups(4).Value)
            Thread.Sleep(400)
            Dim shot = app.X.Shoot("reset")
            Dim c = app.Control("canvas")
            Dim coloured = shot.Fraction(c.X, c.Y, c.X + c.W, c.Y + c.H, AddressOf IsSaturated)
            Assert.True(coloured < 0.001, $"the demo bodies are gone ({coloured:P3} coloured pixels left)")
        End Using
    End Sub

    <GuiFact>
    Public Sub ProjectorView_HighContrastDarkensTheWholeWindow_AndLargeFontsGrowTheCanvasAndItsLabels()
        Using app As New AppDriver()
            Dim normalScale = app.Scale
            Dim from = app.Mark()
            app.ClickAndWait("high-contrast", "^high contrast on$")
            app.WaitFor("^ready$", skip:=from)
            from = app.Mark()
            app.Click("large-fonts")
            app.WaitFor("^large fonts on$", skip:=from)
            app.WaitFor("^ready$", skip:=from)
            app.ReadLayout()
            Dim m = app.ClickAndWait("pause", "^body blue at \((\S+), (\S+)\)")
            Thread.Sleep(400)
            Dim shot = app.X.Shoot("projector")
            Dim c = app.Control("canvas")
            Dim dark = shot.Fraction(c.X, c.Y, c.X + c.W, c.Y + c.H, Function(p) Luma(p) < 40)
            Assert.True(dark > 0.6, $"the high-contrast canvas is dark ({dark:P0})")
            ' Not the canvas alone: the side panel and the tables are dark too.
            Dim side = app.Control("side")
            Dim darkSide = shot.Fraction(side.X, side.Y, side.X + side.W, side.Y + side.H, Function(p) Luma(p) < 60)
            Assert.True(darkSide > 0.6, $"the high-contrast side panel is dark ({darkSide:P0})")
            Dim tabs = app.Control("tabs")
            ' The rows, not the horizontal scroll bar under them (Mono draws it in its own light grey
            ' whatever the theme; with the Export button the tabs sit lower and the bar is a larger share).
            Dim darkTables = shot.Fraction(tabs.X, tabs.Y + tabs.H \ 2, tabs.X + tabs.W, tabs.Y + tabs.H - 24, Function(p) Luma(p) < 60)
            Assert.True(darkTables > 0.6, $"the high-contrast tables are dark ({darkTables:P0})")
            Dim b = app.Control("pause")
            Assert.True(b.H >= 34, $"buttons grow with large fonts (pause is {b.H} px high)")
            ' The canvas grows with large fonts (the tables give up height), and so do its labels.
            Assert.True(app.Scale > normalScale, $"the canvas shrank: {normalScale} → {app.Scale} px/m")
            Dim ball = app.Screen(AppDriver.Dbl(m.Groups(1).Value), AppDriver.Dbl(m.Groups(2).Value))
            Dim rad = CInt(0.2 * app.Scale)
            ' The id "blue" does not fit in the ball at 14 pt: it is written beside it, white on black.
            Dim label = shot.Fraction(ball.X + rad \ 2, ball.Y - rad - 40, ball.X + rad + 70, ball.Y - rad \ 2, Function(p) Luma(p) > 200)
            Assert.True(label > 0.03, $"no label beside the ball ({label:P1} white pixels)")
        End Using
    End Sub

    <GuiFact>
    Public Sub SaveThenOpen_ThroughTheFileDialogs()
        ' A folder of its own: Mono's file dialog lists the folder it is shown, and on a shared temporary
        ' folder of thousands of files its list asks X for a pixmap too large (BadAlloc) and never draws.
        Dim folder = IO.Path.Combine(IO.Path.GetTempPath(), "gui-dialogs-" & Guid.NewGuid().ToString("N"))
        IO.Directory.CreateDirectory(folder)
        Dim path = IO.Path.Combine(folder, "gui-scene.json")
        Try
            Using app As New AppDriver()
                app.PauseAndClear()
                app.PlaceCircle("0.4", "3", 4.0, 2.0)
                app.ClickForDialog("save", "Save the scene")
                Dim from = app.Mark()
                app.TypeAndEnter(path)
                app.WaitFor("^saved " & IO.Path.GetFileName(path) & ": 1 bodies$", skip:=from)
                Assert.Contains("""physics-scene/1""", IO.File.ReadAllText(path), StringComparison.Ordinal)
                app.ClickAndWait("reset", "^reset: 0 bodies")
                app.ClickForDialog("open", "Open a scene")
                from = app.Mark()
                app.TypeAndEnter(path)
                app.WaitFor("^opened " & IO.Path.GetFileName(path) & ": 1 bodies$", skip:=from)
                Thread.Sleep(300)
                Dim p = app.Screen(4.0, 2.0)
                Assert.True(ColouredAround(app.X.Shoot("opened"), p.X + 12, p.Y + 12) > 0.8, "the opened ball is drawn")
            End Using
        Finally
            IO.Directory.Delete(folder, recursive:=True)
        End Try
    End Sub

    ''' <summary>
    ''' The Tutorial, the Maths used and the graph's own window open from their buttons, every page
    ''' title shows whole in the list (at 192 dpi with large fonts too), and Esc closes each of them.
    ''' </summary>
    <GuiTheory>
    <InlineData(0, False)>
    <InlineData(192, True)>
    Public Sub HelpAndGraphWindows_OpenWithTitlesWhole_AndEscClosesEach(dpi As Integer, large As Boolean)
        Using app As New AppDriver(New XSessionOptions With {.Screen = If(dpi > 0, "2560x1600x24", "1400x900x24"), .Dpi = dpi})
            If large Then
                Dim mark = app.Mark()
                app.Click("large-fonts")
                app.WaitFor("^large fonts on$", skip:=mark)
                app.WaitFor("^ready$", skip:=mark)
            End If
            For Each help In {("tutorial", "Tutorial"), ("maths", "Maths used")}
                Dim from = app.Mark()
                app.ClickAndWait(help.Item1, "^help " & help.Item2 & "$")
                Dim id = app.WaitForWindow("^" & help.Item2)
                app.WaitFor("^help page ", skip:=from)
                Dim titles = app.Lines().Skip(from).Select(Function(l) Regex.Match(l, "^help title (\d+) row (\d+) needs (\d+) width \d+ (.*)$")).Where(Function(m) m.Success).ToList()
                Assert.True(titles.Count >= 7, help.Item2 & " lists no titles")
                For Each t In titles
                    Assert.True(CInt(t.Groups(2).Value) >= CInt(t.Groups(3).Value), $"'{t.Groups(4).Value}' needs {t.Groups(3).Value} px in the list and has {t.Groups(2).Value}")
                Next
                CloseWithEsc(app, id, "^help closed " & help.Item2 & " ")
            Next
            ' The graph's window.
            Dim mark2 = app.Mark()
            app.Click("tab-graphs")
            app.WaitFor("^tab Graphs$", skip:=mark2)
            app.WaitFor("^ready$", skip:=mark2)
            app.ReadLayout()
            mark2 = app.Mark()
            app.Click("graph-window")
            app.WaitFor("^graph window shown ", timeout:=TimeSpan.FromSeconds(15), skip:=mark2)
            CloseWithEsc(app, app.WaitForWindow("^Graph "), "^graph window closed$")
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub

    ''' <summary>Clicks into the window <paramref name="id"/> (so it has the keyboard), presses Esc and waits for the trace line that it closed.</summary>
    Private Shared Sub CloseWithEsc(app As AppDriver, id As String, closed As String)
        Dim geometry = app.X.Tool("xdotool", "getwindowgeometry", id).StdOut
        Dim m = Regex.Match(geometry, "Position: (-?\d+),(-?\d+).*Geometry: (\d+)x(\d+)", RegexOptions.Singleline)
        Assert.True(m.Success, geometry)
        Dim x = CInt(m.Groups(1).Value) + CInt(m.Groups(3).Value) * 2 \ 3, y = CInt(m.Groups(2).Value) + CInt(m.Groups(4).Value) \ 2
        Dim from = app.Mark()
        app.ClickAt(x, y)
        app.X.XDo("key", "Escape")
        app.WaitFor(closed, skip:=from)
    End Sub
End Class
