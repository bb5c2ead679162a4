Option Strict On

#If NET Then
Imports System.Runtime.Intrinsics
#End If

''' <summary>
''' The exact, event-driven solver. Between events every free circle follows its parabola exactly;
''' collision times are computed in closed form or by root isolation (<see cref="TimeOfImpact"/>),
''' never detected after the fact, so nothing tunnels at any speed. One step reads as its pipeline:
''' find the earliest event → advance the clock to it → resolve it → reschedule the bodies involved.
''' Bouncing with e &lt; 1 ends in a resting state at the exact time the infinite series of bounces
''' ends; piles go to sleep. See docs/event-driven.md.
''' </summary>
Partial Public NotInheritable Class EventDrivenSolver
    Implements ISolver

    ' Per movable circle. The motion (what every prediction reads) is packed in one struct per body,
    ' one cache line, see BodyState; the rest is kept in parallel arrays.
    Private _n As Integer
    Private _circle As Circle() = Array.Empty(Of Circle)()
    Private _body As BodyState() = Array.Empty(Of BodyState)()
    Private _invMass As Double() = Array.Empty(Of Double)()
    ''' <summary>What a resting circle rests on: rectangle index ≥ 0, or <see cref="SupportFloor"/>/<see cref="SupportOther"/>.</summary>
    Private _support As Integer() = Array.Empty(Of Integer)()
    ''' <summary>Time of the body's last collision, s (for the inelastic-collapse guard).</summary>
    Private _lastHit As Double() = Array.Empty(Of Double)()
    ''' <summary>Start (s) and size of the body's current burst of collisions (for the sleeping rule).</summary>
    Private _burstStart As Double() = Array.Empty(Of Double)()
    Private _burstCount As Integer() = Array.Empty(Of Integer)()
    ''' <summary>Instant (s) of the body's last collision and how many it had at that instant (jam detection).</summary>
    Private _sameTime As Double() = Array.Empty(Of Double)()
    Private _sameCount As Integer() = Array.Empty(Of Integer)()

    ' The next event of each body (one slot per body): its time is filed in the calendar queue, the
    ' rest of it, with the body's counter and cell, is kept in one struct (see EventSlot).
    Private _ev As EventSlot() = Array.Empty(Of EventSlot)()

    ' Sliding over a corner: centre of the arc, its radius, direction (±1), starting speed, leave angle, start and end times.
    Private _slideCx As Double() = Array.Empty(Of Double)()
    Private _slideCy As Double() = Array.Empty(Of Double)()
    Private _slideDir As Double() = Array.Empty(Of Double)()
    Private _slideV0 As Double() = Array.Empty(Of Double)()
    Private _slideAngle As Double() = Array.Empty(Of Double)()
    Private _slideStart As Double() = Array.Empty(Of Double)()

    ' Static obstacles: fixed circles 0 … _nFixed − 1, then rectangles (static index _nFixed + k).
    Private _nFixed As Integer
    Private _fixed As Circle() = Array.Empty(Of Circle)()
    Private _fx As Double() = Array.Empty(Of Double)()
    Private _fy As Double() = Array.Empty(Of Double)()
    Private _fr As Double() = Array.Empty(Of Double)()
    Private _nRect As Integer
    Private _rect As Rectangle() = Array.Empty(Of Rectangle)()
    Private _rx0 As Double() = Array.Empty(Of Double)()
    Private _ry0 As Double() = Array.Empty(Of Double)()
    Private _rx1 As Double() = Array.Empty(Of Double)()
    Private _ry1 As Double() = Array.Empty(Of Double)()

    ''' <summary>Circles too big for the grid: checked against everything.</summary>
    Private _oversized As Integer() = Array.Empty(Of Integer)()
    Private _nOversized As Integer
    ''' <summary>Scratch stack for waking a column of sleeping circles (no allocation per event).</summary>
    Private _stack As Integer() = Array.Empty(Of Integer)()
    ''' <summary>Contact normals gathered by IsHeld (scratch, fixed size).</summary>
    Private ReadOnly _normalX As Double() = New Double(15) {}
    Private ReadOnly _normalY As Double() = New Double(15) {}
    Private _nNormals As Integer
    ''' <summary>Scratch queue of bodies being woken.</summary>
    Private _wake As Integer() = Array.Empty(Of Integer)()
    ''' <summary>Scratch list of the bodies of one cell being tested one by one.</summary>
    Private _scanList As Integer() = Array.Empty(Of Integer)()

    Private ReadOnly _grid As New UniformGrid()
    Private ReadOnly _queue As New EventQueue()
    Private ReadOnly _index As New Dictionary(Of Circle, Integer)()
    Private ReadOnly _restTimes As New Dictionary(Of Circle, Double)()

    Private _world As World
    Private _dirty As Boolean = True
    ''' <summary>The solver's clock, s (absolute, like World.Time).</summary>
    Private _now As Double
    ' Snapshot of the world's parameters, taken at each rebuild.
    Private _g As Double
    Private _e As Double
    Private _walls As Boolean
    Private _width As Double
    Private _height As Double
    ''' <summary>Distance (m) within which bodies count as touching: rounding, never physics.</summary>
    Private _slop As Double

    ''' <summary>Largest radius (m) of a circle in the grid.</summary>
    Private _rMax As Double
    ''' <summary>How many bodies are sliding round a corner (see <see cref="ReachOfPath"/>).</summary>
    Private _sliding As Integer

    Private Const SupportNone As Integer = -1
    Private Const SupportFloor As Integer = -2
    Private Const SupportOther As Integer = -3

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
    ''' Runaway guard: the most events (collisions, cell crossings, …) one <see cref="Advance"/> may
    ''' process. When reached, the rest of the advance is done ballistically, overlaps are pushed
    ''' apart and <see cref="GuardTripped"/> is set.
    ''' </summary>
    Public Property MaxEventsPerAdvance As Long = 100_000_000

#If NET Then
    Private _vectorScan As Boolean = Vector256.IsHardwareAccelerated

    ''' <summary>
    ''' Whether pair tests run four lanes at a time (256-bit vectors, when the processor has them).
    ''' Off, they run one body at a time, as on .NET Framework; the results are the same. Takes
    ''' effect at the next rebuild (it also sets the cell size).
    ''' </summary>
    Friend Property VectorScan As Boolean
        Get
            Return _vectorScan
        End Get
        Set(value As Boolean)
            _vectorScan = value
            _dirty = True
        End Set
    End Property
