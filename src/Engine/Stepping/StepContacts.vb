Option Strict On

''' <summary>
''' Contact handling shared by the stepping solvers, run after each sub-step. Collisions are found after
''' the fact (the bodies already overlap), so each contact is handled in two parts, as in the seed:
''' static resolution pushes the bodies apart along the normal, shared in proportion to inverse mass;
''' dynamic resolution applies the impulse j = −(1 + e)(v_rel · n) / (1/m_A + 1/m_B) along the normal,
''' which leaves the tangential velocity alone (no friction), so a ball resting on a floor can still slide.
''' A contact whose approach speed is below what gravity adds in about one step is a resting contact:
''' it is resolved with e = 0 and not reported, so a ball at rest does not jitter, sink, or flood the log.
''' The phases: movable pairs, then fixed obstacles, then walls (last, so nothing is left outside), then,
''' under gravity, a support pass that treats a circle held up by the floor or an obstacle as immovable
''' for the circles resting on it (shock propagation), bottom row first, so a heavy ball resting on a
''' light one does not sink through it.
''' </summary>
Friend NotInheritable Class StepContacts
    ' m/s: approach speeds at or below this are rounding noise, never a collision.
    Private Const MinimumSpeed As Double = 1.0E-9

    Private ReadOnly _broadPhase As New BroadPhase()
    Private ReadOnly _pairs As New List(Of (A As Integer, B As Integer))
    Private ReadOnly _fixedCircles As New List(Of Circle)
    Private _world As World
    Private _time As Double
    Private _gravity As Double
    Private _restingSpeed As Double
    Private _touched As Boolean()
    Private _supported As Boolean() = Array.Empty(Of Boolean)()

    ''' <summary>
    ''' Resolves every contact after a sub-step of <paramref name="h"/> s that ended at absolute time
    ''' <paramref name="time"/> s. When <paramref name="touched"/> is given (indexed like
    ''' <see cref="World.Circles"/>), the circles whose position or velocity changed are marked in it.
    ''' </summary>
    Friend Sub Resolve(world As World, time As Double, h As Double, touched As Boolean())
        _world = world
        _time = time
        _gravity = world.Gravity
        ' What gravity adds to an approach speed in one step is g·h; twice that leaves room for the
        ' integrator (Euler's ball at rest arrives at g·h, Verlet's too) without catching real bounces.
        ' The floor of a nanometre per second keeps rounding errors between circles moving together
        ' (after an e = 0 collision, say) from being reported as collisions when g = 0.
        _restingSpeed = 2 * _gravity * h + MinimumSpeed
        _touched = touched
        Dim circles = world.Circles
        If _supported.Length < circles.Count Then _supported = New Boolean(circles.Count - 1) {}
        Array.Clear(_supported, 0, circles.Count)

        ' 1. Movable pairs, found by the broad phase.
        _broadPhase.FindOverlaps(circles, _pairs)
        For Each p In _pairs
            Dim a = circles(p.A), b = circles(p.B)
            Dim contact = Collider.CircleCircle(a.Position, a.Radius, b.Position, b.Radius)
            If contact.Depth > 0 Then Respond(p.A, a, p.B, b, contact, CollisionKind.CircleCircle, WallSide.None, False)
        Next

        ' 2. Fixed obstacles (usually few, so each movable circle meets each of them).
        _fixedCircles.Clear()
        For Each c In circles
            If c.IsFixed Then _fixedCircles.Add(c)
        Next
        Dim rectangles = world.Rectangles
        If _fixedCircles.Count > 0 OrElse rectangles.Count > 0 Then
            For i = 0 To circles.Count - 1
                Dim a = circles(i)
                If a.IsFixed Then Continue For
                For Each f In _fixedCircles
                    Dim reach = a.Radius + f.Radius
                    If Math.Abs(a.Position.X - f.Position.X) > reach OrElse Math.Abs(a.Position.Y - f.Position.Y) > reach Then Continue For
                    Dim contact = Collider.CircleCircle(a.Position, a.Radius, f.Position, f.Radius)
                    If contact.Depth > 0 Then Respond(i, a, -1, f, contact, CollisionKind.CircleFixed, WallSide.None, False)
                Next
                For Each r In rectangles
                    Dim lo = r.Min, hi = r.Max
                    If a.Position.X + a.Radius < lo.X OrElse a.Position.X - a.Radius > hi.X OrElse
                       a.Position.Y + a.Radius < lo.Y OrElse a.Position.Y - a.Radius > hi.Y Then Continue For
                    Dim contact = Collider.CircleRectangle(a.Position, a.Radius, lo, hi)
                    If contact.Depth > 0 Then Respond(i, a, -1, r, contact, CollisionKind.CircleRectangle, WallSide.None, False)
                Next
            Next
        End If

        ' 3. Walls last, so that whatever the other contacts did, nothing is left outside the container.
        If world.Walls Then
            For i = 0 To circles.Count - 1
                Dim a = circles(i)
                If a.IsFixed OrElse a Is world.DraggedCircle Then Continue For
                ResolveWalls(i, a)
            Next
        End If

        ' 4. Support: only gravity makes things rest on each other.
        If _gravity > 0 Then
            For Each p In _pairs
                Dim a = circles(p.A), b = circles(p.B)
                If _supported(p.A) = _supported(p.B) Then Continue For
                Dim contact = Collider.CircleCircle(a.Position, a.Radius, b.Position, b.Radius)
                If contact.Depth <= 0 Then Continue For
                If _supported(p.B) Then
                    If contact.Normal.Y > 0 Then Respond(p.A, a, p.B, b, contact, CollisionKind.CircleCircle, WallSide.None, True)
                ElseIf -contact.Normal.Y > 0 Then
                    Respond(p.B, b, p.A, a, New Contact(-contact.Normal, contact.Depth), CollisionKind.CircleCircle, WallSide.None, True)
                End If
            Next
        End If
    End Sub

    Private Sub ResolveWalls(i As Integer, a As Circle)
        Dim w = _world.Width, ht = _world.Height
        ' A circle wider than the container cannot bounce between its sides: keep it centred.
        If 2 * a.Radius >= w Then
            a.Position = New Vector(w / 2, a.Position.Y) : a.Velocity = New Vector(0, a.Velocity.Y) : MarkTouched(i)
        Else
            WallContact(i, a, WallSide.Left)
            WallContact(i, a, WallSide.Right)
        End If
        If 2 * a.Radius >= ht Then
            a.Position = New Vector(a.Position.X, ht / 2) : a.Velocity = New Vector(a.Velocity.X, 0) : MarkTouched(i)
        Else
            WallContact(i, a, WallSide.Bottom)
            WallContact(i, a, WallSide.Top)
        End If
    End Sub

    Private Sub WallContact(i As Integer, a As Circle, side As WallSide)
        Dim contact = Collider.CircleWall(a.Position, a.Radius, side, _world.Width, _world.Height)
        If contact.Depth > 0 Then Respond(i, a, -1, Nothing, contact, CollisionKind.CircleWall, side, False)
    End Sub

    ''' <summary>
    ''' Static then dynamic resolution of one contact of circle A (index ia) with B (index ib, or −1 when
    ''' B is not a movable circle). With <paramref name="support"/>, B is a movable circle already held up
    ''' from below: it is treated as immovable, A is marked as supported in turn, and the contact is a
    ''' resting one (A is already below B's velocity plus what gravity adds in a step).
    ''' </summary>
    Private Sub Respond(ia As Integer, a As Circle, ib As Integer, b As Shape, contact As Contact,
                        kind As CollisionKind, side As WallSide, support As Boolean)
        Dim dragged = _world.DraggedCircle
        Dim bc = TryCast(b, Circle)
        Dim bMovable = bc IsNot Nothing AndAlso Not bc.IsFixed
        ' The dragged circle acts as if of infinite mass: it pushes and is not pushed back.
        Dim invA = If(a Is dragged, 0.0, a.InverseMass)
        Dim invB = If(support OrElse Not bMovable OrElse bc Is dragged, 0.0, bc.InverseMass)
        ' Held up by something immovable (or by a circle that is): the circles resting on A can lean on it.
        If Not bMovable OrElse support Then
            If contact.Normal.Y > 0 AndAlso ia >= 0 Then _supported(ia) = True
        End If
        Dim sumInv = invA + invB
        If sumInv = 0 Then Return ' the dragged circle against something fixed: neither gives way
        Dim n = contact.Normal

        ' Static resolution. Shares in proportion to inverse mass keep the centre of mass still, so
        ' pushing two movable circles apart changes neither momentum nor potential energy.
        Dim shiftA = contact.Depth * (invA / sumInv)
        If invA > 0 Then
            a.Position += n * shiftA
            MarkTouched(ia)
        End If
        If invB > 0 Then
            bc.Position -= n * (contact.Depth * (invB / sumInv))
            MarkTouched(ib)
        End If

        ' Dynamic resolution.
        Dim va = a.Velocity
        Dim vb = If(bMovable, bc.Velocity, Vector.Zero)
        Dim approach = -Vector.Dot(va - vb, n)
        If approach <= 0 Then Return
        Dim arrival = approach
        If (support OrElse Not bMovable) AndAlso _gravity > 0 Then
            ' Pushing A out of something immovable lifts it by shiftA·n_y: m g shiftA n_y of potential energy
            ' that the step never paid for. Take it from the approach speed (v² = u² − 2 g s, the speed A
            ' had when it reached the surface), so that a bounce with e = 1 never gains energy.
            arrival = Math.Sqrt(Math.Max(0.0, approach * approach - 2 * _gravity * shiftA * n.Y))
        End If
        Dim resting = support OrElse arrival <= _restingSpeed
        Dim e = If(resting, 0.0, _world.Restitution)
        Dim arriving = va + n * (approach - arrival)
        Dim result = Impulse.Resolve(arriving, invA, vb, invB, n, e)
        a.Velocity = result.A
        MarkTouched(ia)
        If invB > 0 Then
            bc.Velocity = result.B
            MarkTouched(ib)
        End If
        If Not resting Then
            _world.ReportCollision(New CollisionRecord(_time, a, b, side, kind, va, result.A, vb,
                                                       If(bMovable, bc.Velocity, Vector.Zero)))
        End If
    End Sub

    Private Sub MarkTouched(i As Integer)
        If _touched IsNot Nothing AndAlso i >= 0 Then _touched(i) = True
    End Sub
End Class
