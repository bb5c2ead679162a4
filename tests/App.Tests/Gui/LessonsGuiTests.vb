Option Strict On
Imports System.Globalization
Imports System.Text.RegularExpressions
Imports System.Threading
Imports Xunit

''' <summary>
''' The lesson toolkit in the real window under Xvfb: the Scenes menu opened with the mouse and
''' with its key, each lesson opened from it and photographed, Restart, the keys, and the scene
''' given on the command line (good and bad).
''' </summary>
<Collection(RealWindow.Name)>
Public Class LessonsGuiTests
    ''' <summary>
    ''' Drops the Scenes menu down (with the mouse, or its key) and returns, for each lesson's file, the
    ''' topic that holds it and where that topic's item is on the screen. The menu must be on the screen.
    ''' </summary>
    Private Shared Function OpenMenu(app As AppDriver, Optional withKey As Boolean = False) As Dictionary(Of String, (Topic As Integer, X As Integer, Y As Integer, W As Integer, H As Integer))
        ' A click or key that reaches the window while a frame is being worked out can be lost on a
        ' loaded machine under Mono: it is given again (three times in all) if the menu does not come.
        Dim from = 0
        Dim shown As Match = Nothing
        For attempt = 1 To 3
            from = app.Mark()
            If withKey Then
                app.X.XDo("key", "ctrl+l")
            Else
                app.Click("scenes")
            End If
            Try
                shown = app.WaitFor("^lesson menu shown (\d+)$", TimeSpan.FromSeconds(8), from)
                Exit For
            Catch ex As TimeoutException When attempt < 3
            End Try
        Next
        Dim count = Integer.Parse(shown.Groups(1).Value, CultureInfo.InvariantCulture)
        Dim topics As New Dictionary(Of Integer, (X As Integer, Y As Integer, W As Integer, H As Integer))
        Dim items As New Dictionary(Of String, (Topic As Integer, X As Integer, Y As Integer, W As Integer, H As Integer))(StringComparer.Ordinal)
        For Each line In app.Lines().Skip(from)
            Dim m = Regex.Match(line, "^lesson topic (\d+) (-?\d+) (-?\d+) (\d+) (\d+) (.+)$")
            If m.Success Then topics(Int(m.Groups(1).Value)) = (Int(m.Groups(2).Value), Int(m.Groups(3).Value), Int(m.Groups(4).Value), Int(m.Groups(5).Value))
            m = Regex.Match(line, "^lesson in (\d+) (\S+)$")
            If m.Success Then
                Dim t = topics(Int(m.Groups(1).Value))
                items(m.Groups(2).Value) = (Int(m.Groups(1).Value), t.X, t.Y, t.W, t.H)
            End If
        Next
        Assert.Equal(count, items.Count)
        AssertOnScreen(app, app.WaitFor("^lesson menu at .*$", skip:=from).Value)
        Thread.Sleep(300)
        Return items
    End Function

    ''' <summary>A menu's trace line ("lesson menu at X Y W H screen SW SH fits"): the whole menu on the screen, every line whole.</summary>
    Private Shared Sub AssertOnScreen(app As AppDriver, line As String)
        Dim m = Regex.Match(line, " at (-?\d+) (-?\d+) (\d+) (\d+) screen (\d+) (\d+) (fits|cut)$")
        Assert.True(m.Success, line)
        Dim x = Int(m.Groups(1).Value), y = Int(m.Groups(2).Value), w = Int(m.Groups(3).Value), h = Int(m.Groups(4).Value)
        Assert.True(x >= 0 AndAlso y >= 0 AndAlso x + w <= Int(m.Groups(5).Value) AndAlso y + h <= Int(m.Groups(6).Value), "off the screen: " & line & vbLf & app.X.AppOutput())
        Assert.True(m.Groups(7).Value = "fits", "a line is cut: " & line)
    End Sub

    ''' <summary>Opens a lesson from the menu: a click on its topic, one on the lesson; waits until it is on screen, and returns the message it shows.</summary>
    Private Shared Function OpenLesson(app As AppDriver, file As String) As String
        Dim items = OpenMenu(app)
        Assert.True(items.ContainsKey(file), file & " is not in the menu" & vbLf & app.X.AppOutput())
        Dim topic = items(file)
        Dim from = app.Mark()
        app.ClickAt(topic.X + Math.Min(topic.W \ 3, 150), topic.Y + topic.H \ 2)
        app.WaitFor("^lesson list shown " & topic.Topic & "$", skip:=from)
        AssertOnScreen(app, app.WaitFor("^lesson list " & topic.Topic & " at .*$", skip:=from).Value)
        Dim item = app.WaitFor("^lesson item \d+ (-?\d+) (-?\d+) (\d+) (\d+) " & Regex.Escape(file) & "$", skip:=from)
        Thread.Sleep(300)
        from = app.Mark()
        app.ClickAt(Int(item.Groups(1).Value) + Math.Min(Int(item.Groups(3).Value) \ 3, 150), Int(item.Groups(2).Value) + Int(item.Groups(4).Value) \ 2)
        app.WaitFor("^lesson " & Regex.Escape(file) & ": ", skip:=from)
        ' The lesson's own message comes after the line that names it (Open's "Opened …" comes before).
        Dim lines = app.Lines()
        Dim at = Array.FindLastIndex(lines, Function(l) l.StartsWith("lesson " & file & ": ", StringComparison.Ordinal))
        Dim message = app.WaitFor("^message: (.*)$", skip:=at).Groups(1).Value
        Thread.Sleep(700) ' a few frames of the new scene
        app.ReadLayout()
        Return message
    End Function

    Private Shared Function Int(text As String) As Integer
        Return Integer.Parse(text, CultureInfo.InvariantCulture)
    End Function

    ''' <summary>The whole screen, so the open menu (a window of its own) is in the picture.</summary>
    Private Shared Sub ShootScreen(app As AppDriver, name As String)
        Dim png = IO.Path.Combine(app.X.ShotDirectory, name & ".png")
        Dim r = app.X.Tool("import", "-window", "root", png)
        Assert.True(r.ExitCode = 0, r.ToString())
    End Sub

    <GuiTheory>
    <InlineData("head-on.json")>
    <InlineData("head-on-inelastic.json")>
    <InlineData("glancing-blow.json")>
    <InlineData("newtons-cradle.json")>
    <InlineData("pool-break.json")>
    <InlineData("bouncing-ball.json")>
    <InlineData("pi-3141.json")>
    <InlineData("ideal-gas.json")>
    <InlineData("settling-pile.json")>
    <InlineData("ramp.json")>
    <InlineData("ball-in-v.json")>
    <InlineData("boxes-sliding.json")>
    <InlineData("box-stack.json")>
    <InlineData("polygons.json")>
    <InlineData("pendulum.json")>
    <InlineData("cradle-strings.json")>
    <InlineData("spring-mass.json")>
    <InlineData("galton-board.json")>
    Public Sub ALessonOpensFromTheScenesMenu_WithOneClick_AndIsDrawn(file As String)
        Dim lesson = PhysicsEngine.Presentation.LessonIndex.Read(IO.Path.Combine(ProcessRunner.RepoRoot, "scenes")).Single(Function(l) l.FileName = file)
        Using app As New AppDriver()
            If file = "head-on.json" Then
                OpenMenu(app)
                ShootScreen(app, "lesson-menu")
                app.X.XDo("key", "Escape")
                app.WaitFor("^lesson menu closed$")
            End If
            Dim message = OpenLesson(app, file)
            Assert.Equal(lesson.Title & ": " & lesson.Summary, message)
            Dim shot = app.X.Shoot("lesson-" & IO.Path.GetFileNameWithoutExtension(file))
            ' The canvas shows the scene's coloured bodies, not a blank box.
            Dim c = app.Control("canvas")
            Dim w = app.Control("side").X - c.X
            Dim coloured = shot.Fraction(0, 0, w, c.H, Function(p) Saturation(p) > 60)
            Assert.True(coloured > 0.0005, $"{file}: the canvas shows no coloured bodies ({coloured:P3})" & vbLf & app.X.AppOutput())
            ' The new buttons' captions fit, whatever the message's height did to the panel.
            For Each name In {"scenes", "restart"}
                Dim last = app.Lines().Last(Function(l) l.StartsWith("control " & name & " ", StringComparison.Ordinal))
                Assert.EndsWith(" fits", last, StringComparison.Ordinal)
            Next
            Assert.True(app.X.AppIsRunning, "the app died" & vbLf & app.X.AppOutput())
        End Using
    End Sub

    <GuiFact>
    Public Sub RestartPutsTheLessonBack_AndEachKeyDoesItsJob()
        Using app As New AppDriver()
            Dim items = OpenMenu(app, withKey:=True)
            Assert.Contains("pi-31.json", items.Keys)
            app.X.XDo("key", "Escape")
            app.WaitFor("^lesson menu closed$")
            OpenLesson(app, "pi-31.json")
            Thread.Sleep(8500) ' the blocks meet at 1.6 s, and the 31st collision is at 7.45 s
            Dim from = app.Mark()
            app.X.XDo("key", "ctrl+p")
            app.WaitFor("^key pause$", skip:=from)
            Dim totals = app.WaitFor("^totals t\s=\s(\S+)\ss.*collisions:\s(\d+)", skip:=from)
            Assert.True(AppDriver.Dbl(totals.Groups(1).Value) > 7.5, totals.Value)
            Assert.Equal("31", totals.Groups(2).Value)
            app.X.Shoot("lesson-pi-31-after")
            ' Restart, while paused: the clock and the count back at 0, the blocks where the file has them.
            from = app.Mark()
            app.X.XDo("key", "ctrl+r")
            app.WaitFor("^restarted: 4 bodies$", skip:=from)
            totals = app.WaitFor("^totals t\s=\s(\S+)\ss.*collisions:\s(\d+)", skip:=from)
            Assert.Equal(0.0, AppDriver.Dbl(totals.Groups(1).Value))
            Assert.Equal("0", totals.Groups(2).Value)
            app.X.Shoot("lesson-pi-31-restarted")
            ' The Restart button does the same after a second run.
            app.X.XDo("key", "ctrl+p")
            app.WaitFor("^resumed$", skip:=from)
            Thread.Sleep(3000)
            from = app.Mark()
            app.Click("restart")
            app.WaitFor("^restarted: 4 bodies$", skip:=from)
            from = app.Mark()
            app.X.XDo("key", "ctrl+p")
            totals = app.WaitFor("^totals t\s=\s(\S+)\ss.*collisions:\s(\d+)", skip:=from)
            Assert.True(AppDriver.Dbl(totals.Groups(1).Value) < 1.5, totals.Value)
            ' Ctrl+Shift+R resets: every body gone.
            from = app.Mark()
            app.X.XDo("key", "ctrl+shift+r")
            app.WaitFor("^key reset$", skip:=from)
            app.WaitFor("^reset: 0 bodies", skip:=from)
            ' The keys work with the focus in a text box too, and the box keeps its text.
            app.TypeInto("radius", "0.25")
            from = app.Mark()
            app.X.XDo("key", "ctrl+p")
            app.WaitFor("^resumed$", skip:=from)
            Assert.Equal("0.25", app.Inputs()("Radius"))
            ' The menu without the mouse: its key, the arrow keys (down to the first topic, right into its
            ' lessons, down to the second) and Enter.
            OpenMenu(app, withKey:=True)
            from = app.Mark()
            For Each key In {"Down", "Right", "Down", "Return"}
                app.X.XDo("key", key)
                Thread.Sleep(300)
            Next
            app.WaitFor("^lesson head-on-inelastic.json: ", skip:=from)
            Assert.True(app.X.AppIsRunning, "the app died" & vbLf & app.X.AppOutput())
        End Using
    End Sub

    <GuiFact>
    Public Sub ASceneOnTheCommandLine_OpensAtTheStart()
        Using app As New AppDriver(New XSessionOptions(), IO.Path.Combine("scenes", "glancing-blow.json"))
            app.WaitFor("^opened glancing-blow.json: 2 bodies$")
            app.X.Shoot("lesson-command-line")
            ' The menu and the buttons in the projector settings: large fonts, high contrast.
            app.ClickAndWait("high-contrast", "^high contrast on$")
            Dim from = app.Mark()
            app.Click("large-fonts")
            app.WaitFor("^large fonts on$", skip:=from)
            app.WaitFor("^ready$", skip:=from)
            Dim items = OpenMenu(app)
            Assert.Contains("glancing-blow.json", items.Keys)
            Dim r = items("glancing-blow.json")
            app.MoveTo(r.X + 60, r.Y + r.H \ 2) ' the item under the pointer is highlighted
            Thread.Sleep(300)
            ShootScreen(app, "lesson-menu-large-high-contrast")
            ' Esc closes the topic's list under the pointer, then the menu.
            Dim mark = app.Mark()
            For attempt = 1 To 3
                app.X.XDo("key", "Escape")
                Try
                    app.WaitFor("^lesson menu closed$", TimeSpan.FromSeconds(2), mark)
                    Exit For
                Catch ex As TimeoutException When attempt < 3
                End Try
            Next
            For Each name In {"scenes", "restart"}
                Dim last = app.Lines().Last(Function(l) l.StartsWith("control " & name & " ", StringComparison.Ordinal))
                Assert.EndsWith(" fits", last, StringComparison.Ordinal)
            Next
            Assert.True(app.X.AppIsRunning, "the app died" & vbLf & app.X.AppOutput())
        End Using
    End Sub

    <GuiFact>
    Public Sub ABadSceneOnTheCommandLine_IsOneLineAndAnEmptyBox_NeverACrash()
        Dim folder = IO.Path.Combine(IO.Path.GetTempPath(), "gui-" & Guid.NewGuid().ToString("N"))
        IO.Directory.CreateDirectory(folder)
        Try
            Dim path = IO.Path.Combine(folder, "broken lesson.json")
            IO.File.WriteAllText(path, "{""format"":""physics-scene/1"",""world"":{""width"":8,""height"":5},""bodies"":[{""type"":""circle"",""x"":1,""y"":1,""radius"":-1,""mass"":1}]}")
            Using app As New AppDriver(New XSessionOptions(), path)
                app.WaitFor("^empty scene: broken lesson.json did not open$")
                Dim at = Array.FindLastIndex(app.Lines(), Function(l) l.StartsWith("empty scene: ", StringComparison.Ordinal))
                Dim message = app.WaitFor("^message: (.*)$", skip:=at).Groups(1).Value
                Assert.Equal("Could not open broken lesson.json: bodies[0].radius: must be greater than 0. The box is empty: choose a lesson from Scenes, or Open… another file.", message)
                app.X.Shoot("lesson-bad-command-line")
                ' The empty box works: the menu opens a lesson.
                OpenLesson(app, "newtons-cradle.json")
                Assert.True(app.X.AppIsRunning, "the app died" & vbLf & app.X.AppOutput())
            End Using
        Finally
            IO.Directory.Delete(folder, True)
        End Try
    End Sub

    Private Shared Function Saturation(p As Integer) As Integer
        Dim r = (p >> 16) And 255, g = (p >> 8) And 255, b = p And 255
        Return Math.Max(r, Math.Max(g, b)) - Math.Min(r, Math.Min(g, b))
    End Function
End Class
