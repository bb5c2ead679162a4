Option Strict On

''' <summary>
''' Contact handling shared by the stepping solvers, run after each sub-step, for bodies of every shape.
''' Collisions are found after the fact (the bodies already overlap), so each contact is handled in two
''' parts, as many game engines do: static resolution pushes the bodies apart along the normal, shared in
''' proportion to inverse mass; dynamic resolution applies the impulse j = −(1 + e)(v_rel · n) / (1/m_A + 1/m_B)
''' along the normal, which leaves the tangential velocity alone (no friction), so a ball or a box resting on
''' a floor or a slope can still slide. A contact whose approach speed is below what gravity adds in about one
''' step is a resting contact: it is resolved with e = 0 and not reported, so a body at rest does not jitter,
''' sink, or flood the log.
''' The phases: movable pairs (lowest first), then fixed bodies and walls (which marks the bodies resting on
''' them as supported), then under gravity a support pass in which a supported body is immovable for the
''' body resting on it (shock propagation, so a heavy ball resting on a light one does not sink through it),
''' then the fixed bodies and walls again, so that nothing is left inside a fixed body or outside the container.
''' </summary>
Friend NotInheritable Class StepContacts
    ' m/s: approach speeds at or below this are rounding noise, never a collision.
    Private Const MinimumSpeed As Double = 1.0E-9
    ' Support passes per step at most: each is one sweep over the pairs.
    Private Const MaxSupportPasses As Integer = 8
    ' Final passes over the fixed bodies and walls at most (a body pushed out of one into another).
    Private Const MaxFixedPasses As Integer = 4

    Private ReadOnly _broadPhase As New BroadPhase()
    Private ReadOnly _pairs As New List(Of (A As Integer, B As Integer))
    ' The fixed bodies in the order they are met: fixed circles, fixed rectangles, segments, fixed polygons.
    Private ReadOnly _fixed As New List(Of Shape)
    Private ReadOnly _fixedGrid As New BoundsGrid()
    Private ReadOnly _near As New List(Of Integer)
    Private ReadOnly _differences As New DifferenceCache()
    Private _world As World
    Private _bodies As IReadOnlyList(Of Shape)
    Private _dragged As Shape
    Private _time As Double
    Private _gravity As Double
    Private _restingSpeed As Double
    Private _touched As Boolean()
    ' Where each movable body started the step (m), to tell which side of a fixed body it came from.
    Private _start As Vector() = Array.Empty(Of Vector)()
    ' Whether the current pass over the fixed bodies moved any body.
    Private _moved As Boolean
    ' Per body: the sum of the normals of what holds it (fixed bodies, walls, bodies that are held), or zero.
    Private _support As Vector() = Array.Empty(Of Vector)()
    ' Whether any contact can have friction this step (the world's μk, or some body's own, is above 0).
    Private _friction As Boolean
    ' Whether collisions can lose energy this step (e < 1, or friction): then what they take is added to World.Dissipated.
    Private _lossy As Boolean
    ' The step, s, and how much of a friction impulse's velocity change the step's move would have carried
    ' (1 for semi-implicit Euler, whose x += v h uses the new velocity; ½ for Verlet, whose move is v h + ½ a h²).
    Private _h As Double
    Private _pairKeys As Double() = Array.Empty(Of Double)()
    Private _pairOrder As (A As Integer, B As Integer)() = Array.Empty(Of (A As Integer, B As Integer))()

    ''' <summary>
    ''' Resolves every contact after a sub-step of <paramref name="h"/> s that ended at absolute time
    ''' <paramref name="time"/> s. When <paramref name="touched"/> is given (indexed like
    ''' <see cref="World.Movables"/>), the bodies whose position or velocity changed are marked in it.
    ''' </summary>
    Friend Sub Resolve(world As World, time As Double, h As Double, touched As Boolean())
        _world = world
        _bodies = world.Movables
        _dragged = world.DraggedBody
        _time = time
        _gravity = world.Gravity
        ' What gravity adds to an approach speed in one step is g·h; twice that leaves room for the
        ' integrator (Euler's ball at rest arrives at g·h, Verlet's too) without catching real bounces.
        ' The floor of a nanometre per second keeps rounding errors between bodies moving together
        ' (after an e = 0 collision, say) from being reported as collisions when g = 0.
        _restingSpeed = 2 * _gravity * h + MinimumSpeed
        _touched = touched
        _h = h
        _lossy = world.Restitution < 1 OrElse _friction
        Dim bodies = _bodies
        If _support.Length < bodies.Count Then
            _support = New Vector(bodies.Count - 1) {}
            _start = New Vector(bodies.Count - 1) {}
        End If
        Array.Clear(_support, 0, bodies.Count)
        For i = 0 To bodies.Count - 1
            ' The integrator has just moved it by about v h: where it came from, near enough to tell the side.
            _start(i) = bodies(i).Position - bodies(i).Velocity * h
        Next

        _broadPhase.FindOverlaps(bodies, _pairs)
        If _gravity > 0 Then SortBottomUp(bodies)
        FindFixedBodies()

        ResolvePairs()       ' 1. movable pairs, lowest first, with their real masses
        ResolveFixed()       ' 2. fixed bodies and walls; marks who rests on them
        ' 3. A body pressing on a held one (resting on a fixed body or a wall, or on a body that is) treats it
        ' as immovable: under gravity a stack, and with or without gravity a light body squeezed against a
        ' wall by a heavy one. Lowest pair first lets support climb a stack in one pass; in an irregular pile
        ' height is not quite the order of support, so passes repeat (a few at most) until one finds nothing
        ' left to resolve.
        For pass = 1 To MaxSupportPasses
            If Not ResolveSupport() Then Exit For
        Next
        ' 4. Fixed bodies and walls have the last word: a pair or support push (a heavy ball on a light
        ' one) may have moved a body into one, and no body may end a step inside a fixed body.
        For pass = 1 To MaxFixedPasses
            _moved = False
            ResolveFixed()
            If Not _moved Then Exit For
        Next
    End Sub

    ''' <summary>
    ''' What a friction impulse's velocity change moves the body by within the step, as a fraction of that change
    ''' times the step: 1 for semi-implicit Euler (its move uses the new velocity), ½ for Verlet (a force acting
    ''' through the step moves a body ½ (F/m) h²). Without it a block held by static friction on a ramp would
    ''' creep down by what gravity's part moved it in each step before the contact stopped it.
    ''' </summary>
    Friend Property FrictionShare As Double = 1.0

    ''' <summary>
    ''' Reads, once per advance, whether any contact can have friction (<see cref="World.HasFriction"/>). Without, the
    ''' contacts do no friction work at all.
    ''' </summary>
    Friend Sub Prepare(world As World)
        _friction = world.HasFriction
    End Sub

    Private Sub ResolvePairs()
        Dim bodies = _bodies
        For Each p In _pairs
            Dim a = bodies(p.A), b = bodies(p.B)
            Dim contact = PairContact(a, b)
            If contact.Depth > 0 Then Respond(p.A, a, p.B, b, contact, WallSide.None, False)
        Next
    End Sub

    ''' <summary>One support pass over the pairs; True when it resolved any contact.</summary>
    Private Function ResolveSupport() As Boolean
        Dim bodies = _bodies
        Dim any = False
        For Each p In _pairs
            Dim a = bodies(p.A), b = bodies(p.B)
            Dim contact = PairContact(a, b)
            If contact.Depth <= 0 Then Continue For
            If RestsOn(p.A, a, p.B, b, contact) OrElse RestsOn(p.B, b, p.A, a, New Contact(-contact.Normal, contact.Depth)) Then any = True
        Next
        Return any
    End Function

    ''' <summary>
    ''' The contact of two movable bodies, normal from B towards A: circles and a circle against a box in
    ''' closed form, any other pair through the Minkowski difference of their outlines.
    ''' </summary>
    Private Function PairContact(a As Shape, b As Shape) As Contact
        Dim ca = TryCast(a, Circle)
        If ca IsNot Nothing Then
            Dim cb = TryCast(b, Circle)
            If cb IsNot Nothing Then Return Collider.CircleCircle(ca.Position, ca.Radius, cb.Position, cb.Radius)
            Dim rb = TryCast(b, Rectangle)
            If rb IsNot Nothing Then Return Collider.CircleRectangle(ca.Position, ca.Radius, rb.Min, rb.Max)
        End If
        ' Bodies whose boxes are apart cannot overlap: the box test saves the outline's, the dearest part
        ' of a step of resting boxes, for the pairs the broad phase kept only for their margin.
        Dim ao = a.Outline, bo = b.Outline
        If a.Position.X + ao.MaxX < b.Position.X + bo.MinX OrElse b.Position.X + bo.MaxX < a.Position.X + ao.MinX OrElse
           a.Position.Y + ao.MaxY < b.Position.Y + bo.MinY OrElse b.Position.Y + bo.MaxY < a.Position.Y + ao.MinY Then Return Apart
        Return Collider.OutlineOutline(_differences.Get(bo, ao).Difference, a.Position, b.Position)
    End Function

    ''' <summary>The contact of two bodies known to be apart: no depth, so nothing is done.</summary>
    Private Shared ReadOnly Apart As New Contact(New Vector(0, 1), Double.NegativeInfinity)

    ''' <summary>Orders the pairs by the height of their lower body (the middle of its box), so support spreads up a pile in one pass.</summary>
    Private Sub SortBottomUp(bodies As IReadOnlyList(Of Shape))
        Dim count = _pairs.Count
        If count < 2 Then Return
        If _pairKeys.Length < count Then
            _pairKeys = New Double(count - 1) {}
            _pairOrder = New (A As Integer, B As Integer)(count - 1) {}
        End If
        For k = 0 To count - 1
            Dim p = _pairs(k)
            _pairKeys(k) = Math.Min(Height(bodies(p.A)), Height(bodies(p.B)))
            _pairOrder(k) = p
        Next
        Array.Sort(Of Double, (A As Integer, B As Integer))(_pairKeys, _pairOrder, 0, count)
        _pairs.Clear()
        For k = 0 To count - 1
            _pairs.Add(_pairOrder(k))
        Next
    End Sub

    ''' <summary>The height of the middle of a body's box, m (a circle's centre exactly).</summary>
    Private Shared Function Height(b As Shape) As Double
        Dim o = b.Outline
        Return b.Position.Y + 0.5 * (o.MinY + o.MaxY)
    End Function

    ''' <summary>
    ''' When body B is held up (by a fixed body, a wall, or a body that is) and body A presses on it
    ''' towards what holds it, resolves the contact with B immovable, as a resting contact, and returns True.
    ''' This is shock propagation: a heavy ball resting on a light one is held up by the floor beneath,
    ''' not by the light ball's inertia, so it does not sink through it.
    ''' </summary>
    Private Function RestsOn(ia As Integer, a As Shape, ib As Integer, b As Shape, contact As Contact) As Boolean
        If a Is _dragged OrElse b Is _dragged OrElse Vector.Dot(contact.Normal, _support(ib)) <= 0 Then Return False
        Respond(ia, a, ib, b, contact, WallSide.None, True)
        Return True
    End Function

    ''' <summary>Gathers the fixed bodies, in the order they are met, into a grid for this step.</summary>
    Private Sub FindFixedBodies()
        _fixed.Clear()
        For Each c In _world.Circles
            If c.IsFixed Then _fixed.Add(c)
        Next
        For Each r In _world.Rectangles
            If r.IsFixed Then _fixed.Add(r)
        Next
        For Each s In _world.Segments
            _fixed.Add(s)
        Next
        For Each p In _world.Polygons
            If p.IsFixed Then _fixed.Add(p)
        Next
        _fixedGrid.Reset(_fixed.Count)
        For i = 0 To _fixed.Count - 1
            Dim f = _fixed(i)
            Dim o = f.Outline
            _fixedGrid.SetItem(i, New Vector(f.Position.X + 0.5 * (o.MinX + o.MaxX), f.Position.Y + 0.5 * (o.MinY + o.MaxY)),
                               0.5 * (o.MaxX - o.MinX), 0.5 * (o.MaxY - o.MinY))
        Next
        _fixedGrid.Build(0)
    End Sub

    ''' <summary>Contacts with the fixed bodies (each movable body meets those its step's path came near) and the walls.</summary>
    Private Sub ResolveFixed()
        If _fixed.Count > 0 Then
            Dim bodies = _bodies
            For i = 0 To bodies.Count - 1
                Dim a = bodies(i)
                ' The fixed bodies near the box of the step's path (from where it started to where it is),
                ' so a body that went right through one is caught too. A push moves the body: the rest are
                ' found again from where it is now, so each fixed body is met in order, as if all were tried.
                FixedNear(i, a, -1)
                Dim k = 0
                While k < _near.Count
                    Dim index = _near(k)
                    Dim f = _fixed(index)
                    Dim before = a.Position
                    Dim contact = FixedContact(i, a, f)
                    If contact.Depth > 0 Then
                        Respond(i, a, -1, f, contact, WallSide.None, False)
                        If a.Position <> before Then
                            FixedNear(i, a, index)
                            k = 0
                            Continue While
                        End If
                    End If
                    k += 1
                End While
            Next
        End If
        ResolveWalls()
    End Sub

    ''' <summary>Fills the list of fixed bodies near body i's path this step, keeping those after <paramref name="after"/> in the order.</summary>
    Private Sub FixedNear(i As Integer, a As Shape, after As Integer)
        Dim o = a.Outline
        Dim p = a.Position, s = _start(i)
        Dim lo = New Vector(Math.Min(p.X, s.X) + o.MinX, Math.Min(p.Y, s.Y) + o.MinY)
        Dim hi = New Vector(Math.Max(p.X, s.X) + o.MaxX, Math.Max(p.Y, s.Y) + o.MaxY)
        _fixedGrid.Query(lo, hi, _near)
        If after >= 0 Then _near.RemoveAll(Function(index) index <= after)
    End Sub

    ''' <summary>
    ''' The contact of movable body A with fixed body F, aware of A's path this step: a body whose path
    ''' crossed into F leaves by the side it came in by (see <see cref="Collider.OutlineOutlineFrom(Outline, Outline, Vector, Vector, Vector)"/>).
    ''' </summary>
    Private Function FixedContact(i As Integer, a As Shape, f As Shape) As Contact
        Dim ca = TryCast(a, Circle)
        If ca IsNot Nothing Then
            Dim cf = TryCast(f, Circle)
            If cf IsNot Nothing Then Return Collider.CircleCircleFrom(ca.Position, ca.Radius, cf.Position, cf.Radius, _start(i))
            Dim rf = TryCast(f, Rectangle)
            If rf IsNot Nothing Then Return Collider.CircleRectangleFrom(ca.Position, ca.Radius, rf.Min, rf.Max, _start(i))
        End If
        Dim pair = _differences.Get(f.Outline, a.Outline)
        Return Collider.OutlineOutlineFrom(pair.Difference, pair.CoreDifference, a.Position, f.Position, _start(i))
    End Function

    Private Sub ResolveWalls()
        If Not _world.Walls Then Return
        Dim bodies = _bodies
        For i = 0 To bodies.Count - 1
            Dim a = bodies(i)
            If a Is _dragged Then Continue For
            ResolveWalls(i, a)
        Next
    End Sub

    Private Sub ResolveWalls(i As Integer, a As Shape)
        Dim w = _world.Width, ht = _world.Height
        Dim c = TryCast(a, Circle)
        Dim o = a.Outline
        ' A body as wide as the container cannot bounce between its sides: keep it centred.
        If If(c IsNot Nothing, 2 * c.Radius >= w, o.MaxX - o.MinX >= w) Then
            Dim x = If(c IsNot Nothing, w / 2, (w - o.MinX - o.MaxX) / 2)
            a.Position = New Vector(x, a.Position.Y) : a.Velocity = New Vector(0, a.Velocity.Y) : MarkTouched(i)
        Else
            WallContact(i, a, c, WallSide.Left)
            WallContact(i, a, c, WallSide.Right)
        End If
        If If(c IsNot Nothing, 2 * c.Radius >= ht, o.MaxY - o.MinY >= ht) Then
            Dim y = If(c IsNot Nothing, ht / 2, (ht - o.MinY - o.MaxY) / 2)
            a.Position = New Vector(a.Position.X, y) : a.Velocity = New Vector(a.Velocity.X, 0) : MarkTouched(i)
        Else
            WallContact(i, a, c, WallSide.Bottom)
            WallContact(i, a, c, WallSide.Top)
        End If
    End Sub

    Private Sub WallContact(i As Integer, a As Shape, c As Circle, side As WallSide)
        Dim contact = If(c IsNot Nothing, Collider.CircleWall(c.Position, c.Radius, side, _world.Width, _world.Height),
                         Collider.OutlineWall(a.Position, a.Outline, side, _world.Width, _world.Height))
        If contact.Depth > 0 Then Respond(i, a, -1, Nothing, contact, side, False)
    End Sub

    ''' <summary>
    ''' Static then dynamic resolution of one contact of movable body A (index ia) with B (index ib, or −1
    ''' when B is fixed or a wall, Nothing). With <paramref name="support"/>, B is a movable body already
    ''' held up from below: it is treated as immovable, A is marked as supported in turn, and the contact is
    ''' a resting one (A is already below B's velocity plus what gravity adds in a step).
    ''' </summary>
    Private Sub Respond(ia As Integer, a As Shape, ib As Integer, b As Shape, contact As Contact,
                        side As WallSide, support As Boolean)
        Dim bMovable = b IsNot Nothing AndAlso Not b.IsFixed
        ' Immovable for this contact: fixed bodies and walls, and in the support pass a body held up from below.
        Dim bImmovable = Not bMovable OrElse support
        ' The dragged body acts as if of infinite mass: it pushes and is not pushed back.
        Dim invA = If(a Is _dragged, 0.0, a.InverseMass)
        Dim invB = If(bImmovable OrElse b Is _dragged, 0.0, b.InverseMass)
        Dim sumInv = invA + invB
        If sumInv = 0 Then Return ' the dragged body against something fixed: neither gives way
        Dim n = contact.Normal

        ' Static resolution. Shares in proportion to inverse mass keep the centre of mass still, so
        ' pushing two movable bodies apart changes neither momentum nor potential energy.
        Dim shiftA = contact.Depth * (invA / sumInv)
        If invA > 0 Then
            a.Position += n * shiftA
            MarkTouched(ia)
        End If
        If invB > 0 Then
            b.Position -= n * (contact.Depth * (invB / sumInv))
            MarkTouched(ib)
        End If

        ' Dynamic resolution.
        Dim before = a.Velocity
        Dim va = before
        ' A body held up from below moves at no more than the resting speed; taking it as still keeps the
        ' support pass from handing that jitter (as energy) to the bodies resting on it.
        Dim vb = If(bMovable AndAlso Not support, b.Velocity, Vector.Zero)
        Dim vbBefore = vb
        Dim separation = Vector.Dot(va - vb, n) ' m/s, > 0 when moving apart
        If bImmovable AndAlso _gravity > 0 AndAlso shiftA <> 0 Then
            ' Pushing A out of something immovable lifts it by shiftA·n_y: m g shiftA n_y of potential energy
            ' that the step never paid for. Pay it from the normal speed (w² = w₀² − 2 g s, the suvat relation:
            ' an approaching body had that speed when it reached the surface; a separating one would have that
            ' speed at the height it is moved to), so a bounce with e = 1 never gains energy.
            Dim squared = separation * separation - 2 * _gravity * shiftA * n.Y
            Dim corrected = Math.Sign(separation) * Math.Sqrt(Math.Max(0.0, squared))
            va += n * (corrected - separation)
            separation = corrected
        End If
        If separation < 0 Then
            Dim resting = support OrElse -separation <= _restingSpeed
            Dim result = Impulse.Resolve(va, invA, vb, invB, n, If(resting, 0.0, _world.Restitution))
            ' What the blow took: ½ μ (1 − e²) u², the kinetic energy of the pair before less after. Not a resting
            ' contact's: that only takes back the speed the step's own fall gave (its height is given back too).
            If _lossy AndAlso Not resting Then _world.Dissipate(Energy(va, invA, vb, invB) - Energy(result.A, invA, result.B, invB))
            va = result.A
            If invB > 0 Then
                b.Velocity = result.B
                MarkTouched(ib)
            End If
            If Not resting Then
                _world.ReportCollision(New CollisionRecord(_time, a, b, side, CollisionKinds.Between(a, b), before, va, vb,
                                                           If(bMovable, b.Velocity, Vector.Zero)))
            End If
        End If
        If _friction AndAlso a.Kind <> ShapeKind.Circle AndAlso (b Is Nothing OrElse b.Kind <> ShapeKind.Circle) Then
            va = Rub(ib, a, b, n, before, vbBefore, va, invA, invB)
        End If
        If va <> before Then
            a.Velocity = va
            MarkTouched(ia)
        End If
        ' Resting on something immovable (or on a body that is): the bodies resting on A can lean on it.
        If bImmovable AndAlso Math.Abs(Vector.Dot(va - vb, n)) <= _restingSpeed Then _support(ia) += n
    End Sub

    ''' <summary>Kinetic energy (J) of two bodies of inverse masses invA, invB (1/kg; 0 counts nothing) at velocities va, vb.</summary>
    Private Shared Function Energy(va As Vector, invA As Double, vb As Vector, invB As Double) As Double
        Return If(invA > 0, 0.5 * va.LengthSquared / invA, 0) + If(invB > 0, 0.5 * vb.LengthSquared / invB, 0)
    End Function

    ''' <summary>
    ''' Coulomb friction at a contact just resolved (docs/forces.md, "Friction in the stepping solvers"). The normal
    ''' impulse is what the contact did to the bodies' speed towards each other in this step, j_n = m_eff Δu (the
    ''' blow and the lift's correction alike: on a resting body that is m g cos θ h, its weight's part into the
    ''' surface over the step); friction then gives at most μs j_n to stop the slip, else μk j_n against it
    ''' (<see cref="ContactFriction.TangentialImpulse"/>), with μ the geometric mean of the two surfaces'. The
    ''' bodies' positions move with the velocity change as the step's move would have carried it
    ''' (<see cref="FrictionShare"/>). Returns A's new velocity (B's is set here); the energy it takes is
    ''' added to <see cref="World.Dissipated"/>: the impulse times the slip that remains, the work of the
    ''' friction over the step's move.
    ''' </summary>
    Private Function Rub(ib As Integer, a As Shape, b As Shape, n As Vector, vaStart As Vector, vbStart As Vector, va As Vector,
                         invA As Double, invB As Double) As Vector
        Dim sumInv = invA + invB
        Dim vb = If(invB > 0, b.Velocity, vbStart)
        Dim pressed = (Vector.Dot(va - vb, n) - Vector.Dot(vaStart - vbStart, n)) / sumInv
        If Not (pressed > 0) Then Return va
        Dim w = va - vb
        Dim slipping = w - n * Vector.Dot(w, n)
        Dim slip = slipping.Length
        If Not (slip > 0) Then Return va
        Dim muK = ContactFriction.Mean(_world.KineticFrictionOf(a), _world.KineticFrictionOf(b))
        Dim muS = ContactFriction.Mean(_world.StaticFrictionOf(a), _world.StaticFrictionOf(b))
        Dim jt = ContactFriction.TangentialImpulse(slip, 1 / sumInv, pressed, muS, muK)
        If jt <= 0 Then Return va
        Dim kick = slipping * (-jt / slip) ' on A; B takes the opposite
        Dim shift = _h * FrictionShare
        va += kick * invA
        If invA > 0 Then a.Position += kick * (invA * shift)
        If invB > 0 Then
            b.Velocity -= kick * invB
            b.Position -= kick * (invB * shift)
            MarkTouched(ib)
        End If
        _world.Dissipate(jt * Math.Max(slip - jt * sumInv, 0))
        Return va
    End Function

    Private Sub MarkTouched(i As Integer)
        _moved = True
        If _touched IsNot Nothing AndAlso i >= 0 Then _touched(i) = True
    End Sub
End Class
