Option Strict On

''' <summary>
''' Wraps the solver that moves the world and makes the run it produces replayable, exactly. The
''' event solver keeps state beyond positions and velocities (predictions made at earlier times,
''' resting contacts, sleeping piles), so a state rebuilt from positions and velocities does not in
''' general replay to the last bit. The run is therefore made to restart its solver itself, at every
''' checkpoint: after any change from outside (a push, an added body, a new g or e, the start and the
''' end of a carry), and every <see cref="Timeline.EventsBetweenCheckpoints"/> events. A
''' checkpoint is the world's state at such a restart, and a fresh solver on it does exactly what the
''' first one did next.
''' </summary>
Public NotInheritable Class TimelineSolver
    Implements ISolver

    Private ReadOnly _inner As ISolver
    Private ReadOnly _timeline As Timeline
    Private ReadOnly _describe As Func(Of World, Checkpoint)
    Private _world As World
    Private _pending As Boolean
    Private _eventsAtCheckpoint As Long
    Private _timeAtCheckpoint As Double
    ''' <summary>The body being carried when the last checkpoint was asked for, or Nothing.</summary>
    Private _carried As Shape

    ''' <param name="inner">the solver that does the work</param>
    ''' <param name="timeline">where checkpoints go; Nothing records nothing (a plain run, for comparisons)</param>
    ''' <param name="describe">makes the checkpoint of a world at a restart</param>
    ''' <param name="restartFirst">whether the first advance is a checkpoint (a new run, not a rewound one)</param>
    Public Sub New(inner As ISolver, timeline As Timeline, describe As Func(Of World, Checkpoint), restartFirst As Boolean)
        If inner Is Nothing Then Throw New ArgumentNullException(NameOf(inner))
        _inner = inner
        _timeline = timeline
        _describe = describe
        _pending = restartFirst
    End Sub

    ''' <summary>The solver that does the work.</summary>
    Public ReadOnly Property Inner As ISolver
        Get
            Return _inner
        End Get
    End Property

    ''' <summary><paramref name="solver"/>'s inner solver when it records a timeline, else <paramref name="solver"/> itself: the one that does the work.</summary>
    Friend Shared Function Unwrap(solver As ISolver) As ISolver
        Dim timeline = TryCast(solver, TimelineSolver)
        Return If(timeline IsNot Nothing, timeline.Inner, solver)
    End Function

    ''' <summary>The inner solver's name.</summary>
    Public ReadOnly Property Name As String Implements ISolver.Name
        Get
            Return _inner.Name
        End Get
    End Property

    ''' <summary>The inner solver's time step.</summary>
    Public ReadOnly Property TimeStep As Double? Implements ISolver.TimeStep
        Get
            Return _inner.TimeStep
        End Get
    End Property

    ''' <summary>Attaches both to the world.</summary>
    Public Sub Attach(world As World) Implements ISolver.Attach
        _world = world
        _inner.Attach(world)
        _carried = world?.DraggedBody
        _timeAtCheckpoint = If(world Is Nothing, 0, world.Time)
        _eventsAtCheckpoint = Events()
    End Sub

    ''' <summary>
    ''' A change from outside: the inner solver rebuilds everything at the next advance (not only the
    ''' body changed), so the run restarts there and a checkpoint is taken; the recorded future is ended.
    ''' A carried body moving on is not a new start: a checkpoint every frame of a carry would fill
    ''' the memory in seconds in a large scene, so the carry is kept as its two ends (going back into
    ''' it stops at its start).
    ''' </summary>
    Public Sub Invalidate(body As Shape) Implements ISolver.Invalidate
        If _world IsNot Nothing AndAlso _timeline IsNot Nothing Then _timeline.Truncate(_world.Time)
        Dim carried = _world?.DraggedBody
        If body IsNot Nothing AndAlso body Is carried AndAlso carried Is _carried Then
            _inner.Invalidate(body)
            Return
        End If
        _carried = carried
        _inner.Invalidate(Nothing)
        _pending = True
    End Sub

    ''' <summary>Takes the checkpoint a change asked for now, if one is waiting (before a step to the next collision, say).</summary>
    Public Sub CheckpointIfChanged()
        If _pending Then Restart()
    End Sub

    ''' <summary>Advances, restarting first when a checkpoint is due.</summary>
    Public Sub Advance(duration As Double) Implements ISolver.Advance
        BeforeAdvance()
        _inner.Advance(duration)
        _timeline?.Reached(_world.Time + duration)
    End Sub

    ''' <summary>Advances within a wall-clock deadline, restarting first when a checkpoint is due.</summary>
    Public Function AdvanceWithin(duration As Double, deadline As Long) As Double Implements ISolver.AdvanceWithin
        BeforeAdvance()
        Dim reached = _inner.AdvanceWithin(duration, deadline)
        _timeline?.Reached(reached)
        Return reached
    End Function

    Private Sub BeforeAdvance()
        If _world Is Nothing Then Return
        If _pending Then
            Restart()
            Return
        End If
        If _timeline Is Nothing OrElse _world.Time < _timeline.Latest Then Return ' replaying: the checkpoints ahead exist already
        Dim due As Boolean
        Dim ev = TryCast(_inner, EventDrivenSolver)
        If ev IsNot Nothing Then
            due = ev.EventCount - _eventsAtCheckpoint >= Timeline.EventsBetweenCheckpoints(_world.Bodies.Count)
        Else
            due = _world.Time - _timeAtCheckpoint >= Timeline.SecondsPerCheckpoint
        End If
        If due Then
            _inner.Invalidate(Nothing)
            Restart()
        End If
    End Sub

    Private Sub Restart()
        _pending = False
        _timeAtCheckpoint = _world.Time
        _eventsAtCheckpoint = Events()
        If _timeline Is Nothing OrElse _describe Is Nothing Then Return
        Dim point = _describe(_world)
        If point IsNot Nothing Then _timeline.Add(point)
    End Sub

    Private Function Events() As Long
        Dim ev = TryCast(_inner, EventDrivenSolver)
        Return If(ev Is Nothing, 0, ev.EventCount)
    End Function
End Class
