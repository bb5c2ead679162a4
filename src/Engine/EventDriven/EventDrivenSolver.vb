Option Strict On

''' <summary>
''' The exact, event-driven solver. Between events every free body follows its parabola exactly;
''' collision times are computed in closed form or by root isolation (<see cref="TimeOfImpact"/>),
''' never detected after the fact, so nothing tunnels at any speed. One step reads as its pipeline:
''' find the earliest event → advance the clock to it → resolve it → reschedule the bodies involved.
''' Bouncing with e &lt; 1 ends in a resting state at the exact time the infinite series of bounces
''' ends; piles go to sleep. See docs/event-driven.md.
''' <para>
''' The state has one owner per kind (<see cref="SolverState"/>): the movable bodies
''' (<see cref="BodyTable"/>), the obstacles, the grid, the queue, the rest rules' history and the
''' corner slides. The parts that act on it: <see cref="Predictor"/> (when is each body's next
''' event), <see cref="Responder"/> (what happens at it), <see cref="RestRules"/> and
''' <see cref="CornerSlides"/>; <see cref="ContactRules"/> says which maths each pair of body kinds uses.
''' </para>
''' </summary>
Public NotInheritable Class EventDrivenSolver
    Implements ISolver

    Private ReadOnly _s As New SolverState()
    Private ReadOnly _slides As CornerSlides
    Private ReadOnly _rest As RestRules
    Private ReadOnly _predictor As Predictor
    Private ReadOnly _responder As Responder
    ' A world with links is moved by their closed forms instead (see LinkedEventSolver).
    Private ReadOnly _linked As New LinkedEventSolver()
    ' Steps a world with links while one of its bodies is carried (see AdvanceWithin); attached anew for each carry.
    Private _carried As VerletSolver
    Private _carriedWorld As World
    Private _dirty As Boolean = True
    ''' <summary>When the fast path handed the world over to the general path for good (s; +∞: not yet). See <see cref="HandOver"/>.</summary>
    Private _handedOverAt As Double = Double.PositiveInfinity
    ''' <summary>Events processed at the current instant so far (see <see cref="CountInstant"/>).</summary>
    Private _instantEvents As Long

    Public Sub New()
        _slides = New CornerSlides(_s)
        _rest = New RestRules(_s, _slides)
        _predictor = New Predictor(_s, _slides)
        _responder = New Responder(_s, _rest, _slides)
    End Sub

    ''' <summary>Name on the command line.</summary>
    Public ReadOnly Property Name As String Implements ISolver.Name
        Get
            Return "event"
        End Get
    End Property

    ''' <summary>Nothing: the event-driven solver has no time step.</summary>
    Public ReadOnly Property TimeStep As Double? Implements ISolver.TimeStep
        Get
            Return Nothing
        End Get
    End Property

    ''' <summary>
    ''' A ceiling on the events (collisions, cell crossings, …) one advance may take, for tests that
    ''' check a scene is handled in few events: past it the advance throws. No ceiling by default: a
    ''' scene may legitimately need millions of collisions per simulated second, and a window that
    ''' must stay responsive uses <see cref="AdvanceWithin"/> instead.
    ''' </summary>
    Public Property MaxEventsPerAdvance As Long = Long.MaxValue

    ''' <summary>
    ''' Whether pair tests run four lanes at a time (256-bit vectors, when the processor has them).
    ''' Off, they run one body at a time, as on .NET Framework; the results are the same. Takes
    ''' effect at the next rebuild (it also sets the cell size).
    ''' </summary>
    Friend Property VectorScan As Boolean
        Get
            Return _predictor.VectorScan
        End Get
        Set(value As Boolean)
#If NET Then
            _predictor.VectorScan = value
#Else
            If value Then Throw New PlatformNotSupportedException("this build has no 256-bit vectors")
