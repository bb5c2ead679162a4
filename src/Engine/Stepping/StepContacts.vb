Option Strict On

''' <summary>
''' Contact handling shared by the stepping solvers, run after each sub-step. Collisions are found after
''' the fact (the bodies already overlap), so each contact is handled in two parts, as many game engines do:
''' static resolution pushes the bodies apart along the normal, shared in proportion to inverse mass;
''' dynamic resolution applies the impulse j = −(1 + e)(v_rel · n) / (1/m_A + 1/m_B) along the normal,
''' which leaves the tangential velocity alone (no friction), so a ball resting on a floor can still slide.
''' A contact whose approach speed is below what gravity adds in about one step is a resting contact:
''' it is resolved with e = 0 and not reported, so a ball at rest does not jitter, sink, or flood the log.
''' The phases: movable pairs (lowest first), then obstacles and walls (which marks the circles resting on
''' them as supported), then under gravity a support pass in which a supported circle is immovable for the
''' circle resting on it (shock propagation, so a heavy ball resting on a light one does not sink through
''' it), then the walls again, so that nothing is left outside the container.
''' </summary>
Friend NotInheritable Class StepContacts
    ' m/s: approach speeds at or below this are rounding noise, never a collision.
    Private Const MinimumSpeed As Double = 1.0E-9
    ' Support passes per step at most: each is one sweep over the pairs.
    Private Const MaxSupportPasses As Integer = 8
    ' Final passes over the fixed bodies and walls at most (a circle pushed out of one into another).
    Private Const MaxFixedPasses As Integer = 4

    Private ReadOnly _broadPhase As New BroadPhase()
    Private ReadOnly _pairs As New List(Of (A As Integer, B As Integer))
    Private ReadOnly _fixedCircles As New List(Of Circle)
    Private _world As World
    Private _time As Double
    Private _gravity As Double
    Private _restingSpeed As Double
    Private _touched As Boolean()
    ' Where each movable circle started the step (m), to tell which side of a fixed body it came from.
    Private _start As Vector() = Array.Empty(Of Vector)()
    ' Whether the current pass over the fixed bodies moved any circle.
    Private _moved As Boolean
    ' Per circle: the sum of the normals of what holds it (obstacles, walls, circles that are held), or zero.
    Private _support As Vector() = Array.Empty(Of Vector)()
    Private _pairKeys As Double() = Array.Empty(Of Double)()
    Private _pairOrder As (A As Integer, B As Integer)() = Array.Empty(Of (A As Integer, B As Integer))()

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
        If _support.Length < circles.Count Then
            _support = New Vector(circles.Count - 1) {}
            _start = New Vector(circles.Count - 1) {}
        End If
        Array.Clear(_support, 0, circles.Count)
        For i = 0 To circles.Count - 1
            ' The integrator has just moved it by about v h: where it came from, near enough to tell the side.
            _start(i) = circles(i).Position - circles(i).Velocity * h
        Next

        _broadPhase.FindOverlaps(circles, _pairs)
        If _gravity > 0 Then SortBottomUp(circles)

        ResolvePairs()       ' 1. movable pairs, lowest first, with their real masses
        ResolveObstacles()   ' 2. fixed circles, rectangles, walls; marks who rests on them
        If _gravity > 0 Then ' only gravity makes things rest on each other
            ' 3. A circle resting on a supported one treats it as immovable. Lowest pair first lets support
            ' climb a stack in one pass; in an irregular pile height is not quite the order of support, so
            ' passes repeat (a few at most) until one finds nothing left to resolve.
            For pass = 1 To MaxSupportPasses
                If Not ResolveSupport() Then Exit For
            Next
        End If
        ' 4. Fixed bodies and walls have the last word: a pair or support push (a heavy ball on a light
        ' one) may have moved a circle into one, and no centre may end a step inside a fixed body.
        For pass = 1 To MaxFixedPasses
            _moved = False
            ResolveObstacles()
            If Not _moved Then Exit For
        Next
    End Sub

    Private Sub ResolvePairs()
        Dim circles = _world.Circles
        For Each p In _pairs
            Dim a = circles(p.A), b = circles(p.B)
            Dim contact = Collider.CircleCircle(a.Position, a.Radius, b.Position, b.Radius)
            If contact.Depth > 0 Then Respond(p.A, a, p.B, b, contact, CollisionKind.CircleCircle, WallSide.None, False)
        Next
    End Sub

    ''' <summary>One support pass over the pairs; True when it resolved any contact.</summary>
    Private Function ResolveSupport() As Boolean
        Dim circles = _world.Circles
        Dim any = False
        For Each p In _pairs
            Dim a = circles(p.A), b = circles(p.B)
            Dim contact = Collider.CircleCircle(a.Position, a.Radius, b.Position, b.Radius)
            If contact.Depth <= 0 Then Continue For
            If RestsOn(p.A, a, p.B, b, contact) OrElse RestsOn(p.B, b, p.A, a, New Contact(-contact.Normal, contact.Depth)) Then any = True
        Next
        Return any
    End Function

    ''' <summary>Orders the pairs by the height of their lower circle, so support spreads up a pile in one pass.</summary>
    Private Sub SortBottomUp(circles As IReadOnlyList(Of Circle))
        Dim count = _pairs.Count
        If count < 2 Then Return
        If _pairKeys.Length < count Then
            _pairKeys = New Double(count - 1) {}
            _pairOrder = New (A As Integer, B As Integer)(count - 1) {}
        End If
        For k = 0 To count - 1
            Dim p = _pairs(k)
            _pairKeys(k) = Math.Min(circles(p.A).Position.Y, circles(p.B).Position.Y)
            _pairOrder(k) = p
        Next
        Array.Sort(Of Double, (A As Integer, B As Integer))(_pairKeys, _pairOrder, 0, count)
        _pairs.Clear()
        For k = 0 To count - 1
            _pairs.Add(_pairOrder(k))
        Next
    End Sub

    ''' <summary>
    ''' When circle B is held up (by an obstacle, a wall, or a circle that is) and circle A presses on it
    ''' towards what holds it, resolves the contact with B immovable, as a resting contact, and returns True.
    ''' This is shock propagation: a heavy ball resting on a light one is held up by the floor beneath,
    ''' not by the light ball's inertia, so it does not sink through it.
    ''' </summary>
    Private Function RestsOn(ia As Integer, a As Circle, ib As Integer, b As Circle, contact As Contact) As Boolean
        Dim dragged = _world.DraggedCircle
        If a Is dragged OrElse b Is dragged OrElse Vector.Dot(contact.Normal, _support(ib)) <= 0 Then Return False
        Respond(ia, a, ib, b, contact, CollisionKind.CircleCircle, WallSide.None, True)
        Return True
    End Function

    ''' <summary>Contacts with fixed circles, rectangles (usually few, so each movable circle meets each) and walls.</summary>
    Private Sub ResolveObstacles()
        Dim circles = _world.Circles
        _fixedCircles.Clear()
        For Each c In circles
            If c.IsFixed Then _fixedCircles.Add(c)
        Next
        Dim rectangles = _world.Rectangles
        If _fixedCircles.Count > 0 OrElse rectangles.Count > 0 Then
            For i = 0 To circles.Count - 1
                Dim a = circles(i)
                If a.IsFixed Then Continue For
                For Each f In _fixedCircles
                    ' The box of the step's path (from where it started to where it is), so a circle
                    ' that went right through is caught too.
                    Dim reach = a.Radius + f.Radius
                    If Math.Max(a.Position.X, _start(i).X) + reach < f.Position.X OrElse Math.Min(a.Position.X, _start(i).X) - reach > f.Position.X OrElse
                       Math.Max(a.Position.Y, _start(i).Y) + reach < f.Position.Y OrElse Math.Min(a.Position.Y, _start(i).Y) - reach > f.Position.Y Then Continue For
                    Dim contact = Collider.CircleCircleFrom(a.Position, a.Radius, f.Position, f.Radius, _start(i))
                    If contact.Depth > 0 Then Respond(i, a, -1, f, contact, CollisionKind.CircleFixed, WallSide.None, False)
                Next
                For Each r In rectangles
                    Dim lo = r.Min, hi = r.Max
                    If Math.Max(a.Position.X, _start(i).X) + a.Radius < lo.X OrElse Math.Min(a.Position.X, _start(i).X) - a.Radius > hi.X OrElse
                       Math.Max(a.Position.Y, _start(i).Y) + a.Radius < lo.Y OrElse Math.Min(a.Position.Y, _start(i).Y) - a.Radius > hi.Y Then Continue For
                    Dim contact = Collider.CircleRectangleFrom(a.Position, a.Radius, lo, hi, _start(i))
                    If contact.Depth > 0 Then Respond(i, a, -1, r, contact, CollisionKind.CircleRectangle, WallSide.None, False)
                Next
            Next
        End If
        ResolveWalls()
    End Sub

    Private Sub ResolveWalls()
        If Not _world.Walls Then Return
        Dim circles = _world.Circles
        For i = 0 To circles.Count - 1
            Dim a = circles(i)
            If a.IsFixed OrElse a Is _world.DraggedCircle Then Continue For
            ResolveWalls(i, a)
        Next
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
        ' Immovable for this contact: fixed bodies and walls, and in the support pass a circle held up from below.
        Dim bImmovable = Not bMovable OrElse support
        ' The dragged circle acts as if of infinite mass: it pushes and is not pushed back.
        Dim invA = If(a Is dragged, 0.0, a.InverseMass)
        Dim invB = If(bImmovable OrElse bc Is dragged, 0.0, bc.InverseMass)
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
        Dim before = a.Velocity
        Dim va = before
        ' A circle held up from below moves at no more than the resting speed; taking it as still keeps the
        ' support pass from handing that jitter (as energy) to the circles resting on it.
        Dim vb = If(bMovable AndAlso Not support, bc.Velocity, Vector.Zero)
        Dim separation = Vector.Dot(va - vb, n) ' m/s, > 0 when moving apart
        If bImmovable AndAlso _gravity > 0 AndAlso shiftA <> 0 Then
            ' Pushing A out of something immovable lifts it by shiftA·n_y: m g shiftA n_y of potential energy
            ' that the step never paid for. Pay it from the normal speed (w² = w₀² − 2 g s, the suvat relation:
            ' an approaching ball had that speed when it reached the surface; a separating one would have that
            ' speed at the height it is moved to), so a bounce with e = 1 never gains energy.
            Dim squared = separation * separation - 2 * _gravity * shiftA * n.Y
            Dim corrected = Math.Sign(separation) * Math.Sqrt(Math.Max(0.0, squared))
            va += n * (corrected - separation)
            separation = corrected
        End If
        If separation < 0 Then
            Dim resting = support OrElse -separation <= _restingSpeed
            Dim result = Impulse.Resolve(va, invA, vb, invB, n, If(resting, 0.0, _world.Restitution))
            va = result.A
            If invB > 0 Then
                bc.Velocity = result.B
                MarkTouched(ib)
            End If
            If Not resting Then
                _world.ReportCollision(New CollisionRecord(_time, a, b, side, kind, before, va, vb,
                                                           If(bMovable, bc.Velocity, Vector.Zero)))
            End If
        End If
        If va <> before Then
            a.Velocity = va
            MarkTouched(ia)
        End If
        ' Resting on something immovable (or on a circle that is): the circles resting on A can lean on it.
        If bImmovable AndAlso Math.Abs(Vector.Dot(va - vb, n)) <= _restingSpeed Then _support(ia) += n
    End Sub

    Private Sub MarkTouched(i As Integer)
        _moved = True
        If _touched IsNot Nothing AndAlso i >= 0 Then _touched(i) = True
    End Sub
End Class
