Option Strict On

''' <summary>
''' The world's settings: gravity, restitution, friction and the speed of time (with their sliders and the
''' planets' marks), the container's size and its walls. Each is checked and brought to its limits
''' here, and said in the message when it was.
''' </summary>
Friend NotInheritable Class WorldSettings
    ''' <summary>Gravity after a reset, m/s².</summary>
    Public Const DefaultGravity As Double = 9.81
    ''' <summary>Restitution after a reset.</summary>
    Public Const DefaultRestitution As Double = 1.0

    Private ReadOnly _stage As Stage
    Private ReadOnly _history As EditHistory
    Private ReadOnly _containerChanged As Action
    Private ReadOnly _building As Action

    ''' <param name="history">a new container's size is an edit Undo takes back</param>
    ''' <param name="containerChanged">told when the container's size changed (the view fits it again)</param>
    ''' <param name="building">told before the walls change: Restart keeps the scene's own walls</param>
    Public Sub New(stage As Stage, history As EditHistory, containerChanged As Action, building As Action)
        _stage = stage
        _history = history
        _containerChanged = containerChanged
        _building = building
    End Sub

    ''' <summary>Gravity, restitution, friction, air and speed as after a reset: 9.81 m/s², e = 1, no friction, no air, real time.</summary>
    Public Sub ToDefaults()
        _stage.World.Gravity = DefaultGravity
        _stage.World.Restitution = DefaultRestitution
        KeepFriction(_stage.World, 0, Nothing)
        If _stage.World.AirDensity <> 0 Then _stage.World.AirDensity = 0
        ShowFriction()
        _SpeedIndex = SpeedSteps.RealTimeIndex
    End Sub

    ''' <summary>Position of the speed slider in <see cref="SpeedSteps.Values"/>.</summary>
    Public ReadOnly Property SpeedIndex As Integer = SpeedSteps.RealTimeIndex

    ''' <summary>Simulated seconds per real second.</summary>
    Public ReadOnly Property Speed As Double
        Get
            Return SpeedSteps.Values(SpeedIndex)
        End Get
    End Property

    ''' <summary>The gravity slider: its steps (0 to 100 m/s² in hundredths).</summary>
    Public Shared ReadOnly Property GravitySlider As New SliderScale(GravityMark.Minimum, GravityMark.Maximum, 10000)

    ''' <summary>The restitution slider: 0 to 1 in hundredths.</summary>
    Public Shared ReadOnly Property RestitutionSlider As New SliderScale(0.0, 1.0, 100)

    ''' <summary>Where the gravity slider's thumb belongs.</summary>
    Public ReadOnly Property GravityPosition As Integer
        Get
            Return GravitySlider.PositionOf(_stage.World.Gravity)
        End Get
    End Property

    ''' <summary>Where the restitution slider's thumb belongs.</summary>
    Public ReadOnly Property RestitutionPosition As Integer
        Get
            Return RestitutionSlider.PositionOf(_stage.World.Restitution)
        End Get
    End Property

    ''' <summary>The gravity slider was moved to a position.</summary>
    Public Sub GravitySliderMoved(position As Integer)
        SetGravity(GravitySlider.ValueAt(position))
    End Sub

    ''' <summary>The restitution slider was moved to a position.</summary>
    Public Sub RestitutionSliderMoved(position As Integer)
        SetRestitution(RestitutionSlider.ValueAt(position))
    End Sub

    ''' <summary>Sets g, m/s², clamped to the slider's range.</summary>
    Public Sub SetGravity(g As Double)
        If Double.IsNaN(g) Then Return
        _stage.Guarded(
            Sub()
                _stage.World.Gravity = Math.Max(GravityMark.Minimum, Math.Min(GravityMark.Maximum, g))
                _stage.Emit("gravity " & Units.Num(_stage.World.Gravity))
                _stage.TakeSnapshot()
                _stage.Window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>Sets e, clamped to [0, 1].</summary>
    Public Sub SetRestitution(e As Double)
        If Double.IsNaN(e) Then Return
        _stage.Guarded(
            Sub()
                _stage.World.Restitution = Math.Max(0.0, Math.Min(1.0, e))
                _stage.Emit("restitution " & Units.Num(_stage.World.Restitution))
                _stage.Window.ShowSettings()
                _stage.CheckMessage()
            End Sub)
    End Sub

    ''' <summary>Moves the speed slider to position <paramref name="index"/> (clamped).</summary>
    Public Sub SetSpeedIndex(index As Integer)
        _SpeedIndex = Math.Max(0, Math.Min(SpeedSteps.Values.Count - 1, index))
        _stage.Emit("speed " & SpeedSteps.Label(Speed))
        _stage.Window.ShowSettings()
    End Sub

    ''' <summary>"Speed: 1× (real time)".</summary>
    Public ReadOnly Property SpeedText As String
        Get
            Return "Speed: " & SpeedSteps.Label(Speed)
        End Get
    End Property

    ''' <summary>"Gravity g = 9.81 m/s²".</summary>
    Public ReadOnly Property GravityText As String
        Get
            Return "Gravity g = " & Units.Quantity(_stage.World.Gravity, "m/s²")
        End Get
    End Property

    ''' <summary>"Restitution e = 0.90 (1 = elastic)".</summary>
    Public ReadOnly Property RestitutionText As String
        Get
            Return "Restitution e = " & _stage.World.Restitution.ToString("0.00", Globalization.CultureInfo.InvariantCulture) & "  (1 = elastic)"
        End Get
    End Property

    ''' <summary>The text of a gravity mark's button: "Moon 1.62".</summary>
    Public Shared Function GravityMarkText(mark As GravityMark) As String
        If mark Is Nothing Then Throw New ArgumentNullException(NameOf(mark))
        Return mark.Name & " " & mark.Value.ToString("0.00", Globalization.CultureInfo.InvariantCulture)
    End Function

    ''' <summary>The largest μ typed into the friction boxes: far rougher than rubber on concrete (about 1).</summary>
    Public Const MaxFriction As Double = 10.0

    ''' <summary>Said wherever μ is set: why a ball slides on as if on ice.</summary>
    Public Const BallsNote As String = "Balls take no friction: a real ball would roll, and nothing turns here."

    ''' <summary>"Friction μk = 0.3, μs = 0.5" (μs left out when it is the same as μk), or "No friction (every surface is ice)".</summary>
    Public ReadOnly Property FrictionText As String
        Get
            Return DescribeFriction(_stage.World)
        End Get
    End Property

    ''' <summary>The world's friction in words, as <see cref="FrictionText"/> shows it.</summary>
    Public Shared Function DescribeFriction(w As World) As String
        If w Is Nothing Then Throw New ArgumentNullException(NameOf(w))
        Dim k = w.Friction, s = If(w.StaticFriction, w.Friction)
        If k = 0 AndAlso s = 0 Then Return "No friction (every surface is ice)"
        Dim text = "Friction μk = " & Units.Input(k)
        If s <> k Then text &= ", μs = " & Units.Input(s)
        Return text
    End Function

    ''' <summary>The world's μk and μs the friction boxes were last given.</summary>
    Private _shownFriction As (Kinetic As Double, [Static] As Double?)

    ''' <summary>The friction boxes show the world's μk and μs (a scene opened or restarted, an edit undone).</summary>
    Public Sub ShowFriction()
        _shownFriction = (_stage.World.Friction, _stage.World.StaticFriction)
        _stage.Inputs.FrictionText = Units.Input(_stage.World.Friction)
        _stage.Inputs.StaticFrictionText = If(_stage.World.StaticFriction.HasValue, Units.Input(_stage.World.StaticFriction.Value), "")
    End Sub

    ''' <summary>
    ''' A moment of the run was put on show (going back): when its friction is not the one the boxes
    ''' were given (the teacher set another since), the boxes show its own; otherwise what is typed in
    ''' them stays. Returns whether they changed.
    ''' </summary>
    Public Function FollowFriction() As Boolean
        If _stage.World.Friction = _shownFriction.Kinetic AndAlso Nullable.Equals(_stage.World.StaticFriction, _shownFriction.Static) Then Return False
        ShowFriction()
        Return True
    End Function

    ''' <summary>Gives <paramref name="w"/> these μk and μs, touching it only when they differ (a change restarts the recorded run).</summary>
    Public Shared Sub KeepFriction(w As World, friction As Double, staticFriction As Double?)
        If w Is Nothing Then Throw New ArgumentNullException(NameOf(w))
        If w.Friction = friction AndAlso Nullable.Equals(w.StaticFriction, staticFriction) Then Return
        w.StaticFriction = Nothing
        w.Friction = friction
        w.StaticFriction = staticFriction
    End Sub

    ''' <summary>Sets the world's friction from the typed μk and μs.</summary>
    Public Sub SetFriction()
        SetFriction(_stage.Inputs.FrictionText, _stage.Inputs.StaticFrictionText)
    End Sub

    ''' <summary>
    ''' Sets the world's μk and μs (of every surface without its own: walls, fixed bodies, ramps,
    ''' boxes, polygons) from the typed text, as a scene file's world.friction and
    ''' world.static_friction. An empty μs is the same as μk. A negative or unreadable value, or μs
    ''' below μk, is refused naming its box, and nothing changes; a value above
    ''' <see cref="MaxFriction"/> is brought to it and said. Like gravity, friction is a setting, not
    ''' an edit: Undo leaves it as set.
    ''' </summary>
    Public Sub SetFriction(kineticText As String, staticText As String)
        _stage.Inputs.FrictionText = kineticText
        _stage.Inputs.StaticFrictionText = staticText
        _stage.Guarded(
            Sub()
                Dim hasStatic = If(staticText, "").Trim().Length > 0
                Dim problems As New List(Of String)
                Dim k = NumberInput.ReadNonNegative(kineticText, "friction μk", MaxFriction, problems)
                Dim s = If(hasStatic, NumberInput.ReadNonNegative(staticText, "static friction μs", MaxFriction, problems), k)
                If problems.Count > 0 Then
                    _stage.ShowMessage("Friction is unchanged: " & String.Join("; ", problems) & ".")
                    Return
                End If
                If s.Value < k.Value Then
                    _stage.ShowMessage("Friction is unchanged: static friction μs (" & Units.Sig(s.Value) & ") must be at least friction μk (" & Units.Sig(k.Value) &
                                       "): a surface grips at least as hard before it slides as while it slides.")
                    Return
                End If
                ' μs to Nothing first, so that a μk above the old μs is not refused on the way.
                _stage.World.StaticFriction = Nothing
                _stage.World.Friction = k.Value
                _stage.World.StaticFriction = If(hasStatic, s.Value, CType(Nothing, Double?))
                If k.WasClamped Then _stage.Inputs.FrictionText = Units.Input(k.Value)
                If hasStatic AndAlso s.WasClamped Then _stage.Inputs.StaticFrictionText = Units.Input(s.Value)
                If k.WasClamped OrElse s.WasClamped Then _stage.Window.ShowInputs()
                _stage.Emit("friction " & Units.Num(_stage.World.Friction) & " static " & Units.Num(If(_stage.World.StaticFriction, _stage.World.Friction)))
                Dim clamped = If(k.WasClamped OrElse s.WasClamped, "μ above " & Units.Input(MaxFriction) & " was brought to " & Units.Input(MaxFriction) & ". ", "")
                _stage.ShowMessage(clamped & DescribeFriction(_stage.World) & " on walls, ramps, boxes and polygons. " & BallsNote)
                _stage.TakeSnapshot()
                _stage.Window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>Changes the container's size from the typed width and height (m).</summary>
    Public Sub ResizeContainer()
        ResizeContainer(_stage.Inputs.ContainerWidthText, _stage.Inputs.ContainerHeightText)
    End Sub

    ''' <summary>
    ''' Changes the container's size to the width and height typed (m). A size whose walls would
    ''' leave the balls no room (a ball wider than the box, or more balls than fit without
    ''' overlapping) is refused with the reason, and nothing changes; otherwise balls left outside are
    ''' brought in and overlaps pushed apart at once, so the scene stays sound even while paused.
    ''' </summary>
    Public Sub ResizeContainer(widthText As String, heightText As String)
        _stage.Inputs.ContainerWidthText = widthText
        _stage.Inputs.ContainerHeightText = heightText
        _stage.Guarded(
            Sub()
                ' Brought to its limits and said, as every other box is.
                Dim w = NumberInput.ReadPositive(widthText, "container width (m)", InputLimits.MaxContainer, InputLimits.MinContainer)
                Dim h = NumberInput.ReadPositive(heightText, "container height (m)", InputLimits.MaxContainer, InputLimits.MinContainer)
                If Not w.IsValid OrElse Not h.IsValid Then
                    _stage.ShowMessage(InputLimits.ContainerMessage & " " & Stage.Problems(w, h))
                    Return
                End If
                Dim refusal = ContainerRefusal(w.Value, h.Value)
                If refusal IsNot Nothing Then
                    _stage.ShowMessage("The container cannot be " & Units.Sig(w.Value) & " m × " & Units.Sig(h.Value) & " m: " & refusal & " It keeps its size.")
                    Return
                End If
                Dim before = _history.Capture()
                _stage.World.Resize(w.Value, h.Value)
                SettleOverlaps()
                _history.Commit("the container's new size", before)
                _containerChanged()
                If w.WasClamped Then _stage.Inputs.ContainerWidthText = Units.Input(w.Value)
                If h.WasClamped Then _stage.Inputs.ContainerHeightText = Units.Input(h.Value)
                If w.WasClamped OrElse h.WasClamped Then _stage.Window.ShowInputs()
                _stage.Emit("container " & Units.Num(w.Value) & " x " & Units.Num(h.Value) & " m")
                _stage.ShowMessage(Stage.ClampNote(("container width", w, "m"), ("container height", h, "m")).TrimEnd())
                _stage.TakeSnapshot()
                _stage.Window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>Why the world's balls could not live in a container of w × h m, or Nothing when they can.</summary>
    Private Function ContainerRefusal(w As Double, h As Double) As String
        If Not _stage.World.Walls Then Return Nothing
        Dim widest = _stage.World.Circles.Where(Function(c) Not c.IsFixed).Select(Function(c) 2 * c.Radius).DefaultIfEmpty(0).Max()
        If widest > Math.Min(w, h) Then Return "the widest ball is " & Units.Quantity(widest, "m") & " across and would not fit."
        ' Try it on a copy first: the balls are brought in and pushed apart; if they still overlap, there is no room.
        Dim trial As World
        Try
            trial = Scenes.SceneFile.Load(Scenes.SceneFile.Save(_stage.World))
        Catch ex As Scenes.SceneFormatException
            Return Nothing ' no copy to try it on: the resize itself settles the overlaps
        End Try
        trial.Resize(w, h)
        If OverlapResolver.Resolve(trial) > Placement.Tolerance OrElse Placement.FindProblem(trial) IsNot Nothing Then
            Dim balls = _stage.World.Circles.Where(Function(c) Not c.IsFixed).Count()
            Return "its " & balls & " balls would not fit in it without overlapping. Remove some balls, or choose a larger size."
        End If
        Return Nothing
    End Function

    ''' <summary>Pushes overlapping balls apart now (after the container shrank), and tells the solver.</summary>
    Public Sub SettleOverlaps()
        OverlapResolver.Resolve(_stage.World)
        _stage.World.Solver?.Invalidate(Nothing)
    End Sub

    ''' <summary>
    ''' The container's walls on (its sides reflect balls) or off (balls fly out through where they
    ''' were). Turning them on brings every movable body back inside; a body too large for the box
    ''' makes it refuse, with the reason. Restart goes back to the scene's own choice.
    ''' </summary>
    Public Sub SetWalls(value As Boolean)
        _stage.Guarded(
            Sub()
                ' The start Restart goes back to is taken first, so it keeps the scene's own walls.
                _building()
                If value <> _stage.World.Walls Then
                    _stage.World.Walls = value
                    SettleOverlaps()
                End If
                _stage.Emit("walls " & If(_stage.World.Walls, "on", "off"))
                _stage.ShowMessage(If(_stage.World.Walls, "Walls on: the sides reflect the balls; any ball outside was brought back in.",
                               "No walls: balls fly out through the dashed outline."))
                _stage.TakeSnapshot()
            End Sub)
        _stage.Window.ShowSettings()
    End Sub

End Class
