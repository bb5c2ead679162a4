Option Strict On

' The one rule for bodies in lasting contact (docs/contact.md). After every event, the bodies it changed, and any
' body touching them that could stay touching, are grouped anew: which touching contacts press is not guessed
' arrangement by arrangement but found from the complementarity conditions of the contact forces (each pushes
' and never pulls, and a contact that pushes does not open), with rods and taut strings in the same solve. The
' contacts that press are held by their group's motion, which keeps them exactly until its own events (a force
' falling to zero, a contact leaving its face, a string changing); the others are left free, for the contact
' search.
Partial Friend NotInheritable Class LinkedEventSolver
    ' A touching contact whose bodies part at less than this many slops' worth of bounce (v² < 2 a × 4 slop, a
    ' the acceleration pressing them) may be held: a bounce that small is the end of a series of ever smaller
    ' bounces, which has a finite sum but endless terms.
    Private Const BounceSlops As Double = 4
    ' A bounce slower than this fraction of its bodies' speeds may be held too.
    Private Const CrumbFraction As Double = 0.000001
    ' A body held on a level face is put exactly on it when it is within this many slops of it (pressed a little in
    ' by the bounces that ended there, or a rounding off).
    Private Const SnapSlops As Double = 16
    ' A speed within this fraction of the group's own speeds is rounding: after its contacts' rates are taken away,
    ' a body at rest keeps none of it.
    Private Const RoundingFraction As Double = 0.000000000000001

    Private ReadOnly _solve As New ContactSolve()
    ' The keys of every contact a group's motion holds.
    Private ReadOnly _heldKeys As New HashSet(Of Long)

    ''' <summary>A touching contact that may last: which one, on what feature (global slots), and its key.</summary>
    Private NotInheritable Class Touch
        Friend Key As ContactKey
        Friend Body As Integer
        Friend Other As Integer
        Friend Side As WallSide
        Friend Fixed As Integer
    End Class

    ''' <summary>Whether a group's motion holds the contact whose key has value <paramref name="key"/> now.</summary>
    Private Function IsHeld(key As Long) As Boolean
        Return _heldKeys.Contains(key)
    End Function

    ''' <summary>
    ''' Groups anew, at <paramref name="t"/>, the bodies of <paramref name="seeds"/> (as written to them: their states at
    ''' t, after whatever the event did) and of every group they touch where
    ''' the touch may last, by the one rule; <paramref name="released"/> (a string or contact whose force has just
    ''' fallen to zero) is not held. Returns the bodies whose motion it made anew, for their contacts to be predicted.
    ''' </summary>
    Private Function Regroup(seeds As List(Of Integer), t As Double, released As Object) As List(Of Integer)
        ' 1. The groups concerned: the seeds (their bodies hold their states at t), and any group one of their
        '    bodies touches where it may last.
        Dim inSet As New HashSet(Of Integer)(seeds)
        Dim order As New List(Of Integer)(seeds)
        ' What the gaps read while this works: the seeds' states now, not their old motions' (whose account of the
        ' energy drag and damping took is settled first).
        ' Each seed body's acceleration bound (m/s²) under the motion it had (see Pressing).
        Dim pressedBefore As New Dictionary(Of Integer, Double)
        For Each g In seeds
            _ledger.Settle(_groups(g), _world, t)
            Dim snapped = _groups(g).Motion.Bodies
            For k = 0 To snapped.Length - 1
                pressedBefore(Array.IndexOf(_bodies, snapped(k))) = _groups(g).Motion.AccelerationBound(k, t, t)
            Next
            Dim now(4 * snapped.Length - 1) As Double
            For k = 0 To snapped.Length - 1
                now(4 * k) = snapped(k).CentreOfMass.X
                now(4 * k + 1) = snapped(k).CentreOfMass.Y
                now(4 * k + 2) = snapped(k).Velocity.X
                now(4 * k + 3) = snapped(k).Velocity.Y
            Next
            Retire(_groups(g).Motion)
            _groups(g).Motion = New SnapshotMotion(snapped, t, FreeAccelerations(snapped, _groups(g).Links, now))
        Next
        Dim touches As New List(Of Touch)
        Dim seen As New HashSet(Of Long)
        Dim head = 0
        Do While head < order.Count
            Dim g = order(head)
            head += 1
            For Each body In _groups(g).Bodies
                Dim i = Array.IndexOf(_bodies, body)
                If _world.Walls Then
                    For s = 1 To 4
                        AddIfLasting(touches, i, -1, CType(s, WallSide), -1, t, released, pressedBefore)
                    Next
                End If
                For f = 0 To _fixed.Length - 1
                    AddIfLasting(touches, i, -1, WallSide.None, f, t, released, pressedBefore)
                Next
                For j = 0 To _bodies.Length - 1
                    If j = i OrElse Not seen.Add(PairKey(i, j)) OrElse _neverMeet.Contains(PairKey(i, j)) Then Continue For
                    Dim gj = _groupOf(j)
                    If Not inSet.Contains(gj) Then
                        If Not MayTouch(i, j) Then Continue For
                        Sync(gj, t)
                        _ledger.Settle(_groups(gj), _world, t)
                    End If
                    If AddIfLasting(touches, Math.Min(i, j), Math.Max(i, j), WallSide.None, -1, t, released, pressedBefore) AndAlso inSet.Add(gj) Then order.Add(gj)
                Next
            Next
        Loop

        ' 2. Their bodies, numbered from 0, and the state now.
        Dim members As New List(Of Integer)
        For Each g In order
            For Each body In _groups(g).Bodies
                members.Add(Array.IndexOf(_bodies, body))
            Next
        Next
        Dim local As New Dictionary(Of Integer, Integer)
        For k = 0 To members.Count - 1
            local(members(k)) = k
        Next
        Dim shapes = members.Select(Function(i) _bodies(i)).ToArray()
        Dim links = order.SelectMany(Function(g) _groups(g).Links).Distinct().ToList()

        ' 3. The constraints that may hold: rods, taut strings, and the touching contacts.
        Dim rows As New List(Of Constraint)
        For Each l In links
            Dim a = local(Array.IndexOf(_bodies, l.A))
            Dim b = If(l.IsAnchored, -1, local(Array.IndexOf(_bodies, l.B)))
            If (l.Kind = LinkKind.Rod AndAlso Not LinkedMotions.IsShortRod(l, Slop)) OrElse
               (l.Kind = LinkKind.String AndAlso l IsNot released AndAlso (LinkedMotions.IsTaut(l, _world.Gravity) OrElse EndOfABounce(l, t, pressedBefore))) Then
                Dim c = Constraint.Tie(a, b, If(l.IsAnchored, l.EndB, Vector.Zero), l.Length, l.Kind = LinkKind.Rod)
                c.Tag = l
                rows.Add(c)
            End If
        Next
        Dim y = Constraint.StateOf(shapes)
        For Each touch In touches
            Dim c = FeatureOf(touch, local, y, Nothing)
            If c IsNot Nothing Then rows.Add(c)
        Next

        Dim kinetic = DissipationLedger.Kinetic(shapes)
        ' 4. No contact approaches and no rod stretches: the least change of the velocities (in the kinetic-energy
        '    metric) that makes it so, which rounding alone has made necessary.
        '    A body that two ties in line hold where it is (TieLock) does not move across them either: its rows
        '    along them are one row twice, and its lock is the row they cannot give.
        '    A contact that a tie in line with it already keeps (TieLock.ImpliedContacts) never pushes: it is only watched.
        Dim locks = TieLock.Find(rows, y)
        Dim implied = TieLock.ImpliedContacts(rows, y)
        Dim solved = rows.Where(Function(c) Not implied.Contains(c)).ToList()
        StopApproaches(shapes, solved.Concat(locks).ToList(), y)

        ' 5. The forces: the complementarity solve for the accelerations. A contact that pushes is held; one moving
        '    off the end of its face is moved onto the feature it goes onto, and the forces found again.
        Dim pressing = PressingRows(shapes, links, solved, y, touches, local)
        HoldRates(shapes, pressing.Concat(locks).ToList(), solved.Concat(locks).ToList(), y)
        rows = solved.Concat(rows.Where(Function(c) implied.Contains(c))).ToList()
        ' What the last crumb of a bounce, taken away, held (never more than a bounce of four slops).
        Dim crumb = kinetic - DissipationLedger.Kinetic(shapes)
        If crumb > 0 Then _world.Dissipate(crumb)

        ' 6. The groups: bodies joined by links or by a contact that presses.
        Dim parent = Enumerable.Range(0, members.Count).ToArray()
        For Each l In links
            If l.IsAnchored Then Continue For
            parent(Root(parent, local(Array.IndexOf(_bodies, l.A)))) = Root(parent, local(Array.IndexOf(_bodies, l.B)))
        Next
        For Each c In pressing
            If c.Shape <> ConstraintShape.Tie AndAlso c.B >= 0 Then parent(Root(parent, c.A)) = Root(parent, c.B)
        Next

        ' 7. Each group's motion.
        Dim made As New List(Of LinkedGroup)
        Dim byRoot As New Dictionary(Of Integer, Integer)
        Dim slots(members.Count - 1) As Integer
        For k = 0 To members.Count - 1
            Dim r = Root(parent, k)
            Dim g As Integer
            If Not byRoot.TryGetValue(r, g) Then
                g = made.Count
                byRoot(r) = g
                made.Add(New LinkedGroup(New List(Of Shape), New List(Of Link)))
            End If
            slots(k) = made(g).Bodies.Count
            made(g).Bodies.Add(shapes(k))
        Next
        For Each l In links
            made(byRoot(Root(parent, local(Array.IndexOf(_bodies, l.A))))).Links.Add(l)
        Next
        Dim contactsOf = made.Select(Function(x) New List(Of Constraint)).ToList()
        Dim touchingOf = made.Select(Function(x) New List(Of Constraint)).ToList()
        For Each c In rows
            If c.Shape = ConstraintShape.Tie Then Continue For
            ' A contact between two groups that does not press is left to the contact search.
            If c.B >= 0 AndAlso Root(parent, c.A) <> Root(parent, c.B) Then Continue For
            Dim onSlots = c.WithSlots(slots(c.A), If(c.B >= 0, slots(c.B), -1))
            If pressing.Contains(c) Then contactsOf(byRoot(Root(parent, c.A))).Add(onSlots) Else touchingOf(byRoot(Root(parent, c.A))).Add(onSlots)
        Next
        For g = 0 To made.Count - 1
            made(g).Motion = MotionFor(made(g), contactsOf(g), touchingOf(g), t, released)
            _ledger.Started(made(g), _world)
        Next

        ' 8. In place of the groups they came from.
        For Each g In inSet
            Retire(_groups(g).Motion)
        Next
        Dim kept = Enumerable.Range(0, _groups.Count).Where(Function(g) Not inSet.Contains(g)).Select(Function(g) _groups(g)).ToList()
        kept.AddRange(made)
        _groups = kept
        _heldKeys.Clear()
        For g = 0 To _groups.Count - 1
            Dim m = _groups(g).Motion
            For k = 0 To m.Bodies.Length - 1
                Dim i = Array.IndexOf(_bodies, m.Bodies(k))
                _groupOf(i) = g
                _slotOf(i) = k
            Next
            For Each c In m.HeldContacts.Concat(m.WatchedContacts)
                _heldKeys.Add(DirectCast(c.Tag, ContactKey).Value)
            Next
        Next
        Return members
    End Function

    ''' <summary>Whether bodies i and j are near enough (their boxes, as last written, within a slop) to be touching; a cheap test before syncing j.</summary>
    Private Function MayTouch(i As Integer, j As Integer) As Boolean
        Dim m = MotionOf(j)
        Dim p As Vector, v As Vector
        m.StateAt(_now, _slotOf(j), p, v)
        Dim ci = _bodies(i).CentreOfMass
        Return ci.X + _low(i).X <= p.X + _high(j).X + Slop AndAlso p.X + _low(j).X <= ci.X + _high(i).X + Slop AndAlso
               ci.Y + _low(i).Y <= p.Y + _high(j).Y + Slop AndAlso p.Y + _low(j).Y <= ci.Y + _high(i).Y + Slop
    End Function

    ''' <summary>
    ''' Adds the contact of body i with body j (i &lt; j), wall <paramref name="side"/> or fixed body f when they touch
    ''' at <paramref name="t"/> (within a slop), do not approach, and part no faster than a bounce of
    ''' <see cref="BounceSlops"/> slops: a contact that may last. Returns whether it was added.
    ''' </summary>
    Private Function AddIfLasting(touches As List(Of Touch), i As Integer, j As Integer, side As WallSide, f As Integer, t As Double, released As Object,
                                  pressedBefore As Dictionary(Of Integer, Double)) As Boolean
        Dim key = If(j >= 0, ContactKey.Pair(i, j), If(f >= 0, ContactKey.Fixed(i, f), ContactKey.Wall(i, side)))
        If key.Equals(released) Then Return False
        Dim gap = If(j >= 0, PairGap(i, j), If(f >= 0, FixedGap(i, f), WallGap(i, side)))
        Dim normal As Vector, rate As Double
        If gap.GapAndNormal(t, normal, rate) > Slop Then Return False
        Dim speeds = _bodies(i).Velocity.Length + If(j >= 0, _bodies(j).Velocity.Length, 0)
        If rate < -ClosingSpeed(speeds) AndAlso Not (j < 0 AndAlso KeptOpenByATie(i, normal)) Then Return False
        If rate > CrumbSpeed(i, j, t, pressedBefore) Then Return False
        touches.Add(New Touch With {.Key = key, .Body = i, .Other = j, .Side = side, .Fixed = f})
        Return True
    End Function

    ''' <summary>
    ''' The fastest (m/s) bodies i and j (j −1: a wall, a fixed body or a point) may part and still be held together: a
    ''' bounce of <see cref="BounceSlops"/> slops under what pressed them just before (<see cref="Pressing"/>, gravity at
    ''' least), or one far too slow to matter beside their own speeds (pressed by almost nothing, the four slops would
    ''' allow any bounce at all): holding it takes a 10⁻¹² part of their kinetic energy at most.
    ''' </summary>
    Private Function CrumbSpeed(i As Integer, j As Integer, t As Double, pressedBefore As Dictionary(Of Integer, Double)) As Double
        Dim speeds = _bodies(i).Velocity.Length + If(j >= 0, _bodies(j).Velocity.Length, 0)
        Dim press = Math.Max(_world.Gravity, Pressing(i, t, pressedBefore) + If(j >= 0, Pressing(j, t, pressedBefore), 0))
        Return Math.Max(Math.Sqrt(2 * press * BounceSlops * Slop), CrumbFraction * speeds)
    End Function

    ''' <summary>
    ''' Whether string <paramref name="l"/>, at its full length (within a slop) with its ends coming together, comes back
    ''' slower than a bounce of <see cref="BounceSlops"/> slops, as a touching contact that may last does
    ''' (<see cref="AddIfLasting"/>): then it may hold, as such a contact may. A string snapping taut on a body that a
    ''' contact holds back (a ball rolling on the floor just beside the point straight under its string's anchor, the
    ''' string as long as the height) sends it up that slowly; the contact's own rule took the bounce away and held the
    ''' ball on the floor, and the string, left slack, snapped taut again at once, for ever.
    ''' </summary>
    Private Function EndOfABounce(l As Link, t As Double, pressedBefore As Dictionary(Of Integer, Double)) As Boolean
        If l.Distance < l.Length * (1 - LinkedMotions.FullFraction) - Slop Then Return False
        Dim rate = l.StretchRate
        If rate >= 0 Then Return False
        Return -rate <= CrumbSpeed(Array.IndexOf(_bodies, l.A), If(l.IsAnchored, -1, Array.IndexOf(_bodies, l.B)), t, pressedBefore)
    End Function

    ''' <summary>
    ''' A bound on body i's acceleration at <paramref name="t"/> (m/s²) as it was pressed just before: its motion's
    ''' now, or, for a body of a group being formed anew (whose motion now is its free flight), the one it had
    ''' (<paramref name="pressedBefore"/>, by body), which counts the pushes through its lasting contacts (a ball
    ''' pushed onto a box through another by a spring is pressed there though nothing pulls it by itself).
    ''' </summary>
    Private Function Pressing(i As Integer, t As Double, pressedBefore As Dictionary(Of Integer, Double)) As Double
        Dim now = MotionOf(i).AccelerationBound(_slotOf(i), t, t)
        Dim before As Double
        If pressedBefore.TryGetValue(i, before) AndAlso before > now Then Return before
        Return now
    End Function

    ''' <summary>
    ''' The constraint that keeps <paramref name="touch"/> on the feature of its pair shape it is on or moving onto,
    ''' in the local numbering, at state <paramref name="y"/>; <paramref name="accelerations"/> (or Nothing) break a
    ''' tie at the end of a face. Nothing for a sharp corner on a sharp corner.
    ''' </summary>
    Private Function FeatureOf(touch As Touch, local As Dictionary(Of Integer, Integer), y As Double(), accelerations As Vector()) As Constraint
        Dim i = touch.Body, a = local(i)
        Dim c As Constraint
        Dim size = (_high(i) - _low(i)).Length
        If touch.Other < 0 AndAlso touch.Fixed < 0 Then
            c = ContactFeatures.OnWall(a, touch.Side, _low(i), _high(i), _world.Width, _world.Height)
        Else
            Dim b = If(touch.Other >= 0, local(touch.Other), -1)
            Dim pa = New Vector(y(4 * a), y(4 * a + 1)), va = New Vector(y(4 * a + 2), y(4 * a + 3))
            Dim qa = If(accelerations Is Nothing, Vector.Zero, accelerations(a))
            Dim shift As Vector, k As Outline
            Dim pb = Vector.Zero, vb = Vector.Zero, qb = Vector.Zero
            If touch.Other >= 0 Then
                Dim j = touch.Other
                shift = _offset(i) - _offset(j)
                k = _pairDifferences(i, j)
                pb = New Vector(y(4 * b), y(4 * b + 1))
                vb = New Vector(y(4 * b + 2), y(4 * b + 3))
                If accelerations IsNot Nothing Then qb = accelerations(b)
                size = Math.Max(size, (_high(j) - _low(j)).Length)
            Else
                shift = _fixed(touch.Fixed).Position + _offset(i)
                k = _differences(i, touch.Fixed)
            End If
            c = ContactFeatures.OnOutline(a, b, shift, k, pa - pb - shift, va - vb, qa - qb, Slop, _offFaceNow.Contains(touch.Key.Value))
        End If
        If c Is Nothing Then Return Nothing
        c.Tag = touch.Key
        c.Scale = size
        ContactFriction.Give(_world, c, _bodies(i), If(touch.Other >= 0, _bodies(touch.Other), If(touch.Fixed >= 0, _fixed(touch.Fixed), Nothing)))
        Return c
    End Function

    ''' <summary>
    ''' Coulomb's law at the held flat contacts with friction of a group about to move (docs/contact.md, "Friction"):
    ''' one sliding slides on, its force leaning back against the sliding by μk; one not sliding sticks (a row holds
    ''' its place along the face) if the friction that takes is at most μs times its push, else starts to slide the
    ''' way the other forces take it. Each change is solved again, until none is needed. Returns the contacts with the
    ''' sticking rows among them, the velocities made to stick exactly.
    ''' </summary>
    Private Function ApplyFriction(bodies As Shape(), links As List(Of Link), contacts As List(Of Constraint)) As List(Of Constraint)
        If Not contacts.Any(Function(c) c.Friction > 0 OrElse c.StaticFriction > 0) Then Return contacts
        Dim y = Constraint.StateOf(bodies)
        Dim scale = 0.0
        For Each b In bodies
            scale = Math.Max(scale, b.Velocity.Length)
        Next
        Dim still = 0.000000001 * scale + 0.000000000001
        Dim result As New List(Of Constraint)(contacts)
        Dim sticks As New List(Of Constraint)
        Dim ties = TiesOf(bodies, links)
        ' A contact that sticks holds its place along its face by a row of its own, unless the others hold that
        ' already (a box in a corner: the wall holds it along the floor); then it sticks with no friction of its own.
        Dim basis As New RowBasis(bodies.Select(Function(b) b.InverseMass).ToArray(), ConstrainedMotion.IndependenceMargin)
        For Each c In ties.Concat(contacts)
            basis.TryAdd(c, y)
        Next
        For Each c In contacts
            c.Sliding = 0
            If c.Friction <= 0 AndAlso c.StaticFriction <= 0 Then Continue For
            Dim rate = c.SlidingRate(y)
            If Math.Abs(rate) > still Then
                c.Sliding = Math.Sign(rate)
            Else
                Dim stick = Constraint.Sticking(c, y)
                If Not basis.TryAdd(stick, y) Then Continue For
                sticks.Add(stick)
                result.Add(stick)
            End If
        Next
        For attempt = 1 To 2 * sticks.Count + 1
            If sticks.Count = 0 Then Exit For
            Dim rows = ties.Concat(result).ToArray()
            Dim lambda As Double()
            Try
                Dim accel = FreeState(bodies, links, y)
                lambda = New ConstraintSet(rows, bodies.Select(Function(b) b.InverseMass).ToArray()).Tensions(y, accel)
            Catch ex As InvalidOperationException
                ' Sliding forces that make the rows depend on one another: the sticking rows are let go.
                For Each stick In sticks
                    result.Remove(stick)
                Next
                sticks.Clear()
                Exit For
            End Try
            ' The stuck contact that needs most beyond what static friction gives starts to slide, against its pull.
            Dim worst As Constraint = Nothing, excess = 0.0, pull = 0.0
            For Each stick In sticks
                Dim k = Array.IndexOf(rows, stick), n = Array.IndexOf(rows, stick.StuckTo)
                Dim over = Math.Abs(lambda(k)) - stick.StuckTo.StaticFriction * Math.Max(lambda(n), 0)
                If over > excess + ConstrainedMotion.StickRounding * (Math.Abs(lambda(k)) + Math.Abs(lambda(n))) Then excess = over : worst = stick : pull = lambda(k)
            Next
            If worst Is Nothing Then Exit For
            worst.StuckTo.Sliding = -Math.Sign(pull)
            sticks.Remove(worst)
            result.Remove(worst)
        Next
        If sticks.Count > 0 Then
            ' Stuck means no sliding at all: what rounding left of it is taken away.
            Try
                Call New ConstraintSet(result.ToArray(), bodies.Select(Function(b) b.InverseMass).ToArray()).ProjectRates(y)
                For k = 0 To bodies.Length - 1
                    Dim v = New Vector(y(4 * k + 2), y(4 * k + 3))
                    Dim zero = RoundingFraction * Math.Max(scale, 1)
                    bodies(k).Velocity = New Vector(If(Math.Abs(v.X) <= zero, 0, v.X), If(Math.Abs(v.Y) <= zero, 0, v.Y))
                Next
            Catch ex As InvalidOperationException
                ' Dependent rows: the stick rows only repeat others; nothing to project.
            End Try
        End If
        Return result
    End Function

    ''' <summary>The rods and taut strings of a group as constraints on its bodies' slots.</summary>
    Private Function TiesOf(bodies As Shape(), links As List(Of Link)) As List(Of Constraint)
        Dim ties As New List(Of Constraint)
        For Each l In links
            If l.Kind = LinkKind.Spring OrElse LinkedMotions.IsShortRod(l, Slop) OrElse (l.Kind = LinkKind.String AndAlso Not LinkedMotions.IsTaut(l, _world.Gravity)) Then Continue For
            ties.Add(Constraint.Tie(Array.IndexOf(bodies, l.A), If(l.IsAnchored, -1, Array.IndexOf(bodies, l.B)), If(l.IsAnchored, l.EndB, Vector.Zero), l.Length, l.Kind = LinkKind.Rod))
        Next
        Return ties
    End Function

    ''' <summary>A state-shaped array of the free accelerations (gravity, springs, drag, buoyancy) at state <paramref name="y"/>.</summary>
    Private Function FreeState(bodies As Shape(), links As List(Of Link), y As Double()) As Double()
        Dim free = FreeAccelerations(bodies, links, y)
        Dim d(y.Length - 1) As Double
        For k = 0 To bodies.Length - 1
            d(4 * k) = y(4 * k + 2)
            d(4 * k + 1) = y(4 * k + 3)
            d(4 * k + 2) = free(k).X
            d(4 * k + 3) = free(k).Y
        Next
        Return d
    End Function

    ''' <summary>
    ''' Takes away, by the least change of the velocities in the kinetic-energy metric, any approach of the touching
    ''' contacts and any stretching of the rods and taut strings in <paramref name="rows"/> (rounding's, or a bounce's
    ''' last crumb), writing the velocities to the bodies and to <paramref name="y"/>. Nothing when none is beyond rounding.
    ''' </summary>
    Private Sub StopApproaches(shapes As Shape(), rows As List(Of Constraint), y As Double())
        If rows.Count = 0 Then Return
        Dim speed = 0.0
        For Each s In shapes
            speed = Math.Max(speed, s.Velocity.Length)
        Next
        Dim tolerance = ContactSolve.ApproachTolerance * speed
        Dim solveRows(rows.Count - 1) As ContactRow
        Dim needed = False
        For k = 0 To rows.Count - 1
            Dim u As Vector, value As Double, rate As Double, curvature As Double
            rows(k).Measure(y, u, value, rate, curvature)
            solveRows(k) = New ContactRow(rows(k).A, rows(k).B, u, 0, rows(k).Holds)
            If rate < -tolerance OrElse (rows(k).Holds AndAlso rate > tolerance) Then needed = True
        Next
        If Not needed Then Return
        Dim result(shapes.Length - 1) As Vector, forces(rows.Count - 1) As Double
        _solve.Solve(shapes.Select(Function(s) s.InverseMass).ToArray(), shapes.Select(Function(s) s.Velocity).ToArray(), solveRows, tolerance, result, forces)
        For k = 0 To shapes.Length - 1
            shapes(k).Velocity = result(k)
            y(4 * k + 2) = result(k).X
            y(4 * k + 3) = result(k).Y
        Next
    End Sub

    ''' <summary>
    ''' The rows that hold in the motion to come: the rods, and the strings and contacts whose force the
    ''' complementarity solve of the accelerations finds pushing (pulling, for a string). A contact at the end of
    ''' its face that these accelerations take off it is put on the feature it goes onto, and the forces found again.
    ''' </summary>
    Private Function PressingRows(shapes As Shape(), links As List(Of Link), rows As List(Of Constraint), y As Double(),
                                  touches As List(Of Touch), local As Dictionary(Of Integer, Integer)) As List(Of Constraint)
        Dim n = shapes.Length
        Dim inverse = shapes.Select(Function(s) s.InverseMass).ToArray()
        Dim free = FreeAccelerations(shapes, links, y)
        Dim result(n - 1) As Vector
        Dim forces(rows.Count - 1) As Double
        Dim solveRows As ContactRow() = Nothing
        Dim scale As Double
        For attempt = 1 To 5
            scale = _world.Gravity
            For Each a In free
                scale = Math.Max(scale, a.Length)
            Next
            solveRows = New ContactRow(rows.Count - 1) {}
            For k = 0 To rows.Count - 1
                Dim u As Vector, value As Double, rate As Double, curvature As Double
                rows(k).Measure(y, u, value, rate, curvature)
                solveRows(k) = New ContactRow(rows(k).A, rows(k).B, u, curvature, rows(k).Holds)
                scale = Math.Max(scale, Math.Abs(curvature))
            Next
            If forces.Length < rows.Count Then forces = New Double(rows.Count - 1) {}
            FrictionSolve.Solve(_solve, inverse, free, rows, solveRows, y, ContactSolve.ApproachTolerance * scale, result, forces, Nothing)
            ' A contact on a face's end that these accelerations take off it goes onto its next feature.
            If attempt = 5 Then Exit For
            Dim changed = False
            For Each touch In touches
                Dim k = rows.FindIndex(Function(c) touch.Key.Equals(c.Tag))
                If k < 0 OrElse Not rows(k).Bounded OrElse rows(k).Margin(y) > Slop Then Continue For
                Dim moved = FeatureOf(touch, local, y, result)
                If moved IsNot Nothing AndAlso SameFeature(moved, rows(k)) Then Continue For
                If moved Is Nothing Then rows.RemoveAt(k) Else rows(k) = moved
                changed = True
            Next
            If Not changed Then Exit For
        Next
        Dim pressing As New List(Of Constraint)
        For k = 0 To rows.Count - 1
            If rows(k).Holds OrElse ((forces(k) > 0 OrElse TakesOverFromZero(rows(k), solveRows(k), result, ContactSolve.ApproachTolerance * scale)) AndAlso
                                     Not ReleasedNow(rows(k))) Then pressing.Add(rows(k))
        Next
        Return pressing
    End Function

    ''' <summary>
    ''' Whether contact <paramref name="c"/>, pressing with no force (its relative acceleration, <paramref name="row"/>'s value
    ''' at the accelerations <paramref name="result"/>, is zero within <paramref name="tolerance"/>, m/s²), is held all the
    ''' same: at this instant a string's pull or a contact's push fell to zero, and then the search found the bodies' motion
    ''' closing this contact at once. Its push takes over from nothing: a ball whose string goes slack where it swings up
    ''' round the peg the string is tied to goes on round the peg. Flying, it went into the peg by the third power of time
    ''' until struck a slop in, and the energy moved by that slop's worth each time.
    ''' </summary>
    Private Function TakesOverFromZero(c As Constraint, row As ContactRow, result As Vector(), tolerance As Double) As Boolean
        If Not _anyReleasedNow Then Return False
        Dim key = TryCast(c.Tag, ContactKey)
        If key Is Nothing OrElse Not IsQuiet(key) Then Return False
        Dim a = If(row.A = ContactRow.None, Vector.Zero, result(row.A)), b = If(row.B = ContactRow.None, Vector.Zero, result(row.B))
        Return Math.Abs(Vector.Dot(row.Direction, a - b) + row.Offset) <= tolerance
    End Function

    ''' <summary>Whether contact <paramref name="c"/> was let go earlier in this instant (see TransitionOf): it is watched, not held.</summary>
    Private Function ReleasedNow(c As Constraint) As Boolean
        Dim key = TryCast(c.Tag, ContactKey)
        Return key IsNot Nothing AndAlso _releasedNow.Contains(key.Value)
    End Function

    ''' <summary>Whether two contact constraints are on the same feature.</summary>
    Private Shared Function SameFeature(a As Constraint, b As Constraint) As Boolean
        Return a.Shape = b.Shape AndAlso a.Normal = b.Normal AndAlso a.Length = b.Length
    End Function

    ''' <summary>Each body's acceleration (m/s²) from gravity, the springs, drag and buoyancy alone, at state <paramref name="y"/>.</summary>
    Private Function FreeAccelerations(shapes As Shape(), links As List(Of Link), y As Double()) As Vector()
        Dim a(shapes.Length - 1) As Vector
        For k = 0 To shapes.Length - 1
            a(k) = New Vector(0, -_world.Gravity) + ForcedMotions.Acceleration(shapes(k), _world)
        Next
        For Each l In links
            If l.Kind <> LinkKind.Spring Then Continue For
            Dim ka = Array.IndexOf(shapes, l.A)
            Dim kb = If(l.IsAnchored, -1, Array.IndexOf(shapes, l.B))
            Dim pa = New Vector(y(4 * ka), y(4 * ka + 1)), va = New Vector(y(4 * ka + 2), y(4 * ka + 3))
            Dim pb = If(kb >= 0, New Vector(y(4 * kb), y(4 * kb + 1)), l.EndB)
            Dim vb = If(kb >= 0, New Vector(y(4 * kb + 2), y(4 * kb + 3)), Vector.Zero)
            Dim force = SpringTerm.Pull(l, pa, va, pb, vb)
            a(ka) += force * shapes(ka).InverseMass
            If kb >= 0 Then a(kb) -= force * shapes(kb).InverseMass
        Next
        Return a
    End Function

    ''' <summary>
    ''' The motion of a group newly formed: its closed form when it holds no contact (<see cref="LinkedMotions"/>),
    ''' exact uniform acceleration when it holds only flat ones and has no links, else integrated.
    ''' </summary>
    Private Function MotionFor(group As LinkedGroup, contacts As List(Of Constraint), touching As List(Of Constraint), t As Double, released As Object) As LinkedMotion
        Dim bodies = group.Bodies.ToArray()
        If contacts.Count = 0 Then Return LinkedMotions.Create(group, _world, t, released, Slop)
        SnapToLevelFaces(contacts)
        contacts = ApplyFriction(bodies, group.Links, contacts)
        ' Drag and buoyancy change as the bodies move: such a group is integrated, however flat its faces.
        Dim forces = ForcedMotions.FieldFor(group, _world)
        If forces Is Nothing AndAlso group.Links.Count = 0 AndAlso contacts.All(Function(c) c.Shape = ConstraintShape.Plane) Then
            Return New UniformMotion(bodies, contacts.ToArray(), t, _world.Gravity)
        End If
        Dim size = bodies.Min(Function(b) Math.Min(b.Outline.MaxX - b.Outline.MinX, b.Outline.MaxY - b.Outline.MinY))
        Dim m = New ConstrainedMotion(bodies, group.Links, contacts, t, _world.Gravity, released, size, touching, forces)
        ' At rest, every force balanced: nothing changes until something reaches it, so nothing is integrated.
        If m.IsStill(UniformMotion.RestFraction) Then Return New UniformMotion(bodies, m.HeldContacts, m.HeldLinks, m.StartTensions, m.SlackLinks, m.HeldLocks, t)
        Return m
    End Function

    ''' <summary>
    ''' Puts each body held on a face square to the axes (a floor, a wall, a table top, the top of a box resting on
    ''' one) exactly on it, where it touches within a slop: its reference point's coordinate across the face is the
    ''' face's own level, so that a body at rest on a table is never a rounding error below its top. A body on a
    ''' movable body is placed after that one, so a stack is placed from the bottom up.
    ''' </summary>
    Private Sub SnapToLevelFaces(contacts As List(Of Constraint))
        Dim placed As New HashSet(Of Integer)
        For pass = 0 To contacts.Count
            Dim moved = False
            For Each c In contacts
                If c.Shape <> ConstraintShape.Plane Then Continue For
                Dim n = c.Normal
                If Not ((n.X = 0 AndAlso Math.Abs(n.Y) = 1) OrElse (n.Y = 0 AndAlso Math.Abs(n.X) = 1)) Then Continue For
                Dim key = DirectCast(c.Tag, ContactKey)
                Dim i As Integer, support As Double
                Select Case key.Kind
                    Case 1
                        i = key.Body
                        If placed.Contains(i) Then Continue For
                        Dim o = _bodies(i).Outline
                        Select Case CType(key.Other, WallSide)
                            Case WallSide.Bottom : support = -o.MinY
                            Case WallSide.Top : support = _world.Height - o.MaxY
                            Case WallSide.Left : support = -o.MinX
                            Case Else : support = _world.Width - o.MaxX
                        End Select
                    Case 2
                        i = key.Body
                        If placed.Contains(i) Then Continue For
                        Dim p = _fixed(key.Other).Position
                        support = If(n.X = 0, p.Y, p.X) + If(n.X + n.Y > 0, c.Length, -c.Length)
                    Case Else
                        ' A pair: the body on the far side of the face from the other, once that other is placed.
                        Dim lowFirst = n.X + n.Y > 0
                        i = If(lowFirst, key.Body, key.Other)
                        Dim other = If(lowFirst, key.Other, key.Body)
                        If placed.Contains(i) OrElse Not placed.Contains(other) Then Continue For
                        Dim p = _bodies(other).Position
                        support = If(n.X = 0, p.Y, p.X) + c.Length
                End Select
                Dim q = _bodies(i).Position
                Dim across = If(n.X = 0, q.Y, q.X)
                If Math.Abs(across - support) > SnapSlops * Slop Then Continue For
                _bodies(i).Position = If(n.X = 0, New Vector(q.X, support), New Vector(support, q.Y))
                placed.Add(i)
                moved = True
            Next
            If Not moved Then Exit For
        Next
    End Sub

    ''' <summary>
    ''' Whether contact <paramref name="c"/> approaches, at positions <paramref name="y"/> and the bodies' velocities
    ''' <paramref name="velocities"/>, fast enough to be struck (as Collide judges it).
    ''' </summary>
    Private Shared Function Approaches(c As Constraint, y As Double(), velocities As Vector()) As Boolean
        Dim state = CType(y.Clone(), Double())
        For k = 0 To velocities.Length - 1
            state(4 * k + 2) = velocities(k).X
            state(4 * k + 3) = velocities(k).Y
        Next
        Dim u As Vector, value As Double, rate As Double, curvature As Double
        c.Measure(state, u, value, rate, curvature)
        Dim speeds = velocities(c.A).Length + If(c.B >= 0, velocities(c.B).Length, 0)
        Return rate < -ClosingSpeed(speeds)
    End Function

    ''' <summary>
    ''' Makes the rates of the constraints that will hold (<paramref name="pressing"/>: rods, taut strings, contacts
    ''' that press) exactly zero, and keeps every other touching contact in <paramref name="rows"/> from approaching,
    ''' by the least change of the velocities in the kinetic-energy metric: what is taken away is a bounce of under
    ''' <see cref="BounceSlops"/> slops, or rounding. Then a velocity component within rounding of zero (of the
    ''' group's speeds, or √(g × size) for a group at rest) is zero, so that a body at rest is exactly still. The
    ''' velocities go to the bodies and to <paramref name="y"/>.
    ''' </summary>
    Private Sub HoldRates(shapes As Shape(), pressing As List(Of Constraint), rows As List(Of Constraint), y As Double())
        Dim scale = 0.0
        For Each b In shapes
            scale = Math.Max(scale, Math.Max(b.Velocity.Length, Math.Sqrt(_world.Gravity * (b.Outline.MaxX - b.Outline.MinX + b.Outline.MaxY - b.Outline.MinY))))
        Next
        If rows.Count > 0 Then
            Dim solveRows(rows.Count - 1) As ContactRow
            For k = 0 To rows.Count - 1
                Dim u As Vector, value As Double, rate As Double, curvature As Double
                rows(k).Measure(y, u, value, rate, curvature)
                solveRows(k) = New ContactRow(rows(k).A, rows(k).B, u, 0, pressing.Contains(rows(k)))
            Next
            Dim result(shapes.Length - 1) As Vector, forces(rows.Count - 1) As Double
            Dim inverse = shapes.Select(Function(s) s.InverseMass).ToArray(), velocities = shapes.Select(Function(s) s.Velocity).ToArray()
            _solve.Solve(inverse, velocities, solveRows, ContactSolve.ApproachTolerance * scale, result, forces)
            ' The solve's tolerance is the group's, but whether a touch is struck is judged by its own bodies' speeds
            ' (Collide): a contact left approaching beyond that would be struck at once, and held back here again, for
            ' ever (a 2 mg ball at rest against a wall, beside a 187 t ball sliding off it at 1.3 m/s). Solved again
            ' to below a creep.
            If Enumerable.Range(0, rows.Count).Any(Function(k) Not solveRows(k).Holds AndAlso Approaches(rows(k), y, result)) Then
                _solve.Solve(inverse, velocities, solveRows, Math.Min(ContactSolve.ApproachTolerance * scale, 0.5 * CreepSpeed), result, forces)
            End If
            For k = 0 To shapes.Length - 1
                shapes(k).Velocity = result(k)
            Next
        End If
        Dim zero = RoundingFraction * scale
        For k = 0 To shapes.Length - 1
            Dim v = shapes(k).Velocity
            v = New Vector(If(Math.Abs(v.X) <= zero, 0, v.X), If(Math.Abs(v.Y) <= zero, 0, v.Y))
            shapes(k).Velocity = v
            y(4 * k + 2) = v.X
            y(4 * k + 3) = v.Y
        Next
    End Sub
End Class
