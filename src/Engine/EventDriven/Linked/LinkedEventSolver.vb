Option Strict On

''' <summary>
''' The event solver's loop for a world with links (docs/links.md, "Links in the event solver"; docs/contact.md).
''' Bodies move in groups: bodies joined by links, and bodies in lasting contact with each other. Each group
''' moves by its closed form where one exists (a pendulum, a body on a slack string flying its parabola, a body
''' on a spring, a dumbbell, a free body's parabola, bodies resting and sliding on flat faces:
''' <see cref="UniformMotion"/>), and is integrated with error control where none does (chains, bodies pressed on
''' round things or by springs: <see cref="ConstrainedMotion"/>). Balls, boxes and polygons alike: a link holds a
''' body at its centre of mass, which is the point the motions move (a body's reference point is that centre less
''' its outline's centroid), and shape matters only for contacts. The loop reads as the event solver's: find the
''' earliest event → advance to it → resolve it → regroup what it changed. Events are a group's own (a string
''' going slack or snapping taut, a contact lifting off or leaving its face) and new contacts, found by
''' conservative advancement (<see cref="ConservativeAdvancement"/>): from bounds on the speeds and accelerations
''' it proves how long each gap stays open, so no contact is stepped over, and ends on the first one to rounding.
''' A contact is resolved with the links and lasting contacts of both bodies in one exact solve
''' (<see cref="LinkedImpulse"/>). After every event the bodies it changed are grouped anew by one rule
''' (LinkedEventSolver.Contacts.vb): the contacts that press, found by the complementarity solve of the contact
''' forces, are held; the rest are free. Every pair is predicted again after an event that changes one of its
''' bodies: fine for the classroom scenes with links (tens of bodies), not for a gas.
''' </summary>
Partial Friend NotInheritable Class LinkedEventSolver
    ' Gaps this close count as touching, m; a touching pair that does not approach collides only if it overlaps by this much.
    Private Const Slop As Double = 0.000000001
    ' Events at one instant (a cascade through a row of touching balls) beyond this are a fault, reported.
    Private Const MaxInstantEvents As Integer = 100000
    ' Contacts are looked for this far ahead at most, s, so that the speed bounds (which grow with the
    ' time looked ahead, for a falling body) stay tight; at its end the search is taken up again. About
    ' one frame of the app: a horizon of 0.1 s made a rope's searches come in lumps (a frame in the app
    ' took up to 25 ms on Mono; with 0.02 s, under 10 ms).
    Private Const Horizon As Double = 0.02
    ' The spacing of doubles just above 1: a time t is held to within t times this.
    Private Const UnitRoundoff As Double = 0.00000000000000022204460492503131
    ' A touching pair closes if it approaches faster than this (m/s) plus a billionth of its speeds (ClosingSpeed):
    ' slower is rounding left over from a cascade, and would only report collisions of nothing.
    Private Const CreepSpeed As Double = 0.000000000001
    ' Two sharp shapes touching: how many steps (of the speed bound alone) to spend looking for the gap to
    ' open before searching for the overlap to grow instead.
    Private Const SharpOpeningBudget As Integer = 64
    ' Predictions look to their horizon whatever the advance's end, and are kept from one advance to the
    ' next: a search that began at an advance's end, or stopped there, would find a contact at a time a few
    ' ulps off the one a longer advance finds, so a run would depend on how it is cut into advances.
    Private Const Unbounded As Double = Double.PositiveInfinity

    Private ReadOnly _impulse As New LinkedImpulse()
    ' The energy drag, spring damping and inelastic blows take out of the world (World.Dissipated).
    Private ReadOnly _ledger As New DissipationLedger()
    Private _world As World
    Private _dirty As Boolean = True
    Private _now As Double
    Private _groups As New List(Of LinkedGroup)
    Private _bodies As Shape() = Array.Empty(Of Shape)()
    ' Each body's centroid offset (its centre less its reference point), and its extents from its centre, m.
    Private _offset As Vector() = Array.Empty(Of Vector)()
    Private _low As Vector() = Array.Empty(Of Vector)()
    Private _high As Vector() = Array.Empty(Of Vector)()
    Private _groupOf As Integer() = Array.Empty(Of Integer)()
    Private _slotOf As Integer() = Array.Empty(Of Integer)()
    Private _fixed As Shape() = Array.Empty(Of Shape)()
    ' The earliest contact predicted for each pair (i < j), each ball with each wall side and each fixed body, s.
    Private _pairTime As Double(,) = New Double(-1, -1) {}
    Private _wallTime As Double(,) = New Double(-1, -1) {}
    Private _fixedTime As Double(,) = New Double(-1, -1) {}
    Private _differences As Outline(,) = New Outline(-1, -1) {}
    ' For each pair (i < j): the Minkowski difference of j's outline and i's (for two balls, a point rounded by both radii).
    Private _pairDifferences As Outline(,) = New Outline(-1, -1) {}
    ' Collisions of the advance under way, reported when it is done.
    Private ReadOnly _reports As New List(Of CollisionRecord)
    ' Two balls joined by a rod can never meet: those pairs are never searched.
    Private ReadOnly _neverMeet As New HashSet(Of Long)
    ' Contacts found touching without approaching at the instant _quietAt (see Quiet).
    Private ReadOnly _quiet As New HashSet(Of Long)
    Private _quietAt As Double = Double.NaN
    ' Events within a nanosecond of the last instant, and when that instant was.
    Private _instant As Integer
    Private _lastTime As Double = Double.NaN
    ' The contacts (their keys' values) whose force fell to zero within this instant: none is held again within it.
    Private ReadOnly _releasedNow As New HashSet(Of Long)
    ' Whether a motion ended within this instant by a string's pull or a contact's push falling to zero (see TakesOverFromZero).
    Private _anyReleasedNow As Boolean
    ' The contacts (their keys' values) found within this instant approaching only as a tie in line lets the body graze
    ' them (KeptOpenByATie): the search does not find them closing now again.
    Private ReadOnly _keptOpenNow As New HashSet(Of Long)
    ' The contacts that went off the end of their face at this instant (ConstrainedMotion.LeftItsFeature): found again
    ' at that end with nothing along the face yet to say which way they go, they go onto the corner, not the face.
    Private ReadOnly _offFaceNow As New HashSet(Of Long)

    ''' <summary>Called when the world is given to the solver.</summary>
    Friend Sub Attach(world As World)
        _world = world
        _dirty = True
    End Sub

    ''' <summary>Anything changed outside the solver: read the world again at the next advance.</summary>
    Friend Sub Invalidate()
        _dirty = True
    End Sub

    ''' <summary>Advances exactly <paramref name="duration"/> s and writes every body's state back.</summary>
    Friend Sub Advance(duration As Double)
        AdvanceWithin(duration, Long.MaxValue)
    End Sub

    ''' <summary>
    ''' As <see cref="Advance"/>, stopping between two events once the wall clock passes <paramref name="deadline"/>
    ''' (Stopwatch ticks). The bodies are written back at the time reached, where the state is exact, and that time
    ''' is returned; the next advance carries on from the same predictions, as one long advance would. It starts at
    ''' <paramref name="start"/> (s) when given, the world's bodies being there then (the fast path hands over mid-advance),
    ''' and ends at <paramref name="finish"/> (s) when given: the end of the fast path's advance to the bit (start plus
    ''' what was left of it may round off it, and the next advance would then start the solver afresh, its motions
    ''' rounded differently from those of a run sampled at other times).
    ''' </summary>
    Friend Function AdvanceWithin(duration As Double, deadline As Long, Optional start As Double = Double.NaN, Optional finish As Double = Double.NaN) As Double
        If Double.IsNaN(start) Then start = _world.Time
        If _dirty OrElse _now <> start Then Rebuild(start)
        _reports.Clear()
        Dim reached = AdvanceTo(If(Double.IsNaN(finish), _now + duration, finish), deadline)
        For Each r In _reports
            _world.ReportCollision(r)
        Next
        _reports.Clear()
        Return reached
    End Function

    Private Function AdvanceTo(tEnd As Double, deadline As Long) As Double
        Dim first = True
        Do
            Dim kind As LinkedEventKind, i As Integer, j As Integer
            Dim t = Earliest(kind, i, j)
            If Not (t <= tEnd) Then Exit Do
            ' The clock is read at every event but the first (every advance moves on by one at least): each costs
            ' microseconds here, a regroup milliseconds.
            If Not first AndAlso Diagnostics.Stopwatch.GetTimestamp() > deadline Then
                ' Out of wall-clock time: stop here, between two events, though they be at one instant (the
                ' count of events within it carries over to the next advance, so a run stuck at one instant is
                ' still reported, and a window showing it is not frozen while it is).
                WriteBack(_now)
                Return _now
            End If
            first = False
            CountInstant(t)
            _now = t
            Select Case kind
                Case LinkedEventKind.GroupEnds : TransitionOf(i, t, Unbounded)
                Case LinkedEventKind.Pair : Collide(i, j, WallSide.None, -1, t, Unbounded, Wedged(i, j))
                Case LinkedEventKind.Wall : Collide(i, -1, CType(j, WallSide), -1, t, Unbounded, Wedged(i, -1))
                Case Else : Collide(i, -1, WallSide.None, j, t, Unbounded, Wedged(i, -1))
            End Select
        Loop
        _now = tEnd
        WriteBack(tEnd)
        Return tEnd
    End Function

    ''' <summary>
    ''' The speed (m/s) above which a touching pair whose speeds add up to <paramref name="speeds"/> (m/s) closes:
    ''' <see cref="CreepSpeed"/> plus a billionth of those speeds. Slower is rounding left over from a blow.
    ''' </summary>
    Private Shared Function ClosingSpeed(speeds As Double) As Double
        Return CreepSpeed + 0.000000001 * speeds
    End Function

    ''' <summary>
    ''' Counts the events within a nanosecond of each other, across advances, so that a run of events creeping
    ''' forward by rounding errors is caught as surely as a run at one instant: more than any cascade needs is a
    ''' fault in the solver, reported rather than skipped over.
    ''' </summary>
    Private Sub CountInstant(t As Double)
        If t - _lastTime <= 0.000000001 Then
            _instant += 1
            If _instant > MaxInstantEvents Then Throw New InvalidOperationException($"the event solver could not get past t = {t} s with links ({_instant} events within a nanosecond)")
        Else
            _instant = 0
            _lastTime = t
            Array.Clear(_hitsNow, 0, _hitsNow.Length)
            _releasedNow.Clear()
            _anyReleasedNow = False
            _keptOpenNow.Clear()
            _offFaceNow.Clear()
        End If
    End Sub

    ''' <summary>Reads the world: groups from the links, then every group's motion by the one rule, from the state now.</summary>
    Private Sub Rebuild(start As Double)
        Dim w = _world
        _now = start
        _instant = 0
        _lastTime = Double.NaN
        Dim bodies = w.Movables.ToList()
        _bodies = bodies.ToArray()
        For Each g In _groups
            Retire(g.Motion)
        Next
        _groups = FormGroups(w, bodies)
        Dim n = _bodies.Length
        _offset = New Vector(n - 1) {}
        _low = New Vector(n - 1) {}
        _high = New Vector(n - 1) {}
        For i = 0 To n - 1
            Dim o = _bodies(i).Outline
            _offset(i) = o.Centroid
            _low(i) = New Vector(o.MinX - _offset(i).X, o.MinY - _offset(i).Y)
            _high(i) = New Vector(o.MaxX - _offset(i).X, o.MaxY - _offset(i).Y)
        Next
        _groupOf = New Integer(n - 1) {}
        _slotOf = New Integer(n - 1) {}
        _hitsNow = New Integer(n - 1) {}
        _fixed = w.Bodies.Where(Function(b) b.IsFixed).ToArray()
        _differences = New Outline(n - 1, _fixed.Length - 1) {}
        For i = 0 To n - 1
            For f = 0 To _fixed.Length - 1
                _differences(i, f) = Outline.MinkowskiDifference(_fixed(f).Outline, _bodies(i).Outline)
            Next
        Next
        _pairDifferences = New Outline(n - 1, n - 1) {}
        For i = 0 To n - 1
            For j = i + 1 To n - 1
                _pairDifferences(i, j) = Outline.MinkowskiDifference(_bodies(j).Outline, _bodies(i).Outline)
            Next
        Next
        _neverMeet.Clear()
        For Each l In w.Links
            If l.Kind <> LinkKind.Rod OrElse l.B Is Nothing OrElse l.B.IsFixed Then Continue For
            Dim a = Array.IndexOf(_bodies, l.A), b = Array.IndexOf(_bodies, l.B)
            If BothBalls(a, b) Then _neverMeet.Add(PairKey(a, b))
        Next
        _pairTime = New Double(n - 1, n - 1) {}
        _wallTime = New Double(n - 1, 4) {}
        _fixedTime = New Double(n - 1, Math.Max(_fixed.Length, 1) - 1) {}
        For g = 0 To _groups.Count - 1
            _groups(g).Motion = New SnapshotMotion(_groups(g).Bodies.ToArray(), _now)
            For Each c In _groups(g).Bodies
                Dim i = Array.IndexOf(_bodies, c)
                _groupOf(i) = g
                _slotOf(i) = _groups(g).Bodies.IndexOf(c)
            Next
        Next
        _dirty = False
        Regroup(Enumerable.Range(0, _groups.Count).ToList(), _now, Nothing)
        PredictAll(Unbounded)
    End Sub

    ''' <summary>The height of body i's lowest point as written to it, m.</summary>
    Private Function Lowest(i As Integer) As Double
        Return _bodies(i).Position.Y + _bodies(i).Outline.MinY
    End Function

    Private Function BothBalls(i As Integer, j As Integer) As Boolean
        Return _bodies(i).Kind = ShapeKind.Circle AndAlso _bodies(j).Kind = ShapeKind.Circle
    End Function

    Private Shared Function PairKey(i As Integer, j As Integer) As Long
        Return CLng(Math.Min(i, j)) * Integer.MaxValue + Math.Max(i, j)
    End Function

    ''' <summary>Bodies joined through links, by union–find; a link to a fixed body or a point joins nothing.</summary>
    Private Shared Function FormGroups(w As World, bodies As List(Of Shape)) As List(Of LinkedGroup)
        Dim index As New Dictionary(Of Shape, Integer)
        For i = 0 To bodies.Count - 1
            index(bodies(i)) = i
        Next
        Dim parent = Enumerable.Range(0, bodies.Count).ToArray()
        For Each l In w.Links
            Dim a As Integer, b As Integer
            If Not index.TryGetValue(l.A, a) Then Continue For
            If l.B Is Nothing OrElse l.B.IsFixed OrElse Not index.TryGetValue(l.B, b) Then Continue For
            parent(Root(parent, a)) = Root(parent, b)
        Next
        Dim byRoot As New Dictionary(Of Integer, LinkedGroup)
        Dim groups As New List(Of LinkedGroup)
        For i = 0 To bodies.Count - 1
            Dim r = Root(parent, i)
            Dim g As LinkedGroup = Nothing
            If Not byRoot.TryGetValue(r, g) Then
                g = New LinkedGroup(New List(Of Shape), New List(Of Link))
                byRoot(r) = g
                groups.Add(g)
            End If
            g.Bodies.Add(bodies(i))
        Next
        For Each l In w.Links
            Dim a As Integer
            If index.TryGetValue(l.A, a) Then byRoot(Root(parent, a)).Links.Add(l)
        Next
        Return groups
    End Function

    ''' <summary>The root of x's set in a union–find forest, halving the path on the way.</summary>
    Private Shared Function Root(parent As Integer(), x As Integer) As Integer
        Do While parent(x) <> x
            parent(x) = parent(parent(x))
            x = parent(x)
        Loop
        Return x
    End Function

    ''' <summary>Writes group g's bodies' states at <paramref name="t"/> to them: the motion's centre less the centroid offset is the reference point.</summary>
    Private Sub Sync(g As Integer, t As Double)
        Dim m = _groups(g).Motion
        If m Is Nothing Then Return
        Dim n = m.Bodies.Length
        Dim positions(n - 1) As Vector, velocities(n - 1) As Vector
        m.StatesAt(t, positions, velocities)
        For k = 0 To n - 1
            Dim body = m.Bodies(k)
            body.Position = positions(k) - _offset(Array.IndexOf(_bodies, body))
            body.Velocity = velocities(k)
        Next
    End Sub

    Private Sub WriteBack(t As Double)
        For g = 0 To _groups.Count - 1
            Sync(g, t)
            _groups(g).Motion.UpdateTensions(t)
            _ledger.Settle(_groups(g), _world, t)
        Next
    End Sub

    ''' <summary>The earliest predicted event: a group's end (i the group), a pair (i, j), a wall (i, side j) or a fixed body (i, j).</summary>
    Private Function Earliest(ByRef kind As LinkedEventKind, ByRef i As Integer, ByRef j As Integer) As Double
        Dim best = Double.PositiveInfinity
        For g = 0 To _groups.Count - 1
            Dim t = _groups(g).Motion.TransitionTime
            If t < best Then best = t : kind = LinkedEventKind.GroupEnds : i = g
        Next
        Dim n = _bodies.Length
        For a = 0 To n - 1
            For b = a + 1 To n - 1
                If _pairTime(a, b) < best Then best = _pairTime(a, b) : kind = LinkedEventKind.Pair : i = a : j = b
            Next
            For s = 1 To 4
                If _wallTime(a, s) < best Then best = _wallTime(a, s) : kind = LinkedEventKind.Wall : i = a : j = s
            Next
            For f = 0 To _fixed.Length - 1
                If _fixedTime(a, f) < best Then best = _fixedTime(a, f) : kind = LinkedEventKind.Fixed : i = a : j = f
            Next
        Next
        Return best
    End Function

    Private Function MotionOf(i As Integer) As LinkedMotion
        Return _groups(_groupOf(i)).Motion
    End Function

    ''' <summary>
    ''' Group g's motion ends (a string goes slack or snaps taut, a contact lifts off or leaves its face, or an
    ''' integrated group's look-ahead runs out): do what happens there, report a string snapping taut, and group
    ''' its bodies anew.
    ''' </summary>
    Private Sub TransitionOf(g As Integer, t As Double, tEnd As Double)
        Dim m = _groups(g).Motion
        If m.LookFurther(t) Then
            ' It goes on as it was, looked at further: its bodies' searches, which stopped here, go on from here.
            Repredict(m.Bodies.Select(Function(b) Array.IndexOf(_bodies, b)).ToList(), tEnd)
            Return
        End If
        Sync(g, t)
        Dim before = m.Bodies.Select(Function(b) b.Velocity).ToArray()
        Dim kinetic = DissipationLedger.Kinetic(m.Bodies)
        m.Snapped = Nothing
        m.Transition(_world)
        DissipationLedger.Blow(_world, kinetic, m.Bodies)
        Dim l = m.Snapped
        If l IsNot Nothing Then
            Dim a = Array.IndexOf(m.Bodies, l.A), b = If(l.IsAnchored, -1, Array.IndexOf(m.Bodies, l.B))
            _reports.Add(New CollisionRecord(t, l, before(a), l.A.Velocity, If(b >= 0, before(b), Vector.Zero), If(b >= 0, l.B.Velocity, Vector.Zero)))
        End If
        ' Something let go at this instant: a contact the search finds closing at once may take over from it.
        If m.Released IsNot Nothing Then _anyReleasedNow = True
        ' A contact let go at this instant is not held again within it: at a point where two contacts' forces both reach
        ' zero, each group formed without one found the other's force falling through zero at once, and the two groups
        ' took turns for ever, a few units in the last place of the clock apart.
        Dim key = TryCast(m.Released, ContactKey)
        If key IsNot Nothing Then _releasedNow.Add(key.Value)
        ' A contact that left its face at once, from exactly its end (a ball balanced on a box's corner, its speed and
        ' acceleration along the face both nothing, pushed off by a spring whose pull only grows): the face would be
        ' chosen again and left again at once, for ever.
        Dim leaving = TryCast(TryCast(m, ConstrainedMotion)?.LeftItsFeature, ContactKey)
        If leaving IsNot Nothing Then _offFaceNow.Add(leaving.Value)
        Repredict(Regroup(New List(Of Integer) From {g}, t, m.Released), tEnd)
    End Sub

    ''' <summary>
    ''' Body i hits body j (i &lt; j), a wall or fixed body f at t: resolve it with the links and lasting contacts
    ''' of both, report it, and group the bodies anew; when <paramref name="wedged"/>, or always with e = 0, with every
    ''' contact touching the bodies it moves too (LinkedEventSolver.Wedge.vb).
    ''' </summary>
    Private Sub Collide(i As Integer, j As Integer, side As WallSide, f As Integer, t As Double, tEnd As Double, wedged As Boolean)
        ' With no bounce, a blow is resolved with every contact touching the bodies it moves from the first: pairwise,
        ' the approach it leaves between a body wedged in a cluster and the next is passed round and round.
        If _world.Restitution = 0 Then wedged = True
        Dim gi = _groupOf(i)
        Dim gj = If(j >= 0, _groupOf(j), -1)
        Sync(gi, t)
        If gj >= 0 AndAlso gj <> gi Then Sync(gj, t)
        Dim gap As LinkedGap
        If j >= 0 Then
            gap = PairGap(i, j)
        ElseIf f >= 0 Then
            gap = FixedGap(i, f)
        Else
            gap = WallGap(i, side)
        End If
        Dim normal As Vector, rate As Double
        Dim depth = gap.GapAndNormal(t, normal, rate)
        Dim speeds = _bodies(i).Velocity.Length + If(j >= 0, _bodies(j).Velocity.Length, 0)
        ' Time itself is rounded: a body at 2·10⁷ m/s moves 0.3 nm in one unit in the last place of t = 0.1 s, so the
        ' nearest instant to the touch may leave a gap of a few of those (a search found the same instant for ever).
        Dim clockSlop = Math.Abs(rate) * 4 * Math.Abs(t) * UnitRoundoff
        If depth > Slop + clockSlop Then
            ' Not a contact: a search that reached its horizon or its budget. Only this prediction is taken up again
            ' from now: nothing has moved differently, so body i's others stand.
            PredictAgain(i, j, side, f, tEnd)
            Return
        End If
        Dim key = If(j >= 0, ContactKey.Pair(i, j), If(f >= 0, ContactKey.Fixed(i, f), ContactKey.Wall(i, side)))
        Dim approaching = rate < -ClosingSpeed(speeds)
        Dim grazing = approaching AndAlso j < 0 AndAlso KeptOpenByATie(i, normal)
        If Not approaching OrElse grazing Then
            ' Touching, not approaching, and pressed together (or pressed in by a slop): whether the touch holds is
            ' for the one rule to say. From here on, this instant, the touch is searched for, not solved for.
            ' Or approaching only as a tie in line with it lets the body graze it (a bob through the bottom of its swing
            ' just touching the floor): the tie keeps it from pushing, and the same blow would be struck again at once.
            Quiet(key, t)
            If grazing Then _keptOpenNow.Add(key.Value)
            Dim touched As New List(Of Integer) From {gi}
            If gj >= 0 AndAlso gj <> gi Then touched.Add(gj)
            Repredict(Regroup(touched, t, Nothing), tEnd)
            Return
        End If
        ' A corner on a corner of two sharp shapes takes the bisector of the pair shape's corner (docs/shapes.md).
        If gap.Difference IsNot Nothing Then normal = gap.ContactNormal(t)
        Dim a = _bodies(i)
        Dim b = If(j >= 0, _bodies(j), Nothing)
        Dim aBefore = a.Velocity
        Dim bBefore = If(b Is Nothing, Vector.Zero, b.Velocity)
        _impulse.Clear()
        _impulse.AddContact(a, b, normal, _world.Restitution)
        Dim groups As New List(Of Integer) From {gi}
        If gj >= 0 AndAlso gj <> gi Then groups.Add(gj)
        For Each g In groups
            AddHeldRows(g)
        Next
        If wedged Then groups = AddTouchingContacts(i, j, side, f, t, groups)
        Dim kinetic = _impulse.KineticEnergy
        If wedged Then
            _impulse.ResolveWedged(_world.Restitution)
            ' The wedged solve's tolerance is set by the fastest body it gathered, but whether a touch is struck is judged by
            ' its own bodies' speeds: left approaching beyond that, it is solved again to below a creep (a 1 µg ball in a
            ' corner, a 484 t box pressing it there in a group with balls at 1 m/s, was left approaching the wall at
            ' 1.5·10⁻¹² m/s, struck alone, and pushed in again by the box, for ever).
            If SeparationSpeed(a, b, normal) < -ClosingSpeed(speeds) Then _impulse.ResolveWedgedAgain(_world.Restitution, 0.5 * CreepSpeed)
        Else
            _impulse.Resolve()
        End If
        ' A corner on a corner whose blow along the bisector still leaves it closing on both faces there (the other
        ' rows held it back) is a blow on the two faces at once, resolved as wedged bodies are (Poisson's rule).
        Dim first As Vector, second As Vector
        If gap.SharpCorner(t, first, second) AndAlso StillCloses(a, b, first, second, aBefore, bBefore) Then
            _impulse.AddContact(a, b, first, _world.Restitution)
            _impulse.AddContact(a, b, second, _world.Restitution)
            _impulse.ResolveWedged(_world.Restitution)
        End If
        Dim other = If(b, If(f >= 0, _fixed(f), Nothing))
        ' Friction at the blow's own contact, between bodies that do not turn (a ball would roll: docs/forces.md).
        If _world.HasFriction AndAlso a.Kind <> ShapeKind.Circle AndAlso (other Is Nothing OrElse other.Kind <> ShapeKind.Circle) Then
            _impulse.Rub(ContactFriction.Mean(_world.StaticFrictionOf(a), _world.StaticFrictionOf(other)),
                         ContactFriction.Mean(_world.KineticFrictionOf(a), _world.KineticFrictionOf(other)))
        End If
        Dim lost = kinetic - _impulse.KineticEnergy
        If lost > 0 Then _world.Dissipate(lost)
        ' The blow is solved to a part in 10¹² of the fastest body it moves, and a group's rows bring in all its bodies:
        ' a contact that approached by less than that, but by more than a creep, was left approaching, and would be
        ' struck again at once, for ever (a 2 mg ball left at 10⁻¹² m/s against a wall beside a 187 t ball sliding at
        ' 1.3 m/s). It is stopped by a blow of its own bodies alone.
        If SeparationSpeed(a, b, normal) < -ClosingSpeed(speeds) Then
            _impulse.Clear()
            _impulse.AddContact(a, b, normal, _world.Restitution)
            Dim before = _impulse.KineticEnergy
            _impulse.Resolve()
            Dim stopped = before - _impulse.KineticEnergy
            If stopped > 0 Then _world.Dissipate(stopped)
        End If
        _reports.Add(New CollisionRecord(t, a, other, side, CollisionKinds.Between(a, other), aBefore, a.Velocity, bBefore, If(b Is Nothing, Vector.Zero, b.Velocity)))
        Repredict(Regroup(groups, t, Nothing), tEnd)
    End Sub

    ''' <summary>
    ''' Whether a rod or taut string of body i to a fixed point lies in line with its contact of <paramref name="normal"/>
    ''' (from the body towards a wall or fixed body) and pulls the way that contact opens: the contact can never push
    ''' (<see cref="TieLock.ImpliedContacts"/>), and what it approaches at is only the tie's turning (a bob through the
    ''' bottom of its swing, just touching the floor). A string counts when it is at its full length, not stretching.
    ''' </summary>
    Private Function KeptOpenByATie(i As Integer, normal As Vector) As Boolean
        For Each l In _groups(_groupOf(i)).Links
            If Not l.IsAnchored OrElse l.A IsNot _bodies(i) Then Continue For
            If l.Kind = LinkKind.Spring Then Continue For
            If l.Kind = LinkKind.String AndAlso Not LinkedMotions.IsTaut(l, _world.Gravity, Slop) Then Continue For
            If TieLock.KeepsOpen((l.EndB - l.EndA).Normalized(Vector.Zero), -normal) Then Return True
        Next
        Return False
    End Function

    ''' <summary>
    ''' Whether a blow's bodies a and b (b Nothing: fixed) still close on both faces with normals <paramref name="first"/>
    ''' and <paramref name="second"/> (from a towards b), beyond rounding of the speeds they had before it.
    ''' </summary>
    Private Shared Function StillCloses(a As Shape, b As Shape, first As Vector, second As Vector, aBefore As Vector, bBefore As Vector) As Boolean
        Dim u = a.Velocity - If(b Is Nothing, Vector.Zero, b.Velocity)
        Dim tolerance = ClosingSpeed(aBefore.Length + bBefore.Length)
        Return Vector.Dot(u, first) > tolerance AndAlso Vector.Dot(u, second) > tolerance
    End Function

    ''' <summary>How fast (m/s) b (Nothing: fixed) moves away from a along <paramref name="normal"/> (from a towards b); negative when they approach.</summary>
    Private Shared Function SeparationSpeed(a As Shape, b As Shape, normal As Vector) As Double
        Return Vector.Dot(If(b Is Nothing, Vector.Zero, b.Velocity) - a.Velocity, normal)
    End Function

    ''' <summary>
    ''' Marks contact <paramref name="key"/> as touching without approaching at <paramref name="t"/>: its parabolas'
    ''' exact contact time would be "now" again (they press), so until the clock moves on it is searched for instead.
    ''' </summary>
    Private Sub Quiet(key As ContactKey, t As Double)
        If t <> _quietAt Then
            _quiet.Clear()
            _quietAt = t
        End If
        _quiet.Add(key.Value)
    End Sub

    ''' <summary>Whether contact <paramref name="key"/> was found touching without approaching now.</summary>
    Private Function IsQuiet(key As ContactKey) As Boolean
        Return _quietAt = _now AndAlso _quiet.Contains(key.Value)
    End Function

    ''' <summary>Whether contact <paramref name="key"/> was found within this instant approaching only as a tie in line with it lets its body graze it.</summary>
    Private Function KeptOpenNow(key As ContactKey) As Boolean
        Return _keptOpenNow.Contains(key.Value)
    End Function

    ''' <summary>Group g's held links, lasting contacts and locks as rows of the blow under way: they hold through it.</summary>
    Private Sub AddHeldRows(g As Integer)
        _impulse.AddHeldRowsOf(_groups(g).Motion)
    End Sub
End Class
