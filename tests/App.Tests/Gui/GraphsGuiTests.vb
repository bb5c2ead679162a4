Option Strict On
Imports System.Globalization
Imports System.Text.RegularExpressions
Imports System.Threading
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>
''' The Graphs tab and the Export menu in the real window under Xvfb: the gas lesson's speed
''' histogram counts every ball, and what the Export menu writes through its dialogs is what the
''' window shows (the CSV parsed back against the trace, the pictures of the right size).
''' </summary>
<Collection(RealWindow.Name)>
Public Class GraphsGuiTests
    Private Shared ReadOnly TabHeaders As String() = {"tab-circles", "tab-collision-log", "tab-graphs"}

    Private Shared Function Int(text As String) As Integer
        Return Integer.Parse(text, CultureInfo.InvariantCulture)
    End Function

    ''' <summary>Drops the Export menu down, clicks the item of <paramref name="kind"/>, types <paramref name="path"/> into the Save dialog and waits until it is written.</summary>
    Private Shared Sub ExportThroughTheDialog(app As AppDriver, kind As ExportKind, path As String)
        Dim from = app.Mark()
        app.Click("export")
        app.WaitFor("^export menu shown 5$", skip:=from)
        Dim item = app.WaitFor("^export item " & CInt(kind) & " (-?\d+) (-?\d+) (\d+) (\d+) " & kind.ToString() & "$", skip:=from)
        Thread.Sleep(300)
        app.ClickAt(Int(item.Groups(1).Value) + Math.Min(Int(item.Groups(3).Value) \ 3, 120), Int(item.Groups(2).Value) + Int(item.Groups(4).Value) \ 2)
        app.WaitFor("^export dialog " & kind.ToString() & "$", timeout:=TimeSpan.FromSeconds(15), skip:=from)
        app.WaitForWindow("^Export the ")
        Thread.Sleep(300)
        from = app.Mark()
        ' The dialog offers a file name: replace it with the whole path.
        app.X.XDo("key", "ctrl+a")
        app.TypeAndEnter(path)
        app.WaitFor("^exported " & kind.ToString() & " " & Regex.Escape(path) & " ", timeout:=TimeSpan.FromSeconds(20), skip:=from)
    End Sub

    <GuiFact>
    Public Sub GasLesson_HistogramCountsEveryBall_AndExportsMatchTheWindow()
        Dim folder = IO.Path.Combine(IO.Path.GetTempPath(), "gui-export-" & Guid.NewGuid().ToString("N"))
        IO.Directory.CreateDirectory(folder)
        Try
            Using app As New AppDriver(New XSessionOptions With {.Screen = "1280x800x24"}, IO.Path.Combine("scenes", "ideal-gas.json"))
                app.WaitFor("^opened ideal-gas.json: 1000 bodies")
                Dim from = app.Mark()
                app.Click("tab-graphs")
                app.WaitFor("^tab Graphs$", skip:=from)
                app.WaitFor("^ready$", skip:=from)
                Thread.Sleep(1500) ' a second and a half of the gas on the energy graph
                app.X.Shoot("graphs-energy")
                app.ClickAndWaitRepeatable("graph-speeds", "^graph SpeedHistogram$", attempts:=3)
                Dim shown = app.WaitFor("^graph: SpeedHistogram \|.* \| total (\d+) \|", timeout:=TimeSpan.FromSeconds(10))
                Assert.Equal(1000, Int(shown.Groups(1).Value))
                Thread.Sleep(500)
                app.X.Shoot("graphs-speeds")

                ' Paused, the histogram stands still: the exported bins are the ones on screen.
                app.ClickAndWait("pause", "^paused t=")
                Thread.Sleep(600)
                Dim last = app.LastMatch("^graph: SpeedHistogram \|.* \| total (\d+) \| bin (\S+) \| counts ([\d ]+) \|")
                Assert.Equal(1000, Int(last.Groups(1).Value))
                Dim counts = last.Groups(3).Value.Split(" "c).Select(AddressOf Int).ToArray()
                Dim csvPath = IO.Path.Combine(folder, "speeds.csv")
                ExportThroughTheDialog(app, ExportKind.SeriesCsv, csvPath)
                Dim bytes = IO.File.ReadAllBytes(csvPath)
                Assert.Equal({CByte(&HEF), CByte(&HBB), CByte(&HBF)}, bytes.Take(3).ToArray())
                Dim rows = Csv.Parse(New Text.UTF8Encoding(False).GetString(bytes))
                Assert.Equal("v from (m/s)", rows(0)(0))
                Assert.Equal(counts, rows.Skip(1).Select(Function(r) Int(r(2))).ToArray())
                Dim width = AppDriver.Dbl(last.Groups(2).Value)
                Assert.Equal(width, AppDriver.Dbl(rows(1)(1)) - AppDriver.Dbl(rows(1)(0)), 9)

                ' The graph as a slide-sized picture (1280 × 720 at 96 dpi), the canvas as large as it is on screen.
                Dim graphPng = IO.Path.Combine(folder, "speeds.png")
                ExportThroughTheDialog(app, ExportKind.GraphPng, graphPng)
                Assert.Equal((1280, 720), PngSize(graphPng))
                IO.File.Copy(graphPng, IO.Path.Combine(app.X.ShotDirectory, "graphs-exported-speeds.png"), True)
                Dim canvasPng = IO.Path.Combine(folder, "canvas.png")
                ExportThroughTheDialog(app, ExportKind.CanvasPng, canvasPng)
                Dim canvas = app.Control("canvas")
                Assert.Equal((canvas.W, canvas.H), PngSize(canvasPng))

                ' The pressure after some seconds of gas, and large fonts for the back of the room.
                app.ClickAndWait("pause", "^resumed")
                app.ClickAndWaitRepeatable("graph-pressure", "^graph Pressure$", attempts:=3)
                app.WaitFor("^graph: Pressure \|.*measured over ", timeout:=TimeSpan.FromSeconds(20))
                Thread.Sleep(3000)
                app.X.Shoot("graphs-pressure")
                ' High contrast and large fonts, for the back of the room.
                from = app.Mark()
                app.Click("high-contrast")
                app.WaitFor("^high contrast on$", skip:=from)
                app.WaitFor("^ready$", skip:=from)
                app.ReadLayout()
                from = app.Mark()
                app.Click("large-fonts")
                app.WaitFor("^large fonts on$", skip:=from)
                app.WaitFor("^ready$", skip:=from)
                app.ReadLayout()
                app.ClickAndWaitRepeatable("graph-speeds", "^graph SpeedHistogram$", attempts:=3)
                Thread.Sleep(800)
                app.X.Shoot("graphs-speeds-large")
                ' Its own window, for the projector.
                from = app.Mark()
                app.Click("graph-window")
                Dim win = app.WaitFor("^graph window shown (-?\d+) (-?\d+) (\d+) (\d+)$", timeout:=TimeSpan.FromSeconds(15), skip:=from)
                Assert.True(Int(win.Groups(3).Value) >= 800 AndAlso Int(win.Groups(4).Value) >= 500, win.Value)
                Thread.Sleep(1500)
                Dim png = IO.Path.Combine(app.X.ShotDirectory, "graphs-window-large.png")
                Dim shot = app.X.Tool("import", "-window", "root", png)
                Assert.True(shot.ExitCode = 0, shot.ToString())
                Assert.True(app.X.AppIsRunning)
            End Using
        Finally
            IO.Directory.Delete(folder, True)
        End Try
    End Sub

    ''' <summary>A PNG's width and height, from its IHDR chunk.</summary>
    Private Shared Function PngSize(path As String) As (W As Integer, H As Integer)
        Dim b = IO.File.ReadAllBytes(path)
        Assert.True(b.Length > 24 AndAlso b(1) = AscW("P"c) AndAlso b(2) = AscW("N"c) AndAlso b(3) = AscW("G"c), path & " is not a PNG")
        Dim be = Function(i As Integer) (CInt(b(i)) << 24) Or (CInt(b(i + 1)) << 16) Or (CInt(b(i + 2)) << 8) Or CInt(b(i + 3))
        Return (be(16), be(20))
    End Function

    ''' <summary>On a 1024 × 768 projector with large fonts, the Graphs tab's buttons are whole and on screen, and the tabs' headers are not under Export, Scenes or Restart.</summary>
    <GuiFact>
    Public Sub GraphsTab_FitsA1024x768ProjectorWithLargeFonts()
        Using app As New AppDriver(New XSessionOptions With {.Screen = "1024x768x24"})
            Dim from = app.Mark()
            app.Click("large-fonts")
            app.WaitFor("^large fonts on$", skip:=from)
            app.WaitFor("^ready$", skip:=from)
            from = app.Mark()
            app.Click("tab-graphs")
            app.WaitFor("^tab Graphs$", skip:=from)
            app.WaitFor("^ready$", skip:=from)
            Dim window = app.LastMatch("^window (-?\d+) (-?\d+) (\d+) (\d+)$")
            Dim right = Int(window.Groups(1).Value) + Int(window.Groups(3).Value)
            Dim side = app.Control("side")
            ' The last layout's control lines, however many other trace lines came between them.
            Dim graphControls = app.LastLayout().
                Select(Function(l) Regex.Match(l, "^control (graph-\S+|export) (-?\d+) (-?\d+) (\d+) (\d+) (fits|cut)$")).Where(Function(m) m.Success).ToList()
            Assert.Equal(6, graphControls.Count)
            For Each m In graphControls
                Assert.Equal("fits", m.Groups(6).Value)
                Assert.True(Int(m.Groups(2).Value) + Int(m.Groups(4).Value) <= side.X, m.Value & " runs under the side panel")
            Next
            Dim export = app.Control("export")
            For Each header In TabHeaders
                Dim t = app.Control(header)
                Dim apart = t.Y >= export.Y + export.H OrElse t.X + t.W <= export.X
                Assert.True(apart, header & " is under the Export button")
            Next
            Assert.True(right > 0)
            app.X.Shoot("graphs-1024-large")
        End Using
    End Sub
End Class
