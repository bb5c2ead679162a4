Option Strict On

' Resolving one event: bring the bodies to the event time, apply the impulse (Impulse.Resolve),
' report it, apply the resting and sleeping rules, and reschedule the bodies involved.
Partial Public NotInheritable Class EventDrivenSolver
    Private Sub ProcessEvent(i As Integer)
        If _ev(i).CellTime <= _ev(i).ColTime Then
            CrossCell(i)
            Return
        End If
        Select Case _ev(i).Kind
            Case EventKind.Circle
                Dim j = _ev(i).Other
                If _ev(j).Count <> _ev(i).OtherCount Then
                    Reschedule(i) ' stale: the partner's motion changed since this was predicted
                ElseIf _body(i).Mode = BodyMode.Sliding OrElse _body(j).Mode = BodyMode.Sliding Then
                    ' Something reached a sliding ball's corner: stop following the slide exactly.
                    If _body(i).Mode = BodyMode.Sliding Then Materialize(i)
                    If _body(j).Mode = BodyMode.Sliding Then Materialize(j)
                    Reschedule(i)
                    Reschedule(j)
                Else
                    CollideCircles(i, j)
                End If
            Case EventKind.FixedCircle
                Dim k = _ev(i).Other
                Sync(i)
                Dim n = New Vector(_body(i).Px - _fx(k), _body(i).Py - _fy(k)).Normalized(New Vector(0, 1))
                CollideStatic(i, n, _fixed(k), WallSide.None, CollisionKind.CircleFixed, SupportOther)
            Case EventKind.Rectangle
                CollideRectangle(i, _ev(i).Other, _ev(i).Feature)
            Case EventKind.Wall
                CollideWall(i, CType(_ev(i).Feature, WallSide))
            Case EventKind.EdgeLeave
                LeaveEdge(i, _ev(i).Other)
            Case EventKind.SlideEnd
                EndSlide(i)
            Case Else
                Reschedule(i)
        End Select
    End Sub

    ''' <summary>Moves body i's reference point to the solver's clock (exactly along its path).</summary>
    Private Sub Sync(i As Integer)
        If _now = _body(i).T0 Then Return
        Dim x, y, vx, vy As Double
        _body(i).StateAt(_now, x, y, vx, vy)
        _body(i).Px = x
        _body(i).Py = y
        _body(i).Vy = vy
        _body(i).T0 = _now
        Publish(i)
    End Sub

    Private Sub CollideWall(i As Integer, side As WallSide)
        Sync(i)
        Dim n As Vector
        ' Snap onto the wall: the contact is exact, so rounding never accumulates over many bounces.
        Select Case side
            Case WallSide.Left : n = New Vector(1, 0) : _body(i).Px = _body(i).R
            Case WallSide.Right : n = New Vector(-1, 0) : _body(i).Px = _width - _body(i).R
            Case WallSide.Bottom : n = New Vector(0, 1) : _body(i).Py = _body(i).R
            Case Else : n = New Vector(0, -1) : _body(i).Py = _height - _body(i).R
        End Select
        CollideStatic(i, n, Nothing, side, CollisionKind.CircleWall, If(side = WallSide.Bottom, SupportFloor, SupportNone))
    End Sub

    Private Sub CollideRectangle(i As Integer, k As Integer, feature As Integer)
        Sync(i)
        Dim n As Vector
        Dim support = SupportNone
        Select Case feature
            Case 0 : n = New Vector(-1, 0) : _body(i).Px = Math.Min(_body(i).Px, _rx0(k) - _body(i).R)
            Case 1 : n = New Vector(1, 0) : _body(i).Px = Math.Max(_body(i).Px, _rx1(k) + _body(i).R)
            Case 2 : n = New Vector(0, -1) : _body(i).Py = Math.Min(_body(i).Py, _ry0(k) - _body(i).R)
            Case 3 : n = New Vector(0, 1) : _body(i).Py = Math.Max(_body(i).Py, _ry1(k) + _body(i).R) : support = k
            Case Else
                Dim cx = If(((feature - 4) And 1) = 0, _rx0(k), _rx1(k))
                Dim cy = If(((feature - 4) And 2) = 0, _ry0(k), _ry1(k))
                n = New Vector(_body(i).Px - cx, _body(i).Py - cy).Normalized(New Vector(0, 1))
        End Select
        CollideStatic(i, n, _rect(k), WallSide.None, CollisionKind.CircleRectangle, support)
    End Sub

    ''' <summary>
    ''' Body i (already at the clock) hits something of infinite mass along unit normal n (pointing
    ''' towards i). <paramref name="support"/> names what it would rest on if n points straight up.
    ''' </summary>
    Private Sub CollideStatic(i As Integer, n As Vector, b As Shape, side As WallSide, kind As CollisionKind, support As Integer)
        If Jammed(i) Then Return
        Dim before = New Vector(_body(i).Vx, _body(i).Vy)
        Dim approach = Vector.Dot(before, n)
        Dim after = Impulse.Resolve(before, 1.0, Vector.Zero, 0.0, n, _e).A
        If approach < 0 AndAlso after = before Then
            _body(i).Px += n.X * 4 * _slop ' see CollideCircles: an approach too small to resolve
            _body(i).Py += n.Y * 4 * _slop
        End If
        _body(i).Vx = after.X
        _body(i).Vy = after.Y
        If approach < 0 Then
            _world.ReportCollision(New CollisionRecord(_now, _circle(i), b, side, kind, before, after, Vector.Zero, Vector.Zero))
            _lastHit(i) = _now
        End If
        If _body(i).Mode = BodyMode.Resting AndAlso (after.Y <> 0 OrElse n.Y <> 0) Then MakeFree(i)
        If _body(i).Mode = BodyMode.Free Then AfterSupportContact(i, n, support, 0, 0)
        Changed(i)
        Reschedule(i)
    End Sub

    Private Sub CollideCircles(i As Integer, j As Integer)
        Sync(i)
        Sync(j)
        If _body(j).Mode = BodyMode.Sleeping AndAlso Jammed(i) Then Return
        If _body(i).Mode = BodyMode.Sleeping AndAlso Jammed(j) Then Return
        Dim n = New Vector(_body(i).Px - _body(j).Px, _body(i).Py - _body(j).Py).Normalized(New Vector(0, 1))
        Dim vi = New Vector(_body(i).Vx, _body(i).Vy), vj = New Vector(_body(j).Vx, _body(j).Vy)
        Dim approach = Vector.Dot(vi - vj, n)
        Dim gentle = -approach < GentleSpeed(i, j)
        Dim mi = _body(i).Mode, mj = _body(j).Mode
        ' A gentle touch on a body at rest treats it as a support (infinite mass); a real hit wakes it.
        Dim invI = InverseMassFor(i, mi, mj, gentle, j)
        Dim invJ = InverseMassFor(j, mj, mi, gentle, i)
        Dim result = Impulse.Resolve(vi, invI, vj, invJ, n, EffectiveRestitution(i, j))
        If approach < 0 AndAlso result.A = vi AndAlso result.B = vj Then
            ' The approach was below what the velocities can resolve in floating point (after an
            ' e = 0 contact): part them by a few slops instead, so the pair stops being "touching".
            Dim wi = If(invI > 0 OrElse invJ = 0, 0.5, 0.0), wj = If(invJ > 0 OrElse invI = 0, 0.5, 0.0)
            Dim sep = 4 * _slop / Math.Max(wi + wj, 0.5)
            _body(i).Px += n.X * sep * wi
            _body(i).Py += n.Y * sep * wi
            _body(j).Px -= n.X * sep * wj
            _body(j).Py -= n.Y * sep * wj
        End If
        _body(i).Vx = result.A.X
        _body(i).Vy = result.A.Y
        _body(j).Vx = result.B.X
        _body(j).Vy = result.B.Y
        ' Publish the new courses before waking anything above (which predicts against them).
        Publish(i)
        Publish(j)
        If approach < 0 AndAlso (invI > 0 OrElse invJ > 0) Then
            _world.ReportCollision(New CollisionRecord(_now, _circle(i), _circle(j), WallSide.None, CollisionKind.CircleCircle, vi, result.A, vj, result.B))
            _lastHit(i) = _now
            _lastHit(j) = _now
        End If
        ' Whoever moved leaves rest; a body still asleep stays a support.
        If result.A <> vi AndAlso _body(i).Mode <> BodyMode.Dragged Then WakeFrom(i)
        If result.B <> vj AndAlso _body(j).Mode <> BodyMode.Dragged Then WakeFrom(j)
        If _body(i).Mode = BodyMode.Free AndAlso invJ = 0 AndAlso _body(j).Mode <> BodyMode.Dragged Then
            AfterSupportContact(i, n, SupportOther, _body(j).Vx, _body(j).Vy)
        ElseIf _body(i).Mode = BodyMode.Free Then
            SleepIfSettled(i)
        End If
        If _body(j).Mode = BodyMode.Free AndAlso invI = 0 AndAlso _body(i).Mode <> BodyMode.Dragged Then
            AfterSupportContact(j, -n, SupportOther, _body(i).Vx, _body(i).Vy)
        ElseIf _body(j).Mode = BodyMode.Free Then
            SleepIfSettled(j)
        End If
        Changed(i)
        Changed(j)
        Reschedule(i)
        Reschedule(j)
    End Sub

    ''' <summary>
    ''' Body i's inverse mass in this collision. The dragged circle is immovable. A sleeping body hit
    ''' by a free body from above acts as part of its support (the floor beneath takes the blow); a
    ''' body at rest touched gently also stays put; anything else moves it and wakes it.
    ''' </summary>
    Private Function InverseMassFor(i As Integer, mode As BodyMode, partnerMode As BodyMode, gentle As Boolean, partner As Integer) As Double
        Select Case mode
            Case BodyMode.Dragged
                Return 0
            Case BodyMode.Sleeping, BodyMode.Resting
                If partnerMode = BodyMode.Free Then
                    ' Only a sleeper (which never moves) may take a blow from above as the ground does:
                    ' treating a moving body as immovable can trap a ball in a cycle of instantaneous hits.
                    Dim dy = _body(partner).Py - _body(i).Py
                    Dim above = mode = BodyMode.Sleeping AndAlso dy > 0.3 * (_body(i).R + _body(partner).R)
                    If above OrElse gentle Then Return 0
                End If
                Return _invMass(i)
            Case Else
                Return _invMass(i)
        End Select
    End Function

    ''' <summary>
    ''' Inelastic-collapse guard (the "TC model"): two bodies that both collided within the last
    ''' microsecond-scale interval collide elastically, so an infinite cascade cannot form in finite time.
    ''' </summary>
    Private Function EffectiveRestitution(i As Integer, j As Integer) As Double
        If _e >= 1 OrElse _g = 0 Then Return _e
        Dim tc = 1.0E-4 * Math.Sqrt(Math.Min(_body(i).R, _body(j).R) / _g)
        If _now - _lastHit(i) < tc AndAlso _now - _lastHit(j) < tc Then Return 1.0
        Return _e
    End Function

    ''' <summary>
    ''' A free body wedged between supports that do not give way (a ball falling into a gap slightly
    ''' narrower than itself) is hit by each of them in turn at the same instant, and pairwise impulses
    ''' only shave a little off its speed each time. After <see cref="JamHits"/> hits at one instant the
    ''' contacts are resolved together: the supports block every direction it could move in, so it
    ''' stops (and, under gravity, sleeps). Returns True when that happened and the event is done.
    ''' </summary>
    Private Function Jammed(i As Integer) As Boolean
        If _body(i).Mode <> BodyMode.Free Then Return False
        If _sameTime(i) = _now Then
            _sameCount(i) += 1
        Else
            _sameTime(i) = _now
            _sameCount(i) = 0
        End If
        If _sameCount(i) < JamHits Then Return False
        _body(i).Vx = 0
        _body(i).Vy = 0
        ' Wedged under gravity it goes to sleep where it is (even if the wedge is not quite a held
        ' position, it cannot move at this instant, and a sleeper wakes again when hit).
        If _g > 0 Then Sleep(i)
        Changed(i)
        _sameCount(i) = 0
        Reschedule(i)
        Return True
    End Function

    Private Const JamHits As Integer = 16

    ''' <summary>Normal speed (m/s) below which a touch on a resting body does not wake it: 10 % of √(g r).</summary>
    Private Function GentleSpeed(i As Integer, j As Integer) As Double
        Return 0.1 * Math.Sqrt(_g * Math.Min(_body(i).R, _body(j).R))
    End Function

    ''' <summary>
    ''' After a free body touched something that does not give way (floor, rectangle, fixed circle,
    ''' a body at rest, moving at (sx, sy) m/s) with normal n: the resting and sleeping rules that end
    ''' the Zeno series. Speeds are relative to the support.
    ''' </summary>
    Private Sub AfterSupportContact(i As Integer, n As Vector, support As Integer, sx As Double, sy As Double)
        If _g = 0 OrElse n.Y <= 0 Then Return
        Dim r = _body(i).R
        Dim rx = _body(i).Vx - sx, ry = _body(i).Vy - sy
        Dim vn = rx * n.X + ry * n.Y
        Dim speedScale = Math.Sqrt(_g * r)
        ' Resting rule: the rest of the bounce series is a geometric series of flight times.
        Dim restSpeed = Math.Sqrt(2 * _g * RestHeight(r))
        Dim level = n.Y >= 1 - 1.0E-12 AndAlso support <> SupportNone
        If level AndAlso vn < restSpeed AndAlso (support <> SupportOther OrElse Math.Abs(rx) < 0.02 * speedScale) Then
            EnterRest(i, support, vn)
            Return
        End If
        ' On a level support the bounce series is followed exactly down to restSpeed.
        If level AndAlso support <> SupportOther Then Return
        ' Sleeping rule: slow and held from below (one level support, or supports on both sides).
        If sx = 0 AndAlso sy = 0 Then
            SleepIfSettled(i)
            If _body(i).Mode = BodyMode.Sleeping Then Return
        End If
        ' Zeno guard on a slope: never leave a support slower than restSpeed, so a body sliding
        ' down a curved support hops down it in finitely many events instead of infinitely many.
        If vn < restSpeed Then
            _body(i).Vx += n.X * (restSpeed - vn)
            _body(i).Vy += n.Y * (restSpeed - vn)
        End If
    End Sub

    ''' <summary>
    ''' After a collision between free bodies: one that is now slow and held by what it touches
    ''' sleeps. A body caught in a burst of collisions (the start of inelastic collapse: more than
    ''' <see cref="BurstCollisions"/> within √(r/g)/10) sleeps as soon as it is held, at any speed
    ''' below √(g r): that chatter is a resting contact the event picture cannot end by itself.
    ''' </summary>
    Private Sub SleepIfSettled(i As Integer)
        If _g = 0 Then Return
        Dim speed2 = _body(i).Vx * _body(i).Vx + _body(i).Vy * _body(i).Vy
        Dim scale2 = _g * _body(i).R
        Dim window = 0.1 * Math.Sqrt(_body(i).R / _g)
        If _now - _burstStart(i) > window Then
            _burstStart(i) = _now
            _burstCount(i) = 0
        End If
        _burstCount(i) += 1
        Dim limit2 = If(_burstCount(i) > BurstCollisions, scale2, 0.0004 * scale2)
        If speed2 < limit2 AndAlso IsHeld(i) Then Sleep(i)
    End Sub

    Private Const BurstCollisions As Integer = 20

    ''' <summary>Bounce height (m) below which a ball counts as resting: 10⁻⁶ of its radius.</summary>
    Private Shared Function RestHeight(r As Double) As Double
        Return Math.Max(1.0E-6 * r, 1.0E-12)
    End Function

    Private Sub EnterRest(i As Integer, support As Integer, vn As Double)
        Dim c = _circle(i)
        Dim flight = If(_e < 1, 2 * vn / (_g * (1 - _e)), 0.0)
        Dim known As Double
        If Not (vn = 0 AndAlso _restTimes.TryGetValue(c, known)) Then _restTimes(c) = _now + flight
        _body(i).Vy = 0
        _body(i).Ay = 0
        _support(i) = support
        SetMode(i, BodyMode.Resting)
        ' Slow enough along a level support: asleep (a pile's floor layer must settle to hold the rest).
        If Math.Abs(_body(i).Vx) < 0.05 * Math.Sqrt(_g * _body(i).R) AndAlso support <> SupportNone Then Sleep(i)
    End Sub

    ''' <summary>Sets body i's mode, keeping count of the bodies sliding round a corner.</summary>
    Private Sub SetMode(i As Integer, mode As BodyMode)
        If _body(i).Mode = BodyMode.Sliding Then _sliding -= 1
        If mode = BodyMode.Sliding Then _sliding += 1
        _body(i).Mode = mode
    End Sub

    Private Sub Sleep(i As Integer)
        _body(i).Vx = 0
        _body(i).Vy = 0
        _body(i).Ay = 0
        SetMode(i, BodyMode.Sleeping)
    End Sub

    ''' <summary>A resting or sleeping body that was moved by a hit flies again, and so does what rests on it.</summary>
    Private Sub WakeFrom(i As Integer)
        Dim m = _body(i).Mode
        If m <> BodyMode.Sleeping AndAlso m <> BodyMode.Resting Then Return
        MakeFree(i)
        WakeAbove(i)
    End Sub

    Private Sub MakeFree(i As Integer)
        SetMode(i, BodyMode.Free)
        _body(i).Ay = -_g
        _support(i) = SupportNone
        _restTimes.Remove(_circle(i))
        ' Its lane shows it free at once: WakeAbove predicts the bodies above against it before the
        ' caller's Changed(i), and a lane still marked "not free" sent the vectorised pair test down
        ' another branch than the one-at-a-time test, so the two paths' runs drifted apart.
        Publish(i)
    End Sub

    ''' <summary>Wakes every sleeping or resting body that (directly or through others) rests on body i.</summary>
    Private Sub WakeAbove(i As Integer)
        Dim head = 0, tail = 0
        _wake(tail) = i
        tail += 1
        While head < tail
            Dim k = _wake(head)
            head += 1
            Dim here = PositionNow(k)
            Dim kx = here.X, ky = here.Y
            Dim count = Neighbours(k)
            For q = 0 To count - 1
                Dim j = _stack(q)
                Dim mj = _body(j).Mode
                If mj <> BodyMode.Sleeping AndAlso mj <> BodyMode.Resting Then Continue For
                Dim dx = _body(j).Px - kx, dy = _body(j).Py - ky
                If dy <= 0 Then Continue For
                Dim reach = _body(j).R + _body(k).R + 1.0E-3 * Math.Min(_body(j).R, _body(k).R)
                If dx * dx + dy * dy > reach * reach Then Continue For
                Sync(j)
                MakeFree(j)
                Changed(j)
                Reschedule(j)
                If tail < _wake.Length Then
                    _wake(tail) = j
                    tail += 1
                End If
            Next
        End While
    End Sub

    ''' <summary>Where body k is at the solver's clock, m.</summary>
    Private Function PositionNow(k As Integer) As Vector
        Dim x, y, vx, vy As Double
        _body(k).StateAt(_now, x, y, vx, vy)
        Return New Vector(x, y)
    End Function

    ''' <summary>
    ''' Whether body i is held against gravity by what it touches (within 10⁻³ r): the upward
    ''' vertical lies in the cone of its contact normals, so normal forces alone can balance its
    ''' weight (one level support, or two on either side of the vertical, or a cage). Neighbours count
    ''' whether asleep or not (a settling pile freezes as a whole); only nearby cells are searched.
    ''' </summary>
    Private Function IsHeld(i As Integer) As Boolean
        Dim p = PositionNow(i)
        Dim px = p.X, py = p.Y, r = _body(i).R
        Dim gap = 1.0E-3 * r + _slop
        _nNormals = 0
        If _walls Then
            If py - r <= gap Then Return True
            If px - r <= gap Then AddNormal(1, 0)
            If _width - r - px <= gap Then AddNormal(-1, 0)
            If _height - r - py <= gap Then AddNormal(0, -1)
        End If
        For k = 0 To _nRect - 1
            Dim c = Collider.CircleRectangle(p, r, New Vector(_rx0(k), _ry0(k)), New Vector(_rx1(k), _ry1(k)))
            If c.Depth >= -gap Then AddNormal(c.Normal.X, c.Normal.Y)
        Next
        For k = 0 To _nFixed - 1
            Dim c = Collider.CircleCircle(p, r, New Vector(_fx(k), _fy(k)), _fr(k))
            If c.Depth >= -gap Then AddNormal(c.Normal.X, c.Normal.Y)
        Next
        Dim count = Neighbours(i)
        For q = 0 To count - 1
            Dim j = _stack(q)
            If _body(j).Mode = BodyMode.Sliding OrElse _body(j).Mode = BodyMode.Dragged Then Continue For
            Dim c = Collider.CircleCircle(p, r, PositionNow(j), _body(j).R)
            If c.Depth >= -gap Then AddNormal(c.Normal.X, c.Normal.Y)
        Next
        ' Up = (0, 1) lies between normals a (a.x ≥ 0) and b (b.x ≤ 0) turning anticlockwise by at most π.
        For a = 0 To _nNormals - 1
            If _normalY(a) > 0.999 Then Return True
            For b = 0 To _nNormals - 1
                If _normalX(a) >= 0 AndAlso _normalX(b) <= 0 AndAlso
                   _normalX(a) * _normalY(b) - _normalY(a) * _normalX(b) > 0 Then Return True
            Next
        Next
        Return False
    End Function

    Private Sub AddNormal(x As Double, y As Double)
        If _nNormals < _normalX.Length Then
            _normalX(_nNormals) = x
            _normalY(_nNormals) = y
            _nNormals += 1
        End If
    End Sub

    ''' <summary>Fills the scratch stack with the movable bodies in the 3 × 3 cells around i (all bodies if i is oversized); returns how many.</summary>
    Private Function Neighbours(i As Integer) As Integer
        Dim count = 0
        If _ev(i).Cell < 0 Then
            For j = 0 To _n - 1
                If j <> i Then _stack(count) = j : count += 1
            Next
            Return count
        End If
        Dim col = _ev(i).Col, row = _ev(i).Row
        For rr = Math.Max(0, row - 1) To Math.Min(_grid.Ny - 1, row + 1)
            For cc = Math.Max(0, col - 1) To Math.Min(_grid.Nx - 1, col + 1)
                Dim cell = rr * _grid.Nx + cc
                For lane = cell * UniformGrid.Lanes To cell * UniformGrid.Lanes + _grid.Count(cell) - 1
                    Dim j = _grid.LaneBody(lane)
                    If j <> i AndAlso count < _stack.Length Then _stack(count) = j : count += 1
                Next
                Dim o = _grid.OverflowHead(cell)
                While o >= 0
                    If o <> i AndAlso count < _stack.Length Then _stack(count) = o : count += 1
                    o = _grid.OverflowNext(o)
                End While
            Next
        Next
        For k = 0 To _nOversized - 1
            If _oversized(k) <> i AndAlso count < _stack.Length Then _stack(count) = _oversized(k) : count += 1
        Next
        Return count
    End Function


    ''' <summary>
    ''' A resting body's centre reached the edge of its rectangle: fast enough (v² ≥ g r) it flies off
    ''' on a parabola; slower, it slides round the corner until the normal force vanishes.
    ''' </summary>
    Private Sub LeaveEdge(i As Integer, k As Integer)
        Sync(i)
        Dim vx = _body(i).Vx
        Dim edge = If(vx > 0, _rx1(k), _rx0(k))
        _body(i).Px = edge
        _body(i).Py = _ry1(k) + _body(i).R
        MakeFree(i)
        If vx * vx < _g * _body(i).R Then
            SetMode(i, BodyMode.Sliding)
            _body(i).Ay = 0
            _slideCx(i) = edge
            _slideCy(i) = _ry1(k)
            _slideDir(i) = Math.Sign(vx)
            _slideV0(i) = Math.Abs(vx)
            _slideAngle(i) = CornerSlide.LeaveAngle(Math.Abs(vx), _g, _body(i).R, 0)
            _slideStart(i) = _now
        End If
        Changed(i)
        Reschedule(i)
    End Sub

    ''' <summary>
    ''' Ends a slide early (a neighbour came within reach): the ball becomes free at its exact place
    ''' and velocity on the arc. If it is still pressed against the corner, the contact rules take
    ''' over (it hops round the rest of the corner).
    ''' </summary>
    Private Sub Materialize(i As Integer)
        Dim theta = CornerSlide.AngleAfter(_slideV0(i), _g, _body(i).R, 0, _slideAngle(i), _now - _slideStart(i))
        LaunchFromCorner(i, theta, _body(i).R)
    End Sub

    ''' <summary>
    ''' Turns a ball sliding round a corner into a free ball at angle θ from the vertical, its centre
    ''' <paramref name="arc"/> m from the corner, moving along the tangent at the slide's speed there.
    ''' </summary>
    Private Sub LaunchFromCorner(i As Integer, theta As Double, arc As Double)
        Dim s = _slideDir(i)
        Dim speed = CornerSlide.SpeedAt(_slideV0(i), _g, _body(i).R, 0, theta)
        _body(i).Px = _slideCx(i) + s * arc * Math.Sin(theta)
        _body(i).Py = _slideCy(i) + arc * Math.Cos(theta)
        _body(i).Vx = s * speed * Math.Cos(theta)
        _body(i).Vy = -speed * Math.Sin(theta)
        _body(i).T0 = _now
        MakeFree(i)
        Changed(i)
        MoveToCellOfPosition(i)
    End Sub

    Private Sub MoveToCellOfPosition(i As Integer)
        If _ev(i).Cell < 0 Then Return
        MoveToCell(i, _grid.ColumnOf(_body(i).Px), _grid.RowOf(_body(i).Py))
    End Sub

    Private Sub EndSlide(i As Integer)
        ' It leaves tangentially, touching the corner with zero normal speed; start it a hair (far
        ' below any physical scale) outside, so rounding cannot turn the tangent into a collision.
        Dim arc = _body(i).R + 10 * _slop + 1.0E-9 * _body(i).R
        LaunchFromCorner(i, _slideAngle(i), arc)
        Reschedule(i)
    End Sub

    ''' <summary>The dragged circle moves in a straight line to its target over this advance, with no gravity.</summary>
    Private Sub StartDrag(duration As Double)
        Dim c = _world.DraggedCircle
        Dim i As Integer
        If c Is Nothing OrElse Not _index.TryGetValue(c, i) Then Return
        Sync(i)
        Dim target = _world.DragTarget
        SetMode(i, BodyMode.Dragged)
        _body(i).Ay = 0
        _invMass(i) = 0
        _body(i).Vx = (target.X - _body(i).Px) / duration
        _body(i).Vy = (target.Y - _body(i).Py) / duration
        Changed(i)
        Reschedule(i)
    End Sub

    ''' <summary>Writes every movable circle's exact state at <paramref name="t"/> back to the model.</summary>
    Private Sub WriteBack(t As Double)
        Dim dragged = _world.DraggedCircle
        For i = 0 To _n - 1
            Dim c = _circle(i)
            If _body(i).Mode = BodyMode.Sliding Then
                Dim v0 = _slideV0(i), r = _body(i).R, s = _slideDir(i)
                Dim theta = CornerSlide.AngleAfter(v0, _g, r, 0, _slideAngle(i), t - _slideStart(i))
                Dim speed = CornerSlide.SpeedAt(v0, _g, r, 0, theta)
                c.Position = New Vector(_slideCx(i) + s * r * Math.Sin(theta), _slideCy(i) + r * Math.Cos(theta))
                c.Velocity = New Vector(s * speed * Math.Cos(theta), -speed * Math.Sin(theta))
                Continue For
            End If
            Dim x, y, vx, vy As Double
            _body(i).StateAt(t, x, y, vx, vy)
            c.Position = New Vector(x, y)
            c.Velocity = New Vector(vx, vy)
            If c Is dragged Then c.Position = _world.DragTarget
        Next
    End Sub
End Class
