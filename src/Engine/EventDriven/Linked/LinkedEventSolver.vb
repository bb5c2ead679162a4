Option Strict On

''' <summary>
''' The event solver's loop for a world with links (docs/links.md, "Links in the event solver"). Each group
''' of linked bodies moves by its closed form (<see cref="LinkedMotions"/>): a pendulum, a body on a slack
''' string flying its parabola, a body on a spring, a dumbbell; a free ball flies its parabola. The loop
''' reads as the event solver's: find the earliest event → advance to it → resolve it → re-predict what it
''' changed. Events are a string going slack or snapping taut (exact times from the closed forms) and
''' contacts, found by conservative advancement (<see cref="ConservativeAdvancement"/>): from bounds on the
''' speeds and accelerations it proves how long each gap stays open, so no contact is stepped over, and
''' ends on the first one to rounding. A contact is resolved with the links of both bodies in the same
''' solve (<see cref="LinkedImpulse"/>). Every pair is predicted again after an event that changes one of
''' its bodies: fine for the classroom scenes with links (tens of bodies), not for a gas.
''' </summary>
Friend NotInheritable Class LinkedEventSolver
    ' Gaps this close count as touching, m; a touching pair that does not approach collides only if it overlaps by this much.
    Private Const Slop As Double = 0.000000001
    ' Events at one instant (a cascade through a row of touching balls) beyond this are a fault, reported.
    Private Const MaxInstantEvents As Integer = 100000
    ' Contacts are looked for this far ahead at most, s, so that the speed bounds (which grow with the
    ' time looked ahead, for a falling body) stay tight; at its end the search is taken up again.
    Private Const Horizon As Double = 0.1
    ' A touching pair closes if it approaches faster than this (m/s) plus a billionth of its speeds:
    ' slower is rounding left over from a cascade, and would only report collisions of nothing.
    Private Const CreepSpeed As Double = 0.000000000001

    Private ReadOnly _impulse As New LinkedImpulse()
    Private _world As World
    Private _dirty As Boolean = True
    Private _now As Double
    Private _groups As New List(Of LinkedGroup)
    Private _circles As Circle() = Array.Empty(Of Circle)()
    Private _groupOf As Integer() = Array.Empty(Of Integer)()
    Private _slotOf As Integer() = Array.Empty(Of Integer)()
    Private _fixed As Shape() = Array.Empty(Of Shape)()
    ' The earliest contact predicted for each pair (i < j), each ball with each wall side and each fixed body, s.
    Private _pairTime As Double(,) = New Double(-1, -1) {}
    Private _wallTime As Double(,) = New Double(-1, -1) {}
    Private _fixedTime As Double(,) = New Double(-1, -1) {}
    Private _differences As Outline(,) = New Outline(-1, -1) {}
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
        If _dirty OrElse _now <> _world.Time Then Rebuild()
        Dim tEnd = _now + duration
        PredictAll(tEnd)
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
                Case 0 : TransitionOf(i, t, tEnd)
                Case 1 : Collide(i, j, WallSide.None, -1, t, tEnd)
                Case 2 : Collide(i, -1, CType(j, WallSide), -1, t, tEnd)
                Case Else : Collide(i, -1, WallSide.None, j, t, tEnd)
            End Select
        Loop
        _now = tEnd
        WriteBack(tEnd)
    End Sub

    ''' <summary>Reads the world: groups from the links, then each group's closed form from its state now.</summary>
    Private Sub Rebuild()
        Dim w = _world
        _now = w.Time
        Dim circles As New List(Of Circle)
        For Each b In w.Movables
            If b.Kind = ShapeKind.Circle Then circles.Add(DirectCast(b, Circle))
        Next
        Dim groups = FormGroups(w, circles)
        LinkedMotions.CheckSupported(w, groups)
        _circles = circles.ToArray()
        _groups = groups
        Dim n = _circles.Length
        _groupOf = New Integer(n - 1) {}
        _slotOf = New Integer(n - 1) {}
        Dim index As New Dictionary(Of Circle, Integer)
        For i = 0 To n - 1
            index(_circles(i)) = i
        Next
        _rodPair.Clear()
        For g = 0 To _groups.Count - 1
            For Each c In _groups(g).Bodies
                _groupOf(index(c)) = g
            Next
            For Each l In _groups(g).Links
                If l.Kind = LinkKind.Rod AndAlso l.B IsNot Nothing AndAlso Not l.B.IsFixed Then _rodPair.Add(PairKey(index(DirectCast(l.A, Circle)), index(DirectCast(l.B, Circle))))
            Next
        Next
        _fixed = w.Bodies.Where(Function(b) b.IsFixed).ToArray()
        _differences = New Outline(n - 1, _fixed.Length - 1) {}
        For i = 0 To n - 1
            For f = 0 To _fixed.Length - 1
                _differences(i, f) = Outline.MinkowskiDifference(_fixed(f).Outline, _circles(i).Outline)
            Next
        Next
        _pairTime = New Double(n - 1, n - 1) {}
        _wallTime = New Double(n - 1, 4) {}
        _fixedTime = New Double(n - 1, Math.Max(_fixed.Length, 1) - 1) {}
        For g = 0 To _groups.Count - 1
            Restart(g, _now, False)
        Next
        _dirty = False
    End Sub

    Private Shared Function PairKey(i As Integer, j As Integer) As Long
        Return CLng(Math.Min(i, j)) * Integer.MaxValue + Math.Max(i, j)
    End Function

    ''' <summary>Bodies joined through links, by union–find; a link to a fixed body or a point joins nothing.</summary>
    Private Shared Function FormGroups(w As World, circles As List(Of Circle)) As List(Of LinkedGroup)
        Dim index As New Dictionary(Of Shape, Integer)
        For i = 0 To circles.Count - 1
            index(circles(i)) = i
        Next
        Dim parent = Enumerable.Range(0, circles.Count).ToArray()
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
        For i = 0 To circles.Count - 1
            Dim r = root(i)
            Dim g As LinkedGroup = Nothing
            If Not byRoot.TryGetValue(r, g) Then
                g = New LinkedGroup(New List(Of Circle), New List(Of Link))
                byRoot(r) = g
                groups.Add(g)
            End If
            g.Bodies.Add(circles(i))
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
        group.Motion = LinkedMotions.Create(group, _world, t, slack, Slop)
        For Each c In group.Bodies
            Dim i = Array.IndexOf(_circles, c)
            _slotOf(i) = Array.IndexOf(group.Motion.Bodies, c)
        Next
    End Sub

    ''' <summary>Writes group g's bodies' states at <paramref name="t"/> to them.</summary>
    Private Sub Sync(g As Integer, t As Double)
        Dim m = _groups(g).Motion
        For k = 0 To m.Bodies.Length - 1
            Dim p As Vector, v As Vector
            m.StateAt(t, k, p, v)
            m.Bodies(k).Position = p
            m.Bodies(k).Velocity = v
        Next
    End Sub

    Private Sub WriteBack(t As Double)
        For g = 0 To _groups.Count - 1
            Sync(g, t)
            _groups(g).Motion.UpdateTensions(t)
        Next
    End Sub

    ''' <summary>The earliest predicted event: kind 0 a group's transition (i the group), 1 a pair (i, j), 2 a wall (i, side j), 3 a fixed body (i, j).</summary>
    Private Function Earliest(ByRef kind As Integer, ByRef i As Integer, ByRef j As Integer) As Double
        Dim best = Double.PositiveInfinity
        For g = 0 To _groups.Count - 1
            Dim t = _groups(g).Motion.TransitionTime
            If t < best Then best = t : kind = 0 : i = g
        Next
        Dim n = _circles.Length
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
        For i = 0 To _circles.Length - 1
            PredictBody(i, tEnd, -1)
        Next
    End Sub

    ''' <summary>Predicts every contact of ball i (with balls after it, or all of them when <paramref name="everyPair"/> ≥ 0).</summary>
    Private Sub PredictBody(i As Integer, tEnd As Double, everyPair As Integer)
        Dim n = _circles.Length
        For j = 0 To n - 1
            If j = i OrElse (everyPair < 0 AndAlso j < i) Then Continue For
            Dim a = Math.Min(i, j), b = Math.Max(i, j)
            _pairTime(a, b) = If(_rodPair.Contains(PairKey(a, b)), Double.PositiveInfinity, PredictPair(a, b, tEnd))
        Next
        For s = 1 To 4
            _wallTime(i, s) = If(_world.Walls, PredictGap(i, LinkedGap.Wall(MotionOf(i), _slotOf(i), _circles(i).Radius, CType(s, WallSide), _world.Width, _world.Height), 0, tEnd), Double.PositiveInfinity)
        Next
        For f = 0 To _fixed.Length - 1
            Dim gap = LinkedGap.Obstacle(MotionOf(i), _slotOf(i), _differences(i, f), _fixed(f).Position)
            _fixedTime(i, f) = PredictGap(i, gap, _differences(i, f).Radius, tEnd)
        Next
    End Sub

    Private Function MotionOf(i As Integer) As LinkedMotion
        Return _groups(_groupOf(i)).Motion
    End Function

    Private Function PredictPair(a As Integer, b As Integer, tEnd As Double) As Double
        Dim gap = LinkedGap.Pair(MotionOf(a), _slotOf(a), MotionOf(b), _slotOf(b), _circles(a).Radius + _circles(b).Radius)
        Dim t0 = _now
        Dim until = Math.Min(tEnd, t0 + Horizon)
        Dim speed = MotionOf(a).SpeedBound(_slotOf(a), t0, until) + MotionOf(b).SpeedBound(_slotOf(b), t0, until)
        Dim accel = MotionOf(a).AccelerationBound(_slotOf(a), t0, until) + MotionOf(b).AccelerationBound(_slotOf(b), t0, until) +
                    speed * speed / (_circles(a).Radius + _circles(b).Radius)
        Return Recheck(FirstContact(gap, t0, until, speed, accel), until, tEnd)
    End Function

    Private Function PredictGap(i As Integer, gap As LinkedGap, curvatureRadius As Double, tEnd As Double) As Double
        Dim m = MotionOf(i)
        Dim until = Math.Min(tEnd, _now + Horizon)
        Dim speed = m.SpeedBound(_slotOf(i), _now, until)
        Dim accel = m.AccelerationBound(_slotOf(i), _now, until)
        If curvatureRadius > 0 Then accel += speed * speed / curvatureRadius
        Return Recheck(FirstContact(gap, _now, until, speed, accel), until, tEnd)
    End Function

    ''' <summary>A search that found nothing before the horizon is taken up again there (an event that is not a contact).</summary>
    Private Shared Function Recheck(found As Double, until As Double, tEnd As Double) As Double
        If Double.IsPositiveInfinity(found) AndAlso until < tEnd Then Return until
        Return found
    End Function

    ''' <summary>
    ''' The first contact in [t0, tEnd]: now when touching and closing. When touching and not closing (just
    ''' after a bounce), first the time the gap opens to twice the slop, and from there when it closes; if it
    ''' never opens that far, when the overlap grows by the slop. Otherwise when the gap closes. +∞ for none;
    ''' a search that ran out of its budget returns where it stopped, to be taken up again from there.
    ''' </summary>
    Private Shared Function FirstContact(gap As LinkedGap, t0 As Double, tEnd As Double, speed As Double, accel As Double) As Double
        Dim n As Vector, rate As Double
        Dim d = gap.GapAndNormal(t0, n, rate)
        Dim tolerance = 0.0
        If d <= Slop Then
            If rate < -(CreepSpeed + 0.000000001 * speed) Then Return t0
            Dim opened = ConservativeAdvancement.FirstContact(New Opening(gap, 2 * Slop), t0, tEnd, 0, speed, accel)
            If opened.Found Then
                t0 = opened.Time
            ElseIf opened.ClearUntil < tEnd Then
                Return opened.ClearUntil
            Else
                tolerance = Math.Min(d, 0) - Slop
            End If
        End If
        Dim result = ConservativeAdvancement.FirstContact(gap, t0, tEnd, tolerance, speed, accel)
        If result.Found Then Return result.Time
        If result.ClearUntil < tEnd Then Return result.ClearUntil
        Return Double.PositiveInfinity
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
        Dim slack = _groups(g).Motion.Transition(_world)
        Restart(g, t, slack)
        Repredict(g, -1, tEnd)
    End Sub

    ''' <summary>Ball i hits ball j, a wall or fixed body f at t: resolve it with the links of both, and report it.</summary>
    Private Sub Collide(i As Integer, j As Integer, side As WallSide, f As Integer, t As Double, tEnd As Double)
        Dim gi = _groupOf(i)
        Dim gj = If(j >= 0, _groupOf(j), -1)
        Sync(gi, t)
        If gj >= 0 AndAlso gj <> gi Then Sync(gj, t)
        Dim gap As LinkedGap
        If j >= 0 Then
            gap = LinkedGap.Pair(MotionOf(i), _slotOf(i), MotionOf(j), _slotOf(j), _circles(i).Radius + _circles(j).Radius)
        ElseIf f >= 0 Then
            gap = LinkedGap.Obstacle(MotionOf(i), _slotOf(i), _differences(i, f), _fixed(f).Position)
        Else
            gap = LinkedGap.Wall(MotionOf(i), _slotOf(i), _circles(i).Radius, side, _world.Width, _world.Height)
        End If
        Dim normal As Vector, rate As Double
        Dim depth = gap.GapAndNormal(t, normal, rate)
        Dim speeds = _circles(i).Velocity.Length + If(j >= 0, _circles(j).Velocity.Length, 0)
        If depth > Slop OrElse rate >= -(CreepSpeed + 0.000000001 * speeds) Then
            ' Not a contact: a search that reached its horizon or its budget, or a touch that does not press. Only
            ' this prediction is taken up again from now: nothing has moved differently, so ball i's others stand.
            PredictAgain(i, j, side, f, tEnd)
            Return
        End If
        Dim a = _circles(i)
        Dim b = If(j >= 0, _circles(j), Nothing)
        Dim aBefore = a.Velocity
        Dim bBefore = If(b Is Nothing, Vector.Zero, b.Velocity)
        _impulse.Clear()
        _impulse.AddContact(a, b, normal, _world.Restitution)
        For Each l In _groups(gi).Motion.HeldLinks
            _impulse.AddLink(l)
        Next
        If gj >= 0 AndAlso gj <> gi Then
            For Each l In _groups(gj).Motion.HeldLinks
                _impulse.AddLink(l)
            Next
        End If
        _impulse.Resolve()
        Dim kind = If(j >= 0, CollisionKind.CircleCircle, If(f >= 0, CollisionKind.CircleFixed, CollisionKind.CircleWall))
        If f >= 0 AndAlso _fixed(f).Kind = ShapeKind.Rectangle Then kind = CollisionKind.CircleRectangle
        If f >= 0 AndAlso _fixed(f).Kind <> ShapeKind.Rectangle AndAlso _fixed(f).Kind <> ShapeKind.Circle Then kind = CollisionKind.Other
        _world.ReportCollision(New CollisionRecord(t, a, If(b, If(f >= 0, _fixed(f), Nothing)), side, kind,
                                                   aBefore, a.Velocity, bBefore, If(b Is Nothing, Vector.Zero, b.Velocity)))
        Restart(gi, t, False)
        If gj >= 0 AndAlso gj <> gi Then Restart(gj, t, False)
        Repredict(gi, gj, tEnd)
    End Sub

    ''' <summary>Predicts again from now the one contact of ball i with ball j, wall <paramref name="side"/> or fixed body f.</summary>
    Private Sub PredictAgain(i As Integer, j As Integer, side As WallSide, f As Integer, tEnd As Double)
        If j >= 0 Then
            _pairTime(Math.Min(i, j), Math.Max(i, j)) = PredictPair(Math.Min(i, j), Math.Max(i, j), tEnd)
        ElseIf f >= 0 Then
            _fixedTime(i, f) = PredictGap(i, LinkedGap.Obstacle(MotionOf(i), _slotOf(i), _differences(i, f), _fixed(f).Position), _differences(i, f).Radius, tEnd)
        Else
            _wallTime(i, side) = PredictGap(i, LinkedGap.Wall(MotionOf(i), _slotOf(i), _circles(i).Radius, side, _world.Width, _world.Height), 0, tEnd)
        End If
    End Sub

    ''' <summary>Predicts again every contact of the bodies of groups g and h (−1: none).</summary>
    Private Sub Repredict(g As Integer, h As Integer, tEnd As Double)
        For i = 0 To _circles.Length - 1
            If _groupOf(i) = g OrElse _groupOf(i) = h Then PredictBody(i, tEnd, 0)
        Next
    End Sub
End Class
