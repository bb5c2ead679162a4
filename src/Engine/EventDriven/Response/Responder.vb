Option Strict On

Imports System.Runtime.CompilerServices

''' <summary>
''' Resolving one event (docs/event-driven.md §3): bring the bodies to the event time, apply the
''' impulse along the contact normal (<see cref="Impulse.Resolve"/>), report it, and apply the
''' resting and sleeping rules (<see cref="RestRules"/>). Every body whose motion it changes is
''' marked (<see cref="SolverState.Changed"/>) and rescheduled by the solver afterwards.
''' </summary>
Friend NotInheritable Class Responder
    Private ReadOnly _s As SolverState
    ' The state's body table (made once with it), held here too: one load fewer on every read.
    Private ReadOnly _bodies As BodyTable
    Private ReadOnly _rest As RestRules
    Private ReadOnly _slides As CornerSlides
    Private ReadOnly _clusters As ClusterResponse

    Friend Sub New(state As SolverState, rest As RestRules, slides As CornerSlides)
        _s = state
        _bodies = state.Bodies
        _rest = rest
        _slides = slides
        _clusters = New ClusterResponse(state, rest)
    End Sub

    ''' <summary>Resolves body i's collision-type event, which is due now.</summary>
    Friend Sub Resolve(i As Integer)
        Dim slot = _bodies.Slot
        Select Case slot(i).Kind
            Case EventKind.Body
                Dim j = slot(i).Other
                If slot(j).Count <> slot(i).OtherCount Then
                    _s.Touched.Add(i) ' stale: the partner's motion changed since this was predicted
                ElseIf slot(i).Mode = BodyMode.Rounding OrElse slot(j).Mode = BodyMode.Rounding Then
                    ' A body came near a sliding one. Still clearly apart: look again later (the slide
                    ' goes on exactly). About to touch: stop following the slide exactly.
                    Dim sliding = If(slot(i).Mode = BodyMode.Rounding, i, j)
                    If Not _slides.StillApart(sliding, If(sliding = i, j, i)) Then
                        If slot(i).Mode = BodyMode.Rounding Then _slides.Interrupt(i)
                        If slot(j).Mode = BodyMode.Rounding Then _slides.Interrupt(j)
                    End If
                    _s.Touched.Add(i)
                    _s.Touched.Add(j)
                Else
                    CollideBodies(i, j)
                End If
            Case EventKind.Obstacle
                CollideObstacle(i, slot(i).Other, slot(i).Feature)
            Case EventKind.Wall
                CollideWall(i, CType(slot(i).Feature, WallSide))
            Case EventKind.LeaveSupport
                LeaveSupport(i, slot(i).Other, slot(i).Feature = 1)
            Case EventKind.CornerEnd
                _slides.Finish(i)
            Case Else
                _s.Touched.Add(i)
        End Select
    End Sub

    Private Sub CollideWall(i As Integer, side As WallSide)
        _s.SyncUnpublished(i) ' published by CollideImmovable
        Dim m = _bodies.Motion
        ' The outline's extents; a circle's are its radius (as the wall's time of impact took them).
        Dim r = m(i).R
        Dim minX = -r, maxX = r, minY = -r, maxY = r
        If Not _bodies.Info(i).IsCircle Then
            Dim o = _bodies.Outlines(i)
            minX = o.MinX : maxX = o.MaxX : minY = o.MinY : maxY = o.MaxY
        End If
        Dim n As Vector
        ' Snap onto the wall: the contact is exact, so rounding never accumulates over many bounces.
        Select Case side
            Case WallSide.Left : n = New Vector(1, 0) : m(i).Px = -minX
            Case WallSide.Right : n = New Vector(-1, 0) : m(i).Px = _s.Width - maxX
            Case WallSide.Bottom : n = New Vector(0, 1) : m(i).Py = -minY
            Case Else : n = New Vector(0, -1) : m(i).Py = _s.Height - maxY
        End Select
        CollideImmovable(i, n, Nothing, CollisionKinds.AgainstWall(_bodies.Info(i).Kind), side, If(side = WallSide.Bottom, BodyTable.SupportFloor, BodyTable.SupportNone), -1)
    End Sub

    Private Sub CollideObstacle(i As Integer, s As Integer, feature As Integer)
        _s.SyncUnpublished(i) ' published by CollideImmovable
        Dim m = _bodies.Motion
        Dim n = ContactRules.NormalAtObstacle(_s, i, s, feature, m(i).Px, m(i).Py)
        ' What it could rest on: a face of the obstacle (which one, to slide along and to leave at its
        ' ends), or a rounded corner (a fixed circle, a rectangle's corner), which holds only from right above.
        Dim edge = ContactRules.FaceOf(_s, i, s, feature)
        Dim curve = ContactRules.CurveAt(_s, i, s, feature)
        Dim support = If(edge >= 0, s, If(curve.HasValue, BodyTable.SupportBody, BodyTable.SupportNone))
        CollideImmovable(i, n, _s.Obstacles.Shapes(s), CollisionKinds.Between(_bodies.Info(i).Kind, _s.Obstacles.Kind(s), True), WallSide.None, support, edge, curve)
    End Sub

    ''' <summary>
    ''' Body i (already at the clock) hits something of infinite mass along unit normal n (pointing
    ''' towards i). <paramref name="support"/> names what it would rest on if n points straight up
    ''' (and <paramref name="edge"/> which face of it); <paramref name="kind"/> is what the collision is reported as.
    ''' </summary>
    Private Sub CollideImmovable(i As Integer, n As Vector, other As Shape, kind As CollisionKind, side As WallSide, support As Integer, edge As Integer,
                                 Optional curve As CurvedSupport? = Nothing)
        If _rest.HitTooOften(i) Then
            _s.Publish(i)
            _clusters.Resolve(i)
            Return
        End If
        Dim b = _bodies
        Dim before = New Vector(b.Motion(i).Vx, b.Motion(i).Vy)
        Dim approach = Vector.Dot(before, n)
        Dim after = Impulse.Resolve(before, 1.0, Vector.Zero, 0.0, n, _s.E).A
        If approach < 0 AndAlso after = before Then
            Dim slop = _s.SlopOf(i) ' see CollideBodies: an approach too small to resolve
            b.Motion(i).Px += n.X * 4 * slop
            b.Motion(i).Py += n.Y * 4 * slop
        End If
        b.Motion(i).Vx = after.X
        b.Motion(i).Vy = after.Y
        If approach < 0 Then
            If _s.World.ListensForCollisions Then
                _s.World.ReportCollision(New CollisionRecord(_s.Now, b.Shapes(i), other, side, kind,
                                                             before, after, Vector.Zero, Vector.Zero))
            Else
                _s.World.CountCollision()
            End If
            _rest.NoteHit(i)
        End If
        ' What rests on a supported body (see RestRules.AfterSliderContact) does not go with it when it bounces.
        If b.Mode(i) = BodyMode.Supported AndAlso after <> before Then _rest.WakeAbove(i)
        If b.Mode(i) = BodyMode.Supported AndAlso (after.Y <> 0 OrElse n.Y <> 0) Then _rest.MakeFree(i)
        If b.Mode(i) = BodyMode.Free Then _rest.AfterSupportContact(i, n, support, edge, 0, 0, curve, before)
        If _s.E < 1 Then CollisionLosses.Note(_s, i, before)
        _s.Changed(i)
    End Sub

    Private Sub CollideBodies(i As Integer, j As Integer)
        ' Published once, by Changed at the end (nothing here scans the lanes before that).
        _s.SyncUnpublished(i)
        _s.SyncUnpublished(j)
        Dim b = _bodies
        If _rest.HitTooOften(i) Or _rest.HitTooOften(j) Then
            ' A jam of bodies in motion (a heavy ball sliding into a light one that it lifts up a wall) is
            ' lasting contact that moves: the cluster rule would stop the wedged body dead, and a moving
            ' body taken as a support would lift it with energy from nowhere. Only the general path follows
            ' it exactly. A settling jam (slow bodies pressed into a gap by gravity) keeps the cluster rule.
            If Not ((_rest.InMotion(i) OrElse _rest.InMotion(j)) AndAlso _s.TryHandOver()) Then ResolveJam(i, j)
            Return
        End If
        Dim m = b.Motion
        Dim n = If(b.Info(i).IsCircle AndAlso b.Info(j).IsCircle,
                   New Vector(m(i).Px - m(j).Px, m(i).Py - m(j).Py).Normalized(New Vector(0, 1)),
                   ContactRules.NormalBetweenBodies(_s, i, j))
        Dim vi = New Vector(m(i).Vx, m(i).Vy), vj = New Vector(m(j).Vx, m(j).Vy)
        Dim approach = Vector.Dot(vi - vj, n)
        Dim gentle = -approach < _rest.GentleSpeed(i, j)
        ' A gentle touch on a body at rest treats it as a support (infinite mass); a real hit wakes it.
        Dim invI = _rest.InverseMassFor(i, j, gentle)
        Dim invJ = _rest.InverseMassFor(j, i, gentle)
        Dim onFace = -1 ' a body that the blow leaves sliding on its face (see ResolveWithResting)
        Dim result = If(invI = 0 OrElse invJ = 0, ResolveWithResting(i, j, n, vi, vj, gentle, invI, invJ, onFace),
                        Impulse.Resolve(vi, invI, vj, invJ, n, _rest.EffectiveRestitution(i, j, approach)))
        If approach < 0 AndAlso result.A = vi AndAlso result.B = vj Then PartTouching(i, j, n, If(onFace = i, 0, invI), If(onFace = j, 0, invJ))
        m(i).Vx = result.A.X
        m(i).Vy = result.A.Y
        m(j).Vx = result.B.X
        m(j).Vy = result.B.Y
        If approach < 0 AndAlso (invI > 0 OrElse invJ > 0) Then
            If _s.World.ListensForCollisions Then
                _s.World.ReportCollision(New CollisionRecord(_s.Now, b.Shapes(i), b.Shapes(j), WallSide.None, CollisionKinds.Between(b.Info(i).Kind, b.Info(j).Kind, False), vi, result.A, vj, result.B))
            Else
                _s.World.CountCollision()
            End If
            _rest.NoteHit(i)
            _rest.NoteHit(j)
        End If
        ' A touch shared with a face is booked at once: the rules after it keep their own books (RestRules.AfterSliderContact).
        Dim booked = onFace >= 0 AndAlso _s.E < 1
        If booked Then CollisionLosses.Note(_s, i, vi, j, vj)
        ' Two free bodies, both movable, with no gravity (the elastic gas): no rest rule can apply.
        If b.Slot(i).Mode <> BodyMode.Free OrElse b.Slot(j).Mode <> BodyMode.Free OrElse invI = 0 OrElse invJ = 0 OrElse _s.G <> 0 Then
            RestAfterHit(i, j, n, vi, vj, result.A, result.B, invI, invJ, onFace)
        End If
        If _s.E < 1 AndAlso Not booked Then CollisionLosses.Note(_s, i, vi, j, vj)
        _s.Changed(i)
        _s.Changed(j)
    End Sub

    ''' <summary>
    ''' The impulse when the rest rules make body i or j immovable (<see cref="RestRules.InverseMassFor"/>).
    ''' A sleeper alone on level ground, struck from above, is not: the ground takes the vertical part of
    ''' the blow and the body the horizontal part (<see cref="Impulse.ResolveOnLevelGround"/>), so a ball
    ''' dropped on a resting one knocks it sideways and momentum along the ground is kept. Its inverse
    ''' mass becomes the one the blow meets, n_x²/m, for the rest rules that follow. Nor is a body that
    ''' rests on a face and may slide along it (<see cref="SlidesOnFace"/>), touched gently: taken as immovable it
    ''' would be a moving wall, which can give energy. The face takes the part of the blow that presses the body
    ''' into it, and the body the part along the face (<see cref="Impulse.ResolveOnFace"/>): it stays on its face
    ''' (<paramref name="onFace"/> names it), with the inverse mass (n·t)²/m along n. A blow that lifts it off
    ''' its face meets its whole mass. Apart from <see cref="CollideBodies"/>, which runs at every collision,
    ''' because it is rare.
    ''' </summary>
    <MethodImpl(MethodImplOptions.NoInlining)>
    Private Function ResolveWithResting(i As Integer, j As Integer, n As Vector, vi As Vector, vj As Vector, gentle As Boolean,
                                        ByRef invI As Double, ByRef invJ As Double, ByRef onFace As Integer) As (A As Vector, B As Vector)
        Dim b = _bodies
        Dim e = _rest.EffectiveRestitution(i, j, Vector.Dot(vi - vj, n))
        Dim t As Vector
        If gentle AndAlso invJ = 0 AndAlso invI > 0 AndAlso b.Info(j).InverseMass > 0 AndAlso SlidesOnFace(j, t) Then
            ' The blow on j is along −n: it presses j into its face when the face's normal has s·n ≥ 0.
            If Vector.Dot(n, FaceNormal(t)) >= 0 Then
                onFace = j
                Dim along = Vector.Dot(n, t)
                invJ = b.Info(j).InverseMass * along * along
                Return Impulse.ResolveOnFace(vi, invI, vj, b.Info(j).InverseMass, n, t, e)
            End If
            invJ = b.Info(j).InverseMass
            Return Impulse.Resolve(vi, invI, vj, invJ, n, e)
        End If
        If gentle AndAlso invI = 0 AndAlso invJ > 0 AndAlso b.Info(i).InverseMass > 0 AndAlso SlidesOnFace(i, t) Then
            If Vector.Dot(-n, FaceNormal(t)) >= 0 Then
                onFace = i
                Dim along = Vector.Dot(n, t)
                invI = b.Info(i).InverseMass * along * along
                Dim swapped = Impulse.ResolveOnFace(vj, invJ, vi, b.Info(i).InverseMass, -n, t, e)
                Return (swapped.B, swapped.A)
            End If
            invI = b.Info(i).InverseMass
            Return Impulse.Resolve(vi, invI, vj, invJ, n, e)
        End If
        If Not gentle AndAlso invJ = 0 AndAlso invI > 0 AndAlso n.Y > 0 AndAlso b.Info(j).InverseMass > 0 AndAlso _rest.AloneOnLevelGround(j, i) Then
            invJ = b.Info(j).InverseMass * n.X * n.X
            Return Impulse.ResolveOnLevelGround(vi, invI, vj, b.Info(j).InverseMass, n, e)
        End If
        If Not gentle AndAlso invI = 0 AndAlso invJ > 0 AndAlso n.Y < 0 AndAlso b.Info(i).InverseMass > 0 AndAlso _rest.AloneOnLevelGround(i, j) Then
            invI = b.Info(i).InverseMass * n.X * n.X
            Dim swapped = Impulse.ResolveOnLevelGround(vj, invJ, vi, b.Info(i).InverseMass, -n, e)
            Return (swapped.B, swapped.A)
        End If
        Return Impulse.Resolve(vi, invI, vj, invJ, n, e)
    End Function

    ''' <summary>
    ''' Whether body k rests on a face and slides along it (or may: it is not asleep), and the face's unit
    ''' tangent <paramref name="t"/>: level, (1, 0); sloping, the direction of its acceleration down the face
    ''' (see RestRules.EnterSlide). The face is the floor, a face of a fixed body, or the top of the body it
    ''' rests on (RestRules.AfterSliderContact), which does not move across the face either.
    ''' </summary>
    Private Function SlidesOnFace(k As Integer, ByRef t As Vector) As Boolean
        Dim b = _bodies
        If b.Slot(k).Mode <> BodyMode.Supported Then Return False
        Dim m = b.Motion(k)
        t = If(m.Ax = 0 AndAlso m.Ay = 0, New Vector(1, 0), New Vector(m.Ax, m.Ay).Normalized(New Vector(1, 0)))
        Return True
    End Function

    ''' <summary>The unit normal, pointing up, of a face with unit tangent t that holds a body up.</summary>
    Private Shared Function FaceNormal(t As Vector) As Vector
        Dim s = t.Perpendicular()
        Return If(s.Y < 0, -s, s)
    End Function

    ''' <summary>
    ''' Body i or j has been hit too often at this instant: their cluster of touching bodies is resolved
    ''' at once (see <see cref="ClusterResponse"/>). Apart from <see cref="CollideBodies"/>, which runs at
    ''' every collision, because it is rare.
    ''' </summary>
    <MethodImpl(MethodImplOptions.NoInlining)>
    Private Sub ResolveJam(i As Integer, j As Integer)
        _s.Publish(i)
        _s.Publish(j)
        ' The cluster grows from a body that can move (the other may be asleep or dragged).
        _clusters.Resolve(If(_clusters.CanMove(i), i, j))
    End Sub

    ''' <summary>
    ''' The rest rules after bodies i and j collided along n (towards i), their velocities going from
    ''' vi, vj to ai, aj: whoever moved leaves rest (a body still asleep stays a support); a free body
    ''' that hit something immovable may come to rest on it; a free body may fall asleep. A body the blow
    ''' left sliding on its face (<paramref name="onFace"/>) stays on it.
    ''' </summary>
    <MethodImpl(MethodImplOptions.NoInlining)>
    Private Sub RestAfterHit(i As Integer, j As Integer, n As Vector, vi As Vector, vj As Vector, ai As Vector, aj As Vector,
                             invI As Double, invJ As Double, onFace As Integer)
        Dim b = _bodies
        Dim m = b.Motion
        If ai <> vi AndAlso b.Slot(i).Mode <> BodyMode.Dragged AndAlso onFace <> i Then _rest.WakeFrom(i)
        If aj <> vj AndAlso b.Slot(j).Mode <> BodyMode.Dragged AndAlso onFace <> j Then _rest.WakeFrom(j)
        ' A body the touch moved along its face stays on it; what rested on it does not go with it, and flies.
        If onFace = i AndAlso ai <> vi Then _rest.WakeAbove(i)
        If onFace = j AndAlso aj <> vj Then _rest.WakeAbove(j)
        Dim t As Vector
        If b.Slot(i).Mode = BodyMode.Free AndAlso onFace = j AndAlso SlidesOnFace(j, t) Then
            _rest.AfterSliderContact(i, j, n, t)
        ElseIf b.Slot(i).Mode = BodyMode.Free AndAlso invJ = 0 AndAlso b.Slot(j).Mode <> BodyMode.Dragged Then
            _rest.AfterSupportContact(i, n, BodyTable.SupportBody, -1, m(j).Vx, m(j).Vy, before:=vi)
        ElseIf b.Slot(i).Mode = BodyMode.Free Then
            _rest.SleepIfSettled(i)
        End If
        If b.Slot(j).Mode = BodyMode.Free AndAlso onFace = i AndAlso SlidesOnFace(i, t) Then
            _rest.AfterSliderContact(j, i, -n, t)
        ElseIf b.Slot(j).Mode = BodyMode.Free AndAlso invI = 0 AndAlso b.Slot(i).Mode <> BodyMode.Dragged Then
            _rest.AfterSupportContact(j, -n, BodyTable.SupportBody, -1, m(i).Vx, m(i).Vy, before:=vj)
        ElseIf b.Slot(j).Mode = BodyMode.Free Then
            _rest.SleepIfSettled(j)
        End If
    End Sub

    ''' <summary>
    ''' Bodies i and j approach along n more slowly than their velocities can resolve in floating point
    ''' (after an e = 0 contact): they are parted by a few slops instead, so the pair stops being
    ''' "touching". Kept out of <see cref="CollideBodies"/>, which runs at every collision, because it is rare.
    ''' </summary>
    <MethodImpl(MethodImplOptions.NoInlining)>
    Private Sub PartTouching(i As Integer, j As Integer, n As Vector, invI As Double, invJ As Double)
        Dim m = _bodies.Motion
        Dim wi = If(invI > 0 OrElse invJ = 0, 0.5, 0.0), wj = If(invJ > 0 OrElse invI = 0, 0.5, 0.0)
        Dim sep = 4 * Math.Max(_s.SlopOf(i), _s.SlopOf(j)) / Math.Max(wi + wj, 0.5)
        m(i).Px += n.X * sep * wi
        m(i).Py += n.Y * sep * wi
        m(j).Px -= n.X * sep * wj
        m(j).Py -= n.Y * sep * wj
    End Sub

    ''' <summary>
    ''' A supported body reached an end of the face it rests on (the far end when <paramref name="farEnd"/>).
    ''' Round a rounded corner (a circle's radius) it slides on until the normal force vanishes or the
    ''' next face takes it, or flies off if it is too fast to follow the curve; past a sharp corner
    ''' (a box's), it simply flies on.
    ''' </summary>
    Private Sub LeaveSupport(i As Integer, s As Integer, farEnd As Boolean)
        _s.Sync(i)
        Dim b = _bodies
        Dim k = _s.Shapes.Difference(_s.Obstacles.Outlines(s), b.Outlines(i))
        Dim e = b.SupportEdge(i)
        Dim c = If(farEnd, (e + 1) Mod k.VertexCount, e)
        Dim nextFace = If(farEnd, (e + 1) Mod k.EdgeCount, (e - 1 + k.EdgeCount) Mod k.EdgeCount)
        Dim corner = New Vector(_s.Obstacles.X0(s), _s.Obstacles.Y0(s)) + k.Corners(c)
        Dim n = k.EdgeNormals(e)
        ' Exactly at the end of the face.
        b.Motion(i).Px = corner.X + n.X * k.Radius
        b.Motion(i).Py = corner.Y + n.Y * k.Radius
        Dim v = New Vector(b.Motion(i).Vx, b.Motion(i).Vy)
        _rest.MakeFree(i)
        _rest.WakeAbove(i) ' what rested on it, sliding with it, is left to fall
        If k.Radius > 0 AndAlso Not _slides.Start(i, corner.X, corner.Y, k.Radius, n, v, (n, k.EdgeNormals(nextFace))) AndAlso
           (_slides.Refusal = SlideRefusal.Crowded OrElse _slides.Refusal = SlideRefusal.Blocked) Then
            ' Kept from sliding round (by a neighbour, or a wall or body in the way), and free at the very
            ' end of the face, gravity would bring it straight back onto that face's end; ten touching
            ' tolerances clear of it, it meets the rounded corner beyond instead, and hops round it.
            Dim slop = SolverState.SlopAt(corner.X, corner.Y)
            b.Motion(i).Px += n.X * 10 * slop
            b.Motion(i).Py += n.Y * 10 * slop
        End If
        _s.Changed(i)
    End Sub
End Class
