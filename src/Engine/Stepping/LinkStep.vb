Option Strict On

''' <summary>
''' What the world's links do in one step of a stepping solver (see links.md, "Links in a stepping solver").
''' <list type="bullet">
''' <item>Springs are forces: the elastic pull k (d − L) along the line of the ends, read from the positions
''' at the start of the step, is added to each end's acceleration as F/m. The damping c ḋ is taken at the
''' step's new velocities (<see cref="Damp"/>), so it only slows the ends however strong it is for the step;
''' taken as a force at the step's start it would reverse ḋ and make it c W h − 1 times larger at every step
''' once c W h &gt; 2 (W = w_A + w_B: a light body on a strongly damped spring), growing without bound to
''' infinity and NaN.</item>
''' <item>Rods and taut strings are constraints, applied after the bodies have moved (SHAKE and RATTLE, as
''' molecular dynamics does it): first the ends are pulled back to the length along the link's direction
''' at the start of the step, each in proportion to its inverse mass (so the centre of mass stays where
''' it was), and their velocities get the same change divided by the step, as if the pull had acted
''' through the step; then the velocities along the link's new direction are corrected by an impulse
''' along it. A rod's ends then neither approach nor separate. Correcting along the old direction,
''' with the velocities, is what keeps the energy from leaking away step by step (a plain projection
''' back onto the circle loses a fraction of order h² of the kinetic energy at every step).
''' A string only pulls: it acts only when the ends are further apart than its length. A string that
''' was taut at the start of the step stays taut (the ends stop separating); one that was slack snaps
''' taut, and the ends then separate at −e times the speed at which they arrived, e the world's
''' restitution, as in a collision.</item>
''' </list>
''' Both corrections are solved by Gauss–Seidel sweeps over the links (exact in one sweep for a single
''' link; a chain converges over a few). A fixed body, an anchor point and the dragged body do not move
''' (their inverse mass counts as 0).
''' </summary>
Friend NotInheritable Class LinkStep
    ' Sweeps of the position and velocity corrections at most; a chain of links converges long before.
    Private Const MaxSweeps As Integer = 100
    ' Positions are put back to within this fraction of each length, and velocities to this fraction of the largest correction.
    Private Const Tolerance As Double = 0.000000000001
    ' A string within this fraction of its length at the start of a step is taut, not snapping taut.
    Private Const TautFraction As Double = 0.000000001

    Private _links As Link() = Array.Empty(Of Link)()
    ' Index of each link's ends in World.Movables; −1 for an anchor, a fixed body or the dragged body.
    Private _indexA As Integer() = Array.Empty(Of Integer)()
    Private _indexB As Integer() = Array.Empty(Of Integer)()
    Private _inverseMassA As Double() = Array.Empty(Of Double)()
    Private _inverseMassB As Double() = Array.Empty(Of Double)()
    Private _wasTaut As Boolean() = Array.Empty(Of Boolean)()
    Private _impulse As Double() = Array.Empty(Of Double)()
    Private _target As Double() = Array.Empty(Of Double)()
    Private _normal As Vector() = Array.Empty(Of Vector)()
    Private _active As Boolean() = Array.Empty(Of Boolean)()
    ' Each link's unit direction from A to B at the start of the step, and the position pull it gave (kg·m: impulse × step).
    Private _startNormal As Vector() = Array.Empty(Of Vector)()
    Private _positionPull As Double() = Array.Empty(Of Double)()
    ' The shift (m per unit inverse mass, kg⁻¹) the position pull gave end A; end B got the opposite.
    Private _shift As Vector() = Array.Empty(Of Vector)()
    ' A snapping string's speed of separation (m/s) before any correction.
    Private _arrival As Double() = Array.Empty(Of Double)()

    ''' <summary>Whether the world has links at all (read at the last <see cref="Prepare"/>).</summary>
    Friend ReadOnly Property HasLinks As Boolean
        Get
            Return _links.Length > 0
        End Get
    End Property

    ''' <summary>Reads the world's links and where their bodies sit in <see cref="World.Movables"/>; once per advance.</summary>
    Friend Sub Prepare(world As World)
        Dim links = world.Links
        If links.Count = 0 Then
            If _links.Length > 0 Then _links = Array.Empty(Of Link)()
            Return
        End If
        Dim n = links.Count
        _links = New Link(n - 1) {}
        _indexA = New Integer(n - 1) {}
        _indexB = New Integer(n - 1) {}
        _inverseMassA = New Double(n - 1) {}
        _inverseMassB = New Double(n - 1) {}
        _wasTaut = New Boolean(n - 1) {}
        _impulse = New Double(n - 1) {}
        _target = New Double(n - 1) {}
        _normal = New Vector(n - 1) {}
        _active = New Boolean(n - 1) {}
        _startNormal = New Vector(n - 1) {}
        _positionPull = New Double(n - 1) {}
        _shift = New Vector(n - 1) {}
        _arrival = New Double(n - 1) {}
        Dim index As New Dictionary(Of Shape, Integer)
        Dim movables = world.Movables
        For i = 0 To movables.Count - 1
            If movables(i) IsNot world.DraggedBody Then index(movables(i)) = i
        Next
        For k = 0 To n - 1
            Dim l = links(k)
            _links(k) = l
            _indexA(k) = IndexOf(index, l.A)
            _indexB(k) = IndexOf(index, l.B)
            _inverseMassA(k) = If(_indexA(k) >= 0, l.A.InverseMass, 0)
            _inverseMassB(k) = If(_indexB(k) >= 0, l.B.InverseMass, 0)
        Next
    End Sub

    Private Shared Function IndexOf(index As Dictionary(Of Shape, Integer), body As Shape) As Integer
        Dim i As Integer
        If body Is Nothing OrElse Not index.TryGetValue(body, i) Then Return -1
        Return i
    End Function

    ''' <summary>
    ''' Adds each spring's elastic pull, divided by the mass, to the accelerations (m/s², indexed like
    ''' <see cref="World.Movables"/>), from the positions now; and notes which strings are taut now, before
    ''' the step. The springs' damping is not among them: see <see cref="Damp"/>.
    ''' </summary>
    Friend Sub AddAccelerations(acceleration As Vector())
        For k = 0 To _links.Length - 1
            Dim l = _links(k)
            If l.Kind <> LinkKind.Spring Then
                Dim r = l.EndB - l.EndA
                Dim d = r.Length
                _startNormal(k) = If(d > 0, r / d, Vector.Zero)
                _wasTaut(k) = l.Kind = LinkKind.Rod OrElse d >= l.Length * (1 - TautFraction)
                Continue For
            End If
            Dim force = ElasticForce(l)
            If _indexA(k) >= 0 Then acceleration(_indexA(k)) += force * _inverseMassA(k)
            If _indexB(k) >= 0 Then acceleration(_indexB(k)) -= force * _inverseMassB(k)
        Next
    End Sub

    ''' <summary>The kinetic energy (J) that strings snapping taut with e &lt; 1 took in the last <see cref="Constrain"/>.</summary>
    Friend Property SnapLoss As Double

    ''' <summary>Σ ½ m v² (J) of the movable bodies at the ends of the links that act in this step.</summary>
    Private Function KineticOfActive(bodies As IReadOnlyList(Of Shape)) As Double
        Dim seen As New HashSet(Of Integer)
        Dim sum = 0.0
        For k = 0 To _links.Length - 1
            If Not _active(k) Then Continue For
            For Each i In {_indexA(k), _indexB(k)}
                If i >= 0 AndAlso seen.Add(i) Then sum += bodies(i).KineticEnergy
            Next
        Next
        Return sum
    End Function

    ''' <summary>
    ''' What the springs' damping takes over a step of <paramref name="h"/> s, J, as the solvers book it: for each
    ''' damped spring, what the damping alone would take from the stretch rate ḋ the ends have now (those the last
    ''' step's contacts left) in that time, ḋ²/(2W) (1 − e^(−2 c W h)) with W = w_A + w_B: c ḋ² h for a weak damping,
    ''' and never more than the kinetic energy of the stretching, ḋ²/(2W), however strong. Not what
    ''' <see cref="Damp"/> takes from a step's kicked velocities: a body pressed against a wall by a spring is kicked
    ''' into it at every step and the contact takes that back, so at rest the damping takes nothing. (A spring
    ''' between bodies that cannot move, W = 0, takes c ḋ² h.)
    ''' </summary>
    Friend Function DampingLoss(h As Double) As Double
        Dim loss = 0.0
        For k = 0 To _links.Length - 1
            Dim l = _links(k)
            If l.Kind <> LinkKind.Spring OrElse Not (l.Damping > 0) Then Continue For
            Dim rate = l.StretchRate
            Dim w = _inverseMassA(k) + _inverseMassB(k)
            Dim x = 2 * l.Damping * w * h
            ' 1 − e^(−x), written so that it keeps its digits when x is small.
            Dim share = If(x < 0.00001, x * (1 - x / 2), 1 - Math.Exp(-x))
            loss += If(w > 0, rate * rate / (2 * w) * share, l.Damping * rate * rate * h)
        Next
        Return loss
    End Function

    ''' <summary>
    ''' The elastic force on end A, N: k (d − L) along the unit vector from A to B (so positive pulls A
    ''' towards B). Written as k (d − L)/d times the vector A→B, so a zero-length spring needs no
    ''' direction at d = 0; a spring of positive length with its ends together has no direction, and no force.
    ''' </summary>
    Private Shared Function ElasticForce(l As Link) As Vector
        Dim r = l.EndB - l.EndA
        Dim d = r.Length
        If d = 0 Then Return Vector.Zero
        Return r * (l.Stiffness * (d - l.Length) / d)
    End Function

    ''' <summary>
    ''' The springs' damping over a step of <paramref name="duration"/> s, taken at the step's new velocities
    ''' (backward Euler, as drag is): along each damped spring's line n (at the ends' positions now) the stretch rate
    ''' ḋ = (v_B − v_A)·n that the other forces would give becomes ḋ' = ḋ / (1 + c W t) (W = w_A + w_B), by equal
    ''' and opposite impulses along n (momentum kept). That only ever slows the stretching, however large c W t is
    ''' (a light body on a strongly damped spring), and where the spring's pull has the ends creeping (the overdamped
    ''' limit) it gives them the creep F/c at which the pull and the damping balance. Springs sharing a body are
    ''' taken one after another. <paramref name="velocities"/> (m/s) are indexed like <see cref="World.Movables"/>,
    ''' and changed in place.
    ''' </summary>
    Friend Sub Damp(duration As Double, velocities As Vector())
        For k = 0 To _links.Length - 1
            Dim l = _links(k)
            If l.Kind <> LinkKind.Spring OrElse Not (l.Damping > 0) Then Continue For
            Dim w = _inverseMassA(k) + _inverseMassB(k)
            If w = 0 Then Continue For
            Dim r = l.EndB - l.EndA
            Dim d = r.Length
            If d = 0 Then Continue For
            Dim n = r / d
            Dim va = If(_indexA(k) >= 0, velocities(_indexA(k)), Vector.Zero)
            Dim vb = If(_indexB(k) >= 0, velocities(_indexB(k)), Vector.Zero)
            Dim rate = Vector.Dot(vb - va, n)
            If rate = 0 Then Continue For
            Dim after = rate / (1 + l.Damping * w * duration)
            ' The impulse (N·s) pulling the ends together that takes the stretch rate from rate to after.
            Dim impulse = (rate - after) / w
            If _indexA(k) >= 0 Then velocities(_indexA(k)) += n * (impulse * _inverseMassA(k))
            If _indexB(k) >= 0 Then velocities(_indexB(k)) -= n * (impulse * _inverseMassB(k))
        Next
    End Sub

    ''' <summary>Whether any spring has damping (read at the last <see cref="Prepare"/>).</summary>
    Friend ReadOnly Property HasDamping As Boolean
        Get
            For Each l In _links
                If l.Kind = LinkKind.Spring AndAlso l.Damping > 0 Then Return True
            Next
            Return False
        End Get
    End Property

    ''' <summary>
    ''' After the bodies have moved by a step of <paramref name="h"/> s: puts rods and strings back to
    ''' their lengths and corrects the velocities along them. Marks in <paramref name="touched"/> (when
    ''' given) every body it moved or pushed.
    ''' </summary>
    Friend Sub Constrain(h As Double, restitution As Double, bodies As IReadOnlyList(Of Shape), touched As Boolean())
        SnapLoss = 0
        If _links.Length = 0 Then Return
        ProjectPositions(h, bodies)
        CorrectVelocities(h, restitution, bodies, touched)
    End Sub

    Private Sub ProjectPositions(h As Double, bodies As IReadOnlyList(Of Shape))
        For k = 0 To _links.Length - 1
            _positionPull(k) = 0
            _shift(k) = Vector.Zero
            _arrival(k) = 0
            Dim l = _links(k)
            If l.Kind = LinkKind.String AndAlso Not _wasTaut(k) AndAlso l.Extension > 0 Then
                _normal(k) = (l.EndB - l.EndA) / l.Distance
                _arrival(k) = StretchRate(k, bodies)
            End If
        Next
        For sweep = 1 To MaxSweeps
            Dim worst = 0.0
            For k = 0 To _links.Length - 1
                Dim l = _links(k)
                If l.Kind = LinkKind.Spring Then Continue For
                Dim w = _inverseMassA(k) + _inverseMassB(k)
                If w = 0 Then Continue For
                Dim r = l.EndB - l.EndA
                Dim d2 = r.LengthSquared
                Dim excess2 = d2 - l.Length * l.Length
                ' A string that was taut is held like a rod until its pull is known (it is let go if
                ' that pull would be a push); a slack one acts only when the ends are too far apart.
                If d2 = 0 OrElse (l.Kind = LinkKind.String AndAlso Not _wasTaut(k) AndAlso excess2 <= 0) Then Continue For
                worst = Math.Max(worst, Math.Abs(excess2) / (l.Length * l.Length))
                ' Pull the ends together along the start direction n by s, with |r − s n| = L: the root
                ' near 0, written without cancellation. When that line misses the circle, along r itself.
                Dim n = _startNormal(k)
                Dim p = Vector.Dot(r, n)
                Dim discriminant = p * p - excess2
                Dim pull As Double
                If discriminant < 0 OrElse p <= 0 Then
                    n = r / Math.Sqrt(d2)
                    pull = Math.Sqrt(d2) - l.Length
                Else
                    pull = excess2 / (p + Math.Sqrt(discriminant))
                End If
                Dim share = pull / w
                If _indexA(k) >= 0 Then Move(bodies(_indexA(k)), n * (share * _inverseMassA(k)), h, _wasTaut(k))
                If _indexB(k) >= 0 Then Move(bodies(_indexB(k)), n * (-share * _inverseMassB(k)), h, _wasTaut(k))
                If _wasTaut(k) Then
                    _positionPull(k) += share
                    _shift(k) += n * share
                End If
            Next
            If worst <= Tolerance Then Exit For
        Next
    End Sub

    ''' <summary>
    ''' Moves a body by <paramref name="shift"/> (m); for a link that was already taut, also changes its
    ''' velocity by shift/h, as a pull acting through the step would have. A string that snaps taut only
    ''' moves it: its impulse comes from the restitution rule.
    ''' </summary>
    Private Shared Sub Move(body As Shape, shift As Vector, h As Double, withVelocity As Boolean)
        body.Position += shift
        If withVelocity Then body.Velocity += shift / h
    End Sub

    Private Sub CorrectVelocities(h As Double, restitution As Double, bodies As IReadOnlyList(Of Shape), touched As Boolean())
        ' Which links act, along which direction, and the speed of separation (m/s) each must end with.
        Dim any = False
        For k = 0 To _links.Length - 1
            Dim l = _links(k)
            _impulse(k) = 0
            _active(k) = False
            If l.Kind = LinkKind.Spring Then Continue For
            Dim w = _inverseMassA(k) + _inverseMassB(k)
            Dim r = l.EndB - l.EndA
            Dim d = r.Length
            If w = 0 OrElse d = 0 Then
                l.SetTension(0)
                Continue For
            End If
            If l.Kind = LinkKind.String AndAlso Not _wasTaut(k) AndAlso d < l.Length * (1 - TautFraction) Then
                l.SetTension(0)
                Continue For
            End If
            _normal(k) = r / d
            If Not _wasTaut(k) Then
                ' Snapping taut: like a collision, the ends leave at −e times the speed they arrived.
                _target(k) = -restitution * Math.Max(_arrival(k), 0)
            Else
                _target(k) = 0
            End If
            _active(k) = True
            any = True
            If touched IsNot Nothing Then
                If _indexA(k) >= 0 Then touched(_indexA(k)) = True
                If _indexB(k) >= 0 Then touched(_indexB(k)) = True
            End If
        Next
        If Not any Then Return
        ' A string snapping taut with e < 1 is an inelastic collision: what the sweeps take from the kinetic energy of
        ' the bodies they move is counted (SnapLoss), only then, so a rod's or taut string's own correction is not.
        Dim snapping = False
        If restitution < 1 Then
            For k = 0 To _links.Length - 1
                If _active(k) AndAlso Not _wasTaut(k) Then snapping = True
            Next
        End If
        Dim kineticBefore = If(snapping, KineticOfActive(bodies), 0.0)
        For sweep = 1 To MaxSweeps
            Dim largest = 0.0, change = 0.0
            For k = 0 To _links.Length - 1
                If Not _active(k) Then Continue For
                Dim w = _inverseMassA(k) + _inverseMassB(k)
                Dim delta = (StretchRate(k, bodies) - _target(k)) / w
                ' A string that snaps taut can only pull (one that was taut is checked after the sweeps).
                If _links(k).Kind = LinkKind.String AndAlso Not _wasTaut(k) Then delta = Math.Max(delta, -_impulse(k))
                _impulse(k) += delta
                ApplyImpulse(k, delta, bodies)
                largest = Math.Max(largest, Math.Abs(_impulse(k)) * w)
                change = Math.Max(change, Math.Abs(delta) * w)
            Next
            If change <= Tolerance * largest Then Exit For
        Next
        If snapping Then SnapLoss = Math.Max(kineticBefore - KineticOfActive(bodies), 0)
        For k = 0 To _links.Length - 1
            If Not _active(k) Then Continue For
            ' The pull that gives this impulse over the step, N.
            Dim tension = (_impulse(k) + _positionPull(k) / h) / h
            If _links(k).Kind = LinkKind.String AndAlso _wasTaut(k) AndAlso tension < 0 Then
                ' Holding the length would take a push: the string goes slack instead.
                Release(k, h, bodies)
                tension = 0
            End If
            _links(k).SetTension(tension)
        Next
    End Sub

    ''' <summary>
    ''' Takes back what a taut string did in this step, because it would have pushed: the ends go on as if
    ''' it were slack. Deciding by the sign of the pull, not by whether the ends came closer, is what puts
    ''' the moment of going slack where the tension really falls to zero: with semi-implicit Euler the free
    ''' step moves a body g h² instead of ½ g h² towards the ground, so the ends come closer already where
    ''' v² &lt; 2 g y (y the height above the anchor) instead of v² &lt; g y. If rounding or that first-order
    ''' error leaves the ends a little further apart than the length, they are put back at it (positions
    ''' only, a correction of order h²).
    ''' </summary>
    Private Sub Release(k As Integer, h As Double, bodies As IReadOnlyList(Of Shape))
        ApplyImpulse(k, -_impulse(k), bodies)
        _impulse(k) = 0
        Dim shift = _shift(k)
        If _indexA(k) >= 0 Then Move(bodies(_indexA(k)), shift * -_inverseMassA(k), h, True)
        If _indexB(k) >= 0 Then Move(bodies(_indexB(k)), shift * _inverseMassB(k), h, True)
        Dim l = _links(k)
        Dim r = l.EndB - l.EndA
        Dim d = r.Length
        Dim w = _inverseMassA(k) + _inverseMassB(k)
        If d > l.Length Then
            Dim n = r / d
            Dim share = (d - l.Length) / w
            If _indexA(k) >= 0 Then bodies(_indexA(k)).Position += n * (share * _inverseMassA(k))
            If _indexB(k) >= 0 Then bodies(_indexB(k)).Position -= n * (share * _inverseMassB(k))
        End If
    End Sub

    ''' <summary>The speed at which link k's ends separate along its direction, m/s.</summary>
    Private Function StretchRate(k As Integer, bodies As IReadOnlyList(Of Shape)) As Double
        Dim va = If(_indexA(k) >= 0, bodies(_indexA(k)).Velocity, Vector.Zero)
        Dim vb = If(_indexB(k) >= 0, bodies(_indexB(k)).Velocity, Vector.Zero)
        Return Vector.Dot(vb - va, _normal(k))
    End Function

    ''' <summary>An impulse of <paramref name="impulse"/> N·s pulling link k's ends together.</summary>
    Private Sub ApplyImpulse(k As Integer, impulse As Double, bodies As IReadOnlyList(Of Shape))
        Dim n = _normal(k)
        If _indexA(k) >= 0 Then
            Dim a = bodies(_indexA(k))
            a.Velocity += n * (impulse * _inverseMassA(k))
        End If
        If _indexB(k) >= 0 Then
            Dim b = bodies(_indexB(k))
            b.Velocity -= n * (impulse * _inverseMassB(k))
        End If
    End Sub
End Class
