Option Strict On

''' <summary>
''' Sits between the window and the engine (Passive View): the form forwards the teacher's actions
''' here, this decides what they mean, changes the world and tells the view what to show. Every
''' behaviour of the app is a method here, so tests drive it without a window.
''' </summary>
Partial Public NotInheritable Class SimulationPresenter
    ''' <summary>Gravity after a reset, m/s².</summary>
    Public Const DefaultGravity As Double = 9.81
    ''' <summary>Restitution after a reset.</summary>
    Public Const DefaultRestitution As Double = 1.0
    ''' <summary>The longest real time one frame may advance, s: after a stall the simulation slows rather than jumps.</summary>
    Public Const MaxFrameSeconds As Double = 0.1

    Private ReadOnly _window As ISimulationView
    Private ReadOnly _colours As BodyColours
    Private _canvasWidth As Integer = 800
    Private _canvasHeight As Integer = 500

    ''' <param name="view">the window (or a test's recorder)</param>
    ''' <param name="store">reads and writes scene files; Nothing when this build has none</param>
    ''' <param name="world">the opening scene; Nothing for <see cref="Scenarios.Demo"/></param>
    ''' <param name="colourSeed">seed of the random body colours</param>
    Public Sub New(view As ISimulationView, Optional store As ISceneStore = Nothing, Optional world As World = Nothing,
                   Optional colourSeed As Integer = 12345)
        If view Is Nothing Then Throw New ArgumentNullException(NameOf(view))
        _window = view
        SceneStore = store
        _colours = New BodyColours(colourSeed)
        Attach(If(world, Scenarios.Demo()))
    End Sub

    ''' <summary>The world being shown. Replaced when a scene is opened.</summary>
    Public ReadOnly Property World As World

    ''' <summary>Reads and writes scene files; Nothing disables Open and Save with a message.</summary>
    Public Property SceneStore As ISceneStore

    ''' <summary>Receives one line per action and state change (the app's --trace switch prints them).</summary>
    Public Property Trace As Action(Of String)

    ''' <summary>The last collisions, newest first.</summary>
    Public ReadOnly Property Log As New CollisionLog()

    ''' <summary>What the input boxes should show.</summary>
    Public ReadOnly Property Inputs As New BodyInputs()

    ''' <summary>What the message box shows when there is no message: how to use the mouse.</summary>
    Public Const MouseHint As String = "Right-drag carries a ball. Left-drag back from a ball and let go to fire it like a cue."

    ''' <summary>The message on show ("" for none).</summary>
    Public ReadOnly Property Message As String = ""

    ''' <summary>True while time is stopped.</summary>
    Public ReadOnly Property IsPaused As Boolean

    ''' <summary>Position of the speed slider in <see cref="SpeedSteps.Values"/>.</summary>
    Public ReadOnly Property SpeedIndex As Integer = SpeedSteps.RealTimeIndex

    ''' <summary>Simulated seconds per real second.</summary>
    Public ReadOnly Property Speed As Double
        Get
            Return SpeedSteps.Values(SpeedIndex)
        End Get
    End Property

    ''' <summary>What a left click on a body does.</summary>
    Public ReadOnly Property Mode As ClickMode = ClickMode.Move

    ''' <summary>Bigger text everywhere, for projectors.</summary>
    Public ReadOnly Property LargeFonts As Boolean

    ''' <summary>The dark, high-contrast canvas.</summary>
    Public ReadOnly Property HighContrast As Boolean

    ''' <summary>Whether velocity arrows (with components) are drawn.</summary>
    Public ReadOnly Property ShowArrows As Boolean = True

    ''' <summary>The canvas colours in use.</summary>
    Public ReadOnly Property Theme As Theme
        Get
            Return If(HighContrast, Theme.Dark, Theme.Light)
        End Get
    End Property

    ''' <summary>Metres ↔ canvas pixels for the current container and canvas size.</summary>
    Public ReadOnly Property View As ViewTransform

    ''' <summary>Called once per frame with the real time since the last frame, s.</summary>
    Public Sub Tick(realSeconds As Double)
        If IsPaused OrElse Not (realSeconds > 0) Then Return
        Try
            World.Advance(Math.Min(realSeconds, MaxFrameSeconds) * Speed)
        Catch ex As ArgumentException
            Fail("The simulation stopped: " & ex.Message)
        Catch ex As InvalidOperationException
            Fail("The simulation stopped: " & ex.Message)
        Catch ex As ArithmeticException
            ' Overflow or a non-finite number from an extreme scene: pause with a message, never crash.
            Fail("The simulation stopped: " & ex.Message)
        End Try
        Log.EndFrame()
    End Sub

    Private Sub Fail(text As String)
        _IsPaused = True
        ShowMessage(text)
        _window.ShowSettings()
    End Sub

    ''' <summary>The canvas changed size, px.</summary>
    Public Sub CanvasResized(width As Integer, height As Integer)
        _canvasWidth = Math.Max(1, width)
        _canvasHeight = Math.Max(1, height)
        FitView()
    End Sub

    ''' <summary>Height of the strip under the container that holds the scale bar, px.</summary>
    Public Const ScaleStrip As Integer = 34

    Private Sub FitView()
        ' The container sits above a strip kept free for the scale bar.
        _View = ViewTransform.Fit(World.Width, World.Height, _canvasWidth, Math.Max(1, _canvasHeight - ScaleStrip), 16)
    End Sub

    ''' <summary>Pauses or resumes. On pausing, the trace lists every movable body's state.</summary>
    Public Sub TogglePause()
        _IsPaused = Not _IsPaused
        ' A body carried across the change keeps following the cursor: while paused it is moved
        ' directly, while running the engine carries it (so it pushes what it meets).
        Dim carried = TryCast(_dragged, Circle)
        If carried IsNot Nothing AndAlso Not carried.IsFixed Then
            If _IsPaused Then World.EndDrag(Vector.Zero) Else World.BeginDrag(carried)
        End If
        If _IsPaused Then
            Emit("paused t=" & Units.Num(World.Time, 3) & " s")
            For Each c In World.Circles
                If Not c.IsFixed Then Emit("body " & c.Id & " at " & Units.Pair(c.Position, 3) & " m v " & Units.Pair(c.Velocity, 3) & " m/s")
            Next
        Else
            Emit("resumed")
        End If
        _window.ShowSettings()
    End Sub

    ''' <summary>Sets g, m/s², clamped to the slider's range.</summary>
    Public Sub SetGravity(g As Double)
        If Double.IsNaN(g) Then Return
        World.Gravity = Math.Max(GravityMark.Minimum, Math.Min(GravityMark.Maximum, g))
        Emit("gravity " & Units.Num(World.Gravity))
        _window.ShowSettings()
    End Sub

    ''' <summary>Sets e, clamped to [0, 1].</summary>
    Public Sub SetRestitution(e As Double)
        If Double.IsNaN(e) Then Return
        World.Restitution = Math.Max(0.0, Math.Min(1.0, e))
        Emit("restitution " & Units.Num(World.Restitution))
        _window.ShowSettings()
    End Sub

    ''' <summary>Moves the speed slider to position <paramref name="index"/> (clamped).</summary>
    Public Sub SetSpeedIndex(index As Integer)
        _SpeedIndex = Math.Max(0, Math.Min(SpeedSteps.Values.Count - 1, index))
        Emit("speed " & SpeedSteps.Label(Speed))
        _window.ShowSettings()
    End Sub

    ''' <summary>Removes every body and sets e = 1, g = 9.81 m/s² and real-time speed. The container keeps its size.</summary>
    Public Sub Reset()
        EndGestures()
        _Draft = Nothing
        World.Clear()
        World.Gravity = DefaultGravity
        World.Restitution = DefaultRestitution
        _SpeedIndex = SpeedSteps.RealTimeIndex
        _Mode = ClickMode.Move
        Log.Clear()
        Emit("reset: " & World.Bodies.Count & " bodies, g " & Units.Num(World.Gravity) & ", e " & Units.Num(World.Restitution) & ", speed " & SpeedSteps.Label(Speed))
        ShowMessage("")
        _window.ShowSettings()
        _window.ShowBodies()
    End Sub

    ''' <summary>Switches between moving and deleting.</summary>
    Public Sub ToggleDeleteMode()
        EndGestures()
        _Mode = If(_Mode = ClickMode.Delete, ClickMode.Move, ClickMode.Delete)
        Emit("mode " & If(_Mode = ClickMode.Delete, "delete", "move"))
        ShowMessage(If(_Mode = ClickMode.Delete, "Delete mode: click a body to remove it. Press Delete mode again to stop.", ""))
        _window.ShowSettings()
    End Sub

    ''' <summary>Changes the container's size from the typed width and height, m.</summary>
    Public Sub ResizeContainer(widthText As String, heightText As String)
        Dim w = NumberInput.ReadPositive(widthText, "container width (m)", InputLimits.MaxContainer)
        Dim h = NumberInput.ReadPositive(heightText, "container height (m)", InputLimits.MaxContainer)
        If Not w.IsValid OrElse Not h.IsValid Then
            ShowMessage(InputLimits.ContainerMessage & " " & Problems(w, h))
            Return
        End If
        If w.Value < InputLimits.MinContainer OrElse h.Value < InputLimits.MinContainer Then
            ShowMessage(InputLimits.ContainerMessage & " Each side must be at least " & Units.Num(InputLimits.MinContainer) & " m.")
            Return
        End If
        Try
            World.Resize(w.Value, h.Value)
        Catch ex As ArgumentException
            ' Smaller than the largest ball: the container keeps its size.
            ShowMessage(InputLimits.ContainerMessage & " " & ex.Message & ".")
            Return
        End Try
        FitView()
        Inputs.ContainerWidthText = Units.Num(w.Value)
        Inputs.ContainerHeightText = Units.Num(h.Value)
        Emit("container " & Units.Num(w.Value) & " x " & Units.Num(h.Value) & " m")
        ShowMessage(If(w.WasClamped OrElse h.WasClamped, "The container is at most " & Units.Num(InputLimits.MaxContainer, 0) & " m on each side: clamped.", ""))
        _window.ShowSettings()
    End Sub

    ''' <summary>Bigger text, for projectors.</summary>
    Public Sub SetLargeFonts(value As Boolean)
        _LargeFonts = value
        Emit("large fonts " & If(value, "on", "off"))
        _window.ShowTheme()
    End Sub

    ''' <summary>The dark, high-contrast canvas.</summary>
    Public Sub SetHighContrast(value As Boolean)
        _HighContrast = value
        Emit("high contrast " & If(value, "on", "off"))
        _window.ShowTheme()
    End Sub

    ''' <summary>Velocity arrows on or off.</summary>
    Public Sub SetShowArrows(value As Boolean)
        _ShowArrows = value
        Emit("arrows " & If(value, "on", "off"))
        _window.ShowTheme()
    End Sub

    ''' <summary>The totals line: momentum, kinetic and potential energy of the moving balls, and the collision count.</summary>
    Public ReadOnly Property TotalsText As String
        Get
            Dim p = World.Momentum()
            Dim ke = World.KineticEnergy()
            Dim pe = World.PotentialEnergy()
            Return "t = " & Units.Num(World.Time, 2) & " s    Σp = " & Units.Pair(p) & " kg·m/s  (|Σp| = " & Units.Num(p.Length) & ")    " &
                "ΣKE = " & Units.Num(ke) & " J    ΣPE = " & Units.Num(pe) & " J    KE + PE = " & Units.Num(ke + pe) & " J    collisions: " &
                Log.TotalSeen.ToString(Globalization.CultureInfo.InvariantCulture)
        End Get
    End Property

    ''' <summary>Shows a message and writes it to the trace.</summary>
    Private Sub ShowMessage(text As String)
        _Message = If(text, "")
        If _Message.Length > 0 Then Emit("message: " & _Message)
        _window.ShowMessage(_Message)
    End Sub

    Private Sub Emit(line As String)
        Trace?.Invoke(line)
    End Sub

    Private Shared Function Problems(ParamArray inputs As NumberInput()) As String
        Return String.Join("; ", inputs.Where(Function(i) Not i.IsValid).Select(Function(i) i.Problem)) & "."
    End Function

    ''' <summary>Makes <paramref name="w"/> the world on show: solver, collision log, colours, view.</summary>
    Private Sub Attach(w As World)
        w.Solver = SolverFactory.Create("auto")
        For Each b In w.Bodies
            If String.IsNullOrEmpty(b.Color) Then b.Color = _colours.NextColour()
        Next
        w.CollisionListener = Sub(r) Log.Record(r, w.DraggedCircle)
        _World = w
        Log.Clear()
        Inputs.ContainerWidthText = Units.Num(w.Width)
        Inputs.ContainerHeightText = Units.Num(w.Height)
        FitView()
    End Sub
End Class
