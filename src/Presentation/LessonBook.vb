Option Strict On

''' <summary>
''' The lesson toolkit: the Scenes menu (ready-made scenes from the scenes folder), the scene a file
''' given on the command line opens, and Restart (the scene as it was when opened or last built).
''' </summary>
Friend NotInheritable Class LessonBook
    Private ReadOnly _stage As Stage
    Private ReadOnly _files As SceneFiles

    Public Sub New(stage As Stage, files As SceneFiles)
        _stage = stage
        _files = files
    End Sub

    ''' <summary>The Scenes menu's button.</summary>
    Public Const ScenesCaption As String = "Scenes ▾"
    ''' <summary>The Restart button.</summary>
    Public Const RestartCaption As String = "↺ Restart"

    ''' <summary>The keys of the lesson toolkit, as the tutorial and the window's tips name them.</summary>
    Public Const PauseKey As String = "Ctrl+P"
    ''' <summary>Restart's key.</summary>
    Public Const RestartKey As String = "Ctrl+R"
    ''' <summary>Reset's key: with Shift, so clearing everything is never a slip of the finger.</summary>
    Public Const ResetKey As String = "Ctrl+Shift+R"
    ''' <summary>The Scenes menu's key.</summary>
    Public Const ScenesKey As String = "Ctrl+L"

    ''' <summary>The tutorial's page on lessons, Restart and the keys.</summary>
    Public Shared ReadOnly Property LessonsHelp As New HelpTopic("6. Lesson scenes, Restart and keys",
        "Scenes (" & ScenesKey & ") lists ready-made lessons by topic (collisions, momentum, energy, gases, pendulums and springs, ramps and boxes, friction, forces in air and water): head-on collisions, a glancing blow, Newton's cradle, a pool break, a bouncing ball, π from collisions, an ideal gas, a settling pile and more. Point at a topic and click a lesson to open it; the message box says what it shows (the keys work too: arrows and Enter). The lessons are the scene files in the scenes folder beside the app; a file you save there appears under  & LessonTopics.More &  (its title comes from lessons.txt in that folder, else from the file's name)." & vbLf & "" & vbLf &
        "Restart (" & RestartKey & ") puts every body back where it was, with its velocity, when the scene was opened or last built (a body added or deleted, a fixed body moved, the container resized), and sets the clock and the collision count to 0. Gravity, restitution, friction and speed stay as you set them, so you can run the same start again on the Moon, with e = 0.5 or on a rougher floor. Reset (" & ResetKey & ") still removes every body." & vbLf & "" & vbLf &
        "Keys: " & PauseKey & " pauses and resumes, " & RestartKey & " restarts, " & ResetKey & " resets, " & ScenesKey & " opens the Scenes menu, Esc drops a body you are placing; " & SimulationPresenter.TimeKeysText & "." & vbLf & "" & vbLf &
        "A scene file opened with the app (double-clicked, or given on the command line) opens at the start. A file that cannot be opened leaves an empty box and a message saying why.")

    Private _start As String
    Private _startBodies As Shape() = Array.Empty(Of Shape)()
    Private _startWidth As Double
    Private _startHeight As Double
    Private _startLinks As Integer

    ''' <summary>The folder the Scenes menu lists (the example scenes); Nothing for none.</summary>
    Public Property LessonFolder As String

    ''' <summary>The Scenes menu, read from <see cref="LessonFolder"/> now (a file added since shows at once).</summary>
    Public Function Lessons() As IReadOnlyList(Of Lesson)
        Dim found = LessonIndex.Read(LessonFolder)
        _stage.Emit("lessons " & found.Count & " in " & If(LessonFolder, "(no folder)"))
        Return found
    End Function

    ''' <summary>The Scenes menu by topic (collisions, momentum, energy, …), read from <see cref="LessonFolder"/> now.</summary>
    Public Function LessonMenu() As IReadOnlyList(Of (Topic As String, Lessons As IReadOnlyList(Of Lesson)))
        Return LessonTopics.Group(Lessons())
    End Function

    ''' <summary>Opens a lesson from the Scenes menu; the message gives its title and what it shows. A file that fails keeps the scene on screen, as Open does.</summary>
    Public Sub OpenLesson(lesson As Lesson)
        If lesson Is Nothing Then Throw New ArgumentNullException(NameOf(lesson))
        Dim before = _stage.World
        _files.OpenScene(lesson.Path)
        If ReferenceEquals(_stage.World, before) Then Return ' OpenScene's message says why
        _stage.Emit("lesson " & lesson.FileName & ": " & lesson.Title)
        _stage.ShowMessage(If(lesson.Summary.Length = 0, lesson.Title & ".", lesson.Title & ": " & lesson.Summary) & SolverChoice.StiffSpringAddendum(_stage.World))
    End Sub

    ''' <summary>
    ''' Opens the file given on the command line (how Windows hands the app a file a teacher opens
    ''' with it). A file that cannot be opened leaves an empty box and the message why, not the demo:
    ''' the teacher asked for that file, and a demo in its place would look like it.
    ''' </summary>
    Public Sub OpenAtStart(path As String)
        Dim before = _stage.World
        _files.OpenScene(path)
        If Not ReferenceEquals(_stage.World, before) Then Return
        Dim why = _stage.Message.Replace(" The scene on screen is kept.", "").TrimEnd()
        If why.Length = 0 OrElse why(why.Length - 1) <> "."c Then why &= "."
        _stage.Guarded(
            Sub()
                _stage.Present(New World(before.Width, before.Height, SimulationPresenter.DefaultGravity, SimulationPresenter.DefaultRestitution))
                _stage.Emit("empty scene: " & SceneFiles.SafeName(path) & " did not open")
                _stage.ShowMessage(why & " The box is empty: choose a lesson from Scenes, or Open… another file.")
                _stage.TakeSnapshot()
                _stage.Window.ShowInputs()
                _stage.Window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>
    ''' Puts the scene back as it was when it was opened or last built: every body where it was, with
    ''' its velocity, the clock and the collision log at 0. Gravity, restitution, friction, the air and speed keep what
    ''' the teacher set, so the same start can be run again under other settings; what is typed in the
    ''' boxes stays.
    ''' </summary>
    Public Sub Restart()
        If _start Is Nothing Then
            _stage.ShowMessage("There is no start to go back to: open a scene first.")
            Return
        End If
        _stage.Guarded(
            Sub()
                Dim w = Scenes.SceneFile.Load(_start)
                w.Gravity = _stage.World.Gravity
                w.Restitution = _stage.World.Restitution
                WorldSettings.KeepFriction(w, _stage.World.Friction, _stage.World.StaticFriction)
                w.AirDensity = _stage.World.AirDensity
                Dim typedWidth = _stage.Inputs.ContainerWidthText, typedHeight = _stage.Inputs.ContainerHeightText
                _stage.Present(w)
                _stage.Inputs.ContainerWidthText = typedWidth
                _stage.Inputs.ContainerHeightText = typedHeight
                _stage.Emit("restarted: " & w.Bodies.Count & " bodies")
                _stage.ShowMessage("Restarted: every body is back where the scene started, and the clock at 0." & SolverChoice.StiffSpringAddendum(w))
                _stage.TakeSnapshot()
                _stage.Window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>Keeps the world as it is now as the start Restart goes back to (called when a scene is attached or built).</summary>
    Public Sub RememberStart()
        Try
            _start = Scenes.SceneFile.Save(_stage.World)
        Catch ex As Exception When TypeOf ex Is Scenes.SceneFormatException OrElse TypeOf ex Is ArgumentException OrElse TypeOf ex Is InvalidOperationException
            ' A world that cannot be written keeps the last start it had; it is not tried again
            ' until the teacher builds something else.
        End Try
        _startBodies = _stage.World.Bodies.ToArray()
        _startWidth = _stage.World.Width
        _startHeight = _stage.World.Height
        _startLinks = _stage.World.Links.Count
    End Sub

    ''' <summary>A moment of the run was taken back: its bodies are the start's as far as building goes (going back is not building).</summary>
    Public Sub FollowWorld(w As World)
        _startBodies = w.Bodies.ToArray()
        _startWidth = w.Width
        _startHeight = w.Height
        _startLinks = w.Links.Count
    End Sub

    ''' <summary>
    ''' After every change the presenter makes (through the stage's TakeSnapshot): when the set of
    ''' bodies or the container changed since the start was kept, the teacher has built something,
    ''' and Restart goes back to this. Time running, carrying a ball and cue shots are not building.
    ''' </summary>
    Public Sub NoteBuilding()
        Dim bodies = _stage.World.Bodies
        Dim built = bodies.Count <> _startBodies.Length OrElse _stage.World.Width <> _startWidth OrElse _stage.World.Height <> _startHeight OrElse _stage.World.Links.Count <> _startLinks
        For i = 0 To bodies.Count - 1
            If built Then Exit For
            built = Not ReferenceEquals(bodies(i), _startBodies(i))
        Next
        If built Then
            RememberStart()
            _stage.Emit("start kept: " & bodies.Count & " bodies")
        End If
    End Sub
End Class
