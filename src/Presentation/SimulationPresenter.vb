Option Strict On

''' <summary>
''' Sits between the window and the engine (Passive View): the form forwards the teacher's actions
''' here, this decides what they mean, changes the world and tells the view what to show. Every
''' behaviour of the app is a method here, so tests drive it without a window. The window reads
''' what to show from here too (labels, slider positions, table rows, totals), never from the world.
''' </summary>
Partial Public NotInheritable Class SimulationPresenter
    ''' <summary>Gravity after a reset, m/s².</summary>
    Public Const DefaultGravity As Double = WorldSettings.DefaultGravity
    ''' <summary>Restitution after a reset.</summary>
    Public Const DefaultRestitution As Double = WorldSettings.DefaultRestitution
    ''' <summary>The longest real time one frame may advance, s: after a stall the simulation slows rather than jumps.</summary>
    Public Const MaxFrameSeconds As Double = 0.1
    ''' <summary>Real time between snapshots of the tables while time runs, s (about ten a second: readable, and cheap).</summary>
    Public Const SnapshotSeconds As Double = 0.1

    Private ReadOnly _window As ISimulationView
    ''' <summary>What the parts share: the world, the window, the trace, the message, the log, the typed boxes.</summary>
    Private ReadOnly _stage As Stage
    ''' <summary>The Graphs tab's series, pressure gauge and histogram.</summary>
    Private ReadOnly _graphs As GraphRecorder
    ''' <summary>The Export menu's files.</summary>
    Private ReadOnly _export As ExportWriter
    ''' <summary>The centre of mass, Σp, the momenta diagram, impulses and traces.</summary>
    Private ReadOnly _momentum As MomentumViews
    ''' <summary>Open and Save.</summary>
    Private ReadOnly _files As SceneFiles
    ''' <summary>The Scenes menu, the scene given at start, and Restart's start.</summary>
    Private ReadOnly _lessons As LessonBook
    ''' <summary>Stepping, going back and the timeline: the recorded run.</summary>
    Private ReadOnly _time As TimeMachine
    ''' <summary>How long a frame may spend advancing the world, and what it held back.</summary>
    Private ReadOnly _pacer As FramePacer
    ''' <summary>Values typed into the tables.</summary>
    Private ReadOnly _editor As TableEditor
    ''' <summary>What the mouse does on the canvas: placing, deleting, carrying, the cue, and the ramp, link and corner tools.</summary>
    Private ReadOnly _pointer As PointerTools
    ''' <summary>Undo and redo of the edits.</summary>
    Private ReadOnly _history As EditHistory
    ''' <summary>Heat, cool, and balls added or removed at the gas's temperature.</summary>
    Private ReadOnly _gas As GasControls
    ''' <summary>Zoom, pan and follow.</summary>
    Private ReadOnly _camera As CameraView
    ''' <summary>Gravity, restitution, speed, the container and its walls.</summary>
    Private ReadOnly _settings As WorldSettings
    ''' <summary>The whole container fitted in the canvas: what the camera zooms from.</summary>
    Private _fitted As ViewTransform
    Private _canvasWidth As Integer = 800
    Private _canvasHeight As Integer = 500
    Private _sinceSnapshot As Double
    ''' <summary>The solver new scenes and Restart start with (see <see cref="ChooseSolver"/>).</summary>
    Private _solverChoice As String = SolverChoice.Automatic

    ''' <param name="view">the window (or a test's recorder)</param>
    ''' <param name="store">reads and writes scene files; Nothing when this build has none</param>
    ''' <param name="world">the opening scene; Nothing for <see cref="Scenarios.Demo"/></param>
    ''' <param name="colourSeed">seed of the random colours of new bodies</param>
    Public Sub New(view As ISimulationView, Optional store As ISceneStore = Nothing, Optional world As World = Nothing,
                   Optional colourSeed As Integer = 12345)
        If view Is Nothing Then Throw New ArgumentNullException(NameOf(view))
        _window = view
        _stage = New Stage(view)
        _history = New EditHistory(_stage, Function() _time.Checkpoint(), AddressOf PutBack)
        _pointer = New PointerTools(_stage, _history, Function() Me.View, Function() ScreenScale, Function() Speed, colourSeed,
                                    Function() If(ShowArrows, Arrows.Seconds, 0.0))
        _stage.Connect(AddressOf TakeSnapshot, AddressOf _pointer.EndGestures, AddressOf Present, Function() _pointer.DraggedBody IsNot Nothing)
        _graphs = New GraphRecorder(_stage)
        _export = New ExportWriter(_stage, _graphs)
        _momentum = New MomentumViews(_stage, Function() MomentumRoomPixels)
        _files = New SceneFiles(_stage, store)
        _lessons = New LessonBook(_stage, _files)
        _gas = New GasControls(_stage, _history, colourSeed + 1)
        _camera = New CameraView(_stage)
        _settings = New WorldSettings(_stage, _history, AddressOf FitView, Sub() _lessons.NoteBuilding())
        _editor = New TableEditor(_stage, _history, Function() Snapshot, Sub() _lessons.RememberStart())
        _pacer = New FramePacer(_stage, Function() Speed, Function(seconds, wall) _time.Advance(seconds, wall))
        _time = New TimeMachine(_stage, Function() FrameBudgetSeconds,
                                Sub(r)
                                    _graphs.GraphCollision(r)
                                    _momentum.NoteImpulses(r)
                                End Sub,
                                AddressOf WorldTaken, AddressOf AfterJump)
        Attach(If(world, Scenarios.Demo()))
    End Sub

    ''' <summary>The world being shown. Replaced when a scene is opened. The window draws it; it never changes it.</summary>
    Public ReadOnly Property World As World
        Get
            Return _stage.World
        End Get
    End Property

    ''' <summary>Reads and writes scene files; Nothing disables Open and Save with a message.</summary>
    Public Property SceneStore As ISceneStore
        Get
            Return _files.SceneStore
        End Get
        Set(value As ISceneStore)
            _files.SceneStore = value
        End Set
    End Property

    ''' <summary>Receives one line per action and state change (the app's --trace switch prints them).</summary>
    Public Property Trace As Action(Of String)
        Get
            Return _stage.Trace
        End Get
        Set(value As Action(Of String))
            _stage.Trace = value
        End Set
    End Property

    ''' <summary>The last collisions, newest first.</summary>
    Public ReadOnly Property Log As CollisionLog
        Get
            Return _stage.Log
        End Get
    End Property

    ''' <summary>The text of the input boxes, as typed.</summary>
    Public ReadOnly Property Inputs As BodyInputs
        Get
            Return _stage.Inputs
        End Get
    End Property

    ''' <summary>What the message box shows when there is no message: how to use the mouse.</summary>
    Public Const MouseHint As String = "Right-drag carries a body. Left-drag back from a moving body and let go to fire it like a cue."

    ''' <summary>The message on show ("" for none).</summary>
    Public ReadOnly Property Message As String
        Get
            Return _stage.Message
        End Get
    End Property

    ''' <summary>True while time is stopped.</summary>
    Public ReadOnly Property IsPaused As Boolean
        Get
            Return _stage.IsPaused
        End Get
    End Property

    ''' <summary>What a left click on a body does.</summary>
    Public ReadOnly Property Mode As ClickMode
        Get
            Return _pointer.Mode
        End Get
    End Property

    ''' <summary>Bigger text everywhere, for projectors.</summary>
    Public ReadOnly Property LargeFonts As Boolean

    ''' <summary>The dark, high-contrast theme (canvas and controls).</summary>
    Public ReadOnly Property HighContrast As Boolean

    ''' <summary>Whether velocity arrows (with components) are drawn.</summary>
    Public ReadOnly Property ShowArrows As Boolean = True

    ''' <summary>Whether the grid (1 m and 10 cm lines) is drawn under the bodies.</summary>
    Public ReadOnly Property ShowGrid As Boolean

    ''' <summary>The grid's lines to draw now (none while the grid is off): see <see cref="CanvasGrid.Lines"/>.</summary>
    Public Function GridLines() As IReadOnlyList(Of GridLine)
        If Not ShowGrid Then Return Array.Empty(Of GridLine)()
        Return CanvasGrid.Lines(World.Width, World.Height, View, _canvasWidth, _canvasHeight, ScreenScale)
    End Function

    ''' <summary>The colours in use.</summary>
    Public ReadOnly Property Theme As Theme
        Get
            Return If(HighContrast, Theme.Dark, Theme.Light)
        End Get
    End Property

    ''' <summary>Metres ↔ canvas pixels for the current container and canvas size.</summary>
    Public ReadOnly Property View As ViewTransform

    ''' <summary>The velocity arrows' scale, following the scene.</summary>
    Public ReadOnly Property Arrows As New ArrowScale()

    ''' <summary>The tables and totals of the last snapshot: what the window shows under the canvas.</summary>
    Public ReadOnly Property Snapshot As TableSnapshot

    ''' <summary>The tables under the canvas, in tab order.</summary>
    Public Shared ReadOnly Property Tables As IReadOnlyList(Of BodyTable)
        Get
            Return BodyTable.All
        End Get
    End Property

    ''' <summary>The totals line as one string (the items of <see cref="Snapshot"/>, spaced).</summary>
    Public ReadOnly Property TotalsText As String
        Get
            Return String.Join("    ", Snapshot.Totals)
        End Get
    End Property

    ''' <summary>Whether the container's sides reflect balls (drawn solid) or not (drawn faint and dashed).</summary>
    Public ReadOnly Property HasWalls As Boolean
        Get
            Return World.Walls
        End Get
    End Property

    ''' <summary>
    ''' Called once per frame with the real time since the last frame, s. The advance keeps to the
    ''' frame's budget (see <see cref="FrameBudgetSeconds"/>); the rest of this call's time counts as
    ''' the frame's other work, for the next frames' budget.
    ''' </summary>
    Public Sub Tick(realSeconds As Double)
        If Not (realSeconds > 0) OrElse Double.IsInfinity(realSeconds) Then Return
        Dim frameStart = _pacer.ClockSeconds()
        _pacer.Budget.NextFrame()
        Dim advancing = 0.0 ' wall-clock s
        Dim dt = Math.Min(realSeconds, MaxFrameSeconds)
        If Not IsPaused Then
            Try
                _pointer.CarryTowardsCursor(dt)
                Dim asked = dt * Speed
                Dim advanceStart = _pacer.ClockSeconds()
                Dim done = _pacer.AdvanceWithinBudget(asked)
                advancing = _pacer.ClockSeconds() - advanceStart
                _pacer.NoteAdvance(asked, done)
            Catch ex As ArgumentException
                Fail("The simulation stopped: " & ex.Message)
            Catch ex As InvalidOperationException
                Fail("The simulation stopped: " & ex.Message)
            Catch ex As ArithmeticException
                ' Overflow or a non-finite number from an extreme scene: pause with a message, never crash.
                Fail("The simulation stopped: " & ex.Message)
            End Try
            Log.EndFrame()
            _graphs.SampleGraphs()
            FollowMeasures()
            FollowForcesRest()
        End If
        _momentum.FollowMomentumViews(realSeconds, Not IsPaused)
        ' A followed body moves: the view moves with it (not written to the trace every frame).
        If _camera.Followed IsNot Nothing Then ApplyCamera(announce:=False)
        _sinceSnapshot += realSeconds
        If _sinceSnapshot >= SnapshotSeconds AndAlso Not IsPaused Then TakeSnapshot()
        CheckMessage()
        _pacer.Budget.AddOtherWork(_pacer.ClockSeconds() - frameStart - advancing)
    End Sub

    Private Sub Fail(text As String)
        _stage.IsPaused = True
        _pointer.EndGestures()
        ShowMessage(text)
        TakeSnapshot()
        _window.ShowSettings()
    End Sub

    ''' <summary>Runs one of the teacher's actions; anything the engine refuses becomes a message (see <see cref="Stage.Guarded"/>).</summary>
    Private Sub Guarded(action As Action)
        _stage.Guarded(action)
    End Sub

    ''' <summary>Copies the world's state for the tables and totals, follows it with the arrows' scale, and tells the window.</summary>
    Private Sub TakeSnapshot()
        _sinceSnapshot = 0
        _lessons.NoteBuilding()
        _Snapshot = TableSnapshot.Take(World, Log.TotalSeen)
        _graphs.SampleGraphs()
        ' A step, a scrub or an edit moves time too: the pass timer sees it.
        FollowMeasures()
        ' While a velocity arrow is dragged its scale stays put, so its tip stays under the cursor.
        If _pointer.ArrowBody Is Nothing Then Arrows.Update(Snapshot.FastestSpeed, 0.25 * Math.Min(World.Width, World.Height))
        _window.ShowState()
        CheckMessage()
    End Sub

    ''' <summary>The canvas changed size, px.</summary>
    Public Sub CanvasResized(width As Integer, height As Integer)
        _canvasWidth = Math.Max(1, width)
        _canvasHeight = Math.Max(1, height)
        FitView()
    End Sub

    ''' <summary>Height of the strip under the container that holds the scale bar and the arrow key, px at 96 dpi.</summary>
    Public Const ScaleStrip As Integer = 34

    ''' <summary>Pixels per 96-dpi pixel of the window's screen (2 at 192 dpi): the strip and margins grow with it.</summary>
    Public Property ScreenScale As Double = 1.0

    ''' <summary>Height of the scale strip on this screen, px.</summary>
    Public ReadOnly Property ScaleStripPixels As Integer
        Get
            Return CInt(Math.Round(ScaleStrip * ScreenScale * If(LargeFonts, 1.3, 1.0)))
        End Get
    End Property

    Private Sub FitView()
        ' The container sits above a strip kept free for the scale bar.
        ' With a momentum view on, the momentum panel has a column of its own at the right: it never covers the container.
        _fitted = ViewTransform.Fit(World.Width, World.Height, Math.Max(1, _canvasWidth - CInt(MomentumPanelPixels)), Math.Max(1, _canvasHeight - ScaleStripPixels), CInt(16 * ScreenScale))
        ApplyCamera(announce:=True)
    End Sub

    ''' <summary>The view through the camera (zoom, pan, follow); with <paramref name="announce"/>, a new view is written to the trace.</summary>
    Private Sub ApplyCamera(announce As Boolean)
        Dim before = _View
        ' A followed body that is gone (deleted, a new scene without it) is followed no more.
        If _camera.Followed IsNot Nothing AndAlso Not World.Bodies.Any(Function(b) ReferenceEquals(b, _camera.Followed)) Then _camera.Follow(Nothing)
        _View = _camera.Apply(_fitted)
        If announce AndAlso (before Is Nothing OrElse before.Scale <> _View.Scale OrElse before.OffsetX <> _View.OffsetX OrElse before.OffsetY <> _View.OffsetY) Then
            Emit("view scale " & Units.Num(_View.Scale, 4) & " origin " & Units.Num(_View.OffsetX, 2) & " " & Units.Num(_View.OffsetY, 2))
        End If
    End Sub

    ''' <summary>Pauses or resumes. On pausing, the trace lists every movable body's state.</summary>
    Public Sub TogglePause()
        Guarded(
            Sub()
                _stage.IsPaused = Not _stage.IsPaused
                _pointer.PauseChanged()
                TakeSnapshot()
                If _stage.IsPaused Then
                    Emit("paused t=" & Units.Num(World.Time, 3) & " s")
                    For Each c In World.Circles
                        If Not c.IsFixed Then Emit("body " & c.Id & " at " & Units.Pair(c.Position, 3) & " m v " & Units.Pair(c.Velocity, 3) & " m/s")
                    Next
                    For Each b In World.Movables
                        If b.Kind <> ShapeKind.Circle Then Emit("body " & b.Id & " at " & Units.Pair(b.CentreOfMass, 3) & " m v " & Units.Pair(b.Velocity, 3) & " m/s")
                    Next
                    _momentum.EmitMomentumViews()
                    EmitScreenCheck()
                Else
                    Emit("resumed")
                End If
                _window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>Removes every body and sets e = 1, g = 9.81 m/s² and real-time speed. The container keeps its size.</summary>
    Public Sub Reset()
        Guarded(
            Sub()
                _pointer.Reset()
                Dim before = _history.Capture()
                World.Clear()
                _settings.ToDefaults()
                Log.Clear()
                _momentum.ForgetMomentumViews()
                Emit("reset: " & World.Bodies.Count & " bodies, g " & Units.Num(World.Gravity) & ", e " & Units.Num(World.Restitution) & ", speed " & SpeedSteps.Label(Speed))
                _history.Commit("Reset", before, withSettings:=True)
                ShowMessage("")
                TakeSnapshot()
                _window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>Switches between moving and deleting.</summary>
    Public Sub ToggleDeleteMode()
        _pointer.ToggleDeleteMode()
    End Sub

    ''' <summary>A text box changed: keeps what was typed, exactly.</summary>
    Public Sub InputChanged(field As InputField, text As String)
        Inputs(field) = text
    End Sub

    ''' <summary>The Fixed box was ticked or cleared.</summary>
    Public Sub FixedChanged(isFixed As Boolean)
        Inputs.IsFixed = isFixed
        Emit("fixed " & If(isFixed, "on", "off"))
        _window.ShowSettings()
    End Sub

    ''' <summary>Bigger text, for projectors.</summary>
    Public Sub SetLargeFonts(value As Boolean)
        _LargeFonts = value
        Emit("large fonts " & If(value, "on", "off"))
        FitView()
        _window.ShowTheme()
    End Sub

    ''' <summary>The dark, high-contrast theme.</summary>
    Public Sub SetHighContrast(value As Boolean)
        _HighContrast = value
        Emit("high contrast " & If(value, "on", "off"))
        _window.ShowTheme()
    End Sub

    ''' <summary>The grid on or off: a line every metre and every 10 cm under the bodies, to read positions off the canvas.</summary>
    Public Sub SetShowGrid(value As Boolean)
        _ShowGrid = value
        Emit("grid " & If(value, "on", "off"))
        _window.ShowTheme()
    End Sub

    ''' <summary>Velocity arrows on or off.</summary>
    Public Sub SetShowArrows(value As Boolean)
        _ShowArrows = value
        Emit("arrows " & If(value, "on", "off"))
        _window.ShowTheme()
    End Sub

    ''' <summary>The message while Delete mode is on.</summary>
    Public Const DeleteModeMessage As String = PointerTools.DeleteModeMessage

    ''' <summary>"❚❚ Pause" or "▶ Resume".</summary>
    Public ReadOnly Property PauseText As String
        Get
            Return If(IsPaused, ResumeCaption, PauseCaption)
        End Get
    End Property

    ''' <summary>The pause button's caption while time runs.</summary>
    Public Const PauseCaption As String = "❚❚ Pause"
    ''' <summary>The pause button's caption while paused.</summary>
    Public Const ResumeCaption As String = "▶ Resume"
    ''' <summary>The captions the Delete mode button shows, off and on (the layout leaves room for the longer).</summary>
    Public Shared ReadOnly Property DeleteModeCaptions As String()
        Get
            Return {PointerTools.DeleteModeOffCaption, PointerTools.DeleteModeOnCaption}
        End Get
    End Property

    ''' <summary>"Delete mode" or "Delete mode: ON".</summary>
    Public ReadOnly Property DeleteModeText As String
        Get
            Return _pointer.DeleteModeText
        End Get
    End Property

    ''' <summary>Shows a message (see <see cref="Stage.ShowMessage"/>).</summary>
    Private Sub ShowMessage(text As String, Optional holds As Func(Of Boolean) = Nothing)
        _stage.ShowMessage(text, holds)
    End Sub

    ''' <summary>A message that is no longer true goes (see <see cref="Stage.CheckMessage"/>).</summary>
    Private Sub CheckMessage()
        _stage.CheckMessage()
    End Sub

    Private Sub Emit(line As String)
        _stage.Emit(line)
    End Sub

    ''' <summary>
    ''' With a trace: a check of the scene and of every text the window shows now, for tests (is any
    ''' body where a file would refuse it; does any text read "NaN" or "∞").
    ''' </summary>
    Private Sub EmitScreenCheck()
        If Trace Is Nothing Then Return
        Dim problem = Placement.FindProblem(World)
        Emit("check scene " & If(problem, "ok"))
        Dim texts As New List(Of String) From {Message, TotalsText, SpeedText, GravityText, RestitutionText, _pointer.CueLabel}
        For t = 0 To Tables.Count - 1
            For i = 0 To Snapshot.RowCount(t) - 1
                texts.AddRange(Snapshot.Cells(t, i))
            Next
        Next
        For i = 0 To Snapshot.LinkCount - 1
            texts.AddRange(Snapshot.LinkCells(i))
        Next
        For i = 0 To Log.Count - 1
            texts.AddRange(Log(i).Cells())
        Next
        Dim bad = texts.FirstOrDefault(Function(s) s IsNot Nothing AndAlso (s.Contains("NaN") OrElse s.Contains("∞"c) OrElse s.Contains("not a number")))
        Emit("check texts " & If(bad Is Nothing, "ok", "bad: " & bad))
    End Sub

    Private Shared Function Problems(ParamArray inputs As NumberInput()) As String
        Return Stage.Problems(inputs)
    End Function

    Private Shared Function OneLine(text As String) As String
        Return Stage.OneLine(text)
    End Function

    ''' <summary>
    ''' A moment of the recorded run was put on show (going back, or replaying onto a checkpoint): a
    ''' cue being aimed keeps aiming at the same body of the new world, Restart keeps the start it had
    ''' (going back is not building), and a container of another size is shown in its boxes and the view.
    ''' </summary>
    Private Sub WorldTaken(w As World, resized As Boolean)
        _pointer.FollowWorld(w)
        _camera.FollowWorld(w)
        _lessons.FollowWorld(w)
        ' Going back to before friction was set: the boxes show the friction of the moment on show.
        If _settings.FollowFriction() AndAlso Not resized Then _window.ShowInputs()
        If resized Then
            Inputs.ContainerWidthText = Units.Input(w.Width)
            Inputs.ContainerHeightText = Units.Input(w.Height)
            FitView()
            _window.ShowInputs()
        End If
    End Sub

    ''' <summary>The moment on show was reached by a jump (a scrub, a step back): only the last instant's impulses are drawn.</summary>
    Private Sub AfterJump()
        _momentum.Impulses.KeepLatestInstant(World)
    End Sub

    ''' <summary>Undo or Redo puts the world of <paramref name="point"/> back on show: the gestures end, and the run goes on from it (see <see cref="EditHistory"/>).</summary>
    Private Sub PutBack(point As Checkpoint, withSettings As Boolean)
        _pointer.DropAll()
        Dim friction = World.Friction, staticFriction = World.StaticFriction, air = World.AirDensity
        _time.PutBack(point, withSettings)
        ' Friction and the air are settings like gravity: they stay as set (unless the edit set them too: Reset).
        If Not withSettings Then
            WorldSettings.KeepFriction(World, friction, staticFriction)
            If World.AirDensity <> air Then World.AirDensity = air
        End If
        _settings.ShowFriction()
        ' Undoing is building: Restart comes back to what is on show now.
        _lessons.RememberStart()
        TakeSnapshot()
        _window.ShowInputs()
        _window.ShowSettings()
    End Sub

    ''' <summary>Puts a new world on show: the gestures end, the body being placed is dropped, a new run starts with it.</summary>
    Private Sub Present(w As World)
        _pointer.DropAll()
        _history.Clear()
        _camera.Reset()
        Attach(w)
    End Sub

    ''' <summary>Makes <paramref name="w"/> the world on show: solver, collision log, colours, view, tables.</summary>
    Private Sub Attach(w As World)
        _time.StartTimeline(w, SolverFactory.Create(_solverChoice))
        For Each b In w.Bodies
            ' A body without a colour in its file gets the same one every time: it follows from the id.
            If String.IsNullOrEmpty(b.Color) Then b.Color = BodyColours.ForId(b.Id)
        Next
        _momentum.ForgetMomentumViews()
        ForgetMeasures()
        _stage.World = w
        Log.Clear()
        Inputs.ContainerWidthText = Units.Input(w.Width)
        Inputs.ContainerHeightText = Units.Input(w.Height)
        _settings.ShowFriction()
        FitView()
        _Snapshot = TableSnapshot.Take(w, 0)
        Arrows.Update(Snapshot.FastestSpeed, 0.25 * Math.Min(w.Width, w.Height))
        _lessons.RememberStart()
        ' The run's first checkpoint (the scene written out) now, as part of opening it, rather than in
        ' its first frame: it costs about a frame's time in a scene of hundreds of bodies.
        TryCast(w.Solver, TimelineSolver)?.CheckpointIfChanged()
    End Sub

#Region "The Graphs tab (GraphRecorder)"
    ''' <summary>Kinetic energy's colour on the graphs (red).</summary>
    Public Const KineticColour As Integer = GraphRecorder.KineticColour
    ''' <summary>Potential energy's colour on the graphs (green).</summary>
    Public Const PotentialColour As Integer = GraphRecorder.PotentialColour
    ''' <summary>Total energy's and the measured pressure's colour on the graphs (blue).</summary>
    Public Const TotalColour As Integer = GraphRecorder.TotalColour
    ''' <summary>The theory curves' colour on the graphs (orange).</summary>
    Public Const TheoryColour As Integer = GraphRecorder.TheoryColour

    ''' <summary>The graph the Graphs tab shows.</summary>
    Public ReadOnly Property Graph As GraphKind
        Get
            Return _graphs.Graph
        End Get
    End Property

    ''' <summary>The totals recorded as time runs.</summary>
    Public ReadOnly Property Series As SeriesRecorder
        Get
            Return _graphs.Series
        End Get
    End Property

    ''' <summary>The wall pressure measured since the gas last changed (Nothing before the first frame).</summary>
    Public ReadOnly Property Pressure As WallPressure
        Get
            Return _graphs.Pressure
        End Get
    End Property

    ''' <summary>Simulated time the pressure gauge was last started, s.</summary>
    Public ReadOnly Property PressureStart As Double
        Get
            Return _graphs.PressureStart
        End Get
    End Property

    ''' <summary>The graphs' names in the Graphs tab's chooser, in <see cref="GraphKind"/> order.</summary>
    Public Shared ReadOnly Property GraphNames As IReadOnlyList(Of String) = GraphRecorder.Names

    ''' <summary>The tutorial's page on graphs and exports.</summary>
    Public Shared ReadOnly Property GraphsHelp As HelpTopic = GraphRecorder.GraphsHelp

    ''' <summary>The Maths used pages on the gas graphs.</summary>
    Public Shared ReadOnly Property GraphsMaths As IReadOnlyList(Of HelpTopic) = GraphRecorder.GraphsMaths

    ''' <summary>Shows another graph.</summary>
    Public Sub ChooseGraph(kind As GraphKind)
        _graphs.ChooseGraph(kind)
    End Sub

    ''' <summary>The graph on show, built from what has been recorded.</summary>
    Public Function CurrentGraph() As GraphPlot
        Return _graphs.CurrentGraph()
    End Function

    ''' <summary>The speeds now as a histogram with the 2D Maxwell–Boltzmann curve (see <see cref="GraphRecorder.HistogramGraph"/>).</summary>
    Public Shared Function HistogramGraph(gas As GasState) As GraphPlot
        Return GraphRecorder.HistogramGraph(gas)
    End Function
#End Region

#Region "The Export menu (ExportWriter)"
    ''' <summary>The Export button's caption.</summary>
    Public Const ExportCaption As String = ExportWriter.ExportCaption

    ''' <summary>The Export menu's items, in <see cref="ExportKind"/> order.</summary>
    Public Shared ReadOnly Property ExportNames As IReadOnlyList(Of String) = ExportWriter.Names

    ''' <summary>The series CSV's header: the command line's --series columns, each with its unit.</summary>
    Public Shared ReadOnly Property SeriesHeader As IReadOnlyList(Of String) = ExportWriter.SeriesHeader

    ''' <summary>The file name the Save dialog suggests for an export.</summary>
    Public Function ExportFileName(kind As ExportKind) As String
        Return _export.ExportFileName(kind)
    End Function

    ''' <summary>The Bodies table as CSV: every body, numbers in SI units at full precision.</summary>
    Public Function BodiesCsv() As String
        Return _export.BodiesCsv()
    End Function

    ''' <summary>The collision log as CSV, oldest row first.</summary>
    Public Function LogCsv() As String
        Return _export.LogCsv()
    End Function

    ''' <summary>The graph on show as CSV.</summary>
    Public Function SeriesCsv() As String
        Return _export.SeriesCsv()
    End Function

    ''' <summary>Writes a CSV export to <paramref name="path"/>; says what was written, or why not.</summary>
    Public Sub ExportCsv(kind As ExportKind, path As String)
        _export.ExportCsv(kind, path)
    End Sub

    ''' <summary>Writes a picture the window drew (PNG) to <paramref name="path"/> through <paramref name="write"/>; says what was written, or why not.</summary>
    Public Sub ExportPicture(kind As ExportKind, path As String, write As Action(Of IO.Stream), width As Integer, height As Integer)
        _export.ExportPicture(kind, path, write, width, height)
    End Sub
#End Region

#Region "Seeing momentum (MomentumViews), and the walls"
    ''' <summary>
    ''' The width of the column at the right of the canvas that holds the momentum panel (the momenta
    ''' diagram and the momentum arrows' key) while a momentum view is on, px; 0 otherwise. The
    ''' container is fitted left of it, so the panel never covers the container's corner.
    ''' </summary>
    Public ReadOnly Property MomentumPanelPixels As Double
        Get
            If Not ShowsMomentumArrows Then Return 0
            Dim room = MomentumRoomPixels
            Dim text = 150 * ScreenScale * If(LargeFonts, 1.4, 1.0)
            Return Math.Max(If(ShowMomentaDiagram, 1.25 * room, 0), 0.6 * room + text) + 28 * ScreenScale
        End Get
    End Property

    ''' <summary>
    ''' Where every label of the canvas goes (ids, CM, Σp, Δp), none over another, a body or the
    ''' momentum panel (see <see cref="CanvasLabelLayout"/>), for a canvas of <paramref name="width"/>
    ''' × <paramref name="height"/> px and labels the size <paramref name="measure"/> gives, px.
    ''' </summary>
    Public Function LayOutLabels(measure As Func(Of String, (Width As Double, Height As Double)), width As Integer, height As Integer) As IReadOnlyList(Of CanvasLabel)
        Return CanvasLabelLayout.Lay(Me, measure, ScreenScale, width, height)
    End Function

    ''' <summary>The longest a momentum arrow may be drawn, px: a fifth of the canvas's smaller side.</summary>
    Public ReadOnly Property MomentumRoomPixels As Double
        Get
            Return 0.2 * Math.Min(_canvasWidth, Math.Max(1, _canvasHeight - ScaleStripPixels))
        End Get
    End Property

    ''' <summary>The tutorial's page on the momentum views, the walls toggle and typing into the tables.</summary>
    Public Shared ReadOnly Property MomentumHelp As HelpTopic = MomentumViews.MomentumHelp

    ''' <summary>The maths page on the momentum views.</summary>
    Public Shared ReadOnly Property MomentumMaths As HelpTopic = MomentumViews.MomentumMaths

    ''' <summary>Whether the centre of mass of the movable bodies is marked, with its velocity arrow.</summary>
    Public ReadOnly Property ShowCentreOfMass As Boolean
        Get
            Return _momentum.ShowCentreOfMass
        End Get
    End Property

    ''' <summary>Whether the total momentum Σp is drawn as an arrow from the centre of mass.</summary>
    Public ReadOnly Property ShowTotalMomentum As Boolean
        Get
            Return _momentum.ShowTotalMomentum
        End Get
    End Property

    ''' <summary>Whether the momenta diagram is drawn in a corner of the canvas.</summary>
    Public ReadOnly Property ShowMomentaDiagram As Boolean
        Get
            Return _momentum.ShowMomentaDiagram
        End Get
    End Property

    ''' <summary>Whether each collision's impulses Δp are drawn for a moment at the contact.</summary>
    Public ReadOnly Property ShowImpulses As Boolean
        Get
            Return _momentum.ShowImpulses
        End Get
    End Property

    ''' <summary>Whether bodies leave fading traces of where they have been.</summary>
    Public ReadOnly Property ShowTraces As Boolean
        Get
            Return _momentum.ShowTraces
        End Get
    End Property

    ''' <summary>The impulses on show.</summary>
    Public ReadOnly Property Impulses As ImpulseMarks
        Get
            Return _momentum.Impulses
        End Get
    End Property

    ''' <summary>The path traces.</summary>
    Public ReadOnly Property Traces As PathTraces
        Get
            Return _momentum.Traces
        End Get
    End Property

    ''' <summary>The momentum arrows' scale (Σp, the diagram and the impulses share it).</summary>
    Public ReadOnly Property MomentumArrows As MomentumScale
        Get
            Return _momentum.MomentumArrows
        End Get
    End Property

    ''' <summary>The centre of mass, total mass and total momentum of the movable bodies now.</summary>
    Public ReadOnly Property Momentum As MomentumSummary
        Get
            Return _momentum.Momentum
        End Get
    End Property

    ''' <summary>The momenta diagram of the movable bodies now.</summary>
    Public Function Momenta() As MomentaDiagram
        Return _momentum.Momenta()
    End Function

    ''' <summary>Whether any momentum view needs the momentum scale (and its key) drawn.</summary>
    Public ReadOnly Property ShowsMomentumArrows As Boolean
        Get
            Return _momentum.ShowsMomentumArrows
        End Get
    End Property

    ''' <summary>The centre-of-mass marker and its velocity arrow on or off.</summary>
    Public Sub SetShowCentreOfMass(value As Boolean)
        _momentum.SetShowCentreOfMass(value)
        FitView()
    End Sub

    ''' <summary>The total-momentum arrow on or off.</summary>
    Public Sub SetShowTotalMomentum(value As Boolean)
        _momentum.SetShowTotalMomentum(value)
        FitView()
    End Sub

    ''' <summary>The momenta diagram on or off.</summary>
    Public Sub SetShowMomentaDiagram(value As Boolean)
        _momentum.SetShowMomentaDiagram(value)
        FitView()
    End Sub

    ''' <summary>The impulse arrows on or off.</summary>
    Public Sub SetShowImpulses(value As Boolean)
        _momentum.SetShowImpulses(value)
        FitView()
    End Sub

    ''' <summary>Path traces on or off.</summary>
    Public Sub SetShowTraces(value As Boolean)
        _momentum.SetShowTraces(value)
        FitView()
    End Sub
#End Region

#Region "Scene files (SceneFiles) and lessons (LessonBook)"
    ''' <summary>True when Open and Save can work (a scene store is present).</summary>
    Public ReadOnly Property CanOpenAndSave As Boolean
        Get
            Return _files.CanOpenAndSave
        End Get
    End Property

    ''' <summary>The folder the Open and Save dialogs start in: the example scenes at first, then the last one used.</summary>
    Public Property SceneFolder As String
        Get
            Return _files.SceneFolder
        End Get
        Set(value As String)
            _files.SceneFolder = value
        End Set
    End Property

    ''' <summary>Opens the scene file at <paramref name="path"/>; on any problem shows a message and keeps the current scene.</summary>
    Public Sub OpenScene(path As String)
        _files.OpenScene(path)
    End Sub

    ''' <summary>Saves the scene to <paramref name="path"/>; on any problem shows a message naming the file and why.</summary>
    Public Sub SaveScene(path As String)
        _files.SaveScene(path)
    End Sub

    ''' <summary>The Scenes menu's button.</summary>
    Public Const ScenesCaption As String = LessonBook.ScenesCaption
    ''' <summary>The Restart button.</summary>
    Public Const RestartCaption As String = LessonBook.RestartCaption
    ''' <summary>Pause's key.</summary>
    Public Const PauseKey As String = LessonBook.PauseKey
    ''' <summary>Restart's key.</summary>
    Public Const RestartKey As String = LessonBook.RestartKey
    ''' <summary>Reset's key: with Shift, so clearing everything is never a slip of the finger.</summary>
    Public Const ResetKey As String = LessonBook.ResetKey
    ''' <summary>The Scenes menu's key.</summary>
    Public Const ScenesKey As String = LessonBook.ScenesKey

    ''' <summary>The tutorial's page on lessons, Restart and the keys.</summary>
    Public Shared ReadOnly Property LessonsHelp As HelpTopic = LessonBook.LessonsHelp

    ''' <summary>The folder the Scenes menu lists (the example scenes); Nothing for none.</summary>
    Public Property LessonFolder As String
        Get
            Return _lessons.LessonFolder
        End Get
        Set(value As String)
            _lessons.LessonFolder = value
        End Set
    End Property

    ''' <summary>The Scenes menu, read from <see cref="LessonFolder"/> now.</summary>
    Public Function Lessons() As IReadOnlyList(Of Lesson)
        Return _lessons.Lessons()
    End Function

    ''' <summary>The Scenes menu by topic, read from <see cref="LessonFolder"/> now.</summary>
    Public Function LessonMenu() As IReadOnlyList(Of (Topic As String, Lessons As IReadOnlyList(Of Lesson)))
        Return _lessons.LessonMenu()
    End Function

    ''' <summary>Opens a lesson from the Scenes menu; the message gives its title and what it shows.</summary>
    Public Sub OpenLesson(lesson As Lesson)
        _lessons.OpenLesson(lesson)
    End Sub

    ''' <summary>Opens the file given on the command line; one that cannot be opened leaves an empty box and the message why.</summary>
    Public Sub OpenAtStart(path As String)
        _lessons.OpenAtStart(path)
    End Sub

    ''' <summary>Puts the scene back as it was when it was opened or last built.</summary>
    Public Sub Restart()
        _lessons.Restart()
    End Sub
#End Region

#Region "Stepping and going back in time (TimeMachine)"
    ''' <summary>One frame of simulated time, s (what Step and Step back move by).</summary>
    Public Const FrameSeconds As Double = TimeMachine.FrameSeconds
    ''' <summary>The most frames a step to the next collision looks ahead (10 s of simulated time).</summary>
    Public Const MaxFramesToCollision As Integer = TimeMachine.MaxFramesToCollision
    ''' <summary>The timeline slider's positions.</summary>
    Public Const TimelineSteps As Integer = TimeMachine.TimelineSteps
    ''' <summary>Keys of the time controls, as the tutorial and the tooltips name them.</summary>
    Public Const StepKey As String = TimeMachine.StepKey
    ''' <summary>See <see cref="StepKey"/>.</summary>
    Public Const StepBackKey As String = TimeMachine.StepBackKey
    ''' <summary>See <see cref="StepKey"/>.</summary>
    Public Const NextCollisionKey As String = TimeMachine.NextCollisionKey
    ''' <summary>See <see cref="StepKey"/>.</summary>
    Public Const PreviousCollisionKey As String = TimeMachine.PreviousCollisionKey
    ''' <summary>Button captions of the time controls.</summary>
    Public Const StepBackCaption As String = TimeMachine.StepBackCaption
    ''' <summary>See <see cref="StepBackCaption"/>.</summary>
    Public Const StepCaption As String = TimeMachine.StepCaption
    ''' <summary>See <see cref="StepBackCaption"/>.</summary>
    Public Const PreviousCollisionCaption As String = TimeMachine.PreviousCollisionCaption
    ''' <summary>See <see cref="StepBackCaption"/>.</summary>
    Public Const NextCollisionCaption As String = TimeMachine.NextCollisionCaption
    ''' <summary>The time controls' keys, as the tutorial lists them beside the others.</summary>
    Public Const TimeKeysText As String = TimeMachine.TimeKeysText

    ''' <summary>The tutorial's page on the time controls.</summary>
    Public Shared ReadOnly Property TimeTravelHelp As HelpTopic = TimeMachine.TimeTravelHelp

    ''' <summary>The recorded run of the world on show.</summary>
    Public ReadOnly Property Timeline As Timeline
        Get
            Return _time.Timeline
        End Get
    End Property

    ''' <summary>Step: pauses, then moves one frame (1/60 s) on.</summary>
    Public Sub StepFrame()
        _time.StepFrame()
    End Sub

    ''' <summary>Step back: pauses, then goes one frame (1/60 s) back, or to the earliest moment kept.</summary>
    Public Sub StepBackFrame()
        _time.StepBackFrame()
    End Sub

    ''' <summary>Step to the next collision: pauses and runs on until the next collision (at most 10 s ahead).</summary>
    Public Sub StepToNextCollision()
        _time.StepToNextCollision()
    End Sub

    ''' <summary>Step back a collision: pauses and goes back to the last collision before now (just after it).</summary>
    Public Sub StepToPreviousCollision()
        _time.StepToPreviousCollision()
    End Sub

    ''' <summary>The timeline slider was moved to <paramref name="position"/> (0 to <see cref="TimelineSteps"/>).</summary>
    Public Sub TimelineSliderMoved(position As Integer)
        _time.TimelineSliderMoved(position)
    End Sub

    ''' <summary>Pauses and shows the run as it was at <paramref name="time"/> (s), within the timeline.</summary>
    Public Sub RewindTo(time As Double)
        _time.RewindTo(time)
    End Sub

    ''' <summary>Where the timeline slider's thumb belongs: the time on show within the timeline.</summary>
    Public ReadOnly Property TimelinePosition As Integer
        Get
            Return _time.TimelinePosition
        End Get
    End Property

    ''' <summary>"Timeline: t = 3.20 s (kept 0 – 12.0 s)": the slider's tip.</summary>
    Public ReadOnly Property TimelineText As String
        Get
            Return _time.TimelineText
        End Get
    End Property
#End Region

#Region "The frame budget (FramePacer)"
    ''' <summary>The wall-clock time one piece of an advance is sized to take, s.</summary>
    Public Const PieceSeconds As Double = FramePacer.PieceSeconds
    ''' <summary>The shortest piece, as a fraction of the frame's simulated time.</summary>
    Public Const MinPieceFraction As Double = FramePacer.MinPieceFraction
    ''' <summary>The first piece a scene is advanced by, as a fraction of the frame's simulated time.</summary>
    Public Const FirstPieceFraction As Double = FramePacer.FirstPieceFraction
    ''' <summary>How far behind the wall clock time on screen may fall in one stretch of slow frames before the message says so, s.</summary>
    Public Const SlowNoticeSeconds As Double = FramePacer.SlowNoticeSeconds
    ''' <summary>How long a scene must keep up before the message that it cannot goes, s.</summary>
    Public Const KeptUpSeconds As Double = FramePacer.KeptUpSeconds
    ''' <summary>The message while a scene cannot keep up with the Speed slider.</summary>
    Public Const SlowMessage As String = FramePacer.SlowMessage

    ''' <summary>What is left of a 60 Hz frame for advancing the world, after the frame's measured other work.</summary>
    Public ReadOnly Property Budget As FrameBudget
        Get
            Return _pacer.Budget
        End Get
    End Property

    ''' <summary>Wall-clock seconds, from any start: what the budget is measured with (a test may give a clock of its own).</summary>
    Public Property WallClock As Func(Of Double)
        Get
            Return _pacer.WallClock
        End Get
        Set(value As Func(Of Double))
            _pacer.WallClock = value
        End Set
    End Property

    ''' <summary>Wall-clock seconds one frame may spend advancing the world (see <see cref="FramePacer.FrameBudgetSeconds"/>).</summary>
    Public Property FrameBudgetSeconds As Double
        Get
            Return _pacer.FrameBudgetSeconds
        End Get
        Set(value As Double)
            _pacer.FrameBudgetSeconds = value
        End Set
    End Property

    ''' <summary>Whether the last frame fell short of the chosen speed.</summary>
    Public ReadOnly Property IsRunningSlow As Boolean
        Get
            Return _pacer.IsRunningSlow
        End Get
    End Property

    ''' <summary>Frames that fell short of the chosen speed since the presenter started.</summary>
    Public ReadOnly Property SlowedFrames As Long
        Get
            Return _pacer.SlowedFrames
        End Get
    End Property

    ''' <summary>Simulated seconds the budget held back since the presenter started.</summary>
    Public ReadOnly Property HeldBackSeconds As Double
        Get
            Return _pacer.HeldBackSeconds
        End Get
    End Property

    ''' <summary>The window spent <paramref name="seconds"/> (s) of this frame outside <see cref="Tick"/>; the next frames' budget leaves room for it.</summary>
    Public Sub NoteFrameWork(seconds As Double)
        _pacer.NoteFrameWork(seconds)
    End Sub
#End Region

#Region "Typing into the tables (TableEditor)"
    ''' <summary>The largest speed that can be typed into a table, m/s.</summary>
    Public Const MaxTypedSpeed As Double = TableEditor.MaxTypedSpeed
    ''' <summary>The farthest from the origin a position can be typed, m.</summary>
    Public Const MaxTypedPosition As Double = TableEditor.MaxTypedPosition

    ''' <summary>What column <paramref name="column"/> of table <paramref name="table"/> holds, when it can be typed into.</summary>
    Public Shared Function EditableQuantity(table As Integer, column As Integer) As TableQuantity
        Return TableEditor.EditableQuantity(table, column)
    End Function

    ''' <summary>The column of table <paramref name="table"/> that holds <paramref name="quantity"/>, or −1.</summary>
    Public Shared Function ColumnOf(table As Integer, quantity As TableQuantity) As Integer
        Return TableEditor.ColumnOf(table, quantity)
    End Function

    ''' <summary>Whether the cell can be typed into: an editable column of a movable body's row.</summary>
    Public Function CanEditCell(table As Integer, row As Integer, column As Integer) As Boolean
        Return _editor.CanEditCell(table, row, column)
    End Function

    ''' <summary>The text an edit box opens with: the cell's value with more figures than the table shows.</summary>
    Public Function CellEditText(table As Integer, row As Integer, column As Integer) As String
        Return _editor.CellEditText(table, row, column)
    End Function

    ''' <summary>Sets the quantity of the cell to what was typed, checked as the Add panel checks its boxes; returns whether the world changed.</summary>
    Public Function EditCell(table As Integer, row As Integer, column As Integer, text As String) As Boolean
        Return _editor.EditCell(table, row, column, text)
    End Function
#End Region

#Region "The mouse on the canvas (PointerTools)"
    ''' <summary>How near the first or the last corner a click finishes the polygon, in canvas pixels at 96 dpi.</summary>
    Public Const CornerSnapPixels As Double = PointerTools.CornerSnapPixels

    ''' <summary>The body waiting to be placed, or Nothing.</summary>
    Public ReadOnly Property Draft As BodyDraft
        Get
            Return _pointer.Draft
        End Get
    End Property

    ''' <summary>The body being carried with the right button, or Nothing.</summary>
    Public ReadOnly Property DraggedBody As Shape
        Get
            Return _pointer.DraggedBody
        End Get
    End Property

    ''' <summary>The movable body being aimed at with the cue, or Nothing.</summary>
    Public ReadOnly Property AimedBody As Shape
        Get
            Return _pointer.AimedBody
        End Get
    End Property

    ''' <summary>Where the cursor is while aiming, m.</summary>
    Public ReadOnly Property AimCursor As Vector
        Get
            Return _pointer.AimCursor
        End Get
    End Property

    ''' <summary>The impulse the cue will give when released, N·s (zero when not aiming).</summary>
    Public ReadOnly Property CueImpulse As Vector
        Get
            Return _pointer.CueImpulse
        End Get
    End Property

    ''' <summary>"J = 2.40 N·s   Δv = J/m = 1.20 m/s" while aiming, "" otherwise.</summary>
    Public ReadOnly Property CueLabel As String
        Get
            Return _pointer.CueLabel
        End Get
    End Property

    ''' <summary>Whether the body waiting to be placed could go where the cursor is now.</summary>
    Public ReadOnly Property DraftFits As Boolean
        Get
            Return _pointer.DraftFits
        End Get
    End Property

    ''' <summary>While a ramp is drawn: its first end, m.</summary>
    Public ReadOnly Property RampStart As Vector?
        Get
            Return _pointer.RampStart
        End Get
    End Property

    ''' <summary>Where the cursor is while a ramp, link or polygon is drawn, m.</summary>
    Public ReadOnly Property ToolCursor As Vector?
        Get
            Return _pointer.ToolCursor
        End Get
    End Property

    ''' <summary>The kind of link the link tool makes.</summary>
    Public ReadOnly Property LinkToolKind As LinkKind
        Get
            Return _pointer.LinkToolKind
        End Get
    End Property

    ''' <summary>While a link is made: the body clicked first, or Nothing.</summary>
    Public ReadOnly Property LinkStart As Shape
        Get
            Return _pointer.LinkStart
        End Get
    End Property

    ''' <summary>While a polygon is drawn by its corners: the corners so far; Nothing otherwise.</summary>
    Public ReadOnly Property CornerDraft As CornerDraft
        Get
            Return _pointer.CornerDraft
        End Get
    End Property

    ''' <summary>The polygon the corners and the cursor would make now, m: the preview.</summary>
    Public ReadOnly Property CornerPreview As IReadOnlyList(Of Vector)
        Get
            Return _pointer.CornerPreview
        End Get
    End Property

    ''' <summary>Whether the polygon of the preview could stand where it is.</summary>
    Public ReadOnly Property CornerPreviewFits As Boolean
        Get
            Return _pointer.CornerPreviewFits
        End Get
    End Property

    ''' <summary>Asks for a circle from the typed radius, mass and Fixed box; it then follows the cursor until a click.</summary>
    Public Sub BeginAddCircle()
        _pointer.BeginAddCircle()
    End Sub

    ''' <summary>Asks for a circle of the given radius (m) and mass (kg); it then follows the cursor until a click.</summary>
    Public Sub BeginAddCircle(radiusText As String, massText As String, isFixed As Boolean)
        _pointer.BeginAddCircle(radiusText, massText, isFixed)
    End Sub

    ''' <summary>Asks for a rectangle from the typed width, height, Fixed box and mass; it then follows the cursor until a click.</summary>
    Public Sub BeginAddRectangle()
        _pointer.BeginAddRectangle()
    End Sub

    ''' <summary>Asks for a fixed rectangle of the given width and height, m.</summary>
    Public Sub BeginAddRectangle(widthText As String, heightText As String)
        _pointer.BeginAddRectangle(widthText, heightText)
    End Sub

    ''' <summary>Asks for a rectangle of the given width and height (m): fixed, or a movable box of the given mass (kg).</summary>
    Public Sub BeginAddRectangle(widthText As String, heightText As String, isFixed As Boolean, massText As String)
        _pointer.BeginAddRectangle(widthText, heightText, isFixed, massText)
    End Sub

    ''' <summary>Drops the body waiting to be placed, or the ramp, link or polygon being drawn (Esc).</summary>
    Public Sub CancelPlacement()
        If CancelMeasure() Then Return
        _pointer.CancelPlacement()
    End Sub

    ''' <summary>A mouse button went down on the canvas at (x, y) px (the middle button pans or follows; the others go to the pointer tools).</summary>
    Public Sub PointerDown(button As PointerButton, x As Double, y As Double)
        If button = PointerButton.Middle Then
            _camera.BeginPan(x, y, _fitted)
            Return
        End If
        If MeasurePointerDown(button, x, y) Then Return
        _pointer.PointerDown(button, x, y)
    End Sub

    ''' <summary>The mouse moved over the canvas to (x, y) px.</summary>
    Public Sub PointerMove(x As Double, y As Double)
        If _camera.IsPanning Then
            If _camera.PanTo(x, y, _fitted) Then ApplyCamera(announce:=True)
            Return
        End If
        If MeasurePointerMove(x, y) Then Return
        _pointer.PointerMove(x, y)
    End Sub

    ''' <summary>A mouse button came up at (x, y) px.</summary>
    Public Sub PointerUp(button As PointerButton, x As Double, y As Double)
        If button = PointerButton.Middle Then
            If Not _camera.IsPanning Then Return
            Dim before = _camera.Followed
            Dim p = View.ToWorld(x, y)
            Dim body = If(p.IsFinite, BodyAt(p), Nothing)
            Dim now = _camera.EndPan(body)
            If now IsNot before Then
                ' A click: follow the body under it, or stop following.
                _camera.Follow(Nothing)
                Follow(now)
            End If
            Return
        End If
        If MeasurePointerUp(button, x, y) Then Return
        _pointer.PointerUp(button, x, y)
    End Sub

    ''' <summary>The Fixed box of the rectangle tool was ticked or cleared.</summary>
    Public Sub RectangleFixedChanged(isFixed As Boolean)
        _pointer.RectangleFixedChanged(isFixed)
    End Sub

    ''' <summary>Asks for a regular polygon from the typed sides, radius, angle, mass and Fixed box.</summary>
    Public Sub BeginAddPolygon()
        _pointer.BeginAddPolygon()
    End Sub

    ''' <summary>Asks for a regular polygon of so many sides, corners so far from its centre, turned so many degrees, fixed or of so many kg.</summary>
    Public Sub BeginAddPolygon(sidesText As String, sizeText As String, angleText As String, massText As String, isFixed As Boolean)
        _pointer.BeginAddPolygon(sidesText, sizeText, angleText, massText, isFixed)
    End Sub

    ''' <summary>The ramp tool: the next left drag on the canvas draws a fixed line.</summary>
    Public Sub BeginAddRamp()
        _pointer.BeginAddRamp()
    End Sub

    ''' <summary>The link tool with the typed stiffness (springs only), N/m.</summary>
    Public Sub BeginAddLink(kind As LinkKind)
        _pointer.BeginAddLink(kind)
    End Sub

    ''' <summary>The link tool: the next two left clicks join two bodies, or a body and a fixed anchor.</summary>
    Public Sub BeginAddLink(kind As LinkKind, stiffnessText As String)
        _pointer.BeginAddLink(kind, stiffnessText)
    End Sub

    ''' <summary>Starts the corner tool with the typed mass and the circle's Fixed box.</summary>
    Public Sub BeginAddCorners()
        _pointer.BeginAddCorners()
    End Sub

    ''' <summary>Starts the corner tool: the next left clicks are the corners of a polygon.</summary>
    Public Sub BeginAddCorners(massText As String, isFixed As Boolean)
        _pointer.BeginAddCorners(massText, isFixed)
    End Sub

    ''' <summary>Finishes the polygon being drawn by its corners (Enter).</summary>
    Public Sub FinishCorners()
        _pointer.FinishCorners()
    End Sub

    ''' <summary>How near the tip of a velocity arrow a press grabs it, in canvas pixels at 96 dpi.</summary>
    Public Const ArrowGrabPixels As Double = PointerTools.ArrowGrabPixels

    ''' <summary>The body whose velocity arrow is being dragged by its tip (while paused), or Nothing.</summary>
    Public ReadOnly Property ArrowBody As Shape
        Get
            Return _pointer.ArrowBody
        End Get
    End Property

    ''' <summary>"v = (1.20, −0.500) m/s   |v| = 1.30 m/s" while an arrow is dragged: the velocity it sets.</summary>
    Public ReadOnly Property ArrowLabel As String
        Get
            Return _pointer.ArrowLabel
        End Get
    End Property

    ''' <summary>The topmost body under point <paramref name="p"/> (m), or Nothing.</summary>
    Public Function BodyAt(p As Vector) As Shape
        Return _pointer.BodyAt(p)
    End Function

    ''' <summary>The link whose line passes nearest <paramref name="p"/> (m), within a few pixels, or Nothing.</summary>
    Public Function LinkAt(p As Vector) As Link
        Return _pointer.LinkAt(p)
    End Function
#End Region

#Region "Undo and redo (EditHistory)"
    ''' <summary>The undo key.</summary>
    Public Const UndoKey As String = EditHistory.UndoKey
    ''' <summary>The redo key.</summary>
    Public Const RedoKey As String = EditHistory.RedoKey

    ''' <summary>Whether there is an edit to undo.</summary>
    Public ReadOnly Property CanUndo As Boolean
        Get
            Return _history.CanUndo
        End Get
    End Property

    ''' <summary>Whether there is an undone edit to redo.</summary>
    Public ReadOnly Property CanRedo As Boolean
        Get
            Return _history.CanRedo
        End Get
    End Property

    ''' <summary>Undoes the last edit (add, delete, move, push, typed value, link, resize, Reset): the world exactly as it was before it.</summary>
    Public Sub Undo()
        Guarded(AddressOf _history.Undo)
    End Sub

    ''' <summary>Redoes the last edit undone: the world exactly as it was after it.</summary>
    Public Sub Redo()
        Guarded(AddressOf _history.Redo)
    End Sub
#End Region

#Region "Choosing the solver"
    ''' <summary>The name of the solver moving the scene now ("event", "verlet", "euler").</summary>
    Public ReadOnly Property SolverInUse As String
        Get
            Return _time.SolverInUse
        End Get
    End Property

    ''' <summary>"Solver: exact ▾": the solver button's caption.</summary>
    Public ReadOnly Property SolverText As String
        Get
            Return SolverChoice.ButtonCaption(SolverInUse)
        End Get
    End Property

    ''' <summary>
    ''' Moves the scene with the solver <paramref name="name"/> from now on (one of
    ''' <see cref="SolverChoice.Names"/>), and starts every new scene and Restart with it: choose one and
    ''' press Restart to run the same start again with it, and compare. Anything else is refused with a message.
    ''' A stepping solver on a spring too stiff for its step is told in the message (<see cref="SolverChoice.StiffSpringWarning"/>).
    ''' </summary>
    Public Sub ChooseSolver(name As String)
        If Not SolverChoice.Names.Contains(name) Then
            ShowMessage("There is no solver called '" & name & "': choose one of " & String.Join(", ", SolverChoice.Names.Select(AddressOf SolverChoice.Title)) & ".")
            Return
        End If
        Guarded(
            Sub()
                _solverChoice = name
                _time.UseSolver(name)
                Emit("solver " & name)
                ShowMessage(SolverChoice.Title(name) & " from now: " & SolverChoice.ShortPurpose(name) & ". " & RestartCaption.TrimStart("↺"c, " "c) & " (" & RestartKey & ") runs the same start with it, to compare." &
                    SolverChoice.StiffSpringAddendum(World))
                TakeSnapshot()
                _window.ShowSettings()
            End Sub)
    End Sub
#End Region

#Region "The gas controls (GasControls)"
    ''' <summary>What one press of Heat multiplies the temperature by; Cool divides by it.</summary>
    Public Const HeatFactor As Double = GasControls.HeatFactor
    ''' <summary>Balls one press of Add or Remove adds or removes.</summary>
    Public Const GasStep As Integer = GasControls.BallsPerPress

    ''' <summary>The temperature now: the mean kinetic energy of the moving bodies, kT, J.</summary>
    Public ReadOnly Property GasKT As Double
        Get
            Return _gas.KT
        End Get
    End Property

    ''' <summary>Heats the gas: every speed × √1.25, so kT × 1.25.</summary>
    Public Sub Heat()
        Guarded(Sub() _gas.Heat(True))
    End Sub

    ''' <summary>Cools the gas: every speed ÷ √1.25, so kT ÷ 1.25.</summary>
    Public Sub Cool()
        Guarded(Sub() _gas.Heat(False))
    End Sub

    ''' <summary>Adds <paramref name="count"/> balls like the gas's, at its temperature, at free places.</summary>
    Public Sub AddBalls(Optional count As Integer = GasControls.BallsPerPress)
        Guarded(Sub() _gas.AddBalls(count))
    End Sub

    ''' <summary>Removes <paramref name="count"/> moving balls, chosen at random.</summary>
    Public Sub RemoveBalls(Optional count As Integer = GasControls.BallsPerPress)
        Guarded(Sub() _gas.RemoveBalls(count))
    End Sub
#End Region

#Region "Zoom, pan and follow (CameraView)"
    ''' <summary>How many times the fitted container the view is (1: the whole container).</summary>
    Public ReadOnly Property Zoom As Double
        Get
            Return _camera.Zoom
        End Get
    End Property

    ''' <summary>The body the view follows, or Nothing.</summary>
    Public ReadOnly Property FollowedBody As Shape
        Get
            Return _camera.Followed
        End Get
    End Property

    ''' <summary>The wheel turned <paramref name="notches"/> notches (away from the user: positive, zooms in) over the canvas at (x, y) px: zooms about that point.</summary>
    Public Sub ZoomAt(notches As Double, x As Double, y As Double)
        If _camera.ZoomAt(notches, x, y, _fitted) Then
            ApplyCamera(announce:=True)
            Emit("zoom " & Units.Num(_camera.Zoom, 3))
        End If
    End Sub

    ''' <summary>Back to the whole container (Ctrl+0): zoom 1, nothing followed.</summary>
    Public Sub ResetView()
        _camera.Reset()
        ApplyCamera(announce:=True)
        Emit("zoom " & Units.Num(_camera.Zoom, 3))
    End Sub

    ''' <summary>Follows <paramref name="body"/> (Nothing: stops following).</summary>
    Public Sub Follow(body As Shape)
        _camera.Follow(body)
        ApplyCamera(announce:=True)
        Emit(If(body Is Nothing, "following nothing", "following " & body.Id))
        ShowMessage(If(body Is Nothing, "", "The view follows " & body.Id & ". Click it with the middle button again, or on an empty place, to stop; Ctrl+0 shows the whole box."),
                    Function() _camera.Followed IsNot Nothing)
    End Sub
#End Region

#Region "The world's settings (WorldSettings)"
    ''' <summary>Position of the speed slider in <see cref="SpeedSteps.Values"/>.</summary>
    Public ReadOnly Property SpeedIndex As Integer
        Get
            Return _settings.SpeedIndex
        End Get
    End Property

    ''' <summary>Simulated seconds per real second.</summary>
    Public ReadOnly Property Speed As Double
        Get
            Return _settings.Speed
        End Get
    End Property

    ''' <summary>The gravity slider: its steps (0 to 100 m/s² in hundredths).</summary>
    Public Shared ReadOnly Property GravitySlider As SliderScale = WorldSettings.GravitySlider

    ''' <summary>The restitution slider: 0 to 1 in hundredths.</summary>
    Public Shared ReadOnly Property RestitutionSlider As SliderScale = WorldSettings.RestitutionSlider

    ''' <summary>Where the gravity slider's thumb belongs.</summary>
    Public ReadOnly Property GravityPosition As Integer
        Get
            Return _settings.GravityPosition
        End Get
    End Property

    ''' <summary>Where the restitution slider's thumb belongs.</summary>
    Public ReadOnly Property RestitutionPosition As Integer
        Get
            Return _settings.RestitutionPosition
        End Get
    End Property

    ''' <summary>"Speed: 1× (real time)".</summary>
    Public ReadOnly Property SpeedText As String
        Get
            Return _settings.SpeedText
        End Get
    End Property

    ''' <summary>"Gravity g = 9.81 m/s²".</summary>
    Public ReadOnly Property GravityText As String
        Get
            Return _settings.GravityText
        End Get
    End Property

    ''' <summary>"Restitution e = 0.90  (1 = elastic)".</summary>
    Public ReadOnly Property RestitutionText As String
        Get
            Return _settings.RestitutionText
        End Get
    End Property

    ''' <summary>The text of a gravity mark's button: "Moon 1.62".</summary>
    Public Shared Function GravityMarkText(mark As GravityMark) As String
        Return WorldSettings.GravityMarkText(mark)
    End Function

    ''' <summary>The gravity slider was moved to a position.</summary>
    Public Sub GravitySliderMoved(position As Integer)
        _settings.GravitySliderMoved(position)
    End Sub

    ''' <summary>The restitution slider was moved to a position.</summary>
    Public Sub RestitutionSliderMoved(position As Integer)
        _settings.RestitutionSliderMoved(position)
    End Sub

    ''' <summary>Sets g, m/s², clamped to the slider's range.</summary>
    Public Sub SetGravity(g As Double)
        _settings.SetGravity(g)
    End Sub

    ''' <summary>Sets e, clamped to [0, 1].</summary>
    Public Sub SetRestitution(e As Double)
        _settings.SetRestitution(e)
    End Sub

    ''' <summary>Moves the speed slider to position <paramref name="index"/> (clamped).</summary>
    Public Sub SetSpeedIndex(index As Integer)
        _settings.SetSpeedIndex(index)
    End Sub

    ''' <summary>Changes the container's size from the typed width and height (m).</summary>
    Public Sub ResizeContainer()
        _settings.ResizeContainer()
    End Sub

    ''' <summary>Changes the container's size to the width and height typed (m); a size with no room for the balls is refused with the reason.</summary>
    Public Sub ResizeContainer(widthText As String, heightText As String)
        _settings.ResizeContainer(widthText, heightText)
    End Sub

    ''' <summary>"Friction μk = 0.3, μs = 0.5", or "No friction (every surface is ice)".</summary>
    Public ReadOnly Property FrictionText As String
        Get
            Return _settings.FrictionText
        End Get
    End Property

    ''' <summary>Said where μ is set: balls take no friction (they would roll; nothing turns).</summary>
    Public Const FrictionBallsNote As String = WorldSettings.BallsNote

    ''' <summary>Sets the world's μk and μs from the friction boxes.</summary>
    Public Sub SetFriction()
        _settings.SetFriction()
    End Sub

    ''' <summary>Sets the world's μk and μs from typed text (an empty μs is μk); a negative value or μs below μk is refused, naming the box.</summary>
    Public Sub SetFriction(kineticText As String, staticText As String)
        _settings.SetFriction(kineticText, staticText)
    End Sub

    ''' <summary>The container's walls on or off (a body too large for the box makes it refuse, with the reason).</summary>
    Public Sub SetWalls(value As Boolean)
        _settings.SetWalls(value)
    End Sub
#End Region
End Class
