Option Strict On
Imports System.Globalization
Imports System.Text.RegularExpressions
Imports System.Threading
Imports PhysicsEngine.Presentation
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>
''' Each defect a class would hit, in the real window under Xvfb: the app is driven with the mouse
''' and keyboard, and what it shows is read from its trace and from screenshots.
''' </summary>
<Collection(RealWindow.Name)>
Public Class TrustGuiTests
    Private Shared Function TempScene(name As String, json As String) As String
        Dim folder = IO.Path.Combine(IO.Path.GetTempPath(), "gui-" & Guid.NewGuid().ToString("N"))
        IO.Directory.CreateDirectory(folder)
        Dim path = IO.Path.Combine(folder, name)
        IO.File.WriteAllText(path, json)
        Return path
    End Function

    Private Shared Sub DeleteFolderOf(path As String)
        Dim folder = IO.Path.GetDirectoryName(path)
        If IO.Directory.Exists(folder) Then IO.Directory.Delete(folder, True)
    End Sub

    ''' <summary>Opens a scene through the Open dialog, typing its path, and waits until it is on screen.</summary>
    Private Shared Sub OpenThroughTheDialog(app As AppDriver, path As String, expect As String)
        app.ClickForDialog("open", "Open a scene")
        Dim from = app.Mark()
        app.TypeAndEnter(path)
        app.WaitFor(expect, skip:=from)
        Thread.Sleep(300)
        app.ReadLayout() ' the new container has its own view
    End Sub

    <GuiFact>
    Public Sub ABallPlacedOrCarriedIntoATable_EndsOutsideIt_AndTheSavedSceneOpensAgain()
        Dim path = IO.Path.Combine(IO.Path.GetTempPath(), "gui-table-" & Guid.NewGuid().ToString("N") & ".json")
        Try
            Using app As New AppDriver()
                app.PauseAndClear()
                app.TypeInto("rect-width", "3")
                app.TypeInto("rect-height", "1")
                app.ClickAndWait("add-rectangle", "^adding rectangle ")
                Dim t = app.Screen(4, 0.5)
                Dim from = app.Mark()
                app.MoveTo(t.X - 20, t.Y)
                app.ClickAt(t.X, t.Y)
                app.WaitFor("^placed rectangle", skip:=from)
                ' Clicked inside the table, the ball goes on top of it, the nearest free place.
                app.TypeInto("radius", "0.3")
                app.TypeInto("mass", "1")
                app.ClickAndWait("add-circle", "^adding circle r 0.300")
                from = app.Mark()
                Dim inside = app.Screen(4, 0.6)
                app.MoveTo(inside.X - 10, inside.Y)
                app.ClickAt(inside.X, inside.Y)
                Dim placed = app.WaitFor("^placed circle (\S+) at \((\S+), (\S+)\)", skip:=from)
                app.WaitFor("at the nearest free place: there it would have overlapped fixed rectangle", skip:=from)
                Dim id = placed.Groups(1).Value
                Assert.Equal(1.3, AppDriver.Dbl(placed.Groups(3).Value), 2)
                ' Carried (paused) into the table, it stops at its top.
                Dim top = app.Screen(AppDriver.Dbl(placed.Groups(2).Value), 1.3)
                from = app.Mark()
                app.Drag(3, top.X, top.Y, inside.X, inside.Y + 10)
                Dim dropped = app.WaitFor("^drag end " & id & " at \((\S+), (\S+)\)", skip:=from)
                Assert.True(AppDriver.Dbl(dropped.Groups(2).Value) >= 1.3 - 0.001, "dropped inside the table: " & dropped.Value)
                ' Carried fast while running, from one side to the other through the table: never inside.
                app.ClickAndWait("pause", "^resumed$")
                Dim low = app.Screen(0.5, 0.4), far = app.Screen(7.5, 0.4)
                app.Press(3, top.X, top.Y)
                app.MoveTo(low.X, low.Y)
                app.MoveTo(far.X, far.Y)
                Thread.Sleep(600)
                app.Release(3)
                Thread.Sleep(300)
                app.ClickAndWait("pause", "^paused")
                app.WaitFor("^check scene ok$", skip:=from)
                Dim shot = app.X.Shoot("table-ball")
                app.ClickForDialog("save", "Save the scene")
                from = app.Mark()
                app.TypeAndEnter(path)
                app.WaitFor("^saved ", skip:=from)
            End Using
            Dim reopened = SceneFile.LoadFile(path) ' throws when the saved scene would not open
            Assert.Equal(2, reopened.Bodies.Count)
        Finally
            IO.File.Delete(path)
        End Try
    End Sub

    <GuiFact>
    Public Sub TypedValues_StayWhenPauseResetOrAddIsPressed_WhileABodyIsBeingPlaced()
        Using app As New AppDriver()
            app.TypeInto("mass", "7")
            app.TypeInto("box-width", "6")
            app.ClickAndWait("add-circle", "^adding circle r 0.250 m m 7.000 kg$")
            app.ClickAndWait("pause", "^paused")
            app.ClickAndWait("reset", "^reset:")
            app.ClickAndWait("add-circle", "^adding circle")
            Dim from = app.Mark()
            app.Click("add-rectangle")
            app.WaitFor("^message: Please spawn your current object first!$", skip:=from)
            app.ClickAndWait("pause", "^resumed$")
            Thread.Sleep(200)
            Dim boxes = app.Inputs()
            Assert.Equal("7", boxes("Mass"))
            Assert.Equal("6", boxes("ContainerWidth"))
            Assert.Equal("0.25", boxes("Radius"))
        End Using
    End Sub

    <GuiFact>
    Public Sub TheTableAndTotals_ShowTheStateWhilePaused_ACueShotAtOnce_AndTheHeaderAfterATabSwitch()
        Using app As New AppDriver()
            Thread.Sleep(700) ' the demo moves; pause between two of the running snapshots
            Dim from = app.Mark()
            app.Click("pause")
            Dim state = app.WaitFor("^body red at \((\S+), (\S+)\) m v \((\S+), (\S+)\) m/s", skip:=from)
            Dim vy = AppDriver.Dbl(state.Groups(4).Value)
            ' What the table was last given to draw, once the pause has been shown.
            Thread.Sleep(500)
            Dim row = app.LastMatch("^row Circles 0: red \| \S+ \| \S+ \| \S+ \| (\S+) \| (\S+) \|")
            AssertShown(vy, Shown(row.Groups(2).Value), 0.01)
            ' The totals are of the same moment: Σp from the traced state (masses 2, 1 and 4 kg).
            Dim p = 0.0
            For Each name In {"red", "blue", "green"}
                Dim b = app.WaitFor("^body " & name & " at \(\S+, \S+\) m v \((\S+), (\S+)\) m/s", skip:=from)
                p += If(name = "red", 2, If(name = "blue", 1, 4)) * AppDriver.Dbl(b.Groups(1).Value)
            Next
            Dim totals = app.LastMatch("^totals .*Σp\s=\s\((\S+),")
            AssertShown(p, Shown(totals.Groups(1).Value), 0.1)
            ' A cue shot while paused: the row shows the new velocity at once.
            Dim ball = app.Screen(AppDriver.Dbl(state.Groups(1).Value), AppDriver.Dbl(state.Groups(2).Value))
            from = app.Mark()
            app.Drag(1, ball.X, ball.Y, ball.X - CInt(app.Scale * 0.5), ball.Y, 4)
            Dim fired = app.WaitFor("^fired red J \(.*\) N·s dv \(.*\) m/s v \((\S+), (\S+)\)", skip:=from)
            Thread.Sleep(500)
            Dim shownAfter = app.LastMatch("^row Circles 0: red \| \S+ \| \S+ \| \S+ \| (\S+) \|")
            AssertShown(AppDriver.Dbl(fired.Groups(1).Value), Shown(shownAfter.Groups(1).Value), 0.01)
            ' Rows that change behind another tab: the header row must still be there when it comes back.
            Dim tabs = app.Control("tabs")
            app.ClickAt(tabs.X + 100, tabs.Y + 10)
            app.ClickAndWait("reset", "^reset:")
            app.ClickAt(tabs.X + 25, tabs.Y + 10)
            Thread.Sleep(500)
            Dim shot = app.X.Shoot("header-after-tab-switch")
            Dim header = shot.Fraction(tabs.X + 4, tabs.Y + 26, tabs.X + tabs.W - 4, tabs.Y + 42, Function(px) Luma(px) < 90)
            Assert.True(header > 0.02, $"the header row is blank ({header:P1} dark pixels)")
        End Using
    End Sub

    ''' <summary>A number as the window writes it ("−1.98", "1.00×10⁻³") read back.</summary>
    Private Shared Function Shown(text As String) As Double
        Dim t = text.Replace("−", "-").Replace(Units.Nbsp, " "c)
        Dim m = Regex.Match(t, "^(-?[0-9.]+)(×10([⁻⁰¹²³⁴⁵⁶⁷⁸⁹]+))?$")
        If Not m.Success Then Throw New FormatException("not a shown number: " & text)
        Dim v = Double.Parse(m.Groups(1).Value, CultureInfo.InvariantCulture)
        If m.Groups(3).Success Then
            Dim e = m.Groups(3).Value.Replace("⁻", "-")
            For d = 0 To 9
                e = e.Replace("⁰¹²³⁴⁵⁶⁷⁸⁹"(d), ChrW(AscW("0"c) + d))
            Next
            v *= Math.Pow(10, Integer.Parse(e, CultureInfo.InvariantCulture))
        End If
        Return v
    End Function

    <GuiFact>
    Public Sub AContainerTooSmall_IsRefused_AndTheWholeMessageShows()
        Using app As New AppDriver()
            app.ClickAndWait("pause", "^paused")
            app.TypeInto("box-width", "0.6")
            app.TypeInto("box-height", "0.6")
            Dim before = app.Control("message")
            Dim pauseBefore = app.Control("pause")
            Dim from = app.Mark()
            app.Click("resize")
            app.WaitFor("^message: The container cannot be 0.600 m × 0.600 m: its 3 balls would not fit", skip:=from)
            ' The message area keeps its height: the message shows whole in it, or scrolls within it (and says so).
            Dim shown = app.WaitFor("^message shown (\d+) px, needs (\d+) px(, scrolls)?$", skip:=from)
            Dim height = Integer.Parse(shown.Groups(1).Value, CultureInfo.InvariantCulture), needs = Integer.Parse(shown.Groups(2).Value, CultureInfo.InvariantCulture)
            Assert.Equal(before.H, height)
            Assert.True(needs <= height OrElse shown.Groups(3).Success, shown.Value)
            Assert.True(needs > 40, "a message of three lines or more is measured as " & shown.Value)
            app.WaitFor("^ready$", skip:=from)
            app.ReadLayout()
            Dim message = app.Control("message"), side = app.Control("side"), pause = app.Control("pause")
            Assert.True(message.Y + message.H <= pause.Y, "the message covers the buttons")
            Assert.Equal(pauseBefore, pause)
            Assert.True(app.X.AppIsRunning)
            app.X.Shoot("long-message")
        End Using
    End Sub

    <GuiFact>
    Public Sub TheSmallestBall_AndAFastOne_ShowNoNaNOrInfinity_AndArrowsStayOnTheCanvas()
        Using app As New AppDriver()
            app.PauseAndClear()
            app.TypeInto("radius", "1e-300")
            app.TypeInto("mass", "1e-300")
            Dim from = app.Mark()
            app.Click("add-circle")
            app.WaitFor("^message: radius set to the minimum, 0.0100 m, mass set to the minimum, 0.0100 kg\.", skip:=from)
            Dim target = app.Screen(2, 2.5)
            app.MoveTo(target.X - 10, target.Y)
            from = app.Mark()
            app.ClickAt(target.X, target.Y)
            app.WaitFor("^placed circle", skip:=from)
            ' The hardest shot: Δv = 40 N·s / 0.01 kg = 4000 m/s.
            app.Drag(1, target.X, target.Y, target.X + CInt(3 * app.Scale), target.Y, 6)
            app.WaitFor("^fired ", skip:=from)
            from = app.Mark()
            app.Click("pause") ' resumes
            Thread.Sleep(300)
            app.Click("pause")
            app.WaitFor("^check texts ok$", skip:=from)
            app.WaitFor("^check scene ok$", skip:=from)
            Thread.Sleep(300)
            Dim shot = app.X.Shoot("fast-ball")
            ' The velocity arrow's blue never spills onto the totals line, the tables or the panel.
            Dim arrowBlue As Func(Of Integer, Boolean) = Function(p) p = &H1565C0
            Dim totals = app.Control("totals"), tabs = app.Control("tabs"), side = app.Control("side")
            Assert.Equal(0.0, shot.Fraction(totals.X, totals.Y, totals.X + totals.W, totals.Y + totals.H, arrowBlue))
            Assert.Equal(0.0, shot.Fraction(tabs.X, tabs.Y, tabs.X + tabs.W, tabs.Y + tabs.H, arrowBlue))
            Assert.Equal(0.0, shot.Fraction(side.X, side.Y, side.X + side.W, side.Y + side.H, arrowBlue))
            ' The arrows' scale is shown: the key's arrow, in the strip under the box.
            Dim canvas = app.Control("canvas")
            Dim key = shot.Fraction(canvas.X, canvas.Y + canvas.H - 34, canvas.X + canvas.W \ 2, canvas.Y + canvas.H, arrowBlue)
            Assert.True(key > 0.002, $"no arrow key under the canvas ({key:P2})")
            app.WaitFor("^check texts ok$")
        End Using
    End Sub

    <GuiFact>
    Public Sub ASceneWithoutWalls_OpenedFromTheScenesFolder_IsDrawnWithoutThem()
        Using app As New AppDriver()
            ' The dialog starts in scenes/: the bare name is enough.
            OpenThroughTheDialog(app, "head-on.json", "^opened head-on.json: 2 bodies$")
            app.ClickAndWait("pause", "^paused")
            Dim view = app.LastMatch("^view scale (\S+) origin (\S+) (\S+)$")
            Dim scale = AppDriver.Dbl(view.Groups(1).Value), ox = AppDriver.Dbl(view.Groups(2).Value), oy = AppDriver.Dbl(view.Groups(3).Value)
            Dim c = app.Control("canvas")
            Dim shot = app.X.Shoot("no-walls")
            ' Along the left side of the box (x = 0, y from 0.2 to 1.8 m): no solid dark wall.
            Dim x = c.X + CInt(Math.Round(ox))
            Dim y0 = c.Y + CInt(Math.Round(oy - 1.8 * scale)), y1 = c.Y + CInt(Math.Round(oy - 0.2 * scale))
            Dim wall = shot.Fraction(x - 1, y0, x + 2, y1, Function(p) Luma(p) < 100)
            Assert.True(wall < 0.05, $"a wall is drawn where there is none ({wall:P0} dark pixels)")
            Dim outline = shot.Fraction(x - 1, y0, x + 2, y1, Function(p) p <> &HFAFAFA)
            Assert.True(outline > 0.1, $"the box's outline is still shown, faintly ({outline:P0})")
        End Using
    End Sub

    <GuiFact>
    Public Sub SavingWhereItCannotBeWritten_SaysWhichFileAndWhy()
        Using app As New AppDriver()
            app.ClickForDialog("save", "Save the scene")
            Dim from = app.Mark()
            app.TypeAndEnter("/proc/lesson.json")
            Dim m = app.WaitFor("^message: (Could not save lesson.json: .*)$", skip:=from)
            Assert.Contains("/proc", m.Groups(1).Value, StringComparison.Ordinal)
            Assert.DoesNotContain(".tmp", m.Groups(1).Value, StringComparison.Ordinal)
            Assert.DoesNotContain(".lesson.json", m.Groups(1).Value, StringComparison.Ordinal)
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub

    <GuiFact>
    Public Sub TheLog_GroupsABallsBouncesOnTheFloor_AndItsColumnsFitTheirText()
        Dim path = TempScene("resting.json",
            "{""format"":""physics-scene/1"",""world"":{""width"":4,""height"":3,""gravity"":9.81,""restitution"":1},""bodies"":[" &
            "{""id"":""3"",""type"":""circle"",""x"":2,""y"":0.2015,""radius"":0.2,""mass"":1}]}")
        Try
            Using app As New AppDriver()
                OpenThroughTheDialog(app, path, "^opened resting.json: 1 bodies$")
                ' The log's tab, found by its header wherever the tables before it put it.
                app.Click("tab-collision-log")
                Thread.Sleep(4000)
                Dim rows = app.LastMatch("^log rows (\d+)$")
                Assert.NotNull(rows)
                Assert.Equal("1", rows.Groups(1).Value)
                Dim top = app.LastMatch("^log 0: \S+ \| 3 ↔ floor  \((\d+) times\) \|")
                Assert.True(Integer.Parse(top.Groups(1).Value, CultureInfo.InvariantCulture) > 60, top.Value)
                For Each line In app.Lines().Where(Function(l) l.StartsWith("log column ", StringComparison.Ordinal))
                    Dim m = Regex.Match(line, "^log column \d+ width (\d+) needs (\d+)$")
                    Assert.True(Integer.Parse(m.Groups(1).Value, CultureInfo.InvariantCulture) >= Integer.Parse(m.Groups(2).Value, CultureInfo.InvariantCulture), line)
                Next
                app.X.Shoot("log-grouped")
            End Using
        Finally
            DeleteFolderOf(path)
        End Try
    End Sub

    <GuiFact>
    Public Sub AFileWithoutColours_KeepsThemOnReopening_AndADeeplyNestedFileSaysWhy()
        Dim path = TempScene("plain.json",
            "{""format"":""physics-scene/1"",""world"":{""width"":4,""height"":3,""gravity"":0},""bodies"":[" &
            "{""id"":""lone"",""type"":""circle"",""x"":2,""y"":1.5,""radius"":0.5,""mass"":1}]}")
        Dim deep = IO.Path.Combine(IO.Path.GetDirectoryName(path), "deep.json")
        IO.File.WriteAllText(deep, "{""format"":""physics-scene/1"",""x"":" & New String("["c, 3000) & New String("]"c, 3000) & "}")
        Try
            Using app As New AppDriver()
                OpenThroughTheDialog(app, path, "^opened plain.json: 1 bodies$")
                Dim centre = app.Screen(2.0, 1.8)
                Dim first = app.X.Shoot("colour-first").Pixel(centre.X, centre.Y)
                OpenThroughTheDialog(app, IO.Path.Combine(ProcessRunner.RepoRoot, "scenes", "head-on.json"), "^opened head-on.json")
                OpenThroughTheDialog(app, path, "^opened plain.json: 1 bodies$")
                Dim second = app.X.Shoot("colour-second").Pixel(centre.X, centre.Y)
                Assert.Equal(BodyColours.Parse(BodyColours.ForId("lone"), -1), first)
                Assert.Equal(first, second)
                OpenThroughTheDialog(app, deep, "^message: Could not open deep.json: document: is nested too deeply")
            End Using
        Finally
            DeleteFolderOf(path)
        End Try
    End Sub

    <GuiFact>
    Public Sub TheTutorial_NamesOnlyControlsTheWindowHas()
        Using app As New AppDriver()
            Dim from = app.Mark()
            app.Click("tutorial")
            app.WaitForWindow("^Tutorial")
            app.WaitFor("^help page 5\. ", skip:=from)
            Dim pages = app.Lines().Skip(from).Where(Function(l) l.StartsWith("help page ", StringComparison.Ordinal)).ToList()
            Assert.True(pages.Count >= 5)
            For Each page In pages
                Assert.DoesNotContain("Cancel", page, StringComparison.Ordinal)
                For Each q As Match In Regex.Matches(page, """([^""]+)""")
                    Dim name = q.Groups(1).Value
                    Assert.True(Captions.All.Contains(name) OrElse name = InputLimits.SpawnFirstMessage, $"the tutorial names ""{name}"", which is not on the window")
                Next
            Next
        End Using
    End Sub
    ''' <summary>
    ''' A value as shown to its last digit (<paramref name="digit"/>) against the traced value (itself
    ''' rounded to 3 decimals): within half that digit plus the trace's own rounding, so that 1.675 in the
    ''' trace (1.6749… really) may show as 1.67.
    ''' </summary>
    Private Shared Sub AssertShown(traced As Double, shown As Double, digit As Double)
        Assert.True(Math.Abs(traced - shown) <= digit / 2 + 0.0005 + 1.0E-12, $"shown {shown}, traced {traced}")
    End Sub
End Class
