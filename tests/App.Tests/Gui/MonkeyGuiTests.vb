Option Strict On
Imports System.Globalization
Imports System.Threading
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>
''' Students trying to break it: random clicks, drags, cue shots, key presses, text (accented and
''' symbol characters included) in every box, slider moves, tab switches, saves and opens, for a
''' fixed number of actions from a fixed seed. Afterwards the app still answers, no body is inside
''' another or outside the walls, every scene it saved opens again, and nothing on screen reads NaN
''' or ∞. In CI it runs <see cref="DefaultActions"/> actions; scripts/monkey.sh runs as many as asked
''' (MONKEY_ACTIONS, MONKEY_SEED).
''' </summary>
<Collection(RealWindow.Name)>
Public Class MonkeyGuiTests
    ''' <summary>Actions in a CI run.</summary>
    Public Const DefaultActions As Integer = 150
    ''' <summary>The CI run's seed.</summary>
    Public Const DefaultSeed As Integer = 20261124

    Private Shared ReadOnly TextBoxes As String() = {"radius", "mass", "rect-width", "rect-height", "box-width", "box-height", "sides", "angle", "stiffness"}
    Private Shared ReadOnly Buttons As String() = {
        "pause", "pause", "delete-mode", "moon", "mars", "earth", "jupiter", "add-circle", "add-circle", "add-rectangle",
        "resize", "fixed", "arrows", "high-contrast", "large-fonts", "reset", "add-polygon", "add-corners", "add-ramp", "rect-fixed",
        "centre-of-mass", "impulses", "walls"}
    ''' <summary>The tools that join two bodies (or a body and an anchor).</summary>
    Private Shared ReadOnly LinkTools As String() = {"add-spring", "add-rod", "add-string"}
    ''' <summary>Three of the tables' tabs, by the names the app traces for their headers.</summary>
    Private Shared ReadOnly Tabs As String() = {"tab-circles", "tab-rectangles", "tab-collision-log"}
    Private Shared ReadOnly Sliders As String() = {"speed", "gravity", "restitution"}
    Private Shared ReadOnly Keys As String() = {"Escape", "Escape", "BackSpace", "Left", "Right", "Up", "Down", "a", "1", "minus", "period", "comma", "e",
        "ctrl+z", "ctrl+z", "ctrl+y", "Return", "ctrl+0"}
    Private Shared ReadOnly Texts As String() = {
        "0.3", "0.05", "1", "2", "7", "0.6", "3", "12", "1e-300", "1e300", "-1", "0", "", "abc", "é€ß", "1,5", "²µ§", "NaN", "∞",
        "0,25", "ñ", "1e5", "4.", ".5", "  2  ", "0x10", "½", "١٢", "10", "100"}

    <GuiFact>
    Public Sub Monkey_RandomStudentsCannotBreakIt()
        Dim actions = FromEnvironment("MONKEY_ACTIONS", DefaultActions)
        Dim seed = FromEnvironment("MONKEY_SEED", DefaultSeed)
        Dim rng As New Random(seed)
        Dim folder = IO.Path.Combine(IO.Path.GetTempPath(), "gui-monkey-" & Guid.NewGuid().ToString("N"))
        IO.Directory.CreateDirectory(folder)
        Dim saved As New List(Of String)
        Dim counts As New Dictionary(Of String, Integer)(StringComparer.Ordinal)
        ' The harshest setting seen: a French keyboard, no locale, Xlib's own input method.
        Dim options As New XSessionOptions With {.KeyboardLayout = "fr"}
        For Each name In {"LANG", "LC_ALL", "LC_CTYPE"}
            options.Environment(name) = Nothing
        Next
        options.Environment("XMODIFIERS") = "@im=none"
        Try
            Using app As New AppDriver(options)
                For i = 1 To actions
                    Dim kind = Act(app, rng, folder, i, saved)
                    Dim n As Integer
                    counts.TryGetValue(kind, n)
                    counts(kind) = n + 1
                    Assert.True(app.X.AppIsRunning, $"the app died at action {i} ({kind}), seed {seed}" & vbLf & app.X.AppOutput())
                Next
                ' Still answers: a pause shows, with the checks of the scene and of every text on screen.
                app.X.XDo("key", "Escape")
                Dim from = app.Mark()
                app.Click("pause")
                app.WaitFor("^(paused|resumed)", skip:=from)
                If app.LastMatch("^(paused|resumed)").Value.StartsWith("resumed", StringComparison.Ordinal) Then
                    from = app.Mark()
                    app.Click("pause")
                End If
                app.WaitFor("^paused", TimeSpan.FromSeconds(15), skip:=from)
                Dim scene = app.WaitFor("^check scene (.*)$", skip:=from).Groups(1).Value
                Assert.True(scene = "ok", $"after {actions} actions (seed {seed}): {scene}")
                Dim texts = app.WaitFor("^check texts (.*)$", skip:=from).Groups(1).Value
                Assert.True(texts = "ok", $"after {actions} actions (seed {seed}) the screen shows: {texts}")
                ' Every text traced as shown: no NaN or ∞ anywhere, not in the tables nor the log.
                Dim bad = app.Lines().FirstOrDefault(Function(l) (l.StartsWith("row ", StringComparison.Ordinal) OrElse l.StartsWith("log ", StringComparison.Ordinal) OrElse l.StartsWith("totals ", StringComparison.Ordinal)) AndAlso (l.Contains("NaN") OrElse l.Contains("∞"c)))
                Assert.True(bad Is Nothing, "shown: " & bad)
                app.X.Shoot("monkey-end")
            End Using
            For Each path In saved
                SceneFile.LoadFile(path) ' throws when a scene the app saved would not open
            Next
            Console.WriteLine($"monkey: seed {seed}, {actions} actions ({String.Join(", ", counts.OrderBy(Function(c) c.Key).Select(Function(c) c.Key & " " & c.Value))}), {saved.Count} scenes saved and reopened")
        Finally
            IO.Directory.Delete(folder, True)
        End Try
    End Sub

    ''' <summary>Does one random thing; returns its kind.</summary>
    Private Shared Function Act(app As AppDriver, rng As Random, folder As String, index As Integer, saved As List(Of String)) As String
        Dim c = app.Control("canvas")
        Dim px = Function() c.X + rng.Next(c.W)
        Dim py = Function() c.Y + rng.Next(c.H)
        Dim roll = rng.Next(100)
        Select Case roll
            Case < 18
                app.ClickAt(px(), py())
                Return "click"
            Case < 30
                app.Drag(3, px(), py(), px(), py(), If(rng.Next(2) = 0, 1, 6))
                Return "carry"
            Case < 40
                Dim x = px(), y = py()
                app.Drag(1, x, y, Math.Max(c.X, Math.Min(c.X + c.W - 1, x + rng.Next(-200, 200))), Math.Max(c.Y, Math.Min(c.Y + c.H - 1, y + rng.Next(-200, 200))), 4)
                Return "cue"
            Case < 50
                app.Click(Buttons(rng.Next(Buttons.Length)))
                Return "button"
            Case < 58
                ' A link between two places (bodies or an anchor), then a carry from its first end: a linked body carried.
                Dim a = (px(), py()), b = (px(), py())
                app.Click(LinkTools(rng.Next(LinkTools.Length)))
                app.ClickAt(a.Item1, a.Item2)
                app.ClickAt(b.Item1, b.Item2)
                app.Drag(3, a.Item1, a.Item2, px(), py(), 6)
                Return "link and carry"
            Case < 76
                app.TypeInto(TextBoxes(rng.Next(TextBoxes.Length)), Texts(rng.Next(Texts.Length)), check:=False)
                Return "text"
            Case < 84
                Dim s = app.ScrollIntoView(Sliders(rng.Next(Sliders.Length)))
                app.ClickAt(s.X + 5 + rng.Next(Math.Max(1, s.W - 10)), s.Y + s.H \ 3)
                Return "slider"
            Case < 90
                app.X.XDo("key", Keys(rng.Next(Keys.Length)))
                Return "key"
            Case < 94
                app.Click(Tabs(rng.Next(Tabs.Length)))
                Return "tab"
            Case < 97
                Dim name = "monkey-" & index.ToString(CultureInfo.InvariantCulture) & If(rng.Next(2) = 0, "-é€", "") & ".json"
                Dim path = IO.Path.Combine(folder, name)
                app.X.XDo("key", "Escape")
                app.ClickForDialog("save", "Save the scene")
                Dim from = app.Mark()
                app.TypeAndEnter(path)
                app.WaitFor("^(saved|message: Could not save) ", TimeSpan.FromSeconds(15), skip:=from)
                If IO.File.Exists(path) Then saved.Add(path)
                Return "save"
            Case Else
                Dim choices = saved.Concat(IO.Directory.GetFiles(IO.Path.Combine(ProcessRunner.RepoRoot, "scenes"), "*.json")).ToList()
                Dim path = choices(rng.Next(choices.Count))
                app.X.XDo("key", "Escape")
                app.ClickForDialog("open", "Open a scene")
                Dim from = app.Mark()
                app.TypeAndEnter(path)
                app.WaitFor("^(opened|message: Could not open) ", TimeSpan.FromSeconds(15), skip:=from)
                Return "open"
        End Select
    End Function

    Private Shared Function FromEnvironment(name As String, fallback As Integer) As Integer
        Dim value As Integer
        Dim text = Environment.GetEnvironmentVariable(name)
        If Integer.TryParse(text, NumberStyles.Integer, CultureInfo.InvariantCulture, value) AndAlso value > 0 Then Return value
        Return fallback
    End Function
End Class
