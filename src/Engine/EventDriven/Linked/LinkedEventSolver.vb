Option Strict On

''' <summary>
''' The event solver's loop for a world with links (docs/links.md, "Links in the event solver"). Each group
''' of linked bodies moves by its closed form (<see cref="LinkedMotions"/>): a pendulum, a body on a slack
''' string flying its parabola, a body on a spring, a dumbbell; a free body flies its parabola. Balls, boxes
''' and polygons alike: a link holds a body at its centre of mass, which is the point the closed forms move
''' (a body's reference point is that centre less its outline's centroid), and shape matters only for
''' contacts. The loop
''' reads as the event solver's: find the earliest event → advance to it → resolve it → re-predict what it
''' changed. Events are a string going slack or snapping taut (exact times from the closed forms) and
''' contacts, found by conservative advancement (<see cref="ConservativeAdvancement"/>): from bounds on the
''' speeds and accelerations it proves how long each gap stays open, so no contact is stepped over, and
''' ends on the first one to rounding. A contact is resolved with the links of both bodies in the same
''' solve (<see cref="LinkedImpulse"/>). A body that comes to rest on flat faces rests and slides on them
''' exactly (LinkedEventSolver.Rest.vb). What it cannot follow exactly (a box or polygon coming to rest on a
''' curve or on a body that swings, a body on a rod coming to rest) it refuses with
''' <see cref="UnsupportedSceneException"/>, and the world is put back as it was before the advance. Every pair is predicted again after an event that changes one of
''' its bodies: fine for the classroom scenes with links (tens of bodies), not for a gas.
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
    ' A touching pair closes if it approaches faster than this (m/s) plus a billionth of its speeds:
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
    ' For each pair (i < j) not of two balls: the Minkowski difference of j's outline and i's.
    Private _pairDifferences As Outline(,) = New Outline(-1, -1) {}
    ' Collisions of the advance under way, reported when it is done (none, if it is refused part-way).
    Private ReadOnly _reports As New List(Of CollisionRecord)
    ' Rods join their ends for good: those pairs are never tested.
    Private _rodPair As HashSet(Of Long) = New HashSet(Of Long)()

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
        If _dirty OrElse _now <> _world.Time Then
            Rebuild()
            PredictAll(Unbounded)
        End If
        Dim positions = _bodies.Select(Function(b) b.Position).ToArray()
        Dim velocities = _bodies.Select(Function(b) b.Velocity).ToArray()
        Dim tensions = _world.Links.Select(Function(l) l.Tension).ToArray()
        Dim dissipated = _world.Dissipated
        _reports.Clear()
        Try
            AdvanceTo(_now + duration)
        Catch ex As UnsupportedSceneException
            ' Refused part-way: the world goes back to where the advance started, as the exception promises.
            For i = 0 To _bodies.Length - 1
                _bodies(i).Position = positions(i)
                _bodies(i).Velocity = velocities(i)
            Next
            For k = 0 To _world.Links.Count - 1
                If _world.Links(k).Kind <> LinkKind.Spring Then _world.Links(k).SetTension(tensions(k))
            Next
            _world.RestoreDissipated(dissipated)
            _reports.Clear()
            _dirty = True
            Throw
        End Try
        For Each r In _reports
            _world.ReportCollision(r)
        Next
        _reports.Clear()
    End Sub

    Private Sub AdvanceTo(tEnd As Double)
        Dim instant = 0
        Dim lastTime = Double.NaN
        Do
            Dim kind As Integer, i As Integer, j As Integer
            Dim t = Earliest(kind, i, j)
            If Not (t <= tEnd) Then Exit Do
            ' Events within a nanosecond count as one instant, so that a run of events creeping forward by
            ' rounding errors is caught as surely as a run at one instant.
            If t - lastTime <= 0.000000001 Then
                instant += 1
                If instant > MaxInstantEvents Then Throw New InvalidOperationException($"the event solver could not get past t = {t} s with links ({instant} events within a nanosecond)")
            Else
                instant = 0
                lastTime = t
            End If
            _now = t
            Select Case kind
                Case 0 : TransitionOf(i, t, Unbounded)
                Case 1 : Collide(i, j, WallSide.None, -1, t, Unbounded, instant > WedgedAfter)
                Case 2 : Collide(i, -1, CType(j, WallSide), -1, t, Unbounded, instant > WedgedAfter)
                Case Else : Collide(i, -1, WallSide.None, j, t, Unbounded, instant > WedgedAfter)
            End Select
        Loop
        _now = tEnd
        WriteBack(tEnd)
    End Sub

    ''' <summary>Reads the world: groups from the links, then each group's closed form from its state now.</summary>
    Private Sub Rebuild()
        Dim w = _world
        _now = w.Time
        Dim bodies = w.Movables.ToList()
        Dim groups = FormGroups(w, bodies)
        LinkedMotions.CheckSupported(w, groups)
        _bodies = bodies.ToArray()
        _groups = groups
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
        Dim index As New Dictionary(Of Shape, Integer)
        For i = 0 To n - 1
            index(_bodies(i)) = i
        Next
        _rodPair.Clear()
        For g = 0 To _groups.Count - 1
            For Each c In _groups(g).Bodies
                _groupOf(index(c)) = g
            Next
            For Each l In _groups(g).Links
                If l.Kind = LinkKind.Rod AndAlso l.B IsNot Nothing AndAlso Not l.B.IsFixed Then _rodPair.Add(PairKey(index(l.A), index(l.B)))
            Next
        Next
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
                If Not BothBalls(i, j) Then _pairDifferences(i, j) = Outline.MinkowskiDifference(_bodies(j).Outline, _bodies(i).Outline)
            Next
        Next
        _pairTime = New Double(n - 1, n - 1) {}
        _wallTime = New Double(n - 1, 4) {}
        _fixedTime = New Double(n - 1, Math.Max(_fixed.Length, 1) - 1) {}
        _restOn = New RestSupport(n - 1)() {}
        _supportDifferences.Clear()
        ' Lowest first, so that a body resting on another finds it resting already.
        Dim lowest = Function(g As LinkedGroup) g.Bodies.Min(Function(b) b.Position.Y + b.Outline.MinY)
        For Each g In Enumerable.Range(0, _groups.Count).OrderBy(Function(k) lowest(_groups(k))).ToList()
            Restart(g, _now, False)
        Next
        _dirty = False
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
        Dim root As Func(Of Integer, Integer) = Function(x)
                                                    Do While parent(x) <> x
                                                        parent(x) = parent(parent(x))
                                                        x = parent(x)
                                                    Loop
                                                    Return x
                                                End Function
        For Each l In w.Links
            Dim a As Integer, b As Integer
            If Not index.TryGetValue(l.A, a) Then Continue For
            If l.B Is Nothing OrElse l.B.IsFixed OrElse Not index.TryGetValue(l.B, b) Then Continue For
            parent(root(a)) = root(b)
        Next
        Dim byRoot As New Dictionary(Of Integer, LinkedGroup)
        Dim groups As New List(Of LinkedGroup)
        For i = 0 To bodies.Count - 1
            Dim r = root(i)
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
            If index.TryGetValue(l.A, a) Then byRoot(root(a)).Links.Add(l)
        Next
        Return groups
    End Function

    ''' <summary>Group g's closed form from its bodies' states (already written to them) at <paramref name="t"/>.</summary>
    Private Sub Restart(g As Integer, t As Double, slack As Boolean)
        Dim group = _groups(g)
        _ledger.Settle(group, _world, t)
        group.Motion = If(RestingMotion(g, t), LinkedMotions.Create(group, _world, t, slack, Slop))
        _ledger.Started(group, _world)
        For Each c In group.Bodies
            Dim i = Array.IndexOf(_bodies, c)
            _slotOf(i) = Array.IndexOf(group.Motion.Bodies, c)
        Next
    End Sub

    ''' <summary>Writes group g's bodies' states at <paramref name="t"/> to them: the motion's centre less the centroid offset is the reference point.</summary>
    Private Sub Sync(g As Integer, t As Double)
        Dim m = _groups(g).Motion
        For k = 0 To m.Bodies.Length - 1
            Dim p As Vector, v As Vector
            m.StateAt(t, k, p, v)
            Dim body = m.Bodies(k)
            body.Position = p - _offset(Array.IndexOf(_bodies, body))
            body.Velocity = v
        Next
    End Sub

    Private Sub WriteBack(t As Double)
        For g = 0 To _groups.Count - 1
            Sync(g, t)
            _groups(g).Motion.UpdateTensions(t)
            _ledger.Settle(_groups(g), _world, t)
        Next
    End Sub

    ''' <summary>The earliest predicted event: kind 0 a group's transition (i the group), 1 a pair (i, j), 2 a wall (i, side j), 3 a fixed body (i, j).</summary>
    Private Function Earliest(ByRef kind As Integer, ByRef i As Integer, ByRef j As Integer) As Double
        Dim best = Double.PositiveInfinity
        For g = 0 To _groups.Count - 1
            Dim t = _groups(g).Motion.TransitionTime
            If t < best Then best = t : kind = 0 : i = g
        Next
        Dim n = _bodies.Length
        For a = 0 To n - 1
            For b = a + 1 To n - 1
                If _pairTime(a, b) < best Then best = _pairTime(a, b) : kind = 1 : i = a : j = b
            Next
            For s = 1 To 4
                If _wallTime(a, s) < best Then best = _wallTime(a, s) : kind = 2 : i = a : j = s
            Next
            For f = 0 To _fixed.Length - 1
                If _fixedTime(a, f) < best Then best = _fixedTime(a, f) : kind = 3 : i = a : j = f
            Next
        Next
        Return best
    End Function

    Private Sub PredictAll(tEnd As Double)
        For i = 0 To _bodies.Length - 1
            PredictBody(i, tEnd, -1)
        Next
    End Sub

    ''' <summary>Predicts every contact of body i (with bodies after it, or all of them when <paramref name="everyPair"/> ≥ 0).</summary>
    Private Sub PredictBody(i As Integer, tEnd As Double, everyPair As Integer)
        Dim n = _bodies.Length
        For j = 0 To n - 1
            If j = i OrElse (everyPair < 0 AndAlso j < i) Then Continue For
            Dim a = Math.Min(i, j), b = Math.Max(i, j)
            ' A body resting on another moves along its face exactly: that contact is not searched.
            Dim resting = RestsOn(a, RestSupportKind.Body, b) OrElse RestsOn(b, RestSupportKind.Body, a)
            _pairTime(a, b) = If(resting OrElse _rodPair.Contains(PairKey(a, b)), Double.PositiveInfinity, PredictPair(a, b, tEnd))
        Next
        For s = 1 To 4
            _wallTime(i, s) = If(_world.Walls AndAlso Not RestsOn(i, RestSupportKind.Wall, s), PredictGap(i, WallGap(i, CType(s, WallSide)), tEnd), Double.PositiveInfinity)
        Next
        For f = 0 To _fixed.Length - 1
            _fixedTime(i, f) = If(RestsOn(i, RestSupportKind.Fixed, f), Double.PositiveInfinity, PredictGap(i, FixedGap(i, f), tEnd))
        Next
    End Sub

    Private Function MotionOf(i As Integer) As LinkedMotion
        Return _groups(_groupOf(i)).Motion
    End Function

    Private Function WallGap(i As Integer, side As WallSide) As LinkedGap
        Return LinkedGap.Wall(MotionOf(i), _slotOf(i), _low(i), _high(i), side, _world.Width, _world.Height)
    End Function

    Private Function FixedGap(i As Integer, f As Integer) As LinkedGap
        Return LinkedGap.Obstacle(MotionOf(i), _slotOf(i), _differences(i, f), _fixed(f).Position + _offset(i))
    End Function

    ''' <summary>The gap between bodies a &lt; b: centre distance less the radii for two balls, else the distance to their Minkowski difference.</summary>
    Private Function PairGap(a As Integer, b As Integer) As LinkedGap
        If BothBalls(a, b) Then
            Return LinkedGap.Pair(MotionOf(a), _slotOf(a), MotionOf(b), _slotOf(b), DirectCast(_bodies(a), Circle).Radius + DirectCast(_bodies(b), Circle).Radius)
        End If
        Return LinkedGap.Shapes(MotionOf(a), _slotOf(a), MotionOf(b), _slotOf(b), _pairDifferences(a, b), _offset(a) - _offset(b))
    End Function

    ''' <summary>
    ''' Bodies a &lt; b. The gap is a 1-Lipschitz function of their relative position, so it closes no faster
    ''' than V, the sum of their speed bounds (or, for two bodies each on its parabola, the bound on their
    ''' relative speed). Two balls: its second derivative is at most the relative acceleration plus V²/(r₁ + r₂)
    ''' for the turning of the line of centres. A box or polygon in the pair: the gap is also convex in the
    ''' relative position, which bounds it from below with the relative acceleration alone
    ''' (<see cref="OneSidedAdvancement"/>); from above, the turning of the normal is at most V²/R about a pair
    ''' shape rounded by R (a ball is involved) and unbounded about a sharp one (boxes and polygons).
    ''' </summary>
    Private Function PredictPair(a As Integer, b As Integer, tEnd As Double) As Double
        Dim gap = PairGap(a, b)
        Dim t0 = _now
        Dim until = Math.Min(tEnd, t0 + Horizon)
        Dim ma = MotionOf(a), mb = MotionOf(b)
        Dim speed As Double, accel As Double
        Dim flightA = TryCast(ma, FlightMotion), flightB = TryCast(mb, FlightMotion)
        If Not BothBalls(a, b) AndAlso flightA IsNot Nothing AndAlso flightB IsNot Nothing Then
            FlightMotion.RelativeBounds(flightA, flightB, t0, until, speed, accel)
        Else
            speed = ma.SpeedBound(_slotOf(a), t0, until) + mb.SpeedBound(_slotOf(b), t0, until)
            accel = ma.AccelerationBound(_slotOf(a), t0, until) + mb.AccelerationBound(_slotOf(b), t0, until)
        End If
        If BothBalls(a, b) Then
            Dim curved = accel + speed * speed / (DirectCast(_bodies(a), Circle).Radius + DirectCast(_bodies(b), Circle).Radius)
            Return Recheck(FirstContact(gap, t0, until, speed, curved, curved, False), until, tEnd)
        End If
        Return Recheck(FirstContact(gap, t0, until, speed, accel, UpperCurvature(accel, speed, _pairDifferences(a, b).Radius), True), until, tEnd)
    End Function

    ''' <summary>A bound on the gap's second derivative (m/s²) from above: the acceleration's, plus V²/R for the turning of the normal about a pair shape rounded by R; +∞ (none) for a sharp one.</summary>
    Private Shared Function UpperCurvature(accel As Double, speed As Double, radius As Double) As Double
        If radius > 0 Then Return accel + speed * speed / radius
        Return If(speed > 0, Double.PositiveInfinity, accel)
    End Function

    Private Function PredictGap(i As Integer, gap As LinkedGap, tEnd As Double) As Double
        Dim m = MotionOf(i)
        Dim until = Math.Min(tEnd, _now + Horizon)
        Dim speed = m.SpeedBound(_slotOf(i), _now, until)
        Dim accel = m.AccelerationBound(_slotOf(i), _now, until)
        ' A wall is flat: its gap's second derivative is the acceleration across it.
        If gap.Difference Is Nothing Then Return Recheck(FirstContact(gap, _now, until, speed, accel, accel, False), until, tEnd)
        Dim curved = UpperCurvature(accel, speed, gap.Difference.Radius)
        If _bodies(i).Kind = ShapeKind.Circle Then Return Recheck(FirstContact(gap, _now, until, speed, curved, curved, False), until, tEnd)
        Return Recheck(FirstContact(gap, _now, until, speed, accel, curved, True), until, tEnd)
    End Function

    ''' <summary>A search that found nothing before the horizon is taken up again there (an event that is not a contact).</summary>
    Private Shared Function Recheck(found As Double, until As Double, tEnd As Double) As Double
        If Double.IsPositiveInfinity(found) AndAlso until < tEnd Then Return until
        Return found
    End Function

    ''' <summary>
    ''' The first contact of a gap in [t0, tEnd] (s): now when touching and closing. When touching and not
    ''' closing (just after a bounce), first the time the gap has opened to twice the slop, and from there
    ''' when it closes; if it cannot be shown to open that far, when the overlap grows by the slop. Otherwise
    ''' when the gap closes. <paramref name="below"/> (m/s²) bounds the gap's second derivative from below
    ''' (its fall): the relative acceleration for a box or polygon, whose gap is convex, else the same as
    ''' <paramref name="above"/>, the two-sided bound (+∞ for two sharp shapes, where none exists). The closing
    ''' is searched with the bound from below alone (<see cref="OneSidedAdvancement"/>) when
    ''' <paramref name="oneSided"/>, else with <see cref="ConservativeAdvancement"/>. +∞ for none; a search that
    ''' ran out of its budget returns where it stopped, to be taken up again from there.
    ''' An opening searched for step by step counts only before the overlap could have grown by the slop:
    ''' a body pressed into another (a ball pulled onto a peg it sits on) would otherwise be "opened" on the
    ''' far side, after passing right through it, and the contact between never looked for.
    ''' </summary>
    Private Shared Function FirstContact(gap As LinkedGap, t0 As Double, tEnd As Double, speed As Double, below As Double, above As Double, oneSided As Boolean) As Double
        Dim n As Vector, rate As Double
        Dim d = gap.GapAndNormal(t0, n, rate)
        If d <= Slop Then
            If rate < -(CreepSpeed + 0.000000001 * speed) Then Return t0
            ' Leaving at rate ḋ, the gap is at least d + ḋ s − ½ A s² (A the bound from below): where that
            ' parabola first reaches twice the slop, the gap has opened that far, and it did not close before.
            Dim opens = OpeningTime(d, rate, below, 2 * Slop)
            If opens < Double.PositiveInfinity Then
                If t0 + opens > tEnd Then Return Double.PositiveInfinity
                t0 += opens
            Else
                ' Too slow to show it opening from the bound below (a body sliding along a face, or resting):
                ' look for the opening step by step, with the bound from above, until the overlap could have
                ' grown by the slop; two sharp shapes have no such bound, so briefly, with the speed alone.
                Dim sinks = Closing(gap, t0, tEnd, Math.Min(d, 0) - Slop, speed, below, above, oneSided)
                Dim limit = If(sinks.Found, sinks.Time, sinks.ClearUntil)
                Dim sharp = Double.IsPositiveInfinity(above)
                Dim opened = ConservativeAdvancement.FirstContact(New Opening(gap, 2 * Slop), t0, limit, 0, speed, above, If(sharp, SharpOpeningBudget, 100000))
                If Not opened.Found Then Return If(opened.ClearUntil < limit AndAlso Not sharp, opened.ClearUntil, Finding(sinks, tEnd))
                t0 = opened.Time
            End If
        End If
        Return Finding(Closing(gap, t0, tEnd, 0, speed, below, above, oneSided), tEnd)
    End Function

    ''' <summary>The search for the gap closing to −<paramref name="tolerance"/> (m), one- or two-sided (see <see cref="FirstContact"/>).</summary>
    Private Shared Function Closing(gap As LinkedGap, t0 As Double, tEnd As Double, tolerance As Double, speed As Double,
                                    below As Double, above As Double, oneSided As Boolean) As AdvancementResult
        Return If(oneSided,
                  OneSidedAdvancement.FirstContact(gap, t0, tEnd, tolerance, speed, below),
                  ConservativeAdvancement.FirstContact(gap, t0, tEnd, tolerance, speed, above))
    End Function

    ''' <summary>A search's answer as a time: when it found the contact, where it stopped short of <paramref name="tEnd"/> (to be taken up again), or +∞.</summary>
    Private Shared Function Finding(result As AdvancementResult, tEnd As Double) As Double
        If result.Found Then Return result.Time
        If result.ClearUntil < tEnd Then Return result.ClearUntil
        Return Double.PositiveInfinity
    End Function

    ''' <summary>
    ''' The first s &gt; 0 (s) at which d + ḋ s − ½ A s² reaches <paramref name="target"/> (m), for a gap d (m)
    ''' opening at ḋ (m/s) with its second derivative at least −A (m/s²); +∞ when that parabola never does.
    ''' </summary>
    Private Shared Function OpeningTime(d As Double, rate As Double, accel As Double, target As Double) As Double
        If rate <= 0 OrElse Double.IsInfinity(accel) OrElse Double.IsNaN(accel) Then Return Double.PositiveInfinity
        Dim rise = target - d
        If rise <= 0 Then Return 0
        If accel <= 0 Then Return rise / rate
        Dim disc = rate * rate - 2 * accel * rise
        If disc < 0 Then Return Double.PositiveInfinity
        ' The smaller root of ½ A s² − ḋ s + rise = 0, written without cancellation.
        Return 2 * rise / (rate + Math.Sqrt(disc))
    End Function

    ''' <summary>How far a gap is from opening to <c>target</c> (m): target − gap, zero once it has opened that far.</summary>
    Private NotInheritable Class Opening
        Implements IDistanceFunction

        Private ReadOnly _gap As LinkedGap
        Private ReadOnly _target As Double

        Public Sub New(gap As LinkedGap, target As Double)
            _gap = gap
            _target = target
        End Sub

        Public Function Distance(time As Double) As Double Implements IDistanceFunction.Distance
            Return _target - _gap.Distance(time)
        End Function

        Public Function Rate(time As Double) As Double Implements IDistanceFunction.Rate
            Return -_gap.Rate(time)
        End Function
    End Class

    ''' <summary>Group g's closed form ends (a string goes slack or snaps taut): do what happens there and go on with the next form.</summary>
    Private Sub TransitionOf(g As Integer, t As Double, tEnd As Double)
        Sync(g, t)
        Dim kinetic = DissipationLedger.Kinetic(_bodies)
        Dim slack = _groups(g).Motion.Transition(_world)
        DissipationLedger.Blow(_world, kinetic, _bodies)
        Restart(g, t, slack)
        Repredict(RestartResting(New List(Of Integer) From {g}, t), tEnd)
    End Sub

    ''' <summary>
    ''' Body i hits body j (i &lt; j), a wall or fixed body f at t: resolve it with the links of both, and report
    ''' it; when <paramref name="wedged"/>, with every contact touching the bodies it moves too (LinkedEventSolver.Wedge.vb).
    ''' </summary>
    Private Sub Collide(i As Integer, j As Integer, side As WallSide, f As Integer, t As Double, tEnd As Double, wedged As Boolean)
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
        If depth > Slop OrElse rate >= -(CreepSpeed + 0.000000001 * speeds) Then
            ' Not a contact: a search that reached its horizon or its budget, or a touch that does not press. Only
            ' this prediction is taken up again from now: nothing has moved differently, so body i's others stand.
            PredictAgain(i, j, side, f, tEnd)
            Return
        End If
        ' A corner on a corner of two sharp shapes takes the bisector of the pair shape's corner (docs/shapes.md).
        If gap.Difference IsNot Nothing Then normal = gap.ContactNormal(t)
        Dim a = _bodies(i)
        Dim b = If(j >= 0, _bodies(j), Nothing)
        Dim aBefore = a.Velocity
        Dim bBefore = If(b Is Nothing, Vector.Zero, b.Velocity)
        Dim kinetic = DissipationLedger.Kinetic(_bodies)
        _impulse.Clear()
        _impulse.AddContact(a, b, normal, _world.Restitution)
        Dim held As New HashSet(Of Integer)
        AddSupportRows(i, held)
        If j >= 0 Then AddSupportRows(j, held)
        For Each l In _groups(gi).Motion.HeldLinks
            _impulse.AddLink(l)
        Next
        If gj >= 0 AndAlso gj <> gi Then
            For Each l In _groups(gj).Motion.HeldLinks
                _impulse.AddLink(l)
            Next
        End If
        Dim gathered = If(wedged, AddTouchingContacts(i, j, side, f, t, held), New List(Of Integer))
        If wedged Then _impulse.ResolveWedged(_world.Restitution) Else _impulse.Resolve()
        DissipationLedger.Blow(_world, kinetic, _bodies)
        Dim other = If(b, If(f >= 0, _fixed(f), Nothing))
        Dim aAfter = a.Velocity
        Dim bAfter = If(b Is Nothing, Vector.Zero, b.Velocity)
        ' Every group the blow moved, the lowest first: a body that comes to rest on another finds its new motion.
        held.Add(i)
        If j >= 0 Then held.Add(j)
        Dim changed = held.Select(Function(k) _groupOf(k)).Concat(gathered).Distinct().OrderBy(Function(g) _groups(g).Bodies.Min(Function(c) Lowest(Array.IndexOf(_bodies, c)))).ToList()
        For Each g In changed
            Restart(g, t, False)
        Next
        ' The gap as the new motions close it, for how hard they press the two together.
        Dim after = If(j >= 0, PairGap(i, j), If(f >= 0, FixedGap(i, f), WallGap(i, side)))
        RefuseRest(i, j, other, side, normal, bAfter - aAfter, after)
        _reports.Add(New CollisionRecord(t, a, other, side, CollisionKinds.Between(a, other), aBefore, aAfter, bBefore, bAfter))
        Repredict(RestartResting(changed, t), tEnd)
    End Sub

    ''' <summary>
    ''' A contact after which neither body rests (<see cref="RestingMotion"/>), yet one would bounce less than
    ''' four slops high across a contact that gravity presses on: it is coming to rest where no rule here holds
    ''' it. The series of ever smaller bounces has a finite sum but endless terms; it is refused, in words that
    ''' say what was coming to rest on what, rather than followed into a pile-up of events. Balls among balls
    ''' and against walls are followed as they always were; a ball on a fixed body, see <see cref="RefuseBallRest"/>.
    ''' </summary>
    Private Sub RefuseRest(i As Integer, j As Integer, other As Shape, side As WallSide, normal As Vector, relativeAfter As Vector, after As LinkedGap)
        If j >= 0 AndAlso (_restOn(i) IsNot Nothing OrElse _restOn(j) IsNot Nothing) Then
            ' One now resting on the other is held there by the rest rules.
            If Not (RestsOn(i, RestSupportKind.Body, j) OrElse RestsOn(j, RestSupportKind.Body, i)) Then RefuseRestOnResting(i, j, normal, relativeAfter, after)
            Return
        End If
        If _restOn(i) IsNot Nothing OrElse (j >= 0 AndAlso _restOn(j) IsNot Nothing) Then Return
        Dim a = _bodies(i)
        If a.Kind = ShapeKind.Circle AndAlso (other Is Nothing OrElse other.Kind = ShapeKind.Circle OrElse other.IsFixed) Then
            RefuseBallRest(i, other, side, normal, relativeAfter, after)
            Return
        End If
        If other Is Nothing AndAlso side <> WallSide.Bottom Then Return
        ' How hard their motions press them together: two bodies falling freely together do not press at all,
        ' and part after a gentle touch in finitely many events.
        Dim pressing = Vector.Dot(AccelerationOf(i) - If(j >= 0, AccelerationOf(j), Vector.Zero), normal)
        If pressing <= 0 Then Return
        Dim separating = Vector.Dot(relativeAfter, normal)
        If separating > LinkedMotions.RestingSpeed(pressing, Slop) Then Return
        ' The body above is the one coming to rest.
        If j >= 0 AndAlso normal.Y > 0 Then
            Throw New UnsupportedSceneException(RestRefusal.Message(_bodies(j), _groups(_groupOf(j)).Links, a, _groups(_groupOf(i)).Links, -normal))
        End If
        Throw New UnsupportedSceneException(RestRefusal.Message(a, _groups(_groupOf(i)).Links, other, If(j >= 0, _groups(_groupOf(j)).Links, Nothing), normal))
    End Sub

    ''' <summary>
    ''' Body k's acceleration now (m/s²): a body on a parabola or sliding has its own; any other falls at g and
    ''' is pulled by its springs (written to it now), the pull of rods and strings aside.
    ''' </summary>
    Private Function AccelerationOf(k As Integer) As Vector
        Dim flight = TryCast(MotionOf(k), FlightMotion)
        If flight IsNot Nothing Then Return flight.Acceleration
        Dim body = _bodies(k)
        Dim a = New Vector(0, -_world.Gravity) + ForcedMotions.Acceleration(body, _world)
        For Each l In _groups(_groupOf(k)).Links
            If l.Kind <> LinkKind.Spring Then Continue For
            Dim along = (l.EndB - l.EndA).Normalized(Vector.Zero)
            If l.A Is body Then a += along * (l.Tension / body.Mass)
            If l.B Is body Then a -= along * (l.Tension / body.Mass)
        Next
        Return a
    End Function

    ''' <summary>
    ''' Ball i, after a contact with a fixed body below it (or, as a body with links, with the floor) that left
    ''' it resting on nothing (a curve, a corner, or with links that do not let it rest), would bounce less
    ''' than four slops high: it is coming to rest where no rule holds it. The bounces would never end, each
    ''' pressing a slop further in (a ball on a peg beside a pendulum: 40 000 collisions per simulated second,
    ''' sinking 40 μm a second). Refused, as for boxes. Balls on movable balls are left as they are. What
    ''' presses is gravity and the ball's springs, or, when more, what the motion after the blow does to
    ''' <paramref name="after"/>, the gap: a ball at the end of a chain of rods is swung into a side wall by
    ''' the rods' pull, which no sum of forces here knows.
    ''' </summary>
    Private Sub RefuseBallRest(i As Integer, other As Shape, side As WallSide, normal As Vector, relativeAfter As Vector, after As LinkedGap)
        Dim links = _groups(_groupOf(i)).Links
        If other Is Nothing Then
            If links.Count = 0 Then Return
        ElseIf Not other.IsFixed Then
            Return
        End If
        ' The normal points from the ball to what it hits: gravity presses it in only when that is below it,
        ' a spring when it pulls the ball towards it (a ball pulled sideways onto a wall or a peg).
        Dim pressing = Math.Max(Vector.Dot(AccelerationOf(i), normal), Squeeze(after, _now))
        If pressing <= 0 Then Return
        If Vector.Dot(relativeAfter, normal) > LinkedMotions.RestingSpeed(pressing, Slop) Then Return
        Throw New UnsupportedSceneException(RestRefusal.Message(_bodies(i), links, other, Nothing, normal, side))
    End Sub

    ''' <summary>
    ''' Bodies i and j, of which one rests or both do, and collide (a ball on balls resting on the floor, a ball
    ''' sliding down a slope into one resting at its foot): the one that does not rest (or, both resting, the
    ''' higher) is coming to rest on the other where no rule holds it if it would bounce less than four slops
    ''' high, pressed as the motions after the blow press the gap <paramref name="after"/> closed. Left to
    ''' bounce, each bounce began a slop deeper (2.3 μm by t = 0.7 s for a ball sliding into one at the bottom
    ''' of a V). Refused, as on a fixed body. Bodies that slide into each other on a level face do not press.
    ''' </summary>
    Private Sub RefuseRestOnResting(i As Integer, j As Integer, normal As Vector, relativeAfter As Vector, after As LinkedGap)
        Dim pressing = Squeeze(after, _now)
        If pressing <= 0 OrElse Vector.Dot(relativeAfter, normal) > LinkedMotions.RestingSpeed(pressing, Slop) Then Return
        Dim body As Integer
        If (_restOn(i) Is Nothing) <> (_restOn(j) Is Nothing) Then
            body = If(_restOn(i) Is Nothing, i, j)
        Else
            body = If(_bodies(i).Position.Y >= _bodies(j).Position.Y, i, j)
        End If
        Dim support = If(body = i, j, i)
        Throw New UnsupportedSceneException(RestRefusal.Message(_bodies(body), _groups(_groupOf(body)).Links, _bodies(support),
                                                                _groups(_groupOf(support)).Links, If(body = i, normal, -normal)))
    End Sub

    ''' <summary>
    ''' How fast a gap's closing speeds up at <paramref name="t"/> (m/s²): minus its second derivative, from its
    ''' rate a tenth of a microsecond on (far shorter than a bounce that could matter, far longer than the
    ''' rounding of the rate).
    ''' </summary>
    Private Shared Function Squeeze(gap As LinkedGap, t As Double) As Double
        Const H As Double = 0.0000001
        Return -(gap.Rate(t + H) - gap.Rate(t)) / H
    End Function

    ''' <summary>Predicts again from now the one contact of body i with body j, wall <paramref name="side"/> or fixed body f.</summary>
    Private Sub PredictAgain(i As Integer, j As Integer, side As WallSide, f As Integer, tEnd As Double)
        If j >= 0 Then
            _pairTime(Math.Min(i, j), Math.Max(i, j)) = PredictPair(Math.Min(i, j), Math.Max(i, j), tEnd)
        ElseIf f >= 0 Then
            _fixedTime(i, f) = PredictGap(i, FixedGap(i, f), tEnd)
        Else
            _wallTime(i, side) = PredictGap(i, WallGap(i, side), tEnd)
        End If
    End Sub

    ''' <summary>Predicts again every contact of the bodies of the given groups.</summary>
    Private Sub Repredict(groups As List(Of Integer), tEnd As Double)
        For i = 0 To _bodies.Length - 1
            If groups.Contains(_groupOf(i)) Then PredictBody(i, tEnd, 0)
        Next
    End Sub
End Class
