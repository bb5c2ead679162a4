Option Strict On

Imports System.Runtime.CompilerServices

''' <summary>
''' How bodies come to rest (docs/event-driven.md §5–6): the end of a bounce series on a level
''' support, sleeping in a pile, waking, and the guards against inelastic collapse. This keeps each
''' body's recent contact history (its bursts here; its last collision and its hits at one instant in
''' <see cref="BodyInfo"/>, beside what every collision reads, and written only from here) and the rest times.
''' </summary>
Friend NotInheritable Class RestRules
    Private ReadOnly _s As SolverState
    Private ReadOnly _slides As CornerSlides
    Private ReadOnly _bodies As BodyTable
    ''' <summary>Each body's current burst of collisions (its last hits are in BodyTable.Info).</summary>
    Private _bursts As BurstHistory() = Array.Empty(Of BurstHistory)()
    ''' <summary>When each supported body's series of ever smaller bounces ends, s.</summary>
    Private ReadOnly _restTimes As New Dictionary(Of Shape, Double)()
    ''' <summary>Contact normals gathered by IsHeld (scratch, fixed size).</summary>
    Private ReadOnly _normalX As Double() = New Double(15) {}
    Private ReadOnly _normalY As Double() = New Double(15) {}
    ''' <summary>Whether each gathered normal is a wall's or a fixed body's, rather than another body's.</summary>
    Private ReadOnly _normalFixed As Boolean() = New Boolean(15) {}
    Private _nNormals As Integer
    ''' <summary>
    ''' Set by <see cref="IsHeld"/>: the body would be held by what it touches if that stood still, but it leans on
    ''' the slope of a body that would be pushed aside (a ball in the V between two balls on a frictionless floor).
    ''' </summary>
    Private _leansOnLoose As Boolean
    ''' <summary>Whether a cluster of still bodies is held by the contact forces (see <see cref="HeldOnSlope"/>).</summary>
    Private ReadOnly _equilibrium As EquilibriumCheck
    ''' <summary>Scratch: each walk up a stack's queue and the bodies found on one body (see <see cref="WalkAbove"/>), and one body's neighbours.</summary>
    Private _wake As Integer() = Array.Empty(Of Integer)()
    Private _settle As Integer() = Array.Empty(Of Integer)()
    Private ReadOnly _wakeFound As New List(Of Integer)
    Private ReadOnly _settleFound As New List(Of Integer)
    Private _neighbours As Integer() = Array.Empty(Of Integer)()
    ''' <summary>What each walk up a stack does with a body it finds (made once, not at every walk).</summary>
    Private ReadOnly _settleOne As Func(Of Integer, Boolean)
    Private ReadOnly _wakeOne As Func(Of Integer, Boolean)

    ''' <summary>Hits at one instant after which a body's cluster is resolved at once (see <see cref="HitTooOften"/>).</summary>
    Private Const JamHits As Integer = 16
    ''' <summary>Collisions within √(r/g)/10 that count as a burst (the start of inelastic collapse).</summary>
    Private Const BurstCollisions As Integer = 20

    Friend Sub New(state As SolverState, slides As CornerSlides)
        _s = state
        _bodies = state.Bodies
        _slides = slides
        _equilibrium = New EquilibriumCheck(state)
        _settleOne = AddressOf SettleOnBelow
        _wakeOne = AddressOf WakeOne
    End Sub

    ''' <summary>Forgets every body's history (after a rebuild); rest times survive while the body still sits still.</summary>
    Friend Sub Reset()
        Dim n = _s.Bodies.Count
        If _bursts.Length < n Then
            Dim capacity = Math.Max(n, 2 * _bursts.Length)
            _bursts = New BurstHistory(capacity - 1) {}
            _wake = New Integer(capacity - 1) {}
            _settle = New Integer(capacity - 1) {}
            _neighbours = New Integer(capacity - 1) {}
        End If
        Dim stillResting As New HashSet(Of Shape)()
        For i = 0 To n - 1
            _bursts(i) = BurstHistory.Fresh
            _bodies.Info(i).ResetHits()
            Dim body = _s.Bodies.Shapes(i)
            If _restTimes.ContainsKey(body) AndAlso _s.Bodies.Mode(i) = BodyMode.Free AndAlso _s.Bodies.Motion(i).Vy = 0 Then stillResting.Add(body)
        Next
        Dim stale As New List(Of Shape)()
        For Each body In _restTimes.Keys
            If Not stillResting.Contains(body) Then stale.Add(body)
        Next
        For Each body In stale
            _restTimes.Remove(body)
        Next
    End Sub

    ''' <summary>When the body's bounce series ended (s), or Nothing while it is not resting.</summary>
    Friend Function RestTime(body As Shape) As Double?
        Dim t As Double
        If body IsNot Nothing AndAlso _restTimes.TryGetValue(body, t) Then Return t
        Return Nothing
    End Function

    ''' <summary>The body was moved from outside: whatever rest it had is over.</summary>
    Friend Sub ForgetRest(body As Shape)
        _restTimes.Remove(body)
    End Sub

    ''' <summary>Records that body i collided now (for the inelastic-collapse guard).</summary>
    Friend Sub NoteHit(i As Integer)
        _bodies.Info(i).LastHit = _s.Now
    End Sub

    ''' <summary>
    ''' Body i's inverse mass in a collision with <paramref name="partner"/>. The dragged body is
    ''' immovable. A sleeping body hit by a free body from above acts as part of its support (the floor
    ''' beneath takes the blow); a body at rest touched gently also stays put; anything else moves it.
    ''' </summary>
    Friend Function InverseMassFor(i As Integer, partner As Integer, gentle As Boolean) As Double
        Dim b = _s.Bodies
        Dim mode = b.Slot(i).Mode
        Select Case mode
            Case BodyMode.Dragged
                Return 0
            Case BodyMode.Sleeping, BodyMode.Supported
                If b.Slot(partner).Mode = BodyMode.Free Then
                    ' Only a sleeper (which never moves) may take a blow from above as the ground does:
                    ' treating a moving body as immovable can trap a ball in a cycle of instantaneous hits.
                    Dim dy = b.Motion(partner).Py - b.Motion(i).Py
                    Dim above = mode = BodyMode.Sleeping AndAlso dy > 0.3 * (b.Size(i).Scale + b.Size(partner).Scale)
                    If above OrElse gentle Then Return 0
                End If
                Return b.Info(i).InverseMass
            Case Else
                Return b.Info(i).InverseMass
        End Select
    End Function

    ''' <summary>
    ''' Whether sleeping body k lies on level fixed ground (the floor, or the level top of a fixed body)
    ''' touching nothing else (within 10⁻³ of its size) and with no movable body but
    ''' <paramref name="partner"/> within its size: a blow from above
    ''' is then shared exactly, the ground taking its vertical part and k its horizontal part (see
    ''' Responder), rather than k taking the whole blow as the ground would, the rule that keeps a
    ''' settled pile still (<see cref="InverseMassFor"/>).
    ''' </summary>
    Friend Function AloneOnLevelGround(k As Integer, partner As Integer) As Boolean
        Dim b = _s.Bodies
        If b.Mode(k) <> BodyMode.Sleeping Then Return False
        Dim p = b.PositionAt(k, _s.Now)
        Dim o = b.Outlines(k)
        Dim gap = 1.0E-3 * b.Size(k).Scale + SolverState.SlopAt(p.X, p.Y)
        Dim grounds = 0
        If _s.Walls Then
            If p.Y + o.MinY <= gap Then grounds += 1
            If p.X + o.MinX <= gap OrElse _s.Width - o.MaxX - p.X <= gap OrElse _s.Height - o.MaxY - p.Y <= gap Then Return False
        End If
        Dim firstNear, lastNear As Integer
        Dim near = _s.ObstaclesNear(k, firstNear, lastNear)
        For q = firstNear To lastNear
            Dim c = ContactRules.OverlapWithObstacle(_s, k, near(q), p)
            If c.Depth < -gap Then Continue For
            ' Anything it touches but level ground beneath it would take part of the blow.
            If c.Normal.X <> 0 OrElse Not (c.Normal.Y > 0) Then Return False
            grounds += 1
        Next
        If grounds = 0 Then Return False
        ' Alone: no other movable body within its own size, so that the sideways kick does not at once
        ' drive it into a pile (where the pile's rule, and its stillness, should hold).
        Dim clear = b.Size(k).Scale
        Dim count = GridNeighbours.Collect(_s, k, _neighbours)
        For q = 0 To count - 1
            Dim j = _neighbours(q)
            If j = partner Then Continue For
            If b.Mode(j) = BodyMode.Rounding Then Return False ' near, on a path PositionAt does not follow
            If ContactRules.OverlapWithBody(_s, k, j, p, b.PositionAt(j, _s.Now)).Depth >= -clear Then Return False
        Next
        Return True
    End Function

    ''' <summary>
    ''' Inelastic-collapse guard (the "TC model" of Luding and McNamara): two bodies that both collided
    ''' within the last 10⁻⁴ √(r/g) collide elastically, so an infinite cascade cannot form in finite time.
    ''' Only when they meet slowly, at a normal speed (<paramref name="approach"/>, m/s, negative when they
    ''' approach) of at most 2 √(g r): a fast hit keeps e. Elastic at any speed, rapid hits let a closing gap
    ''' pump a light body between heavy ones to thousands of m/s (tests/cases/event-feather-pumped-in-cage.json).
    ''' </summary>
    Friend Function EffectiveRestitution(i As Integer, j As Integer, approach As Double) As Double
        If _s.E >= 1 OrElse _s.G = 0 Then Return _s.E
        Dim r = Math.Min(_s.Bodies.Size(i).Scale, _s.Bodies.Size(j).Scale)
        Dim tc = 1.0E-4 * Math.Sqrt(r / _s.G)
        If _s.Now - _bodies.Info(i).LastHit < tc AndAlso _s.Now - _bodies.Info(j).LastHit < tc AndAlso
           approach * approach <= 4 * _s.G * r Then Return 1.0
        Return _s.E
    End Function

    ''' <summary>
    ''' Whether body i is in motion rather than settling, under gravity: faster than ½ √(g r), five times the
    ''' speed of a gentle touch (<see cref="GentleSpeed"/>). Bodies settling into a pile are far slower.
    ''' </summary>
    Friend Function InMotion(i As Integer) As Boolean
        If _s.G = 0 Then Return False
        Dim m = _s.Bodies.Motion(i)
        Return m.Vx * m.Vx + m.Vy * m.Vy > 0.25 * _s.G * _s.Bodies.Size(i).Scale
    End Function

    ''' <summary>Normal speed (m/s) below which a touch on a resting body does not wake it: 10 % of √(g r).</summary>
    Friend Function GentleSpeed(i As Integer, j As Integer) As Double
        If _s.G = 0 Then Return 0 ' without reading the sizes, which no collision of a gas needs otherwise
        Return 0.1 * Math.Sqrt(_s.G * Math.Min(_s.Bodies.Size(i).Scale, _s.Bodies.Size(j).Scale))
    End Function

    ''' <summary>
    ''' Counts a collision of body i at the clock's instant and says whether it has now been hit more
    ''' than <see cref="JamHits"/> times at that one instant: pairwise impulses are then not getting
    ''' past it (a light body squeezed between heavy ones, a ball wedged in a narrow gap), and its
    ''' cluster of touching bodies should be resolved at once (see <see cref="ClusterResponse"/>).
    ''' </summary>
    <MethodImpl(MethodImplOptions.AggressiveInlining)>
    Friend Function HitTooOften(i As Integer) As Boolean
        If _bodies.Info(i).SameTime = _s.Now Then
            _bodies.Info(i).SameCount += 1
        Else
            _bodies.Info(i).SameTime = _s.Now
            _bodies.Info(i).SameCount = 0
        End If
        Return _bodies.Info(i).SameCount >= JamHits
    End Function

    ''' <summary>Starts body i's count of hits at this instant afresh (its cluster was just resolved).</summary>
    Friend Sub ForgetHits(i As Integer)
        _bodies.Info(i).SameCount = 0
    End Sub

    ''' <summary>
    ''' After a free body touched something that does not give way (floor, rectangle, fixed circle,
    ''' a body at rest, moving at (sx, sy) m/s) with normal n: the resting and sleeping rules that end
    ''' the Zeno series. Speeds are relative to the support. <paramref name="before"/> is the body's velocity
    ''' just before the contact (m/s; Nothing: as now), which a hop down a slope may not exceed in energy.
    ''' </summary>
    Friend Sub AfterSupportContact(i As Integer, n As Vector, support As Integer, edge As Integer, sx As Double, sy As Double,
                                   Optional curve As CurvedSupport? = Nothing, Optional before As Vector? = Nothing)
        If _s.G = 0 OrElse n.Y <= 0 Then Return
        Dim b = _s.Bodies
        Dim r = b.Size(i).Scale
        Dim rx = b.Motion(i).Vx - sx, ry = b.Motion(i).Vy - sy
        Dim vn = rx * n.X + ry * n.Y
        Dim speedScale = Math.Sqrt(_s.G * r)
        Dim still = sx = 0 AndAlso sy = 0
        ' Resting rule: the rest of the bounce series is a geometric series of flight times,
        ' 2 v_n / (g n_y (1 − e)) (gravity's part along the normal pulls it back). It is summed once what
        ' is left is shorter than RestWindow, so the state shown is at rest no more than that before the
        ' series really ends (or once the hops are far below rounding).
        Dim restSpeed = Math.Sqrt(2 * _s.G * RestHeight(r))
        Dim level = n.Y >= RestingFaces.LevelCosine AndAlso support <> BodyTable.SupportNone
        Dim seriesLeft = If(_s.E < 1, 2 * vn / (_s.G * n.Y * (1 - _s.E)), Double.PositiveInfinity)
        Dim ended = seriesLeft <= RestWindow OrElse vn < 1.0E-6 * restSpeed
        If level AndAlso ended AndAlso (support <> BodyTable.SupportBody OrElse Math.Abs(rx) < 0.02 * speedScale) Then
            EnterRest(i, support, edge, vn)
            Return
        End If
        ' On a level support the bounce series is followed exactly down to its end.
        If level AndAlso support <> BodyTable.SupportBody Then Return
        ' On a sloping face of a fixed body, likewise; then it slides down the face, exactly. Unless
        ' something else holds it too (the other side of a V): slow and held there, it sleeps.
        If support >= 0 AndAlso edge >= 0 AndAlso still Then
            SleepIfSettled(i)
            If b.Mode(i) = BodyMode.Sleeping Then Return
            If ended Then EnterSlide(i, support, edge, n)
            Return
        End If
        ' On a curve that does not move, once the hops are tiny it slides round the curve, exactly.
        If curve.HasValue AndAlso still AndAlso vn < restSpeed Then
            Dim c = curve.Value
            If _slides.Start(i, c.Centre.X, c.Centre.Y, c.Radius, n, New Vector(b.Motion(i).Vx, b.Motion(i).Vy), c.Cone) Then Return
        End If
        ' Sleeping rule: slow and held from below (one level support, or supports on both sides).
        If still Then
            SleepIfSettled(i)
            If b.Mode(i) = BodyMode.Sleeping Then Return
        End If
        ' Zeno guard: never leave the support slower than restSpeed, so a body sliding down a curved
        ' support hops down it in finitely many events instead of infinitely many. On a support that does
        ' not move, the hop is paid for by the body's own speed or by a move down the slope, never by new
        ' energy (see HopDownSlope). On one that moves (a body resting and sliding, touched gently, taken
        ' as immovable), energy is not kept anyway: the hop is given.
        If vn < restSpeed Then
            If still Then
                HopDownSlope(i, n, restSpeed, If(before.HasValue, before.Value, New Vector(rx, ry)))
            Else
                b.Motion(i).Vx += n.X * (restSpeed - vn)
                b.Motion(i).Vy += n.Y * (restSpeed - vn)
            End If
        End If
    End Sub

    ''' <summary>
    ''' Body i (at the clock, touching a support that does not move along normal n, too slow to leave it)
    ''' leaves it at the normal speed <paramref name="minimum"/> (m/s) with no more energy than it came with
    ''' at <paramref name="before"/> (m/s): from its speed along the slope, or from height, by first moving
    ''' down the tangent (<see cref="SlopeHop"/>), at most <see cref="MaxSlopeShift"/> of its size and only
    ''' where it is clear. A body that cannot move there is held by what is in the way; it gets no hop.
    ''' </summary>
    Private Sub HopDownSlope(i As Integer, n As Vector, minimum As Double, before As Vector)
        Dim m = _s.Bodies.Motion
        Dim after = New Vector(m(i).Vx, m(i).Vy)
        Dim p = New Vector(m(i).Px, m(i).Py)
        Dim shift As Vector
        Dim v = SlopeHop.Depart(before, after, n, minimum, _s.G, MaxSlopeShift * _s.Bodies.Size(i).Scale, shift)
        If shift <> Vector.Zero AndAlso Not IsClear(i, p + shift) Then v = SlopeHop.Depart(before, after, n, minimum, _s.G, 0, shift)
        m(i).Vx = v.X
        m(i).Vy = v.Y
        If shift = Vector.Zero Then Return
        ' The books need nothing here: the kinetic energy gained is m g times the height dropped, so kinetic plus
        ' potential is unchanged. The collision's own loss is counted after this (CollisionLosses, from the
        ' velocity before the contact; a hop that leaves with more than it came with counts as no loss), or by a
        ' cluster's books, which are of kinetic plus potential energy.
        m(i).Px = p.X + shift.X
        m(i).Py = p.Y + shift.Y
        _s.MoveToCellOfPosition(i)
    End Sub

    ''' <summary>
    ''' After free body i touched body j gently along normal n (from j towards i), j sliding on a fixed face
    ''' along unit tangent t, the touch shared with the face (Impulse.ResolveOnFace): what ends the bounces
    ''' of i on j without new energy. Fast enough to leave (a normal relative speed of at least the resting
    ''' hop's), i flies. Slower, it hops off at that speed only where a move down the tangent line pays for
    ''' the whole hop (<see cref="HopOffSlider"/>); otherwise, on a level face, the touch becomes lasting contact:
    ''' i rests on j and the two slide on together (<see cref="JoinSlider"/>); on a sloping one, i is held by
    ''' what keeps it from moving down the tangent, and gets no hop. Whatever this changes in the pair's
    ''' energy, kinetic and potential, is counted in World.Dissipated here (a hop paid by height changes none).
    ''' </summary>
    Friend Sub AfterSliderContact(i As Integer, j As Integer, n As Vector, t As Vector)
        If _s.G = 0 OrElse n.Y <= 0 Then Return
        Dim b = _s.Bodies
        Dim m = b.Motion
        Dim vn = (m(i).Vx - m(j).Vx) * n.X + (m(i).Vy - m(j).Vy) * n.Y
        Dim minimum = Math.Sqrt(2 * _s.G * RestHeight(b.Size(i).Scale))
        If vn >= minimum Then Return
        Dim before = PairEnergy(i, j)
        ' On a sloping face the hop is paid by height but where something is in the way, which then holds it.
        If Not HopOffSlider(i, j, n, t, minimum, vn) AndAlso LevelSlider(j) Then JoinSlider(i, j)
        _s.World.Dissipate(before - PairEnergy(i, j))
    End Sub

    ''' <summary>Kinetic plus potential energy of bodies i and j at the clock (their motions start now), J.</summary>
    Private Function PairEnergy(i As Integer, j As Integer) As Double
        Dim b = _s.Bodies
        Dim m = b.Motion
        Dim mi = b.Shapes(i).Mass, mj = b.Shapes(j).Mass
        Return mi * (0.5 * (m(i).Vx * m(i).Vx + m(i).Vy * m(i).Vy) + _s.G * m(i).Py) +
               mj * (0.5 * (m(j).Vx * m(j).Vx + m(j).Vy * m(j).Vy) + _s.G * m(j).Py)
    End Function

    ''' <summary>
    ''' Body i, touching body j (which slides on a fixed face along unit tangent t) along normal n, leaves it
    ''' at the normal relative speed <paramref name="minimum"/> (m/s), from <paramref name="vn"/>, if a move of i
    ''' down the tangent line of the contact pays for it: the push between the two (i along n, j along t, as the
    ''' touch itself pushed them) raises the pair's kinetic energy by ½ μ (minimum² − vn²), μ = 1/(1/m_i + (n·t)²/m_j),
    ''' and i drops the height h with m_i g h equal to that. The move is at most <see cref="MaxSlopeShift"/> of
    ''' i's size and only where i is clear; otherwise nothing is done and False is returned.
    ''' </summary>
    Private Function HopOffSlider(i As Integer, j As Integer, n As Vector, t As Vector, minimum As Double, vn As Double) As Boolean
        Dim b = _s.Bodies
        Dim invI = b.Info(i).InverseMass, invJ = b.Info(j).InverseMass
        Dim slope = Math.Abs(n.X) ' height lost per metre along the tangent line
        If invI = 0 OrElse slope = 0 Then Return False
        Dim along = Vector.Dot(n, t)
        Dim mu = 1 / (invI + invJ * along * along) ' kg: the pair's mass along n
        Dim distance = mu * (minimum * minimum - vn * vn) * invI / (2 * _s.G * slope)
        If Not (distance <= MaxSlopeShift * b.Size(i).Scale) Then Return False
        Dim shift = New Vector(n.Y, -n.X) * (Math.Sign(n.X) * distance)
        Dim p = New Vector(b.Motion(i).Px, b.Motion(i).Py)
        If Not IsClear(i, p + shift) Then Return False
        b.Motion(i).Px = p.X + shift.X
        b.Motion(i).Py = p.Y + shift.Y
        _s.MoveToCellOfPosition(i)
        Dim push = mu * (minimum - vn) ' N·s
        b.Motion(i).Vx += n.X * push * invI
        b.Motion(i).Vy += n.Y * push * invI
        b.Motion(j).Vx -= t.X * push * invJ * along
        b.Motion(j).Vy -= t.Y * push * invJ * along
        Return True
    End Function

    ''' <summary>Whether supported body j slides on a level face (the floor, a level top): it moves at a constant velocity.</summary>
    Private Function LevelSlider(j As Integer) As Boolean
        Dim m = _s.Bodies.Motion(j)
        Return m.Ax = 0 AndAlso m.Ay = 0 AndAlso m.Vy = 0
    End Function

    ''' <summary>
    ''' Body i comes to rest on body j, which slides on a level face: the two move on together, as one body
    ''' would, at the velocity that keeps the pair's momentum along the face, V = (m_i v_ix + m_j v_jx)/(m_i + m_j).
    ''' That is a perfectly inelastic touch of the two along the face (energy only lost, never gained; i's
    ''' vertical speed, below the slowest hop, is lost too). i is supported by j from now on: a blow that moves
    ''' j, or j leaving its face, sets it free (<see cref="WakeAbove"/>).
    ''' </summary>
    Private Sub JoinSlider(i As Integer, j As Integer)
        Dim b = _s.Bodies
        Dim m = b.Motion
        Dim mi = b.Shapes(i).Mass, mj = b.Shapes(j).Mass
        Dim speed = (mi * m(i).Vx + mj * m(j).Vx) / (mi + mj)
        m(j).Vx = speed
        m(i).Vx = speed
        m(i).Vy = 0
        m(i).Ax = 0
        m(i).Ay = 0
        b.Support(i) = BodyTable.SupportBody
        b.SupportEdge(i) = -1
        b.SetMode(i, BodyMode.Supported)
    End Sub

    ''' <summary>
    ''' The bounce series on a sloping face has ended: the body slides along the face with no friction,
    ''' its velocity along the face kept, and the part of gravity along the face, g − (g·n) n, as its
    ''' acceleration: an exact parabola along the slope, s(t) = s₀ + u t + ½ g sin θ t².
    ''' </summary>
    Private Sub EnterSlide(i As Integer, support As Integer, edge As Integer, n As Vector)
        Dim b = _s.Bodies
        Dim v = New Vector(b.Motion(i).Vx, b.Motion(i).Vy)
        Dim along = v - n * Vector.Dot(v, n)
        b.Motion(i).Vx = along.X
        b.Motion(i).Vy = along.Y
        ' Reached only for a face that is not level (AfterSupportContact rests the body on a level one).
        Dim a = RestingFaces.SlideAcceleration(n, _s.G)
        b.Motion(i).Ax = a.X
        b.Motion(i).Ay = a.Y
        b.Support(i) = support
        b.SupportEdge(i) = edge
        b.SetMode(i, BodyMode.Supported)
    End Sub

    ''' <summary>
    ''' After a collision between free bodies: one that is now slow and held by what it touches
    ''' sleeps. A body caught in a burst of collisions (the start of inelastic collapse: more than
    ''' <see cref="BurstCollisions"/> within √(r/g)/10) sleeps as soon as it is held, at any speed
    ''' below √(g r): that chatter is a resting contact the event picture cannot end by itself.
    ''' </summary>
    Friend Sub SleepIfSettled(i As Integer)
        If _s.G = 0 Then Return
        Dim m = _s.Bodies.Motion(i)
        Dim size = _s.Bodies.Size(i).Scale
        Dim speed2 = m.Vx * m.Vx + m.Vy * m.Vy
        Dim scale2 = _s.G * size
        Dim window = 0.1 * Math.Sqrt(size / _s.G)
        If _s.Now - _bursts(i).Start > window Then
            _bursts(i).Start = _s.Now
            _bursts(i).Count = 0
        End If
        _bursts(i).Count += 1
        Dim limit2 = If(_bursts(i).Count > BurstCollisions, scale2, 0.0004 * scale2)
        If Not speed2 < limit2 Then Return
        If IsHeld(i, limit2) Then
            Sleep(i)
        ElseIf _leansOnLoose Then
            ' Settling where the contact forces would push its supports aside: the fast path's rest rules cannot
            ' follow the slow push (each blow on a sleeper goes to the ground), the general path's forces can.
            _s.TryHandOver()
        End If
    End Sub

    ''' <summary>
    ''' A body that goes to sleep is put exactly where it touches what holds it: on a level face alone, straight
    ''' down onto it; on the top of a ball or peg alone, straight out onto it; on exactly two supports (flat faces
    ''' of fixed bodies or walls, the round outline of a ball or peg, a rounded corner: the bottom of a V, a corner
    ''' of the box, a ball on the floor against its neighbour, a ball in the hollow between two others), at the point
    ''' nearest it where it touches both (<see cref="RestSupport.Touching"/>). It was within 10⁻³ of its size of
    ''' there; exactly there, its contacts touch, so the forces that hold it are those a free-body diagram finds, and
    ''' a scene that should end at that point does. A sharp corner, or more than two supports, leaves it where it is.
    ''' </summary>
    Private Sub Settle(i As Integer)
        Dim b = _s.Bodies
        Dim p = New Vector(b.Motion(i).Px, b.Motion(i).Py)
        Dim gap = 1.0E-3 * b.Size(i).Scale + SolverState.SlopAt(p.X, p.Y)
        Dim o = b.Outlines(i)
        Dim count = 0
        Dim s1, s2 As RestSupport
        Dim add = Sub(support As RestSupport)
                      ' Supports above (a body resting on this one) press down and do not hold it.
                      If support.NormalAt(p).Y < 0 Then Return
                      If count = 0 Then s1 = support Else s2 = support
                      count += 1
                  End Sub
        Dim addFlat = Sub(n As Vector, h As Double)
                          If Vector.Dot(n, p) - h <= gap Then add(RestSupport.Flat(n, h))
                      End Sub
        ' The faces of the pair shape (the support's outline minus the body's) that p lies on, or its round part there.
        Dim addShape = Sub(shape As Outline, origin As Vector)
                           Dim first, second As Integer
                           Dim faces = OutlineContact.TouchingEdges(shape, p - origin, gap, first, second)
                           If faces = 0 Then
                               Dim pen = OutlineContact.Penetration(shape, p - origin)
                               If pen.Depth < -gap Then Return
                               ' Off every face but touching: on the rounding of a corner or of a ball (the core's point
                               ' nearest p is the corner), or on a sharp corner, where no single point is right.
                               If shape.Radius <= 0 Then
                                   count += 2
                                   Return
                               End If
                               add(RestSupport.Round(p - pen.Normal * (shape.Radius - pen.Depth), shape.Radius))
                               Return
                           End If
                           For Each e In {first, second}
                               If e < 0 Then Continue For
                               Dim n = shape.EdgeNormals(e)
                               addFlat(n, Vector.Dot(n, origin + shape.Corners(e)) + shape.Radius)
                           Next
                       End Sub
        If _s.Walls Then
            addFlat(New Vector(1, 0), -o.MinX)
            addFlat(New Vector(-1, 0), o.MaxX - _s.Width)
            addFlat(New Vector(0, 1), -o.MinY)
            addFlat(New Vector(0, -1), o.MaxY - _s.Height)
        End If
        Dim firstNear, lastNear As Integer
        Dim near = _s.ObstaclesNear(i, firstNear, lastNear)
        For q = firstNear To lastNear
            Dim k = near(q)
            addShape(_s.Shapes.Difference(_s.Obstacles.Outlines(k), o), New Vector(_s.Obstacles.X0(k), _s.Obstacles.Y0(k)))
        Next
        ' Bodies at rest below do not move up or down either: a box under it holds it by its top face.
        Dim neighbours = GridNeighbours.Collect(_s, i, _neighbours)
        For q = 0 To neighbours - 1
            Dim j = _neighbours(q)
            ' Asleep, or resting on something level: it does not move up or down.
            If Not (b.Mode(j) = BodyMode.Sleeping OrElse (b.Mode(j) = BodyMode.Supported AndAlso b.Motion(j).Ay = 0 AndAlso b.Motion(j).Ax = 0)) Then Continue For
            addShape(_s.Shapes.Difference(b.Outlines(j), o), New Vector(b.Motion(j).Px, b.Motion(j).Py))
        Next
        Dim target As Vector
        If count = 1 AndAlso s1.NormalAt(p).Y >= RestingFaces.LevelCosine Then
            ' One level support holds it: exactly on it.
            target = s1.Nearest(p)
        ElseIf count = 2 Then
            Dim crossing = RestSupport.Touching(p, s1, s2)
            If Not crossing.HasValue Then Return
            target = crossing.Value
        Else
            Return
        End If
        ' Never up, beyond rounding: what rests there fell there, and a rise would be energy from nowhere.
        If (target - p).Length > gap OrElse target.Y - p.Y > SolverState.SlopAt(p.X, p.Y) OrElse Not IsClear(i, target) Then Return
        b.Motion(i).Px = target.X
        b.Motion(i).Py = target.Y
        ' It stands for the last crumb of its fall, which the bounces that would have ended it take:
        ' the height it drops here is dissipated (m g Δy, J). A rise, by rounding, is not counted.
        _s.World.Dissipate(b.Shapes(i).Mass * _s.G * (p.Y - target.Y))
    End Sub

    ''' <summary>Whether body i could be at p (m) without overlapping anything it collides with (beyond the touching tolerance).</summary>
    Private Function IsClear(i As Integer, p As Vector) As Boolean
        Dim b = _s.Bodies
        Dim tolerance = SolverState.SlopAt(p.X, p.Y)
        Dim o = b.Outlines(i)
        If _s.Walls AndAlso (p.X + o.MinX < -tolerance OrElse p.Y + o.MinY < -tolerance OrElse
                             p.X + o.MaxX > _s.Width + tolerance OrElse p.Y + o.MaxY > _s.Height + tolerance) Then Return False
        Dim firstNear, lastNear As Integer
        Dim near = _s.ObstaclesNear(i, firstNear, lastNear)
        For q = firstNear To lastNear
            If ContactRules.OverlapWithObstacle(_s, i, near(q), p).Depth > tolerance Then Return False
        Next
        Dim count = GridNeighbours.Collect(_s, i, _neighbours)
        For q = 0 To count - 1
            Dim j = _neighbours(q)
            If b.Mode(j) = BodyMode.Rounding Then Continue For
            If ContactRules.OverlapWithBody(_s, i, j, p, b.PositionAt(j, _s.Now)).Depth > tolerance Then Return False
        Next
        Return True
    End Function

    ''' <summary>
    ''' The bounce series on a level support is followed exactly until what is left of it is shorter
    ''' than this, s: a state sampled later than the rest time minus this is truly at rest.
    ''' </summary>
    Friend Const RestWindow As Double = 0.0001

    ''' <summary>
    ''' The furthest a body at rest on a slope moves down its tangent to pay for a hop, as a fraction of
    ''' its size: near the top of a curve the full height would take a long move, and a lower hop is paid
    ''' by a short one instead.
    ''' </summary>
    Private Const MaxSlopeShift As Double = 0.001

    ''' <summary>Bounce height (m) of the slowest hop a body may leave a slope with: 10⁻⁶ of its radius.</summary>
    Private Shared Function RestHeight(r As Double) As Double
        Return Math.Max(1.0E-6 * r, 1.0E-12)
    End Function

    Private Sub EnterRest(i As Integer, support As Integer, edge As Integer, vn As Double)
        Dim b = _s.Bodies
        Dim body = b.Shapes(i)
        Dim flight = If(_s.E < 1, 2 * vn / (_s.G * (1 - _s.E)), 0.0)
        Dim known As Double
        If Not (vn = 0 AndAlso _restTimes.TryGetValue(body, known)) Then _restTimes(body) = _s.Now + flight
        b.Motion(i).Vy = 0
        b.Motion(i).Ay = 0
        b.Support(i) = support
        b.SupportEdge(i) = edge
        b.SetMode(i, BodyMode.Supported)
        ' Slow enough along a level support: asleep (a pile's floor layer must settle to hold the rest).
        If Math.Abs(b.Motion(i).Vx) < 0.05 * Math.Sqrt(_s.G * b.Size(i).Scale) AndAlso support <> BodyTable.SupportNone Then Sleep(i)
    End Sub

    ''' <summary>Body i (at the clock) goes to sleep where it is, put exactly on what holds it when that is flat (see <see cref="Settle"/>).</summary>
    Friend Sub Sleep(i As Integer)
        Dim b = _s.Bodies
        b.Motion(i).Vx = 0
        b.Motion(i).Vy = 0
        b.Motion(i).Ay = 0
        b.Motion(i).Ax = 0
        b.SetMode(i, BodyMode.Sleeping)
        Settle(i)
        SettleAbove(i)
    End Sub

    ''' <summary>
    ''' A body may fall asleep on one still moving (a box on a box that was still bouncing). When the one
    ''' below sleeps too, each sleeping body above it (and above those, upwards) is put exactly on it
    ''' if it is within the touching tolerance, so a stack ends face on face; one that is no longer held
    ''' at all (the body below moved away after it fell asleep) wakes and falls.
    ''' </summary>
    Private Sub SettleAbove(i As Integer)
        ' The sleepers on it, or near enough above it to have fallen asleep on it while it still moved.
        WalkAbove(i, _settle, _settleFound, False, 0.1, _settleOne)
    End Sub

    ''' <summary>
    ''' Sleeping body j, found on a body that has just settled (<see cref="SettleAbove"/>): put exactly on what holds
    ''' it, or, held no longer, set falling. Returns whether the walk goes on above it: it moved and still sleeps.
    ''' </summary>
    Private Function SettleOnBelow(j As Integer) As Boolean
        Dim b = _s.Bodies
        Dim before = New Vector(b.Motion(j).Px, b.Motion(j).Py)
        Settle(j)
        If Not IsHeld(j) Then
            ' It fell asleep on a body that has since moved away: it falls after it, from now, and
            ' so does whatever sleeps on it (which it no longer holds up once it moves).
            MakeFree(j)
            _s.Changed(j)
            WakeAbove(j)
            Return False
        End If
        If b.Motion(j).Px = before.X AndAlso b.Motion(j).Py = before.Y Then Return False
        _s.Changed(j)
        Return True
    End Function

    ''' <summary>A resting or sleeping body that was moved by a hit flies again, and so does what rests on it.</summary>
    Friend Sub WakeFrom(i As Integer)
        Dim m = _s.Bodies.Mode(i)
        If m <> BodyMode.Sleeping AndAlso m <> BodyMode.Supported Then Return
        MakeFree(i)
        WakeAbove(i)
    End Sub

    ''' <summary>Body i flies freely under gravity from now on (its rest, if any, is over).</summary>
    Friend Sub MakeFree(i As Integer)
        Dim b = _s.Bodies
        _s.Sync(i) ' its path so far ends here: gravity starts now, not when it fell asleep
        b.SetMode(i, BodyMode.Free)
        b.Motion(i).Ay = -_s.G
        b.Motion(i).Ax = 0
        b.Support(i) = BodyTable.SupportNone
        b.SupportEdge(i) = -1
        _restTimes.Remove(b.Shapes(i))
        ' Its lane shows it free at once, before anything is predicted against it (the vector and the
        ' one-at-a-time pair tests must see the same mode, or they take different branches).
        _s.Publish(i)
    End Sub

    ''' <summary>Wakes every sleeping or resting body that (directly or through others) rests on body i.</summary>
    Friend Sub WakeAbove(i As Integer)
        ' Sleeping or resting on it, touching it (within 10⁻³ of the smaller size).
        WalkAbove(i, _wake, _wakeFound, True, 0.001, _wakeOne)
    End Sub

    ''' <summary>Body j, found resting on one that moves (<see cref="WakeAbove"/>), flies from now; the walk goes on above it.</summary>
    Private Function WakeOne(j As Integer) As Boolean
        _s.Sync(j)
        MakeFree(j)
        _s.Changed(j)
        Return True
    End Function

    ''' <summary>
    ''' Walks up from body i, breadth first, through the bodies that rest on it, and on those. At each body k reached,
    ''' the bodies j near it that rest on it are found first: asleep (or resting too, when <paramref name="orResting"/>),
    ''' their centre above k's (at the clock), and their contact with k within <paramref name="reach"/> of the smaller
    ''' size (a fraction) with its normal pointing up from k. Then <paramref name="visit"/> acts on each in turn and
    ''' returns whether the walk goes on above it. <paramref name="queue"/> (one slot a body) and
    ''' <paramref name="found"/> are the walk's own scratch, so that a visit may start a walk of the other kind.
    ''' </summary>
    Private Sub WalkAbove(i As Integer, queue As Integer(), found As List(Of Integer), orResting As Boolean, reach As Double,
                          visit As Func(Of Integer, Boolean))
        Dim b = _s.Bodies
        Dim head = 0, tail = 0
        queue(tail) = i
        tail += 1
        While head < tail
            Dim k = queue(head)
            head += 1
            Dim here = b.PositionAt(k, _s.Now)
            Dim count = GridNeighbours.Collect(_s, k, _neighbours)
            found.Clear()
            For q = 0 To count - 1
                Dim j = _neighbours(q)
                Dim mj = b.Mode(j)
                If mj <> BodyMode.Sleeping AndAlso Not (orResting AndAlso mj = BodyMode.Supported) Then Continue For
                If b.Motion(j).Py - here.Y <= 0 Then Continue For
                Dim c = ContactRules.OverlapWithBody(_s, j, k, New Vector(b.Motion(j).Px, b.Motion(j).Py), here)
                If c.Depth < -reach * Math.Min(b.Size(j).Scale, b.Size(k).Scale) OrElse c.Normal.Y <= 0 Then Continue For
                found.Add(j)
            Next
            ' Found first, then acted on: a visit may search neighbours of its own (IsHeld, another walk).
            For q = 0 To found.Count - 1
                Dim j = found(q)
                If visit(j) AndAlso tail < queue.Length Then
                    queue(tail) = j
                    tail += 1
                End If
            Next
        End While
    End Sub

    ''' <summary>
    ''' Whether body i, stopped where it is now, would be held there by what it touches (<see cref="IsHeld"/>),
    ''' counting neighbours at any speed that do not move away from it. Asked of a body wedged at an instant, to
    ''' choose between sleep and the general path: in a settling pile the balls around a wedged ball still move
    ''' but hold it all the same, and a pile handed over to the general path settles hundreds of times slower.
    ''' </summary>
    Friend Function WouldBeHeld(i As Integer) As Boolean
        Return IsHeld(i, Double.PositiveInfinity)
    End Function

    ''' <summary>
    ''' Whether body i is held against gravity by what it touches (within 10⁻³ r): the upward
    ''' vertical lies in the cone of its contact normals, so normal forces alone can balance its
    ''' weight (one level support, or two on either side of the vertical, or a cage). A neighbour counts if it
    ''' is asleep or moves slower than <paramref name="supportSpeed2"/> (m²/s², the speed below which body i
    ''' itself may sleep; by default that of a body outside a burst): a settling pile freezes as a whole, but a
    ''' body on its way elsewhere holds nothing, or what slept on it would hang in the air when it went. Only
    ''' nearby cells are searched.
    ''' </summary>
    Private Function IsHeld(i As Integer, Optional supportSpeed2 As Double = -1) As Boolean
        Dim b = _s.Bodies
        _leansOnLoose = False
        Dim p = b.PositionAt(i, _s.Now)
        Dim px = p.X, py = p.Y
        Dim o = b.Outlines(i)
        Dim gap = 1.0E-3 * b.Size(i).Scale + SolverState.SlopAt(px, py)
        _nNormals = 0
        If _s.Walls Then
            If py + o.MinY <= gap Then Return True
            If px + o.MinX <= gap Then AddNormal(1, 0)
            If _s.Width - o.MaxX - px <= gap Then AddNormal(-1, 0)
            If _s.Height - o.MaxY - py <= gap Then AddNormal(0, -1)
        End If
        ' Rectangles, then the other fixed bodies: the order the normals were always gathered in.
        Dim firstNear, lastNear As Integer
        Dim near = _s.ObstaclesNear(i, firstNear, lastNear)
        For pass = 0 To 1
            For q = firstNear To lastNear
                Dim k = near(q)
                If (_s.Obstacles.Kind(k) = ShapeKind.Rectangle) <> (pass = 0) Then Continue For
                Dim c = ContactRules.OverlapWithObstacle(_s, i, k, p)
                If c.Depth >= -gap Then AddNormal(c.Normal.X, c.Normal.Y)
            Next
        Next
        Dim count = GridNeighbours.Collect(_s, i, _neighbours)
        For q = 0 To count - 1
            Dim j = _neighbours(q)
            If b.Mode(j) = BodyMode.Rounding OrElse b.Mode(j) = BodyMode.Dragged Then Continue For
            If b.Mode(j) <> BodyMode.Sleeping AndAlso Not Settling(j, If(supportSpeed2 < 0, 0.0004 * _s.G * b.Size(j).Scale, supportSpeed2)) Then Continue For
            Dim c = ContactRules.OverlapWithBody(_s, i, j, p, b.PositionAt(j, _s.Now))
            If c.Depth < -gap Then Continue For
            ' A body moving away from it (one still falling, under it) does not hold it up: what slept on
            ' it would be left in the air, kept by it from being put on what is under both.
            If b.Mode(j) <> BodyMode.Sleeping AndAlso MovesAway(j, c.Normal) Then Continue For
            AddNormal(c.Normal.X, c.Normal.Y, False)
        Next
        ' One support alone holds a body only if it is level to rounding, whatever it is: on a frictionless
        ' slope of any angle, however small, a body slides (g sin θ along it), and off the top of a peg or of
        ' another ball it rolls (a ball dropped 0.05° off another's top rolls off it to the floor).
        ' Otherwise up = (0, 1) must lie between two of the normals (RestingFaces.HoldsUp, which is symmetric in
        ' its two normals and never holds for a normal paired with itself, so each pair is asked once).
        For a = 0 To _nNormals - 1
            If _normalY(a) > RestingFaces.LevelCosine Then Return HeldOnSlope(i)
            Dim na = New Vector(_normalX(a), _normalY(a))
            For k = a + 1 To _nNormals - 1
                If RestingFaces.HoldsUp(na, New Vector(_normalX(k), _normalY(k))) Then Return HeldOnSlope(i)
            Next
        Next
        Return False
    End Function

    ''' <summary>
    ''' Body i is held by its own contacts (<see cref="IsHeld"/>, just asked). When one of them is a slope of
    ''' a fixed body (a peg's shoulder, a tilted face: neither level nor upright), that is not enough: the
    ''' bodies it leans on with it may be pushed aside, as a frictionless arch of balls between two pegs is.
    ''' Then it is held only if the contact forces hold its whole cluster of still bodies (<see cref="EquilibriumCheck"/>).
    ''' When it leans on the slope of another body, asleep or settling, in a world the fast path may hand over (at most
    ''' <see cref="SolverState.HandOverBodies"/> movable bodies), the sleepers it touches are asked too, as movable
    ''' bodies: two balls on a frictionless floor, nothing at their sides, do not hold a ball in the V between them.
    ''' Such a body is not held and <see cref="_leansOnLoose"/> says why. In a crowd the sleepers hold as fixed bodies,
    ''' as a settled pile needs: the pile of 40 balls in the benchmark would otherwise go to the general path.
    ''' </summary>
    Private Function HeldOnSlope(i As Integer) As Boolean
        Dim onBodySlope = False
        For a = 0 To _nNormals - 1
            If _normalY(a) > RestingFaces.LevelCosine OrElse _normalY(a) <= 0 Then Continue For
            If _normalFixed(a) Then Return _equilibrium.Holds(i)
            onBodySlope = True
        Next
        If Not onBodySlope OrElse _s.Bodies.Count > SolverState.HandOverBodies Then Return True
        _leansOnLoose = Not _equilibrium.Holds(i, sleepersMove:=True)
        Return Not _leansOnLoose
    End Function

    ''' <summary>
    ''' Whether body j, not asleep, is slow enough now to be settling with a pile (below the speed at which a
    ''' body outside a burst may sleep): only such a body can hold another up. One faster than that is on its
    ''' way somewhere, and what slept on it would be left hanging in the air when it goes.
    ''' </summary>
    Private Function Settling(j As Integer, speed2 As Double) As Boolean
        Dim x, y, vx, vy As Double
        _bodies.Motion(j).StateAt(_s.Now, x, y, vx, vy)
        Return vx * vx + vy * vy < speed2
    End Function

    ''' <summary>Whether body j moves away (now) along n, the normal of its contact pointing from it towards the body it would hold.</summary>
    Private Function MovesAway(j As Integer, n As Vector) As Boolean
        Dim x, y, vx, vy As Double
        _bodies.Motion(j).StateAt(_s.Now, x, y, vx, vy)
        Return vx * n.X + vy * n.Y < 0
    End Function

    Private Sub AddNormal(x As Double, y As Double, Optional fixedSupport As Boolean = True)
        If _nNormals < _normalX.Length Then
            _normalX(_nNormals) = x
            _normalY(_nNormals) = y
            _normalFixed(_nNormals) = fixedSupport
            _nNormals += 1
        End If
    End Sub
End Class
