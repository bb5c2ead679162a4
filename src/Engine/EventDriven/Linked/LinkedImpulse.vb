Option Strict On

''' <summary>
''' A collision of linked bodies, resolved with the links' own impulses and the lasting contacts in the same
''' solve. Each row is one condition on the speed at which two points separate along a unit vector u (from end
''' A to end B), after the blow: the contact's row asks for −e times the speed it arrived at (Newton's
''' experimental law), each rod and taut string touching these bodies for 0 (it keeps its length), each lasting
''' contact for at least 0 (they may part, never press into each other). Row i's impulse λᵢ acts on its ends
''' equally and oppositely (v_A −= λ u/m_A, v_B += λ u/m_B), so momentum is conserved between bodies (a fixed
''' point takes what acts on it); a contact can only push (λ ≥ 0), a string only pull (λ ≤ 0), a rod both.
''' That is a complementarity problem, solved exactly by <see cref="ContactSolve"/> (the velocities closest to
''' those before, in the kinetic-energy metric, that meet every row). With e = 1 no energy is lost: every link's
''' impulse does no work (its ends' separation speed is 0 before and after), and the contact's does none either
''' (the speed is reversed). The held rows' speeds before are 0 only to the accuracy of the motion they come from,
''' and a held row's impulse can be far larger than the blow's own (a heavy body's string pulling in line with a
''' light body's rod to a point: the rod takes the heavy body's whole blow), so its small speed times that impulse
''' would be work done: those speeds are first put to 0 by themselves (<see cref="HoldRows"/>), which only loses energy.
''' </summary>
Friend NotInheritable Class LinkedImpulse
    Private ReadOnly _bodies As New List(Of Shape)
    Private ReadOnly _velocities As New List(Of Vector)
    Private ReadOnly _rows As New List(Of Row)
    Private ReadOnly _solve As New ContactSolve()
    ' The most (m/s) a row may be left approaching by the blow under way (ResolveWedgedAgain's creep; none otherwise).
    Private _creep As Double = Double.PositiveInfinity
    ' The velocities a wedged blow started from (ResolveWedged), for solving it again.
    Private ReadOnly _before As New List(Of Vector)

    Private Structure Row
        Public A As Integer
        Public B As Integer
        Public U As Vector
        Public Target As Double
        ''' <summary>−1 a string (pulls only), 0 a rod (both ways), +1 a contact (pushes only).</summary>
        Public Sign As Integer
        ''' <summary>The contact being resolved or a lasting one (Poisson's rule gives back e times its impulse), not a link.</summary>
        Public IsContact As Boolean
        ''' <summary>A rod or taut string that the group held before the blow: its ends were not separating.</summary>
        Public Held As Boolean
        ''' <summary>The restitution of a contact being resolved, whose target is −this times the speed it arrives at.</summary>
        Public Restitution As Double
        Public Impulse As Double
    End Structure

    ''' <summary>Σ ½ m v² of the bodies of the blow, at their velocities so far (before it, or after it once resolved), J.</summary>
    Friend ReadOnly Property KineticEnergy As Double
        Get
            Dim sum = 0.0
            For i = 0 To _bodies.Count - 1
                sum += 0.5 * _bodies(i).Mass * _velocities(i).LengthSquared
            Next
            Return sum
        End Get
    End Property

    ''' <summary>Forgets the rows of the previous collision.</summary>
    Friend Sub Clear()
        _bodies.Clear()
        _velocities.Clear()
        _rows.Clear()
    End Sub

    Private Function IndexOf(body As Shape) As Integer
        If body Is Nothing OrElse body.IsFixed Then Return -1
        Dim i = _bodies.IndexOf(body)
        If i >= 0 Then Return i
        _bodies.Add(body)
        _velocities.Add(body.Velocity)
        Return _bodies.Count - 1
    End Function

    ''' <summary>The contact: <paramref name="a"/> touches <paramref name="b"/> (Nothing: a wall or a fixed body) with <paramref name="normal"/> from a towards b.</summary>
    Friend Sub AddContact(a As Shape, b As Shape, normal As Vector, restitution As Double)
        Dim row As New Row With {.A = IndexOf(a), .B = If(b Is Nothing, -1, IndexOf(b)), .U = normal, .Sign = 1, .IsContact = True, .Restitution = restitution}
        row.Target = ArrivalTarget(row)
        _rows.Add(row)
    End Sub

    ''' <summary>A lasting contact <paramref name="c"/> of a group whose bodies are <paramref name="bodies"/>: they may part, never press in.</summary>
    Friend Sub AddHeld(bodies As Shape(), c As Constraint)
        ' The constraint's u points from B to A; a row's from A to B.
        AddContact(bodies(c.A), If(c.B >= 0, bodies(c.B), Nothing), -c.UnitAt(bodies), 0)
    End Sub

    ''' <summary>
    ''' Every row motion <paramref name="m"/> holds, through the blow: its rods and taut strings, its lasting contacts,
    ''' and the locks of bodies two ties in line hold where they are.
    ''' </summary>
    Friend Sub AddHeldRowsOf(m As LinkedMotion)
        For Each l In m.HeldLinks
            AddLink(l)
        Next
        For Each c In m.HeldContacts
            AddHeld(m.Bodies, c)
        Next
        For Each c In m.HeldLocks
            AddLock(m.Bodies(c.A), c.Normal)
        Next
    End Sub

    ''' <summary>A body that two ties in line hold where it is (<see cref="TieLock"/>): it does not move along <paramref name="direction"/> through the blow.</summary>
    Friend Sub AddLock(body As Shape, direction As Vector)
        _rows.Add(New Row With {.A = IndexOf(body), .B = -1, .U = direction, .Target = 0, .Sign = 0, .Held = True})
    End Sub

    ''' <summary>A rod or a taut string that holds its length through the blow.</summary>
    Friend Sub AddLink(link As Link)
        Dim row = LinkRow(link, If(link.Kind = LinkKind.String, -1, 0), False)
        row.Held = True
        _rows.Add(row)
    End Sub

    ''' <summary>
    ''' A string at its full length that its group's motion holds slack: in a wedged blow it may snap taut at the
    ''' same instant, so it is a row that only pulls and, as a string going taut is a collision, gives back
    ''' restitution times its impulse like a contact (<see cref="ResolveWedged"/>).
    ''' </summary>
    Friend Sub AddStringAtLength(link As Link)
        _rows.Add(LinkRow(link, -1, True))
    End Sub

    ''' <summary>The row of a link along it, from end A to end B, asking for no stretch (<paramref name="sign"/> as <see cref="Row.Sign"/>).</summary>
    Private Function LinkRow(link As Link, sign As Integer, isContact As Boolean) As Row
        Return New Row With {.A = IndexOf(link.A), .B = IndexOf(link.B), .U = (link.EndB - link.EndA).Normalized(Vector.Zero), .Target = 0,
                             .Sign = sign, .IsContact = isContact}
    End Function

    Private Function SeparationSpeed(row As Row) As Double
        Return Vector.Dot(RelativeVelocity(row), row.U)
    End Function

    ''' <summary>Solves the rows and writes the new velocities to the bodies.</summary>
    Friend Sub Resolve()
        HoldRows()
        Solve()
        WriteVelocities()
    End Sub

    ''' <summary>
    ''' Solves the rows as one blow in two phases (Poisson's hypothesis), for bodies wedged among contacts that
    ''' pairwise blows pass back and forth for ever (a ball caged with no room between the ends of a rod): first
    ''' every contact only stops its approach (target 0), which projects the velocities onto those that approach
    ''' nowhere; then each contact (and string snapping taut) gives back <paramref name="restitution"/> times the
    ''' impulse it took, and what that sends into another contact is stopped again. The projection is orthogonal in
    ''' the kinetic-energy metric, so the energy after the first phase is the energy before less that of the change;
    ''' giving back at most all of the change (e ≤ 1) gains nothing, and stopping again only loses.
    ''' </summary>
    Friend Sub ResolveWedged(restitution As Double)
        _before.Clear()
        _before.AddRange(_velocities)
        HoldRows()
        For i = 0 To _rows.Count - 1
            Dim row = _rows(i)
            If row.IsContact Then row.Target = 0
            _rows(i) = row
        Next
        Solve()
        ' Nothing to give back: the projection is the blow.
        If restitution = 0 Then
            WriteVelocities()
            Return
        End If
        For i = 0 To _rows.Count - 1
            Dim row = _rows(i)
            If row.IsContact AndAlso row.Impulse <> 0 Then
                Dim give = restitution * row.Impulse
                If row.A >= 0 Then _velocities(row.A) -= row.U * (give * InverseMass(row.A))
                If row.B >= 0 Then _velocities(row.B) += row.U * (give * InverseMass(row.B))
            End If
        Next
        Solve()
        WriteVelocities()
    End Sub

    ''' <summary>
    ''' The wedged blow just resolved (<see cref="ResolveWedged"/>), solved again from the velocities it started from, with
    ''' the solve's tolerance (a part in 10¹² of the fastest body's speed) never above <paramref name="creepMetresPerSecond"/>.
    ''' The blow gathers every body of the groups it touches, but whether a contact is struck is judged by its own two
    ''' bodies' speeds: a wedged body left approaching a wall by a part in 10¹² of a fast body elsewhere in its group
    ''' is struck again at once. Writes the new velocities to the bodies.
    ''' </summary>
    Friend Sub ResolveWedgedAgain(restitution As Double, creepMetresPerSecond As Double)
        For i = 0 To _velocities.Count - 1
            _velocities(i) = _before(i)
        Next
        _creep = creepMetresPerSecond
        Try
            ResolveWedged(restitution)
        Finally
            _creep = Double.PositiveInfinity
        End Try
    End Sub

    Private Function InverseMass(i As Integer) As Double
        Return If(i >= 0, _bodies(i).InverseMass, 0)
    End Function

    ''' <summary>Newton's rule for a contact being resolved: it leaves at e times the speed it arrives at now (m/s; 0 when it does not approach).</summary>
    Private Function ArrivalTarget(row As Row) As Double
        Return -row.Restitution * Math.Min(SeparationSpeed(row), 0)
    End Function

    ''' <summary>
    ''' Puts the held links' separation speeds to 0 exactly: the velocities closest to those now (kinetic-energy metric)
    ''' at which no held link's ends separate or approach. That projection takes the energy of the change away and adds
    ''' none; left to the blow, a held row's speed s before it would do ½ λ s of work with the row's impulse λ (a rod
    ''' 2·10⁻⁸ m/s off, in line with a 1.5 t ball's string snapping taut on a 58 mg body, took 37 kN·s and gave 3·10⁻⁴ J).
    ''' </summary>
    Private Sub HoldRows()
        ' Most blows hold no link, or none whose ends move: they allocate nothing here.
        Dim heldCount = 0
        Dim moving = False
        For i = 0 To _rows.Count - 1
            If Not _rows(i).Held Then Continue For
            heldCount += 1
            If SeparationSpeed(_rows(i)) <> 0 Then moving = True
        Next
        If Not moving Then Return
        Dim rows(heldCount - 1) As ContactRow
        Dim k = 0
        For i = 0 To _rows.Count - 1
            Dim r = _rows(i)
            If Not r.Held Then Continue For
            rows(k) = New ContactRow(If(r.B >= 0, r.B, ContactRow.None), If(r.A >= 0, r.A, ContactRow.None), r.U, 0, True)
            k += 1
        Next
        SolveRows(rows, 0)
        ' The contacts struck give back the speeds they arrive at now.
        For i = 0 To _rows.Count - 1
            Dim r = _rows(i)
            If Not r.IsContact OrElse r.Held OrElse r.Restitution = 0 Then Continue For
            r.Target = ArrivalTarget(r)
            _rows(i) = r
        Next
    End Sub

    ''' <summary>
    ''' The velocities closest to those now (kinetic-energy metric) at which every row is met, and each row's
    ''' impulse (N·s, in the row's own sign). A row separating at s along u with target T is the solve's row
    ''' with value sign × (s − T) ≥ 0 (= 0 for a rod): the row's B end is the solve's A.
    ''' </summary>
    Private Sub Solve()
        If _rows.Count = 0 Then Return
        Dim rows(_rows.Count - 1) As ContactRow
        Dim largestTargetSpeed = 0.0
        For i = 0 To _rows.Count - 1
            Dim r = _rows(i)
            Dim s = If(r.Sign = 0, 1, r.Sign)
            ' Value s·(u·(v_B − v_A) − T): with the solve's A = this row's B and direction s·u.
            rows(i) = New ContactRow(If(r.B >= 0, r.B, ContactRow.None), If(r.A >= 0, r.A, ContactRow.None), r.U * s, -s * r.Target, r.Sign = 0)
            largestTargetSpeed = Math.Max(largestTargetSpeed, Math.Abs(r.Target))
        Next
        Dim forces = SolveRows(rows, largestTargetSpeed)
        For i = 0 To _rows.Count - 1
            Dim r = _rows(i)
            r.Impulse = If(r.Sign = 0, 1, r.Sign) * forces(i)
            _rows(i) = r
        Next
    End Sub

    ''' <summary>
    ''' Solves <paramref name="rows"/> (in the solve's own terms, on the bodies of the blow) from the velocities now
    ''' with <see cref="ContactSolve"/>, puts the velocities it finds in their place and returns each row's force
    ''' (N·s, in the solve's sign). Its tolerance is <see cref="ContactSolve.ApproachTolerance"/> times the fastest
    ''' body's speed or <paramref name="targetSpeedMetresPerSecond"/> (the largest target speed asked of a row),
    ''' whichever is more, and never above the creep a wedged blow may be solved again to (<see cref="ResolveWedgedAgain"/>).
    ''' </summary>
    Private Function SolveRows(rows As ContactRow(), targetSpeedMetresPerSecond As Double) As Double()
        Dim inverse = _bodies.Select(Function(b) b.InverseMass).ToArray()
        Dim scale = 0.0
        For Each v In _velocities
            scale = Math.Max(scale, v.Length)
        Next
        scale = Math.Max(scale, targetSpeedMetresPerSecond)
        Dim result(_bodies.Count - 1) As Vector
        Dim forces(rows.Length - 1) As Double
        _solve.Solve(inverse, _velocities, rows, Math.Min(ContactSolve.ApproachTolerance * scale, _creep), result, forces)
        For i = 0 To _bodies.Count - 1
            _velocities(i) = result(i)
        Next
        Return forces
    End Function

    ''' <summary>
    ''' Coulomb friction at the blow's own contact (the first added), once its normal impulse is known: the bodies'
    ''' slip across the contact is stopped if that takes at most <paramref name="staticCoefficient"/> times the normal
    ''' impulse, else <paramref name="kineticCoefficient"/> times it acts against the slip, never reversing it
    ''' (<see cref="ContactFriction.TangentialImpulse"/>). The other rows hold through it, as through the normal blow:
    ''' the end of a rod struck on a rough floor is stopped with the rod keeping its length, so the stop is solved with
    ''' the rows and one more asking for no slip. Friction given alone, the rod put right after by a blow of its own,
    ''' drove a light body on a rod back into the floor at the same instant, again and again.
    ''' Writes the new velocities to the bodies.
    ''' </summary>
    Friend Sub Rub(staticCoefficient As Double, kineticCoefficient As Double)
        If _rows.Count = 0 Then Return
        Dim row = _rows(0)
        If Not row.IsContact OrElse Not (row.Impulse > 0) Then Return
        Dim normalImpulse = row.Impulse
        Dim relative = RelativeVelocity(row)
        Dim slipVector = relative - row.U * Vector.Dot(relative, row.U)
        Dim slip = slipVector.Length
        Dim w = InverseMass(row.A) + InverseMass(row.B)
        If slip = 0 OrElse w = 0 Then Return
        Dim along = slipVector / slip
        Dim sliding = ContactFriction.TangentialImpulse(slip, 1 / w, normalImpulse, kineticCoefficient, kineticCoefficient)
        If _rows.Count = 1 Then
            Push(row, along, ContactFriction.TangentialImpulse(slip, 1 / w, normalImpulse, staticCoefficient, kineticCoefficient))
            WriteVelocities()
            Return
        End If
        Dim before = _velocities.ToList()
        Dim kinetic = KineticEnergy
        RubWithRows(row, along, normalImpulse, sliding, staticCoefficient)
        If KineticEnergy > kinetic Then
            ' The rows' answer to friction pressed the contact further, and its push, at the speed it parts with,
            ' gave back more than friction took: solved again with the contact only kept from approaching, where
            ' every row's target is nothing and the solve can only take energy away.
            Restore(before)
            Dim target = _rows(0).Target
            SetTarget(0, 0)
            RubWithRows(row, along, normalImpulse, sliding, staticCoefficient)
            SetTarget(0, target)
        End If
        WriteVelocities()
    End Sub

    ''' <summary>
    ''' Friction at contact <paramref name="row"/> (slipping along <paramref name="along"/> after a normal impulse of
    ''' <paramref name="normalImpulse"/>) with every row holding: stuck, with no slip, if the friction that takes is at
    ''' most <paramref name="staticCoefficient"/> times what the contact's row pushed in all; else the impulse
    ''' <paramref name="sliding"/> against the slip, and the rows put right with it, stopping the slip at most.
    ''' </summary>
    Private Sub RubWithRows(row As Row, along As Vector, normalImpulse As Double, sliding As Double, staticCoefficient As Double)
        Dim before = _velocities.ToList()
        ' Stuck: the friction is the new row's impulse; the push, what the contact's row took in both solves.
        _rows.Add(New Row With {.A = row.A, .B = row.B, .U = along, .Target = 0, .Sign = 0})
        Solve()
        Dim friction = -_rows(_rows.Count - 1).Impulse
        Dim pushed = normalImpulse + _rows(0).Impulse
        _rows.RemoveAt(_rows.Count - 1)
        If friction <= staticCoefficient * pushed Then Return
        Dim stuck = _velocities.ToList()
        Restore(before)
        Push(row, along, sliding)
        Solve()
        ' It would have reversed the slip: it stops instead.
        If Vector.Dot(RelativeVelocity(row), along) < 0 Then Restore(stuck)
    End Sub

    ''' <summary>Puts back the velocities <paramref name="saved"/> (one for each body of the blow, as <c>_velocities.ToList()</c> gave them).</summary>
    Private Sub Restore(saved As List(Of Vector))
        For i = 0 To saved.Count - 1
            _velocities(i) = saved(i)
        Next
    End Sub

    ''' <summary>Sets row <paramref name="i"/>'s target separation speed, m/s.</summary>
    Private Sub SetTarget(i As Integer, target As Double)
        Dim r = _rows(i)
        r.Target = target
        _rows(i) = r
    End Sub

    ''' <summary>How fast row <paramref name="row"/>'s B end moves relative to its A end, m/s.</summary>
    Private Function RelativeVelocity(row As Row) As Vector
        Return If(row.B >= 0, _velocities(row.B), Vector.Zero) - If(row.A >= 0, _velocities(row.A), Vector.Zero)
    End Function

    ''' <summary>An impulse <paramref name="jt"/> (N·s) against the slip <paramref name="along"/> of row <paramref name="row"/>'s ends.</summary>
    Private Sub Push(row As Row, along As Vector, jt As Double)
        If row.A >= 0 Then _velocities(row.A) += along * (jt * InverseMass(row.A))
        If row.B >= 0 Then _velocities(row.B) -= along * (jt * InverseMass(row.B))
    End Sub

    Private Sub WriteVelocities()
        For i = 0 To _bodies.Count - 1
            _bodies(i).Velocity = _velocities(i)
        Next
    End Sub
End Class
