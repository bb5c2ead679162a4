Option Strict On

''' <summary>
''' Time controls: step a frame, step to the next collision, step back a frame or a collision, and
''' scrub the timeline. The run is recorded as checkpoints (Timeline, TimelineSolver); going back
''' rebuilds the last checkpoint before the moment and replays forward to it, exactly.
''' </summary>
Friend NotInheritable Class TimeMachine
    Private ReadOnly _stage As Stage
    Private ReadOnly _frameBudget As Func(Of Double)
    Private ReadOnly _collided As Action(Of CollisionRecord)
    Private ReadOnly _taken As Action(Of World, Boolean)
    Private ReadOnly _jumped As Action

    ''' <param name="frameBudget">the wall-clock seconds a frame may spend advancing, now</param>
    ''' <param name="collided">told of every collision of the world on show (the graphs, the impulse marks)</param>
    ''' <param name="taken">told when a checkpoint's world is put on show, and whether its container differs in size</param>
    ''' <param name="jumped">told when the moment on show was reached by a jump (replayed at once), not by time running</param>
    Public Sub New(stage As Stage, frameBudget As Func(Of Double), collided As Action(Of CollisionRecord), taken As Action(Of World, Boolean), jumped As Action)
        _stage = stage
        _frameBudget = frameBudget
        _collided = collided
        _taken = taken
        _jumped = jumped
    End Sub

    ''' <summary>One frame of simulated time, s (what Step and Step back move by).</summary>
    Public Const FrameSeconds As Double = 1.0 / 60.0
    ''' <summary>The most frames a step to the next collision looks ahead (10 s of simulated time).</summary>
    Public Const MaxFramesToCollision As Integer = 600
    ''' <summary>The timeline slider's positions.</summary>
    Public Const TimelineSteps As Integer = 1000

    ''' <summary>Keys of the time controls, as the tutorial and the tooltips name them.</summary>
    Public Const StepKey As String = ". or →"
    ''' <summary>See <see cref="StepKey"/>.</summary>
    Public Const StepBackKey As String = ", or ←"
    ''' <summary>See <see cref="StepKey"/>.</summary>
    Public Const NextCollisionKey As String = "Ctrl+→"
    ''' <summary>See <see cref="StepKey"/>.</summary>
    Public Const PreviousCollisionKey As String = "Ctrl+←"

    ''' <summary>Button captions of the time controls.</summary>
    Public Const StepBackCaption As String = "◀|"
    ''' <summary>See <see cref="StepBackCaption"/>.</summary>
    Public Const StepCaption As String = "|▶"
    ''' <summary>See <see cref="StepBackCaption"/>.</summary>
    Public Const PreviousCollisionCaption As String = "◀◀"
    ''' <summary>See <see cref="StepBackCaption"/>.</summary>
    Public Const NextCollisionCaption As String = "▶▶"

    ''' <summary>The time controls' keys, as the tutorial lists them beside the others.</summary>
    Public Const TimeKeysText As String = StepKey & " steps one frame on, " & StepBackKey & " one frame back, " & NextCollisionKey & " goes on to the next collision, " &
        PreviousCollisionKey & " back to the last one (not while typing in a box, which keeps its keys)"

    ''' <summary>The tutorial's page on the time controls: stepping, going back, and what is kept.</summary>
    Public Shared ReadOnly Property TimeTravelHelp As New HelpTopic("9. Stepping and going back in time",
        "The last row of the panel is a player: ◀◀ ◀| Timeline |▶ ▶▶." & vbLf & "" & vbLf &
        "|▶ (" & StepKey & ") pauses and moves time on by one frame, 1/60 s. ◀| (" & StepBackKey & ") goes one frame back." & vbLf & "" & vbLf &
        "▶▶ (" & NextCollisionKey & ") runs on to the next collision and stops just after it: its impulse has been given, and the message says which collision it was and when. The exact solver knows the time of every collision, so this is the very instant of contact, not the end of a frame. It looks at most 10 s ahead. ◀◀ (" & PreviousCollisionKey & ") goes back to the last collision before now." & vbLf & "" & vbLf &
        "The Timeline slider takes you to any earlier moment of the run, at any restitution and gravity, and forward again up to the latest moment reached. Resume then replays the run exactly as it happened, to the last digit: every push, drag and change of g or e is part of it. Anything you change after going back (a push, a drag, a new body, a new g or e) starts a new run from there, and what came after is forgotten, like typing after Undo." & vbLf & "" & vbLf &
        "What is kept: the run is recorded as checkpoints, one at every change you make (a carry counts as two: where it starts and where you let go), and one after every 500 events of the solver per body (collisions and the like; at least 100 000). At most " & Timeline.MaxCheckpoints.ToString(Globalization.CultureInfo.InvariantCulture) & " checkpoints and 64 MB are kept (for the benchmark's gas of 1000 balls, about an hour of running). When either limit is reached the oldest checkpoint is dropped, and the left end of the timeline moves on: the slider's tip, and the message after going back, say which stretch of time is kept." & vbLf & "" & vbLf &
        "While you carry a body the run follows every movement of the mouse, which is not kept: going back to a moment during a carry stops where the carry began, and a replay shows the carried body only from where you let it go. Going back is exact with the exact solver; a scene that runs with the Verlet solver (chains of links) replays with its fixed time step.")

    Private _timeline As Timeline
    Private _firstCollision As CollisionRecord?
    Private _watchCollisions As Boolean
    ''' <summary>The time of the last collision the world on show reported, s (Nothing after going back in time, when it is not known).</summary>
    Private _lastCollisionTime As Double?
    ''' <summary>While stepping to the next collision: the time of the collision before it, s, when known.</summary>
    Private _beforeFirst As Double?

    ''' <summary>The recorded run of the world on show.</summary>
    Public ReadOnly Property Timeline As Timeline
        Get
            Return _timeline
        End Get
    End Property

    ''' <summary>A new run starts (a scene opened, restarted or reset): an empty timeline, and the world records into it.</summary>
    Public Sub StartTimeline(w As World, solver As ISolver)
        _timeline = New Timeline()
        UseTimeline(w, solver, restartFirst:=True)
    End Sub

    ''' <summary>Makes <paramref name="w"/> move with <paramref name="solver"/>, recording into the timeline; collisions go to the log.</summary>
    Private Sub UseTimeline(w As World, solver As ISolver, restartFirst As Boolean)
        w.CollisionListener = AddressOf OnCollision
        w.Solver = New TimelineSolver(solver, _timeline, AddressOf Describe, restartFirst)
    End Sub

    ''' <summary>The solver that moves the world, whether or not it records.</summary>
    Private Function Recording(solver As ISolver) As ISolver
        Return New TimelineSolver(solver, _timeline, AddressOf Describe, restartFirst:=True)
    End Function

    Private Function Describe(w As World) As Checkpoint
        Try
            Return Timeline.Take(w, SolverName(w), _stage.Log.TotalSeen)
        Catch ex As Exception When TypeOf ex Is Scenes.SceneFormatException OrElse TypeOf ex Is ArgumentException OrElse TypeOf ex Is InvalidOperationException
            _stage.Emit("checkpoint failed: " & Stage.OneLine(ex.Message))
            Return Nothing
        End Try
    End Function

    ''' <summary>The name of the solver that moves the world on show ("event", "verlet", "euler").</summary>
    Public ReadOnly Property SolverInUse As String
        Get
            Return SolverName(_stage.World)
        End Get
    End Property

    ''' <summary>From now on the world on show moves with the solver <paramref name="name"/>: a change, so the run recorded ahead is forgotten.</summary>
    Public Sub UseSolver(name As String)
        _stage.World.Solver = Recording(SolverFactory.Create(name))
    End Sub

    Private Shared Function SolverName(w As World) As String
        Return TimelineSolver.Unwrap(w.Solver).Name
    End Function

    Private Sub OnCollision(r As CollisionRecord)
        _stage.Log.Record(r, _stage.World.DraggedBody)
        _collided(r)
        If _watchCollisions AndAlso Not _firstCollision.HasValue Then
            _firstCollision = r
            _beforeFirst = _lastCollisionTime
        End If
        _lastCollisionTime = r.Time
    End Sub

    ''' <summary>
    ''' Advances the world on show by up to <paramref name="seconds"/> within <paramref name="wallSeconds"/>
    ''' of wall-clock time; returns the simulated seconds done. Behind the latest moment of the run, it
    ''' stops at the next checkpoint and takes the world from it, so the run goes on as it was recorded.
    ''' </summary>
    Private Function AdvanceOnTimeline(seconds As Double, wallSeconds As Double) As Double
        Dim start = _stage.World.Time
        Dim ahead = _timeline?.After(start)
        If ahead IsNot Nothing AndAlso start + seconds >= ahead.Time Then
            _stage.World.AdvanceWithin(ExactClock.DurationTo(start, ahead.Time), wallSeconds)
            If _stage.World.Time = ahead.Time Then Take(ahead)
            Return _stage.World.Time - start
        End If
        ' Past the recorded future a carried body restored from a checkpoint has no hand on it any more.
        If ahead Is Nothing AndAlso _stage.World.DraggedBody IsNot Nothing AndAlso Not _stage.IsCarrying Then _stage.World.EndDrag(Vector.Zero)
        Return _stage.World.AdvanceWithin(seconds, wallSeconds)
    End Function

    ''' <summary>
    ''' Advances by up to <paramref name="seconds"/> within <paramref name="wallSeconds"/> of wall-clock
    ''' time; returns the simulated seconds done.
    ''' </summary>
    Public Function Advance(seconds As Double, wallSeconds As Double) As Double
        Dim before = _stage.World.Time
        Dim done = AdvanceOnTimeline(seconds, wallSeconds)
        ' Each whole second of simulated time passed, for tests that wait for a run to get somewhere.
        If _stage.Tracing AndAlso Math.Floor(_stage.World.Time) > Math.Floor(before) Then _stage.Emit("clock " & Units.Num(Math.Floor(_stage.World.Time), 0) & " s")
        Return done
    End Function

    ''' <summary>Puts the world of a checkpoint on show, with its clock and collision count.</summary>
    Private Sub Take(point As Checkpoint)
        Dim w = Timeline.Build(point)
        _lastCollisionTime = Nothing
        Dim resized = w.Width <> _stage.World.Width OrElse w.Height <> _stage.World.Height
        UseTimeline(w, SolverFactory.Create(point.SolverName), restartFirst:=False)
        _stage.World = w
        _stage.Log.ContinueFrom(point.Collisions)
        ' The other parts follow the new world (a cue being aimed, Restart's start, the view).
        _taken(w, resized)
    End Sub

    ''' <summary>The world on show now as a checkpoint (every number to the last bit), or Nothing when it cannot be written down.</summary>
    Public Function Checkpoint() As Checkpoint
        Return Describe(_stage.World)
    End Function

    ''' <summary>
    ''' Puts the world of <paramref name="point"/> on show as a change (Undo and Redo): exactly as it
    ''' was, clock and collision count included, with the gravity and restitution set now (or its
    ''' own, <paramref name="withSettings"/>: undoing Reset). Unlike
    ''' going back in time it starts a new run from there: what was recorded after that moment is
    ''' forgotten, as after any change.
    ''' </summary>
    Public Sub PutBack(point As Checkpoint, withSettings As Boolean)
        Dim now = _stage.World
        Dim w = Timeline.Build(point)
        If Not withSettings Then
            w.Gravity = now.Gravity
            w.Restitution = now.Restitution
        End If
        _lastCollisionTime = Nothing
        Dim resized = w.Width <> now.Width OrElse w.Height <> now.Height
        UseTimeline(w, SolverFactory.Create(point.SolverName), restartFirst:=True)
        _stage.World = w
        _stage.Log.ContinueFrom(point.Collisions)
        _taken(w, resized)
    End Sub

    ''' <summary>Pauses (if running) for a step, ending any gesture.</summary>
    Private Sub PauseForStep()
        _stage.EndGestures()
        If Not _stage.IsPaused Then
            _stage.IsPaused = True
            _stage.Emit("paused t=" & Units.Num(_stage.World.Time, 3) & " s")
        End If
    End Sub

    ''' <summary>Advances exactly <paramref name="seconds"/> of simulated time (following the recorded run where there is one).</summary>
    Private Sub AdvanceExactly(seconds As Double)
        Dim target = _stage.World.Time + seconds
        Do While _stage.World.Time < target
            Advance(ExactClock.DurationTo(_stage.World.Time, target), _frameBudget())
        Loop
        _stage.Log.EndFrame()
    End Sub

    ''' <summary>Step: pauses, then moves one frame (1/60 s) on.</summary>
    Public Sub StepFrame()
        _stage.Guarded(
            Sub()
                PauseForStep()
                AdvanceExactly(FrameSeconds)
                ShowStep("step")
            End Sub)
    End Sub

    ''' <summary>Step back: pauses, then goes one frame (1/60 s) back, or to the earliest moment kept.</summary>
    Public Sub StepBackFrame()
        _stage.Guarded(
            Sub()
                PauseForStep()
                ShowMoment(_stage.World.Time - FrameSeconds)
                ShowStep("step back")
            End Sub)
    End Sub

    ''' <summary>
    ''' Step to the next collision: pauses and runs on until the next collision. With the event solver
    ''' it lands exactly at the collision's time (its impulse already given: just after it); with a
    ''' stepping solver, at the end of the frame in which the count changed. Looks at most
    ''' <see cref="MaxFramesToCollision"/> frames ahead.
    ''' </summary>
    Public Sub StepToNextCollision()
        _stage.Guarded(
            Sub()
                PauseForStep()
                TryCast(_stage.World.Solver, TimelineSolver)?.CheckpointIfChanged()
                Dim before = _stage.Log.TotalSeen
                _firstCollision = Nothing
                _watchCollisions = True
                Try
                    For k = 1 To MaxFramesToCollision
                        AdvanceExactly(FrameSeconds)
                        If _stage.Log.TotalSeen > before Then Exit For
                    Next
                Finally
                    _watchCollisions = False
                End Try
                If Not _firstCollision.HasValue Then
                    ShowStep("next collision: none")
                    _stage.ShowMessage("No collision in the next " & Units.Quantity(MaxFramesToCollision * FrameSeconds, "s") & " of simulated time.")
                    Return
                End If
                Dim hit = _firstCollision.Value
                ' The collision before it, to write the time with enough figures to tell the two apart.
                Dim previousTime = If(_beforeFirst, LastCollisionBefore(hit.Time)?.Last.Time)
                If SolverName(_stage.World) = "event" AndAlso hit.Time < _stage.World.Time Then ShowMoment(hit.Time)
                ShowStep("next collision")
                _stage.ShowMessage(CollisionMessage(_stage.Log.TotalSeen, hit, previousTime))
            End Sub)
    End Sub

    ''' <summary>Step back a collision: pauses and goes back to the last collision before now (just after it).</summary>
    Public Sub StepToPreviousCollision()
        _stage.Guarded(
            Sub()
                PauseForStep()
                TryCast(_stage.World.Solver, TimelineSolver)?.CheckpointIfChanged()
                Dim now = _stage.World.Time
                Dim last = LastCollisionBefore(now)
                If Not last.HasValue Then
                    ShowStep("previous collision: none")
                    _stage.ShowMessage("There is no earlier collision in the recorded run.")
                    Return
                End If
                Dim found = last.Value.Last
                ShowMoment(found.Time)
                ShowStep("previous collision")
                _stage.ShowMessage(CollisionMessage(_stage.Log.TotalSeen, found, last.Value.Before?.Time))
            End Sub)
    End Sub

    ''' <summary>
    ''' The last collision strictly before <paramref name="time"/>, and the one before it when the same
    ''' stretch between checkpoints holds it, found by replaying the recorded run on a copy; Nothing
    ''' when there is none.
    ''' </summary>
    Private Function LastCollisionBefore(time As Double) As (Last As CollisionRecord, Before As CollisionRecord?)?
        Dim until = time
        Dim point = _timeline.Before(until)
        Do While point IsNot Nothing
            Dim last As CollisionRecord? = Nothing
            Dim previous As CollisionRecord? = Nothing
            Dim probe = Timeline.Build(point)
            probe.Solver = SolverFactory.Create(point.SolverName)
            Dim limit = until
            probe.CollisionListener =
                Sub(r)
                    If r.Time >= limit Then Return
                    previous = last
                    last = r
                End Sub
            probe.Advance(ExactClock.DurationTo(probe.Time, until))
            If last.HasValue Then Return (last.Value, previous)
            until = point.Time
            point = _timeline.Before(until)
        Loop
        Return Nothing
    End Function

    ''' <summary>
    ''' "Collision 908: red ↔ blue at t = 3.141593 s.": the time with enough figures to tell it from the
    ''' collision before (<paramref name="before"/>, s, when known), and said when both were at the same instant.
    ''' </summary>
    Private Shared Function CollisionMessage(count As Long, hit As CollisionRecord, before As Double?) As String
        Dim same = before.HasValue AndAlso before.Value = hit.Time
        Return "Collision " & count & ": " & PairName(hit) & " at t = " & Units.SigApart(hit.Time, before) & " s" &
               If(same, ", the same instant as the collision before it.", ".")
    End Function

    ''' <summary>The timeline slider was moved to <paramref name="position"/> (0 to <see cref="TimelineSteps"/>).</summary>
    Public Sub TimelineSliderMoved(position As Integer)
        Dim p = Math.Max(0, Math.Min(TimelineSteps, position))
        Dim t = _timeline.Earliest + (_timeline.Latest - _timeline.Earliest) * p / TimelineSteps
        If p = TimelineSteps Then t = _timeline.Latest
        RewindTo(t)
    End Sub

    ''' <summary>Pauses and shows the run as it was at <paramref name="time"/> (s), within the timeline.</summary>
    Public Sub RewindTo(time As Double)
        If Double.IsNaN(time) Then Return
        _stage.Guarded(
            Sub()
                PauseForStep()
                ShowMoment(time)
                ShowStep("rewound")
                ' True while there is a recorded run ahead to replay: a change (a new g, a push) starts a
                ' new run and forgets it, and a replay that reaches the latest moment has none left.
                _stage.ShowMessage("Back at t = " & Units.Quantity(_stage.World.Time, "s") & " (kept: " & Units.Sig(_timeline.Earliest) & " to " & Units.Quantity(_timeline.Latest, "s") & "). Resume replays the run as it was; any change starts a new one from here.",
                            Function() _stage.World.Time < _timeline.Latest)
            End Sub)
    End Sub

    ''' <summary>
    ''' Puts the run as it was at <paramref name="time"/> (s, brought within the timeline) on show: the
    ''' last checkpoint at or before it, replayed forward. While a body was carried the run depended on
    ''' the mouse, which is not kept, so there it stops where the carry began.
    ''' </summary>
    Private Sub ShowMoment(time As Double)
        TryCast(_stage.World.Solver, TimelineSolver)?.CheckpointIfChanged()
        Dim t = Math.Max(_timeline.Earliest, Math.Min(_timeline.Latest, time))
        Dim point = _timeline.AtOrBefore(t)
        If point Is Nothing Then Return
        If point.IsCarrying Then t = point.Time
        Take(point)
        _stage.World.Advance(ExactClock.DurationTo(_stage.World.Time, t))
        _stage.Log.EndFrame()
        _jumped()
    End Sub

    Private Shared Function PairName(r As CollisionRecord) As String
        Dim entry = CollisionLogEntry.FromRecord(r, Nothing)
        Return entry.AName & " ↔ " & entry.BName
    End Function

    Private Sub ShowStep(what As String)
        _stage.TakeSnapshot()
        _stage.Window.ShowSettings()
        _stage.Emit(what & " t=" & Units.Num(_stage.World.Time, 6) & " s, collisions " & _stage.Log.TotalSeen & ", timeline " & Units.Num(_timeline.Earliest, 6) & " to " & Units.Num(_timeline.Latest, 6) & " s, " & _timeline.Points.Count & " checkpoints")
        If Not _stage.Tracing Then Return
        Dim count = 0
        For Each b In _stage.World.Movables
            _stage.Emit("state " & b.Id & " " & Exact(b.Position.X) & " " & Exact(b.Position.Y) & " " & Exact(b.Velocity.X) & " " & Exact(b.Velocity.Y))
            count += 1
        Next
        ' The last line of a step's states, so that a reader of the trace knows it has them all.
        _stage.Emit("states end, " & count & " bodies")
    End Sub

    ''' <summary>A number to the last bit ("R" round-trips), for tests that compare states exactly.</summary>
    Private Shared Function Exact(v As Double) As String
        Return v.ToString("R", Globalization.CultureInfo.InvariantCulture)
    End Function

    ''' <summary>Where the timeline slider's thumb belongs: the time on show within the timeline.</summary>
    Public ReadOnly Property TimelinePosition As Integer
        Get
            Dim span = _timeline.Latest - _timeline.Earliest
            If Not (span > 0) Then Return TimelineSteps
            Return CInt(Math.Round(Math.Max(0, Math.Min(1, (_stage.World.Time - _timeline.Earliest) / span)) * TimelineSteps))
        End Get
    End Property

    ''' <summary>"Timeline: t = 3.20 s (kept 0 – 12.0 s)": the slider's tip.</summary>
    Public ReadOnly Property TimelineText As String
        Get
            Return "Timeline: t = " & Units.Quantity(_stage.World.Time, "s") & " (kept " & Units.Sig(_timeline.Earliest) & " – " & Units.Quantity(_timeline.Latest, "s") & ")"
        End Get
    End Property
End Class