#Else
    ''' <summary>.NET Framework has no 256-bit vectors: pair tests run one body at a time.</summary>
    Private ReadOnly _vectorScan As Boolean
#End If
    ''' <summary>Average bodies per grid cell, when set (> 0): for tests that compare the pair tests on one grid.</summary>
    Friend Property CellOccupancy As Double

    ''' <summary>True once an advance hit <see cref="MaxEventsPerAdvance"/> or looped without time moving.</summary>
    Public ReadOnly Property GuardTripped As Boolean

    ''' <summary>Every event processed so far (collisions, cell crossings, stale re-predictions, …).</summary>
    Public ReadOnly Property EventCount As Long

    ''' <summary>
    ''' Grid cells searched for partners so far, summed over every prediction and cell crossing: with
    ''' <see cref="EventCount"/>, the work per event, which should not grow with the number of bodies.
    ''' </summary>
    Public ReadOnly Property CellsSearched As Long

    ''' <summary>Attaches the solver to a world; the first advance builds every prediction.</summary>
    Public Sub Attach(world As World) Implements ISolver.Attach
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        _world = world
        _dirty = True
    End Sub

    ''' <summary>
    ''' When a bouncing circle came to rest: the time (s) its infinite series of ever smaller bounces
    ''' ends, t + 2 v_n / (g (1 − e)). Nothing while it is not resting.
    ''' </summary>
    Public Function RestTime(circle As Circle) As Double?
        If circle Is Nothing Then Return Nothing
        Dim t As Double
        If _restTimes.TryGetValue(circle, t) Then Return t
        Return Nothing
    End Function

    ''' <summary>True when the circle is asleep (part of a settled pile, acting as a fixed obstacle).</summary>
    Public Function IsAsleep(circle As Circle) As Boolean
        If circle Is Nothing OrElse _dirty Then Return False
        Dim i As Integer
        Return _index.TryGetValue(circle, i) AndAlso _body(i).Mode = BodyMode.Sleeping
    End Function

    ''' <summary>
    ''' Advances exactly <paramref name="duration"/> seconds: find the earliest event, advance the
    ''' clock to it, resolve it, reschedule the bodies involved; repeat until the next event lies
    ''' beyond the end. Then every circle is written back at its exact state at the end.
    ''' </summary>
    Public Sub Advance(duration As Double) Implements ISolver.Advance
        If _world Is Nothing Then Throw New InvalidOperationException("the solver is not attached to a world")
        If _dirty OrElse _now <> _world.Time Then Rebuild()
        Dim tEnd = _world.Time + duration
        StartDrag(duration)
        Dim processed As Long = 0
        Dim sameTime = 0
        Dim sameTimeLimit = 1000 + 50 * _n
        Do
            Dim i = _queue.Top
            If i < 0 Then Exit Do
            Dim t = _queue.TimeOf(i)
            If Not (t <= tEnd) Then Exit Do
            If processed >= MaxEventsPerAdvance OrElse sameTime > sameTimeLimit Then
                TripGuard(tEnd)
                Return
            End If
            If t = _now Then sameTime += 1 Else sameTime = 0
            _now = t
            ProcessEvent(i)
            If CheckLanesEveryEvent Then CheckLanes()
            processed += 1
        Loop
        _EventCount += processed
        _now = tEnd
        WriteBack(tEnd)
    End Sub

    ''' <summary>
    ''' Keeps predictions valid after a change outside the solver. Nothing (g, e, walls, size, clear),
    ''' a fixed body, or an added or removed circle: rebuild everything at the next advance. A movable
    ''' circle that was pushed, moved, dragged or released: re-read it, and reschedule it (events of
    ''' others with it become stale through its counter).
    ''' </summary>
    Public Sub Invalidate(body As Shape) Implements ISolver.Invalidate
        If _dirty OrElse _world Is Nothing Then Return
        Dim c = TryCast(body, Circle)
        Dim i As Integer
        If c Is Nothing OrElse c.IsFixed OrElse Not _index.TryGetValue(c, i) OrElse Not _world.Circles.Contains(c) Then
            _dirty = True
            Return
        End If
        If OverlapsSomething(c) Then
            _dirty = True ' the rebuild pushes the overlap apart first
            Return
        End If
        _restTimes.Remove(c)
        LoadBody(i, c)
        Changed(i)
        MoveToCellOfPosition(i)
        WakeAbove(i)
        Reschedule(i)
    End Sub

    Private Sub TripGuard(tEnd As Double)
        _GuardTripped = True
        _now = tEnd
        WriteBack(tEnd)
        OverlapResolver.Resolve(_world)
        _dirty = True
    End Sub
End Class
