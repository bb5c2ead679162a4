Option Strict On
Imports System.IO
Imports PhysicsEngine.Presentation
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>The lesson toolkit without a window: the Scenes menu's list, opening a lesson, Restart and the command-line file.</summary>
Public Class LessonsTests
    Private Shared ReadOnly Property ScenesFolder As String
        Get
            Return Path.Combine(ProcessRunner.RepoRoot, "scenes")
        End Get
    End Property

    Private Shared Function Harness() As PresenterHarness
        Dim h As New PresenterHarness(store:=New SceneFileStore())
        h.P.LessonFolder = ScenesFolder
        Return h
    End Function

    <Fact>
    Public Sub TheIndex_OrdersAndNamesItsFiles_AndEveryOtherFileFollowsTitledFromItsName()
        Dim index = "# a comment" & vbCrLf &
                    "b.json | Bee | what b shows" & vbCrLf &
                    vbCrLf &
                    "gone.json | Not there | skipped: no such file" & vbCrLf &
                    "a.json|Ay" & vbCrLf &
                    "b.json | Bee again | skipped: listed already" & vbCrLf &
                    "my_new-scene.json |  | a line with no title"
        Dim files As String() = {"z-last.json", "a.json", "my_new-scene.json", "b.json", "c-scene.json"}
        Dim entries = LessonIndex.Parse(index, files)
        Dim names As String() = {"b.json", "a.json", "my_new-scene.json", "c-scene.json", "z-last.json"}
        Dim titles As String() = {"Bee", "Ay", "My new scene", "C scene", "Z last"}
        Dim lines As String() = {"what b shows", "", "a line with no title", "", ""}
        Assert.Equal(names, entries.Select(Function(e) e.FileName))
        Assert.Equal(titles, entries.Select(Function(e) e.Title))
        Assert.Equal(lines, entries.Select(Function(e) e.Summary))
    End Sub

    <Fact>
    Public Sub WithoutAnIndex_EveryFileIsListedByName()
        Dim files As String() = {"peg-board.json", "Demo.json"}
        Dim entries = LessonIndex.Parse(Nothing, files)
        Dim names As String() = {"Demo.json", "peg-board.json"}
        Dim titles As String() = {"Demo", "Peg board"}
        Assert.Equal(names, entries.Select(Function(e) e.FileName))
        Assert.Equal(titles, entries.Select(Function(e) e.Title))
    End Sub

    <Fact>
    Public Sub TheMenu_ListsEverySceneFileOnce_WithATitleAndALineForEach()
        Dim h = Harness()
        Dim lessons = h.P.Lessons()
        Dim files = Directory.GetFiles(ScenesFolder, "*.json").Select(Function(f) Path.GetFileName(f)).OrderBy(Function(f) f, StringComparer.Ordinal)
        Assert.Equal(files, lessons.Select(Function(l) l.FileName).OrderBy(Function(f) f, StringComparer.Ordinal))
        For Each l In lessons
            Assert.False(String.IsNullOrWhiteSpace(l.Title), l.FileName)
            Assert.False(String.IsNullOrWhiteSpace(l.Summary), l.FileName & " has no line in " & LessonIndex.IndexFileName)
            Assert.DoesNotContain(vbLf, l.MenuText, StringComparison.Ordinal)
        Next
        ' Every line of the index names a file that is there, so the index cannot drift from the folder.
        For Each line In File.ReadAllLines(Path.Combine(ScenesFolder, LessonIndex.IndexFileName))
            If line.Trim().Length = 0 OrElse line(0) = "#"c Then Continue For
            Assert.True(File.Exists(Path.Combine(ScenesFolder, line.Split("|"c)(0).Trim())), line)
        Next
        ' The lessons the classroom asked for.
        For Each name In {"head-on.json", "head-on-inelastic.json", "glancing-blow.json", "newtons-cradle.json", "pool-break.json",
                          "bouncing-ball.json", "pi-31.json", "pi-314.json", "pi-3141.json", "ideal-gas.json", "settling-pile.json"}
            Assert.Contains(name, lessons.Select(Function(l) l.FileName))
        Next
    End Sub

    <Fact>
    Public Sub AFileAddedToTheFolder_IsInTheMenuAtOnce_AndAMissingFolderGivesAnEmptyMenu()
        Dim folder = Path.Combine(Path.GetTempPath(), "lessons-" & Guid.NewGuid().ToString("N"))
        Directory.CreateDirectory(folder)
        Try
            Dim h = Harness()
            h.P.LessonFolder = folder
            Assert.Empty(h.P.Lessons())
            File.Copy(Path.Combine(ScenesFolder, "head-on.json"), Path.Combine(folder, "my-own_scene.json"))
            Dim l = Assert.Single(h.P.Lessons())
            Assert.Equal("My own scene", l.Title)
            Assert.Equal("My own scene", l.MenuText)
            h.P.OpenLesson(l)
            Assert.Equal(2, h.P.World.Bodies.Count)
            Assert.Equal("My own scene.", h.View.LastMessage)
            h.P.LessonFolder = Path.Combine(folder, "not-there")
            Assert.Empty(h.P.Lessons())
        Finally
            Directory.Delete(folder, True)
        End Try
    End Sub

    <Fact>
    Public Sub EveryLesson_OpensInTheApp_WithItsTitleAndLineAsTheMessage()
        Dim h = Harness()
        For Each l In h.P.Lessons()
            h.P.OpenLesson(l)
            Dim expected = SceneFile.LoadFile(l.Path)
            Assert.Equal(expected.Bodies.Select(Function(b) b.Id), h.P.World.Bodies.Select(Function(b) b.Id))
            Assert.Equal(l.Title & ": " & l.Summary, h.View.LastMessage)
            Assert.Equal(0.0, h.P.World.Time)
            For k = 1 To 10
                h.P.Tick(1 / 60.0)
            Next
            Assert.Null(Placement.FindProblem(h.P.World))
        Next
    End Sub

    <Fact>
    Public Sub ALessonThatCannotBeOpened_SaysWhy_AndKeepsTheScene()
        Dim folder = Path.Combine(Path.GetTempPath(), "lessons-" & Guid.NewGuid().ToString("N"))
        Directory.CreateDirectory(folder)
        Try
            File.WriteAllText(Path.Combine(folder, "broken.json"), "{""format"":""physics-scene/1""")
            Dim h = Harness()
            h.P.LessonFolder = folder
            Dim before = h.P.World
            h.P.OpenLesson(Assert.Single(h.P.Lessons()))
            Assert.Same(before, h.P.World)
            Assert.StartsWith("Could not open broken.json: ", h.View.LastMessage, StringComparison.Ordinal)
        Finally
            Directory.Delete(folder, True)
        End Try
    End Sub

    ''' <summary>The count the app shows for π from collisions: ⌈π/θ⌉ − 1 with θ = atan √(m/M) (see the CLI test for why).</summary>
    <Theory>
    <InlineData("pi-31.json")>
    <InlineData("pi-314.json")>
    <InlineData("pi-3141.json")>
    Public Sub PiLessons_ShowTheirCollisionCountOnTheTotalsLine(name As String)
        Dim h = Harness()
        h.P.OpenLesson(h.P.Lessons().Single(Function(l) l.FileName = name))
        Dim m = h.P.World.Find("small").Mass, big = h.P.World.Find("big").Mass
        Dim expected = CLng(Math.Ceiling(Math.PI / Math.Atan(Math.Sqrt(m / big)))) - 1
        For k = 1 To 300 ' 30 s at real time: the big block has long turned round and gone
            h.P.Tick(0.1)
        Next
        Assert.Equal(expected, h.P.Log.TotalSeen)
        Assert.Contains("collisions: " & expected.ToString(Globalization.CultureInfo.InvariantCulture), h.P.TotalsText.Replace(Units.Nbsp, " "c), StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub Restart_PutsEveryBodyBackAsOpened_TheClockAndCountAtZero_AndKeepsTheSettings()
        Dim h = Harness()
        Dim l = h.P.Lessons().Single(Function(x) x.FileName = "head-on.json")
        h.P.OpenLesson(l)
        Dim file = SceneFile.LoadFile(l.Path)
        For k = 1 To 40
            h.P.Tick(0.1)
        Next
        Assert.Equal(1, h.P.Log.TotalSeen)
        h.P.SetGravity(1.62)
        h.P.SetRestitution(0.5)
        h.P.InputChanged(InputField.ContainerWidth, "12")
        h.P.Restart()
        Assert.Equal(0.0, h.P.World.Time)
        Assert.Equal(0, h.P.Log.TotalSeen)
        For Each b In file.Bodies
            Dim now = h.P.World.Find(b.Id)
            Assert.Equal(b.Position, now.Position)
            Assert.Equal(b.Velocity, now.Velocity)
            Assert.Equal(b.Color, now.Color)
        Next
        Assert.Equal(1.62, h.P.World.Gravity)
        Assert.Equal(0.5, h.P.World.Restitution)
        Assert.Equal("12", h.P.Inputs.ContainerWidthText)
        Assert.StartsWith("Restarted", h.View.LastMessage, StringComparison.Ordinal)
        ' And it runs again: with e = 0.5 the pair now leaves at the closed-form speeds for e = 0.5.
        For k = 1 To 40
            h.P.Tick(0.1)
        Next
        Dim vCm = (1.0 * 2.0 + 3.0 * -1.0) / 4.0
        Assert.Equal(vCm - 0.5 * 3.0 * (2.0 - -1.0) / 4.0, h.P.World.Find("light").Velocity.X, 9)
    End Sub

    <Fact>
    Public Sub Restart_GoesBackToTheSceneAsLastBuilt_NotToAMomentDuringTheRun()
        Dim h As New PresenterHarness(New World(8.0, 5.0, 0.0, 1.0), New SceneFileStore())
        Dim a = h.Ball(2, 2, mass:=1.0, id:="a")
        h.P.World.SetVelocity(a, New Vector(1, 0))
        h.P.Reset()                                ' building: an empty box
        h.P.SetGravity(0)
        h.P.BeginAddCircle("0.2", "1", False)      ' building: a ball placed at (4, 2.5)
        h.LeftClick(4, 2.5)
        Dim placed = h.P.World.Circles.Single()
        Assert.Equal(New Vector(4, 2.5), placed.Position)
        h.P.World.SetVelocity(placed, New Vector(3, 1)) ' a cue shot's effect: not building
        For k = 1 To 20
            h.P.Tick(0.1)
        Next
        Assert.NotEqual(New Vector(4, 2.5), h.P.World.Circles.Single().Position)
        h.P.Restart()
        Dim back = h.P.World.Circles.Single()
        Assert.Equal(New Vector(4, 2.5), back.Position)
        Assert.Equal(Vector.Zero, back.Velocity)
        ' Reset still clears everything, and Restart then has nothing to bring back.
        h.P.Reset()
        h.P.Restart()
        Assert.Empty(h.P.World.Bodies)
    End Sub

    <Fact>
    Public Sub TheCommandLineFile_OpensAtTheStart()
        Dim h = Harness()
        h.P.OpenAtStart(Path.Combine(ScenesFolder, "newtons-cradle.json"))
        Assert.Equal(6, h.P.World.Bodies.Count)
        Assert.Equal("Opened newtons-cradle.json. This scene has no walls: balls can leave the box.", h.View.LastMessage)
    End Sub

    <Theory>
    <InlineData("bad.json", "{""format"":""physics-scene/1"",""world"":{""width"":8,""height"":5},""bodies"":[{""type"":""circle"",""x"":1,""y"":1,""radius"":-1,""mass"":1}]}", "Could not open bad.json: bodies[0].radius: must be greater than 0. The box is empty")>
    <InlineData("huge.json", "{""format"":""physics-scene/1"",""world"":{""width"":8,""height"":5},""bodies"":[{""type"":""circle"",""x"":1,""y"":1,""radius"":0.1,""mass"":1,""vx"":1e300}]}", "Could not open huge.json: bodies[0] speed: ")>
    <InlineData("cut.json", "{""format"":", "Could not open cut.json: ")>
    <InlineData("missing.json", Nothing, "Could not open missing.json: ")>
    Public Sub ACommandLineFileThatDoesNotOpen_LeavesAnEmptyBox_AndOneLineSayingWhy(name As String, text As String, start As String)
        Dim folder = Path.Combine(Path.GetTempPath(), "lessons-" & Guid.NewGuid().ToString("N"))
        Directory.CreateDirectory(folder)
        Try
            Dim file = Path.Combine(folder, name)
            If text IsNot Nothing Then IO.File.WriteAllText(file, text)
            Dim h As New PresenterHarness(Scenarios.Demo(), New SceneFileStore())
            h.P.OpenAtStart(file)
            Assert.Empty(h.P.World.Bodies)
            Dim message = h.View.LastMessage
            Assert.StartsWith(start, message, StringComparison.Ordinal)
            Assert.EndsWith("The box is empty: choose a lesson from Scenes, or Open… another file.", message, StringComparison.Ordinal)
            Assert.DoesNotContain("kept", message, StringComparison.Ordinal)
            Assert.DoesNotContain(vbLf, message, StringComparison.Ordinal)
            Assert.DoesNotContain(folder, message, StringComparison.Ordinal)
            ' The empty box is usable at once: a ball can be placed and runs.
            h.P.BeginAddCircle("0.2", "1", False)
            h.LeftClick(4, 2.5)
            h.P.Tick(0.1)
            Assert.Single(h.P.World.Bodies)
        Finally
            Directory.Delete(folder, True)
        End Try
    End Sub

    <Fact>
    Public Sub TheTutorial_GivesEveryKey()
        Dim all = String.Join(vbLf, HelpTexts.Tutorial.Select(Function(t) t.Text))
        For Each key In {SimulationPresenter.PauseKey, SimulationPresenter.RestartKey, SimulationPresenter.ResetKey, SimulationPresenter.ScenesKey}
            Assert.Contains(key, all, StringComparison.Ordinal)
        Next
        Assert.Equal(4, {SimulationPresenter.PauseKey, SimulationPresenter.RestartKey, SimulationPresenter.ResetKey, SimulationPresenter.ScenesKey}.Distinct().Count())
    End Sub
End Class
