Option Strict On

''' <summary>
''' Bodies sliding round a corner (<see cref="BodyMode.Rounding"/>): a rounded corner of the pair
''' shape of a body and the fixed body it slides on (a rectangle's corner, a segment's end, a fixed
''' circle, a body asleep), round which its reference point moves on a circular arc. This owns where
''' each arc is and how its slide started, and answers where the body is on it, when the slide ends,
''' and when a neighbour comes within reach. The maths is <see cref="CornerSlide"/>'s: angles θ are
''' measured from the upward vertical, increasing in the direction of travel.
''' </summary>
Friend NotInheritable Class CornerSlides
    Private ReadOnly _s As SolverState
    ' Per body: the corner (centre of the arc, m), the arc's radius (m), the direction (±1: +1 clockwise),
    ' the angle and speed at the start (rad, m/s), the angle where the slide ends (rad), whether it ends
    ' there on the next face (rather than by leaving the corner), and when it started (s).
    Private _cx As Double() = Array.Empty(Of Double)()
    Private _cy As Double() = Array.Empty(Of Double)()
    Private _radius As Double() = Array.Empty(Of Double)()
    Private _dir As Double() = Array.Empty(Of Double)()
    Private _theta0 As Double() = Array.Empty(Of Double)()
    Private _v0 As Double() = Array.Empty(Of Double)()
    Private _endAngle As Double() = Array.Empty(Of Double)()
    Private _ontoFace As Boolean() = Array.Empty(Of Boolean)()
    Private _start As Double() = Array.Empty(Of Double)()
    ''' <summary>
    ''' True when the body is still climbing towards a turning point it reaches at <see cref="_start"/>:
    ''' the slide is then described from that point on, where it is at rest, and the climb is its mirror
    ''' image in time (before _start the body is where the slide puts it at _start − t, moving the other way).
    ''' </summary>
    Private _climbing As Boolean() = Array.Empty(Of Boolean)()
    ''' <summary>Where each sliding body was last found (m) and when (s): one quadrature per body per instant, however many neighbours ask.</summary>
    Private _seenAt As Double() = Array.Empty(Of Double)()
    Private _seenX As Double() = Array.Empty(Of Double)()
    Private _seenY As Double() = Array.Empty(Of Double)()
    ''' <summary>How many times each slide has been looked at again because a neighbour came near (see <see cref="StillApart"/>).</summary>
    Private _looks As Integer() = Array.Empty(Of Integer)()
    ''' <summary>Scratch list of a body's neighbours (no allocation per event).</summary>
    Private _neighbours As Integer() = Array.Empty(Of Integer)()

    ''' <summary>
    ''' Looks at a slide beyond this many end it (the slide is then cut short, as when a neighbour is
    ''' about to touch). Conservative advancement ends only when the gap closes: a neighbour that
    ''' hovers just outside <see cref="Near"/> (a ball bouncing between a peg and a ball rounding it)
    ''' would otherwise cost ever shorter looks, hundreds per bounce.
    ''' </summary>
    Private Const MaxLooks As Integer = 64

    Friend Sub New(state As SolverState)
        _s = state
    End Sub

    Friend Sub Reset(n As Integer)
        If _cx.Length >= n Then Return
        _cx = New Double(n - 1) {}
        _cy = New Double(n - 1) {}
        _radius = New Double(n - 1) {}
        _dir = New Double(n - 1) {}
        _theta0 = New Double(n - 1) {}
        _v0 = New Double(n - 1) {}
        _endAngle = New Double(n - 1) {}
        _ontoFace = New Boolean(n - 1) {}
        _start = New Double(n - 1) {}
        _climbing = New Boolean(n - 1) {}
        _seenAt = Enumerable.Repeat(Double.NaN, n).ToArray()
        _seenX = New Double(n - 1) {}
        _seenY = New Double(n - 1) {}
        _looks = New Integer(n - 1) {}
        _neighbours = New Integer(n - 1) {}
    End Sub

    ''' <summary>
    ''' Body i, at the clock, its reference point <paramref name="radius"/> m from the corner
    ''' (<paramref name="cx"/>, <paramref name="cy"/>) along <paramref name="normal"/>, moving at
    ''' <paramref name="velocity"/> (m/s; only its part along the arc's tangent counts), starts sliding
    ''' round it. It leaves when the normal force vanishes, or reaches a face that takes it first: the
    ''' corner's normals end at the two <paramref name="cone"/> normals (Nothing for a full circle: a
    ''' fixed circle, a ball at rest). A body climbing towards the top too slowly to pass it turns back
    ''' and slides down again. Returns False, doing nothing, when it is too fast to follow the curve at
    ''' all (it flies off at once), rests exactly on top, or has a moving neighbour touching it.
    ''' </summary>
    Friend Function Start(i As Integer, cx As Double, cy As Double, radius As Double, normal As Vector, velocity As Vector,
                          cone As (Vector, Vector)?) As Boolean
        Dim g = _s.G
        _Refusal = SlideRefusal.Still
        If Not (g > 0) Then Return False
        ' A neighbour already touching would cut the slide short at once, and it would start again
        ' at once; a wall or a fixed body in the way would not be seen. The contact rules carry it round
        ' instead (in hops).
        _Refusal = SlideRefusal.Crowded
        If Crowded(i, New Vector(cx, cy), radius, New Vector(cx, cy) + normal * radius) Then Return False
        _Refusal = SlideRefusal.Blocked
        If Not Clear(i, cx, cy, radius) Then Return False
        _Refusal = SlideRefusal.Still
        Dim phi = Math.Atan2(normal.X, normal.Y)
        Dim tangent = New Vector(Math.Cos(phi), -Math.Sin(phi)) ' clockwise
        Dim vt = Vector.Dot(velocity, tangent)
        ' Which way round: as it moves, or (at rest) the way gravity pulls it.
        Dim dir As Double = If(vt <> 0, Math.Sign(vt), If(normal.X <> 0, Math.Sign(normal.X), 1))
        Dim theta0 = dir * phi
        Dim speed = Math.Abs(vt)
        If speed = 0 AndAlso theta0 = 0 Then Return False ' at rest exactly on top: it stays
        Dim climbing = False
        Dim startTime = _s.Now
        If theta0 < 0 Then
            ' Climbing towards the top: it turns back where v² = v0² + 2gR (cos θ0 − cos θ) reaches 0,
            ' unless it has the speed to pass the top.
            Dim cosTurn = Math.Cos(theta0) + speed * speed / (2 * g * radius)
            If cosTurn < 1 AndAlso CornerSlide.LeaveAngle(speed, g, radius, theta0) > theta0 Then
                ' From the turning point on it slides back the other way, starting at rest; the climb is
                ' the mirror image in time of the slide back down to here.
                Dim turn = Math.Acos(cosTurn) ' > 0: the turning point's angle, seen going back
                Dim climb = CornerSlide.Duration(0, g, radius, turn, -theta0)
                If Not (climb < Double.PositiveInfinity) Then Return False
                dir = -dir
                theta0 = turn
                speed = 0
                climbing = True
                startTime = _s.Now + climb
            End If
        End If
        Dim leave = CornerSlide.LeaveAngle(speed, g, radius, theta0)
        _Refusal = SlideRefusal.FliesOff
        If leave <= theta0 AndAlso Not climbing Then Return False
        _Refusal = SlideRefusal.None
        Dim finish = leave
        Dim ontoFace = False
        If cone.HasValue Then
            ' The arc ends where the next face ahead begins: beyond that the face holds it.
            Dim ahead = Math.Min(AngleAhead(cone.Value.Item1, dir, theta0), AngleAhead(cone.Value.Item2, dir, theta0))
            If ahead < leave Then
                finish = ahead
                ontoFace = True
            End If
        End If
        Dim b = _s.Bodies
        ' An arc wider than a body's own reach can carry it beyond the cells searched around it.
        If radius > _s.RMax Then _s.Roam(i)
        b.SetMode(i, BodyMode.Rounding)
        b.Motion(i).Ay = Double.NaN ' not a parabola: no prediction may read it as one
        b.Motion(i).Ax = 0
        _cx(i) = cx
        _cy(i) = cy
        _radius(i) = radius
        _dir(i) = dir
        _theta0(i) = theta0
        _v0(i) = speed
        _endAngle(i) = finish
        _ontoFace(i) = ontoFace
        _start(i) = startTime
        _climbing(i) = climbing
        _seenAt(i) = Double.NaN
        _looks(i) = 0
        Return True
    End Function

    ''' <summary>Why the last <see cref="Start"/> refused a slide (None when it started one).</summary>
    Friend ReadOnly Property Refusal As SlideRefusal

    ''' <summary>
    ''' Whether body i can go the whole way round the corner (cx, cy) at <paramref name="radius"/> m
    ''' without meeting a wall or another fixed body: the slide checks neither, so the whole circle its
    ''' reference point could follow must keep its outline inside the container and clear of every
    ''' obstacle but the one it rounds (the obstacles whose pair shape holds the corner itself).
    ''' </summary>
    Private Function Clear(i As Integer, cx As Double, cy As Double, radius As Double) As Boolean
        Dim o = _s.Bodies.Outlines(i)
        If _s.Walls AndAlso (cx - radius + o.MinX < 0 OrElse cy - radius + o.MinY < 0 OrElse
                             cx + radius + o.MaxX > _s.Width OrElse cy + radius + o.MaxY > _s.Height) Then Return False
        Dim corner = New Vector(cx, cy)
        Dim tolerance = 1.0E-9 * radius + 16 * SolverState.SlopAt(cx, cy)
        For k = 0 To _s.Obstacles.Count - 1
            Dim depth = ContactRules.OverlapWithObstacle(_s, i, k, corner).Depth
            If depth >= radius - tolerance Then Continue For ' the corner is this obstacle's own
            If depth > -radius - tolerance Then Return False
        Next
        Return True
    End Function

    ''' <summary>The angle (in the direction of travel) of a cone normal, the first time it comes at or after θ0.</summary>
    Private Shared Function AngleAhead(normal As Vector, dir As Double, theta0 As Double) As Double
        Dim theta = dir * Math.Atan2(normal.X, normal.Y)
        While theta <= theta0
            theta += 2 * Math.PI
        End While
        Return theta
    End Function

    ''' <summary>Time (s, from now) until sliding body i leaves its corner or reaches the next face.</summary>
    Friend Function TimeToEnd(i As Integer) As Double
        Return Math.Max(0, CornerSlide.Duration(_v0(i), _s.G, _radius(i), _theta0(i), _endAngle(i)) - (_s.Now - _start(i)))
    End Function

    ''' <summary>Where on its arc body i is at time t (rad) and which way it moves: +1 on, −1 still climbing back to the turning point.</summary>
    Private Function AngleAt(i As Integer, t As Double, ByRef sense As Double) As Double
        Dim tau = t - _start(i)
        sense = If(tau < 0, -1.0, 1.0)
        Return CornerSlide.AngleAfter(_v0(i), _s.G, _radius(i), _theta0(i), _endAngle(i), Math.Abs(tau))
    End Function

    ''' <summary>
    ''' When body k could first touch sliding body j: no earlier than k enters the disc of radius
    ''' (arc + reach j + reach k) about the corner, and no earlier than the gap between them now could
    ''' close. That gap is |p_k − p_j| − reach j − reach k; j moves at most at √(v0² + 4gR) on its arc
    ''' (energy), k at |v_k| + |a_k| t, so the gap closes no sooner than the root of
    ''' ½|a_k| t² + (V_j + |v_k|) t = gap. At that time the pair is looked at again (see
    ''' <see cref="StillApart"/>): a conservative advancement that follows the slide exactly until k
    ''' really comes close. A body asleep counts as one at rest (a slide can run into a pile). +∞ if k
    ''' never gets there, or slides round a corner itself.
    ''' <para>
    ''' Also +∞ when k cannot get there before <paramref name="until"/> (s from now): the caller keeps
    ''' only a time earlier than that, so the answer is the same. A slide round a corner wider than
    ''' a body's reach roams (it looks at every body each time it is rescheduled), and most of those
    ''' bodies are far away: a bound from k's speed rules them out without the quartic.
    ''' </para>
    ''' </summary>
    Friend Function TimeToReach(j As Integer, k As Integer, Optional until As Double = Double.PositiveInfinity) As Double
        Dim b = _s.Bodies
        Dim mk = b.Slot(k).Mode
        If mk = BodyMode.Rounding Then Return Double.PositiveInfinity
        Dim xk, yk, vxk, vyk As Double
        b.Motion(k).StateAt(_s.Now, xk, yk, vxk, vyk)
        Dim reach = b.Size(k).Reach + _radius(j) + b.Size(j).Reach ' m: the disc k enters
        Dim slop = SolverState.SlopAt(xk, yk)
        If until < Double.PositiveInfinity AndAlso
           EarliestEntry(xk - _cx(j), yk - _cy(j), vxk, vyk, b.Motion(k).Ax, b.Motion(k).Ay, reach, slop) >= until Then
            Return Double.PositiveInfinity
        End If
        Dim disc = TimeOfImpact.CircleCircleAccelerated(xk - _cx(j), yk - _cy(j), vxk, vyk, b.Motion(k).Ax, b.Motion(k).Ay, reach, slop)
        If Not (disc < Double.PositiveInfinity) Then Return disc
        Dim gap = Me.Gap(j, k)
        If gap <= Near(j, k) Then Return disc
        Dim speed = Math.Sqrt(_v0(j) * _v0(j) + 4 * _s.G * _radius(j)) + Math.Sqrt(vxk * vxk + vyk * vyk)
        Dim accel = Math.Sqrt(b.Motion(k).Ax * b.Motion(k).Ax + b.Motion(k).Ay * b.Motion(k).Ay)
        Dim closing = 2 * gap / (speed + Math.Sqrt(speed * speed + 2 * accel * gap))
        Return Math.Max(disc, closing)
    End Function

    ''' <summary>
    ''' A lower bound (s) on when a body at (dx, dy) from a disc's centre (m), moving at (vx, vy) (m/s)
    ''' with acceleration (ax, ay) (m/s²), can first come within <paramref name="reach"/> m of it, as
    ''' <see cref="TimeOfImpact.CircleCircleAccelerated"/> counts touching (within the touching
    ''' tolerance <paramref name="slop"/>, m). Its speed is at most |v| + |a| t, so the distance beyond
    ''' the disc closes no sooner than the root of ½|a| t² + |v| t = distance. The distance is taken two
    ''' tolerances short and the time a millionth short, so rounding here or in the exact test never
    ''' puts the bound after the exact time. 0 when it is already that close; +∞ when it cannot move.
    ''' </summary>
    Friend Shared Function EarliestEntry(dx As Double, dy As Double, vx As Double, vy As Double, ax As Double, ay As Double,
                                          reach As Double, slop As Double) As Double
        Dim outside = Math.Sqrt(dx * dx + dy * dy) - reach - 2 * slop
        If Not (outside > 0) Then Return 0
        Dim speed = Math.Sqrt(vx * vx + vy * vy)
        Dim accel = Math.Sqrt(ax * ax + ay * ay)
        Return (1 - 1.0E-6) * 2 * outside / (speed + Math.Sqrt(speed * speed + 2 * accel * outside))
    End Function

    ''' <summary>
    ''' Whether sliding body j and body k are still clearly apart (further than <see cref="Near"/>): the
    ''' slide goes on. After <see cref="MaxLooks"/> looks the slide is treated as about to be touched.
    ''' </summary>
    Friend Function StillApart(j As Integer, k As Integer) As Boolean
        _looks(j) += 1
        Return _looks(j) <= MaxLooks AndAlso Gap(j, k) > Near(j, k)
    End Function

    ''' <summary>The gap (m) between the discs that hold sliding body j and body k now (negative if they overlap).</summary>
    Private Function Gap(j As Integer, k As Integer) As Double
        Dim b = _s.Bodies
        If _seenAt(j) <> _s.Now Then
            Dim pj, vj As Vector
            StateAt(j, _s.Now, pj, vj)
            _seenAt(j) = _s.Now
            _seenX(j) = pj.X
            _seenY(j) = pj.Y
        End If
        Return (b.PositionAt(k, _s.Now) - New Vector(_seenX(j), _seenY(j))).Length - b.Size(j).Reach - b.Size(k).Reach
    End Function

    ''' <summary>How close (m) sliding body j and body k count as about to touch (see <see cref="NearGap"/>).</summary>
    Private Function Near(j As Integer, k As Integer) As Double
        Return NearGap(j, k, _cx(j), _cy(j))
    End Function

    ''' <summary>How close (m) bodies i and k count as about to touch near (x, y): 10⁻⁶ of the smaller reach, and the touching tolerance there.</summary>
    Private Function NearGap(i As Integer, k As Integer, x As Double, y As Double) As Double
        Dim b = _s.Bodies
        Return 1.0E-6 * Math.Min(b.Size(i).Reach, b.Size(k).Reach) + 16 * SolverState.SlopAt(x, y)
    End Function

    ''' <summary>
    ''' Whether body i, with its reference point at <paramref name="p"/>, has a neighbour (moving or asleep, not
    ''' itself sliding) already within the slide's reach (the disc about the corner that its outline sweeps),
    ''' which the slide's look-ahead does not watch (it sees bodies coming in), or within 10⁻³ of the
    ''' smaller size (or <see cref="Near"/>, if larger): a slide would
    ''' be cut short almost at once, after ever shorter looks while the neighbour hovers just outside
    ''' <see cref="Near"/> (two balls pressed together on a peg). Such a pair settles as a cluster instead.
    ''' </summary>
    Private Function Crowded(i As Integer, corner As Vector, radius As Double, p As Vector) As Boolean
        Dim b = _s.Bodies
        Dim count = GridNeighbours.Collect(_s, i, _neighbours)
        For q = 0 To count - 1
            Dim k = _neighbours(q)
            Dim mk = b.Slot(k).Mode
            If mk = BodyMode.Rounding Then Continue For
            Dim pk = b.PositionAt(k, _s.Now)
            Dim gap = (pk - p).Length - b.Size(i).Reach - b.Size(k).Reach
            If gap <= Math.Max(NearGap(i, k, p.X, p.Y), 0.001 * Math.Min(b.Size(i).Reach, b.Size(k).Reach)) Then Return True
            ' Already where the slide could reach it: the slide's look-ahead only sees bodies coming in.
            If (pk - corner).Length < b.Size(k).Reach + radius + b.Size(i).Reach Then Return True
        Next
        Return False
    End Function

    ''' <summary>Fills the scratch list with body i's grid neighbours (see <see cref="Neighbour"/>); returns how many.</summary>
    Friend Function Neighbours(i As Integer) As Integer
        Return GridNeighbours.Collect(_s, i, _neighbours)
    End Function

    Friend Function Neighbour(q As Integer) As Integer
        Return _neighbours(q)
    End Function

    ''' <summary>Sliding body i's reference point (m) and velocity (m/s) at time t (s), exactly on its arc.</summary>
    Friend Sub StateAt(i As Integer, t As Double, ByRef position As Vector, ByRef velocity As Vector)
        Dim sense As Double
        Dim theta = AngleAt(i, t, sense)
        Dim speed = sense * CornerSlide.SpeedAt(_v0(i), _s.G, _radius(i), _theta0(i), theta)
        Dim s = _dir(i)
        position = New Vector(_cx(i) + s * _radius(i) * Math.Sin(theta), _cy(i) + _radius(i) * Math.Cos(theta))
        velocity = New Vector(s * speed * Math.Cos(theta), -speed * Math.Sin(theta))
    End Sub

    ''' <summary>
    ''' Ends a slide early (a neighbour came within reach): the body becomes free at its exact place
    ''' and velocity on the arc. If it is still pressed against the corner, the contact rules take
    ''' over (it hops round the rest of the corner).
    ''' </summary>
    Friend Sub Interrupt(i As Integer)
        Dim sense As Double
        Dim theta = AngleAt(i, _s.Now, sense)
        Launch(i, theta, _radius(i), sense)
    End Sub

    ''' <summary>
    ''' The slide is over. Leaving the corner, it goes off tangentially, touching it with zero normal
    ''' speed: it starts a hair (ten touching tolerances, far below any physical scale) outside, so
    ''' rounding cannot turn the tangent into a collision. Reaching the next face, it goes on from exactly there, and the face's
    ''' own contact takes over.
    ''' </summary>
    Friend Sub Finish(i As Integer)
        Dim r = _radius(i)
        Launch(i, _endAngle(i), If(_ontoFace(i), r, r + 10 * SolverState.SlopAt(_cx(i) + r, _cy(i) + r)), 1)
    End Sub

    ''' <summary>
    ''' Turns body i into a free body at angle θ on its arc, its reference point <paramref name="arc"/> m
    ''' from the corner, moving along the tangent at the slide's speed there (backwards, sense −1, while
    ''' it is still climbing to its turning point).
    ''' </summary>
    Private Sub Launch(i As Integer, theta As Double, arc As Double, sense As Double)
        Dim b = _s.Bodies
        Dim s = _dir(i)
        Dim speed = sense * CornerSlide.SpeedAt(_v0(i), _s.G, _radius(i), _theta0(i), theta)
        b.Motion(i).Px = _cx(i) + s * arc * Math.Sin(theta)
        b.Motion(i).Py = _cy(i) + arc * Math.Cos(theta)
        b.Motion(i).Vx = s * speed * Math.Cos(theta)
        b.Motion(i).Vy = -speed * Math.Sin(theta)
        b.Motion(i).T0 = _s.Now
        b.SetMode(i, BodyMode.Free)
        b.Motion(i).Ay = -_s.G
        b.Support(i) = BodyTable.SupportNone
        _s.StopRoaming(i)
        _s.Changed(i)
        _s.MoveToCellOfPosition(i)
    End Sub
End Class
