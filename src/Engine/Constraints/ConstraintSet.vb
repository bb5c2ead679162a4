Option Strict On

''' <summary>
''' The forces with which a group's held constraints (rods, taut strings, lasting contacts: <see cref="Constraint"/>)
''' keep ψ = 0, and the projection that puts a drifted state back on them (docs/links.md, "Chains", and
''' docs/contact.md). A state array holds per body x, y, vx, vy (m, m/s); an accelerations array has the same
''' layout, with the accelerations in the velocity places. Constraint i's force λ (N) acts on A as +λu and on B
''' as −λu. Holding ψ = 0 means ψ̈ = 0, where ψ̈ = u·(a_A − a_B) + κ; writing the accelerations as the free ones
''' plus the forces ÷ mass gives one linear equation per constraint, M λ = u·(a_B − a_A)_free − κ, with
''' M_ij = (u_i·u_j) Σ σ_i σ_j w_p over the bodies p the two share (w_p the inverse mass, σ = −1 at end A and
''' +1 at end B). M is J W Jᵀ, symmetric and positive definite while no constraint is redundant (the group's
''' contacts are chosen by the complementarity solve, which keeps only independent ones), so it is solved by
''' Cholesky's method. Which constraints share which bodies never changes, so those sums are worked out once;
''' the buffers are reused, so one instance serves one motion at a time.
''' </summary>
Friend NotInheritable Class ConstraintSet
    Private ReadOnly _rows As Constraint()
    Private ReadOnly _inverseMass As Double()
    ' Σ σ_i σ_j w_p over the shared bodies, for i ≥ j; zero where constraints i and j share none.
    Private ReadOnly _shared As Double()()
    Private ReadOnly _nx As Double(), _ny As Double(), _factor As Double()()
    ' Friction: the force directions (where a sliding contact's leans back from its normal), and the general
    ' (unsymmetric) matrix and its pivots when any row slides.
    Private ReadOnly _fx As Double(), _fy As Double()
    Private ReadOnly _slides As Boolean
    Private ReadOnly _general As Double(,)
    Private ReadOnly _independence As Double
    ' Whether the bodies the rows move differ in inverse mass by more than SpreadRatio (see SolveSpread).
    Private ReadOnly _spread As Boolean
    ' When not Nothing (AccelerationRounding), the spread solve adds here the size of every term it sums into each
    ' acceleration (m/s², laid out as the state).
    Private _termSizes As Double()
    ' The spacing of doubles just above 1.
    Private Const UnitRoundoff As Double = 0.00000000000000022204460492503131
    ' Past this ratio of inverse masses the forces are solved in a basis of the rows made orthogonal slot by slot:
    ' the plain solve loses about its logarithm in digits.
    Private Const SpreadRatio As Double = 1000000.0
    ' A pivot of the plain factorization below this fraction of its row's own size has lost half its digits.
    Private Const WellFactored As Double = 0.00000001

    ''' <summary>The fraction of its own size (squared) below which what a constraint adds to those before it counts as nothing.</summary>
    Friend Const DefaultIndependence As Double = 0.000000000001

    ''' <summary>
    ''' The constraints of a group whose bodies have the given inverse masses (1/kg, 0 for a body that cannot move).
    ''' A constraint counts as depending on those before it (the solve refuses) when what it adds to their span is
    ''' below <paramref name="independence"/> of its own size (squared).
    ''' </summary>
    Friend Sub New(rows As Constraint(), inverseMass As Double(), Optional independence As Double = DefaultIndependence)
        _independence = independence
        _rows = rows
        _inverseMass = inverseMass
        Dim m = rows.Length
        _nx = New Double(m - 1) {}
        _ny = New Double(m - 1) {}
        _fx = New Double(m - 1) {}
        _fy = New Double(m - 1) {}
        _slides = rows.Any(Function(r) r.Sliding <> 0)
        If _slides Then
            _general = New Double(m - 1, m - 1) {}
        End If
        _spread = IsSpread(rows, inverseMass)
        _shared = New Double(m - 1)() {}
        _factor = New Double(m - 1)() {}
        For i = 0 To m - 1
            _shared(i) = New Double(i) {}
            _factor(i) = New Double(i) {}
            For j = 0 To i
                _shared(i)(j) = SharedInverseMass(rows(i), rows(j), inverseMass)
            Next
        Next
    End Sub

    ''' <summary>Whether the bodies the rows move differ in inverse mass by more than <see cref="SpreadRatio"/> (see <see cref="IsSpread"/>).</summary>
    Friend ReadOnly Property Spread As Boolean
        Get
            Return _spread
        End Get
    End Property

    ''' <summary>The constraints, in the order of the forces.</summary>
    Friend ReadOnly Property Rows As Constraint()
        Get
            Return _rows
        End Get
    End Property

    ''' <summary>
    ''' How far each component of the accelerations that <see cref="Tensions"/> finds at <paramref name="state"/> may be
    ''' off by rounding alone (m/s², laid out as the state; <paramref name="free"/>, the free accelerations, is used up):
    ''' one unit in the last place of the sum of the sizes of the terms added into it. Among bodies of very different
    ''' masses (the spread solve) a light body's acceleration can be the small sum of great terms: a 2 µg ball among
    ''' bodies of up to 755 t came out as −31.72381591796875 m/s², then −31.7237548828125 at positions 4·10⁻¹⁶ of
    ''' themselves away, in steps of 2⁻¹⁴ m/s². Elsewhere nothing is counted: every component is 0.
    ''' </summary>
    Friend Function AccelerationRounding(state As Double(), free As Double()) As Double()
        Dim sizes(state.Length - 1) As Double
        _termSizes = sizes
        Try
            Tensions(state, free)
        Finally
            _termSizes = Nothing
        End Try
        For i = 0 To sizes.Length - 1
            sizes(i) *= UnitRoundoff
        Next
        Return sizes
    End Function

    ''' <summary>
    ''' The constraints' forces (N) for <paramref name="state"/>, with <paramref name="accelerations"/> holding the
    ''' free accelerations (gravity, springs) on entry and, on return, those plus the forces ÷ mass.
    ''' </summary>
    Friend Function Tensions(state As Double(), accelerations As Double()) As Double()
        Dim m = _rows.Length
        Dim lambda(m - 1) As Double
        If m = 0 Then Return lambda
        ' λ holds the curvatures until each row's right-hand side is made of it.
        MeasureNormals(state, curvatures:=lambda)
        For i = 0 To m - 1
            Dim c = _rows(i)
            Dim u = New Vector(_nx(i), _ny(i))
            Dim f = c.ForceDirection(u)
            _fx(i) = f.X
            _fy(i) = f.Y
            Dim relative = AccelerationB(accelerations, c) - Acceleration(accelerations, c.A)
            lambda(i) = Vector.Dot(u, relative) - lambda(i)
        Next
        If _slides Then
            ' A sliding contact's force is not along its normal: M_ij = (u_i·f_j) Σ σσw is not symmetric.
            SolveGeneral(lambda)
            ApplyForces(accelerations, lambda)
        ElseIf NeedsSpreadSolve() Then
            SolveSpread(lambda, accelerations)
        Else
            Solve(lambda)
            Apply(accelerations, lambda, 2)
        End If
        Return lambda
    End Function

    ''' <summary>
    ''' Solves M λ = <paramref name="b"/> in place, and adds the forces ÷ mass to <paramref name="accelerations"/>, for
    ''' rows on bodies of very different masses. A 2 mg ball wedged in a corner under a 187 t one: in the metric of
    ''' M = J W Jᵀ their pair's row is almost all the light ball's part, and the heavy ball's part, which alone
    ''' holds it up, is lost to rounding (the light ball's forces, 10¹¹ m/s² each, cancel to nothing). So the rows
    ''' are first made orthogonal with every body slot weighing the same (Gram–Schmidt: Q = T J, T unit lower
    ''' triangular); M' = Q W Qᵀ = T M Tᵀ is solved for μ = T⁻ᵀ λ, the accelerations are W Qᵀ μ (no great forces
    ''' cancelling), and λ = Tᵀ μ. The wedged ball's rows are then its own, the heavy ball's row is its own, and M'
    ''' is as well conditioned as the bodies' own parts.
    ''' </summary>
    Private Sub SolveSpread(b As Double(), accelerations As Double())
        Dim m = _rows.Length, n = _inverseMass.Length, slots = 2 * n
        Dim q(m - 1)() As Double, sizes(m - 1) As Double
        ' support(i): the movable bodies on which Q_i may not be zero, in increasing order. Elsewhere it is exactly
        ' zero, so the sums below, taken over a support, add up the same terms in the same order as over every body
        ' and give the same result to the last bit, and rows that share no body (most of a pile's) cost nothing.
        ' A body that cannot move is in no support: nothing reads its slots.
        Dim support(m - 1)() As Integer
        Dim marked(n - 1) As Boolean
        ' taken(i)(j): how much of Q_j was taken from row i (the strictly lower part C of T⁻¹ = I + C).
        Dim taken(m - 1)() As Double
        For i = 0 To m - 1
            Dim r = _rows(i)
            Dim row(slots - 1) As Double
            row(2 * r.A) = _nx(i)
            row(2 * r.A + 1) = _ny(i)
            If r.B >= 0 Then
                row(2 * r.B) -= _nx(i)
                row(2 * r.B + 1) -= _ny(i)
            End If
            If _inverseMass(r.A) > 0 Then marked(r.A) = True
            If r.B >= 0 AndAlso _inverseMass(r.B) > 0 Then marked(r.B) = True
            Dim size = MassMetric.Unit(row, row, MarkedBodies(marked))
            taken(i) = New Double(m - 1) {}
            ' Twice over: one pass of Gram–Schmidt can leave rounding's part of the span behind.
            For pass = 1 To 2
                For j = 0 To i - 1
                    Dim bodies = support(j)
                    If Not Shares(bodies, marked) Then Continue For
                    Dim p = MassMetric.Unit(row, q(j), bodies) / sizes(j)
                    If p = 0 Then Continue For
                    taken(i)(j) += p
                    Dim qj = q(j)
                    For Each k In bodies
                        row(2 * k) -= p * qj(2 * k)
                        row(2 * k + 1) -= p * qj(2 * k + 1)
                        marked(k) = True
                    Next
                Next
            Next
            support(i) = MarkedBodies(marked)
            Array.Clear(marked, 0, n)
            sizes(i) = MassMetric.Unit(row, row, support(i))
            If Not (sizes(i) > _independence * size) Then Throw New InvalidOperationException("the constraints of a group hold its bodies in more ways than they can move (a constraint is redundant)")
            q(i) = row
        Next
        ' b' = T b, from (I + C) b' = b.
        For i = 0 To m - 1
            For j = 0 To i - 1
                b(i) -= taken(i)(j) * b(j)
            Next
        Next
        ' M' by Cholesky's method, row by row, as the general solve factors M.
        Dim f(m - 1)() As Double
        For i = 0 To m - 1
            Dim li(i) As Double
            For j = 0 To i - 1
                li(j) = MassMetric.Weighted(_inverseMass, q(i), q(j), If(support(i).Length < support(j).Length, support(i), support(j)))
            Next
            If Not FactorRow(f, li, i, MassMetric.Weighted(_inverseMass, q(i), q(i), support(i)), _independence) Then Throw New InvalidOperationException("the constraints of a group hold its bodies in more ways than they can move (a constraint is redundant)")
            f(i) = li
        Next
        SolveFactored(f, b, m)
        ' The accelerations W Qᵀ μ; then λ = Tᵀ μ, from (I + C)ᵀ λ = μ.
        For i = 0 To m - 1
            For Each k In support(i)
                Dim w = _inverseMass(k)
                accelerations(4 * k + 2) += w * b(i) * q(i)(2 * k)
                accelerations(4 * k + 3) += w * b(i) * q(i)(2 * k + 1)
                If _termSizes IsNot Nothing Then
                    _termSizes(4 * k + 2) += Math.Abs(w * b(i) * q(i)(2 * k))
                    _termSizes(4 * k + 3) += Math.Abs(w * b(i) * q(i)(2 * k + 1))
                End If
            Next
        Next
        For i = m - 1 To 0 Step -1
            For k = i + 1 To m - 1
                b(i) -= taken(k)(i) * b(k)
            Next
        Next
    End Sub

    ''' <summary>The bodies marked in <paramref name="marked"/>, in increasing order.</summary>
    Private Shared Function MarkedBodies(marked As Boolean()) As Integer()
        Dim count = 0
        For k = 0 To marked.Length - 1
            If marked(k) Then count += 1
        Next
        Dim bodies(count - 1) As Integer
        count = 0
        For k = 0 To marked.Length - 1
            If marked(k) Then
                bodies(count) = k
                count += 1
            End If
        Next
        Return bodies
    End Function

    ''' <summary>Whether any of <paramref name="bodies"/> is marked in <paramref name="marked"/>.</summary>
    Private Shared Function Shares(bodies As Integer(), marked As Boolean()) As Boolean
        For Each k In bodies
            If marked(k) Then Return True
        Next
        Return False
    End Function

    ''' <summary>
    ''' Measures every row at <paramref name="state"/>: its normal u into _nx, _ny and, into whichever of the arrays
    ''' is given, its ψ (m), ψ̇ (m/s) and κ (m/s²).
    ''' </summary>
    Private Sub MeasureNormals(state As Double(), Optional values As Double() = Nothing, Optional rates As Double() = Nothing, Optional curvatures As Double() = Nothing)
        For i = 0 To _rows.Length - 1
            Dim u As Vector, value As Double, rate As Double, curvature As Double
            _rows(i).Measure(state, u, value, rate, curvature)
            _nx(i) = u.X
            _ny(i) = u.Y
            If values IsNot Nothing Then values(i) = value
            If rates IsNot Nothing Then rates(i) = rate
            If curvatures IsNot Nothing Then curvatures(i) = curvature
        Next
    End Sub

    ''' <summary>
    ''' Whether M, for the normals measured, must be solved the orthogonalised way (<see cref="SolveSpread"/>): its
    ''' rows move bodies of very different masses and the plain factor lost too many digits. False when the plain
    ''' factor, made here, serves <see cref="Solve"/>.
    ''' </summary>
    Private Function NeedsSpreadSolve() As Boolean
        If _spread Then Return Not FactorsWell()
        Factor()
        Return False
    End Function

    ''' <summary>
    ''' Factors M and says whether every pivot kept at least <see cref="WellFactored"/> of its row's own size (what
    ''' the rows share cost it no more than half its digits); False also where the factorization refuses a row.
    ''' </summary>
    Private Function FactorsWell() As Boolean
        Try
            Factor()
        Catch ex As InvalidOperationException
            Return False
        End Try
        For j = 0 To _rows.Length - 1
            If _factor(j)(j) * _factor(j)(j) < WellFactored * _shared(j)(j) Then Return False
        Next
        Return True
    End Function

    ''' <summary>
    ''' Moves the bodies back onto ψ = 0 and takes away their ψ̇, each by the least mass-weighted change (a
    ''' Gauss–Newton step on ψ, repeated until within a few roundings; then one linear solve for the rates). The
    ''' centre of mass is not moved by constraints between bodies.
    ''' </summary>
    Friend Sub Project(state As Double())
        ProjectPositions(state)
        ProjectRates(state)
    End Sub

    ''' <summary>
    ''' Moves the bodies back onto ψ = 0 by the least mass-weighted change of their positions (Gauss–Newton steps on ψ,
    ''' until within a few roundings), velocities as they are.
    ''' </summary>
    Friend Sub ProjectPositions(state As Double())
        Dim m = _rows.Length
        If m = 0 Then Return
        Dim c(m - 1) As Double
        For iteration = 1 To 4
            MeasureNormals(state, values:=c)
            Dim worst = 0.0
            For i = 0 To m - 1
                ' Moving the ends by μ along u (A along it, B against it, each by its inverse mass) raises ψ by
                ' M μ: so M μ = −ψ (for a tie, d − L).
                c(i) = -c(i)
                worst = Math.Max(worst, Math.Abs(c(i)) / _rows(i).Scale)
            Next
            ' Gauss–Newton converges quadratically: from the integrator's drift one step reaches rounding.
            If worst <= 0.000000000000001 Then Exit For
            ApplyLeastChange(state, c, 0, NeedsSpreadSolve())
        Next
    End Sub

    ''' <summary>Takes away the constraints' ψ̇ by the least mass-weighted change of the velocities, positions as they are.</summary>
    Friend Sub ProjectRates(state As Double())
        Dim m = _rows.Length
        If m = 0 Then Return
        Dim c(m - 1) As Double
        MeasureNormals(state, rates:=c)
        For i = 0 To m - 1
            c(i) = -c(i)
        Next
        ApplyLeastChange(state, c, 2, NeedsSpreadSolve())
    End Sub

    ''' <summary>
    ''' Solves M μ = <paramref name="c"/> (μ in place) and adds the change W Jᵀ μ it makes to the positions (offset 0)
    ''' or the velocities (offset 2) of <paramref name="values"/>, laid out as a state. When <paramref name="spread"/>,
    ''' the orthogonalised way (<see cref="SolveSpread"/>): put back on its rows, a 1 µg ball wedged between a wall and
    ''' a 484 t box is moved by its own rows, where the plain factor found them the same row and refused the step.
    ''' </summary>
    Private Sub ApplyLeastChange(values As Double(), c As Double(), offset As Integer, spread As Boolean)
        If spread Then
            ' SolveSpread adds its change in the velocity places of a state's layout.
            Dim n = _inverseMass.Length
            Dim change(4 * n - 1) As Double
            SolveSpread(c, change)
            For k = 0 To n - 1
                values(4 * k + offset) += change(4 * k + 2)
                values(4 * k + offset + 1) += change(4 * k + 3)
            Next
        Else
            Solve(c)
            Apply(values, c, offset)
        End If
    End Sub

    ''' <summary>
    ''' Takes from <paramref name="values"/> (laid out as a state: per body x, y, vx, vy) the part the constraints fix
    ''' at <paramref name="state"/>: in the positions and in the velocities each, the least mass-weighted change that
    ''' leaves J × values = 0, as <see cref="ProjectRates"/> takes away ψ̇. What is left moves the bodies only as the
    ''' constraints let them move. False, <paramref name="values"/> as it was, when a row slides (its force is not
    ''' along its normal, and the least change in that metric is not the one the forces make).
    ''' </summary>
    Friend Function TryRemoveHeld(state As Double(), values As Double()) As Boolean
        Dim m = _rows.Length
        If m = 0 Then Return True
        If _slides Then Return False
        MeasureNormals(state)
        ' Bodies of very different masses: the orthogonalised solve, as the forces are found (see SolveSpread).
        Dim spread = NeedsSpreadSolve()
        For Each offset In {0, 2}
            Dim c(m - 1) As Double
            For i = 0 To m - 1
                Dim r = _rows(i)
                Dim ax = values(4 * r.A + offset), ay = values(4 * r.A + offset + 1)
                Dim bx = If(r.B >= 0, values(4 * r.B + offset), 0.0), by = If(r.B >= 0, values(4 * r.B + offset + 1), 0.0)
                c(i) = _nx(i) * (bx - ax) + _ny(i) * (by - ay)
            Next
            ApplyLeastChange(values, c, offset, spread)
        Next
        Return True
    End Function

    ''' <summary>The largest |ψ| ÷ scale over the constraints, and the largest |ψ̇| (m/s).</summary>
    Friend Sub Drift(state As Double(), ByRef lengthError As Double, ByRef rateError As Double)
        lengthError = 0
        rateError = 0
        For Each row In _rows
            Dim u As Vector, value As Double, rate As Double, curvature As Double
            row.Measure(state, u, value, rate, curvature)
            lengthError = Math.Max(lengthError, Math.Abs(value) / row.Scale)
            rateError = Math.Max(rateError, Math.Abs(rate))
        Next
    End Sub

    ''' <summary>Σ σ_p σ_q w over the bodies constraints <paramref name="p"/> and <paramref name="q"/> share (1/kg): M_pq ÷ (u_p·u_q).</summary>
    Friend Shared Function SharedInverseMass(p As Constraint, q As Constraint, inverseMass As Double()) As Double
        Dim s = 0.0
        If p.A = q.A Then s += inverseMass(p.A)
        If p.B >= 0 AndAlso p.B = q.B Then s += inverseMass(p.B)
        If p.A = q.B Then s -= inverseMass(p.A)
        If p.B >= 0 AndAlso p.B = q.A Then s -= inverseMass(p.B)
        Return s
    End Function

    ''' <summary>
    ''' Whether the movable bodies that <paramref name="rows"/> move differ in inverse mass by more than
    ''' <see cref="SpreadRatio"/>: the forces are then solved in an orthogonalised basis (see SolveSpread), not by Cholesky's method alone.
    ''' </summary>
    Friend Shared Function IsSpread(rows As IEnumerable(Of Constraint), inverseMass As Double()) As Boolean
        Dim largest = 0.0, smallest = Double.PositiveInfinity
        For Each r In rows
            For Each body In {r.A, r.B}
                If body < 0 OrElse inverseMass(body) <= 0 Then Continue For
                largest = Math.Max(largest, inverseMass(body))
                smallest = Math.Min(smallest, inverseMass(body))
            Next
        Next
        Return largest > SpreadRatio * smallest
    End Function

    ''' <summary>Adds Σ_j λ_j × (constraint j's direction at each end) × w to the values at <paramref name="offset"/> (0 positions, 2 velocities or accelerations).</summary>
    Private Sub Apply(values As Double(), lambda As Double(), offset As Integer)
        For j = 0 To _rows.Length - 1
            Dim t = _rows(j)
            Dim wa = _inverseMass(t.A) * lambda(j)
            values(4 * t.A + offset) += wa * _nx(j)
            values(4 * t.A + offset + 1) += wa * _ny(j)
            If t.B >= 0 Then
                Dim wb = _inverseMass(t.B) * lambda(j)
                values(4 * t.B + offset) -= wb * _nx(j)
                values(4 * t.B + offset + 1) -= wb * _ny(j)
            End If
        Next
    End Sub

    ''' <summary>Adds Σ_j λ_j × (constraint j's force direction at each end) × w to the accelerations.</summary>
    Private Sub ApplyForces(values As Double(), lambda As Double())
        For j = 0 To _rows.Length - 1
            Dim t = _rows(j)
            Dim wa = _inverseMass(t.A) * lambda(j)
            values(4 * t.A + 2) += wa * _fx(j)
            values(4 * t.A + 3) += wa * _fy(j)
            If t.B >= 0 Then
                Dim wb = _inverseMass(t.B) * lambda(j)
                values(4 * t.B + 2) -= wb * _fx(j)
                values(4 * t.B + 3) -= wb * _fy(j)
            End If
        Next
    End Sub

    ''' <summary>Solves M λ = b in place, M_ij = (u_i·f_j) × the shared inverse mass, by Gaussian elimination with partial pivoting.</summary>
    Private Sub SolveGeneral(b As Double())
        Dim m = _rows.Length
        For i = 0 To m - 1
            For j = 0 To m - 1
                Dim sharedMass = If(i >= j, _shared(i)(j), _shared(j)(i))
                _general(i, j) = If(sharedMass = 0, 0, sharedMass * (_nx(i) * _fx(j) + _ny(i) * _fy(j)))
            Next
        Next
        For k = 0 To m - 1
            Dim p = k
            For i = k + 1 To m - 1
                If Math.Abs(_general(i, k)) > Math.Abs(_general(p, k)) Then p = i
            Next
            If Not (Math.Abs(_general(p, k)) > _independence * Math.Abs(_shared(k)(k))) Then Throw New InvalidOperationException("the constraints of a group hold its bodies in more ways than they can move (a constraint is redundant)")
            If p <> k Then
                For j = 0 To m - 1
                    Dim swap = _general(k, j)
                    _general(k, j) = _general(p, j)
                    _general(p, j) = swap
                Next
                Dim sb = b(k)
                b(k) = b(p)
                b(p) = sb
            End If
            For i = k + 1 To m - 1
                Dim factor = _general(i, k) / _general(k, k)
                If factor = 0 Then Continue For
                For j = k To m - 1
                    _general(i, j) -= factor * _general(k, j)
                Next
                b(i) -= factor * b(k)
            Next
        Next
        For i = m - 1 To 0 Step -1
            Dim sum = b(i)
            For j = i + 1 To m - 1
                sum -= _general(i, j) * b(j)
            Next
            b(i) = sum / _general(i, i)
        Next
    End Sub

    ''' <summary>Cholesky's factor L (M = L Lᵀ, lower triangle) of M for the directions in _nx, _ny, row by row.</summary>
    Private Sub Factor()
        For i = 0 To _rows.Length - 1
            Dim li = _factor(i)
            For j = 0 To i - 1
                Dim s = _shared(i)(j)
                If s <> 0 Then s *= _nx(i) * _nx(j) + _ny(i) * _ny(j)
                li(j) = s
            Next
            If Not FactorRow(_factor, li, i, _shared(i)(i), _independence) Then Throw New InvalidOperationException("the constraints of a group hold its bodies in more ways than they can move (a constraint is redundant)")
        Next
    End Sub

    ''' <summary>
    ''' Row k of Cholesky's factor L, from the rows before it (<paramref name="factor"/>(0 … k − 1)): on entry
    ''' <paramref name="row"/>(j) holds M_kj for j &lt; k, and <paramref name="own"/> is M_kk; on return row(j) holds
    ''' L_kj and row(k) the root of the pivot, M_kk less the part the rows before already span. False when that pivot
    ''' is not above <paramref name="independence"/> × M_kk: the row depends on those before it (row is then spoilt).
    ''' <see cref="GrowingFactor"/> grows a factor with it too, so the two agree to the last bit.
    ''' </summary>
    Friend Shared Function FactorRow(factor As Double()(), row As Double(), k As Integer, own As Double, independence As Double) As Boolean
        ForwardSubstitute(factor, row, k)
        Dim diagonal = own
        For p = 0 To k - 1
            diagonal -= row(p) * row(p)
        Next
        If Not (diagonal > independence * own) Then Return False
        row(k) = Math.Sqrt(diagonal)
        Return True
    End Function

    ''' <summary>Solves M x = b in place with the factor.</summary>
    Private Sub Solve(b As Double())
        SolveFactored(_factor, b, b.Length)
    End Sub

    ''' <summary>
    ''' Solves L Lᵀ x = <paramref name="b"/> in place for the first <paramref name="count"/> rows of Cholesky's factor
    ''' L (<paramref name="factor"/>(i)(j) = L_ij, j ≤ i).
    ''' </summary>
    Private Shared Sub SolveFactored(factor As Double()(), b As Double(), count As Integer)
        ForwardSubstitute(factor, b, count)
        For i = count - 1 To 0 Step -1
            Dim s = b(i)
            For p = i + 1 To count - 1
                s -= factor(p)(i) * b(p)
            Next
            b(i) = s / factor(i)(i)
        Next
    End Sub

    ''' <summary>Solves L y = <paramref name="b"/> in place for the first <paramref name="count"/> rows of L.</summary>
    Private Shared Sub ForwardSubstitute(factor As Double()(), b As Double(), count As Integer)
        For i = 0 To count - 1
            Dim li = factor(i)
            Dim s = b(i)
            For p = 0 To i - 1
                s -= li(p) * b(p)
            Next
            b(i) = s / li(i)
        Next
    End Sub

    Private Shared Function Acceleration(accelerations As Double(), k As Integer) As Vector
        Return New Vector(accelerations(4 * k + 2), accelerations(4 * k + 3))
    End Function

    Private Shared Function AccelerationB(accelerations As Double(), t As Constraint) As Vector
        Return If(t.B >= 0, Acceleration(accelerations, t.B), Vector.Zero)
    End Function
End Class