#End If
            _dirty = True
        End Set
    End Property

    ''' <summary>Average bodies per grid cell, when set (> 0): for tests that compare the pair tests on one grid.</summary>
    Friend Property CellOccupancy As Double

    ''' <summary>Checks every lane against its body after every event (slow: for tests).</summary>
    Friend Property CheckLanesEveryEvent As Boolean

    ''' <summary>Every event processed so far (collisions, cell crossings, stale re-predictions, …).</summary>
    Public ReadOnly Property EventCount As Long

    ''' <summary>
    ''' Grid cells searched for partners so far, summed over every prediction and cell crossing: with
    ''' <see cref="EventCount"/>, the work per event, which should not grow with the number of bodies.
    ''' </summary>
    Public ReadOnly Property CellsSearched As Long
        Get
            Return _s.CellsSearched
        End Get
    End Property

    ''' <summary>The general path of lasting contact this solver hands a world to (for counting its work).</summary>
    Friend ReadOnly Property General As LinkedEventSolver
        Get
            Return _linked
        End Get
    End Property

    ''' <summary>Attaches the solver to a world; the first advance builds every prediction.</summary>
    Public Sub Attach(world As World) Implements ISolver.Attach
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        _s.World = world
        _linked.Attach(world)
        _dirty = True
        _handedOverAt = Double.PositiveInfinity
    End Sub

    ''' <summary>
    ''' When a bouncing circle came to rest: the time (s) its infinite series of ever smaller bounces
    ''' ends, t + 2 v_n / (g (1 − e)). Nothing while it is not resting.
    ''' </summary>
    Public Function RestTime(body As Shape) As Double?
        Return _rest.RestTime(body)
    End Function

    ''' <summary>True when the body is asleep (part of a settled pile, acting as a fixed obstacle).</summary>
    Public Function IsAsleep(body As Shape) As Boolean
        If body Is Nothing OrElse _dirty Then Return False
        Dim i = _s.Bodies.IndexOf(body)
        Return i >= 0 AndAlso _s.Bodies.Mode(i) = BodyMode.Sleeping
    End Function

    ''' <summary>
    ''' Advances exactly <paramref name="duration"/> seconds: find the earliest event, advance the
    ''' clock to it, resolve it, reschedule the bodies involved; repeat until the next event lies
    ''' beyond the end. Then every body is written back at its exact state at the end.
    ''' </summary>
    Public Sub Advance(duration As Double) Implements ISolver.Advance
        AdvanceWithin(duration, Long.MaxValue)
    End Sub

    ''' <summary>
    ''' As <see cref="Advance"/>, stopping after the event at which the wall clock passes
    ''' <paramref name="deadline"/> (Stopwatch ticks). The bodies are written back at that event's
    ''' time, where the state is exact, and the next advance carries on from the same predictions.
    ''' </summary>
    Public Function AdvanceWithin(duration As Double, deadline As Long) As Double Implements ISolver.AdvanceWithin
        If _s.World IsNot Nothing AndAlso _s.World.Time >= _handedOverAt Then Return AdvanceLinked(duration, deadline) ' see HandOver
        If _s.World Is Nothing Then Throw New InvalidOperationException("the solver is not attached to a world")
        ' Links, drag, liquids and friction take the general path; a scene with none of them, this one.
        If _s.World.Links.Count > 0 OrElse _s.World.HasDragOrLiquids OrElse _s.World.HasFriction Then Return AdvanceLinked(duration, deadline)
        If _dirty OrElse _s.Now <> _s.World.Time Then Rebuild()
        Dim tEnd = _s.World.Time + duration
        StartDrag(duration)
        Dim processed As Long = 0
        Do
            ' Find the earliest event.
            Dim i = _s.Queue.Top
            If i < 0 Then Exit Do
            Dim t = _s.Queue.TimeOf(i)
            If Not (t <= tEnd) Then Exit Do
            If (processed And 255) = 255 AndAlso Diagnostics.Stopwatch.GetTimestamp() > deadline AndAlso t > _s.Now Then
                ' Out of wall-clock time: stop here, between two instants.
                _EventCount += processed
                WriteBack(_s.Now)
                Return _s.Now
            End If
            If processed >= MaxEventsPerAdvance Then TooManyEvents()
            ' Advance the clock to it.
            CountInstant(t)
            _s.Now = t
            ' Resolve it, then reschedule every body it changed.
            If _s.Bodies.Slot(i).CellTime <= _s.Bodies.Slot(i).ColTime Then
                _predictor.CrossCell(i)
            Else
                _responder.Resolve(i)
                RescheduleTouched()
                If _s.HandOver Then
                    _EventCount += processed + 1
                    Return HandOver(tEnd, deadline)
                End If
            End If
            If CheckLanesEveryEvent Then LaneCheck.Check(_s)
            processed += 1
        Loop
        _EventCount += processed
        _s.Now = tEnd
        WriteBack(tEnd)
        Return tEnd
    End Function

    ''' <summary>A scene with links: the linked solver's closed forms, or stepping while a body is carried by hand.</summary>
    Private Function AdvanceLinked(duration As Double, deadline As Long) As Double
        If _s.World.DraggedBody IsNot Nothing Then
            ' A body carried by hand follows the hand, not a closed form: while it is carried the
            ' scene is stepped (position Verlet, as the stepping solvers carry bodies), and when it
            ' is let go the closed forms start again from the state it was left in.
            If _carried Is Nothing Then _carried = New VerletSolver(VerletSolver.DefaultTimeStep)
            If _carriedWorld IsNot _s.World Then
                _carried.Attach(_s.World)
                _carriedWorld = _s.World
            End If
            _carried.Advance(duration)
            _linked.Invalidate()
            _dirty = True
            Return _s.World.Time + duration
        End If
        _carriedWorld = Nothing
        Dim reached = _linked.AdvanceWithin(duration, deadline)
        _dirty = True
        Return reached
    End Function

    ''' <summary>
    ''' A rule met what the fast path cannot follow exactly (<see cref="SolverState.HandOver"/>): from the clock
    ''' on, this world goes to the general path of lasting contact (LinkedEventSolver), the rest of this advance
    ''' and every later one, until the solver is attached anew or the world goes back before that instant.
    ''' </summary>
    Private Function HandOver(tEnd As Double, deadline As Long) As Double
        _s.HandOver = False
        _handedOverAt = _s.Now
        WriteBack(_s.Now)
        _dirty = True
        If _s.World.DraggedBody IsNot Nothing Then Return _s.Now ' carried by hand: the next advance steps it (AdvanceLinked)
        Return _linked.AdvanceWithin(tEnd - _s.Now, deadline, _s.Now, tEnd)
    End Function

    ''' <summary>
    ''' Counts the events at one instant, across advances. Touching bodies can legitimately collide
    ''' many times at one instant (a chain passing an impulse along, a light ball between heavy ones);
    ''' the rest rules end such a cascade (see RestRules), so an instant that takes more events than
    ''' this is a fault in the solver, reported rather than skipped over.
    ''' </summary>
    Private Sub CountInstant(t As Double)
        If t = _s.Now Then
            _instantEvents += 1
            If _instantEvents > 1_000_000L + 1000L * _s.Bodies.Count Then StuckAt(t)
        Else
            _instantEvents = 0
        End If
    End Sub

    ''' <summary>More events in one advance than any scene should need: the run cannot go on.</summary>
    Private Sub TooManyEvents()
        Throw New InvalidOperationException($"more than {MaxEventsPerAdvance} events in one advance (t = {_s.Now} s)")
    End Sub

    ''' <summary>Too many events at one instant: the run cannot go on (thrown apart so CountInstant stays small).</summary>
    Private Sub StuckAt(t As Double)
        Throw New InvalidOperationException($"the event solver could not get past t = {t} s ({_instantEvents} events at that instant)")
    End Sub

    Private Sub RescheduleTouched()
        Dim touched = _s.Touched
        For k = 0 To touched.Count - 1
            _predictor.Reschedule(touched(k))
        Next
        touched.Clear()
    End Sub

    ''' <summary>
    ''' Keeps predictions valid after a change outside the solver. Nothing (g, e, walls, size, clear),
    ''' a fixed body, or an added or removed body: rebuild everything at the next advance. A movable
    ''' body that was pushed, moved, dragged or released: re-read it, and reschedule it (events of
    ''' others with it become stale through its counter).
    ''' </summary>
    Public Sub Invalidate(body As Shape) Implements ISolver.Invalidate
        _linked.Invalidate()
        Dim w = _s.World
        If _dirty OrElse w Is Nothing Then Return
        Dim i = _s.Bodies.IndexOf(body)
        If i < 0 OrElse body.IsFixed OrElse Not w.Movables.Contains(body) Then
            _dirty = True
            Return
        End If
        If OverlapsSomething(body) Then
            _dirty = True ' the rebuild pushes the overlap apart first
            Return
        End If
        _rest.ForgetRest(body)
        _s.Bodies.Reload(i, w, _s.Now)
        _s.StopRoaming(i)
        _s.Changed(i)
        _s.MoveToCellOfPosition(i)
        _rest.WakeAbove(i)
        RescheduleTouched()
    End Sub

    ''' <summary>Re-reads the whole world: after a global change, or when bodies were added or removed.</summary>
    Private Sub Rebuild()
        Dim w = _s.World
        OverlapResolver.Resolve(w)
        _s.G = w.Gravity
        _s.E = w.Restitution
        _s.Walls = w.Walls
        _s.Width = w.Width
        _s.Height = w.Height
        _s.Now = w.Time
        _s.HandOver = False
        _s.Obstacles.Load(w)
        _s.Bodies.Load(w, _s.Now)
        _s.Shapes.Clear()
        Dim n = _s.Bodies.Count
        _s.Touched.Reset(n)
        _predictor.Reset(n)
        _slides.Reset(n)
        _rest.Reset()
        GridLayout.Lay(_s, If(CellOccupancy > 0, CellOccupancy, GridLayout.BodiesPerCell(VectorScan)))
        _s.Queue.Reset(Enumerable.Repeat(Double.PositiveInfinity, n).ToArray(), n)
        For i = 0 To n - 1
            _predictor.Reschedule(i)
        Next
        _dirty = False
    End Sub

    ''' <summary>Whether body c (just moved or added by the user) overlaps anything it collides with, beyond rounding.</summary>
    Private Function OverlapsSomething(c As Shape) As Boolean
        Dim tol = SolverState.SlopAt(c.Position.X, c.Position.Y)
        For Each o In _s.World.Bodies
            If o Is c Then Continue For
            Dim depth As Double
            If c.Kind = ShapeKind.Circle AndAlso o.Kind = ShapeKind.Circle Then
                depth = c.Outline.Radius + o.Outline.Radius - (c.Position - o.Position).Length
            Else
                depth = OutlineContact.Penetration(_s.Shapes.Difference(o.Outline, c.Outline), c.Position - o.Position).Depth
            End If
            If depth > tol Then Return True
        Next
        Return False
    End Function

    ''' <summary>The dragged body moves in a straight line to its target over this advance, with no gravity.</summary>
    Private Sub StartDrag(duration As Double)
        Dim i = _s.Bodies.IndexOf(_s.World.DraggedBody)
        If i < 0 Then Return
        _s.Sync(i)
        Dim target = _s.World.DragTarget
        Dim b = _s.Bodies
        b.SetMode(i, BodyMode.Dragged)
        b.Motion(i).Ay = 0
        b.Motion(i).Ax = 0
        b.Info(i).InverseMass = 0
        b.Motion(i).Vx = (target.X - b.Motion(i).Px) / duration
        b.Motion(i).Vy = (target.Y - b.Motion(i).Py) / duration
        _s.Changed(i)
        RescheduleTouched()
    End Sub

    ''' <summary>Writes every movable body's exact state at <paramref name="t"/> back to the model.</summary>
    Private Sub WriteBack(t As Double)
        Dim b = _s.Bodies
        Dim dragged = _s.World.DraggedBody
        For i = 0 To b.Count - 1
            Dim c = b.Shapes(i)
            If b.Mode(i) = BodyMode.Rounding Then
                Dim position, velocity As Vector
                _slides.StateAt(i, t, position, velocity)
                c.Position = position
                c.Velocity = velocity
                Continue For
            End If
            Dim x, y, vx, vy As Double
            b.Motion(i).StateAt(t, x, y, vx, vy)
            c.Position = New Vector(x, y)
            c.Velocity = New Vector(vx, vy)
            If c Is dragged Then c.Position = _s.World.DragTarget
        Next
    End Sub

    ''' <summary>When the fast path handed the world over to the general path (s; +∞: it has not).</summary>
    Friend ReadOnly Property HandedOverAt As Double
        Get
            Return _handedOverAt
        End Get
    End Property

    ''' <summary>Gridded bodies that did not fit in their cell's lanes (for tests).</summary>
    Friend ReadOnly Property OverflowCount As Integer
        Get
            Dim count = 0
            For i = 0 To _s.Bodies.Count - 1
                If _s.Bodies.Slot(i).Cell >= 0 AndAlso _s.Grid.LaneOf(i) < 0 Then count += 1
            Next
            Return count
        End Get
    End Property
End Class
