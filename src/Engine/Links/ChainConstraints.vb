Option Strict On

''' <summary>
''' The forces with which rods and taut strings hold a chain of bodies together, and the projection that
''' puts a drifted state back on the lengths (docs/links.md, "Chains"). A state array holds per body
''' x, y, vx, vy (m, m/s); an accelerations array has the same layout, with the accelerations in the
''' velocity places. For tie i from A to B, n is the unit vector from A towards B and its tension λ (N,
''' positive when it pulls) acts on A as +λn and on B as −λn. Holding d = L means d̈ = 0, where
''' d̈ = n·(a_B − a_A) + (|w|² − (n·w)²)/d with w = v_B − v_A (the second term is the centripetal part).
''' Writing the accelerations as the free ones plus the ties' forces ÷ mass gives one linear equation per
''' tie, M λ = n·(a_B − a_A)_free + (|w|² − (n·w)²)/d, with M_ij = (n_i·n_j) Σ σ_i σ_j w_p over the bodies p
''' the two ties share (w_p the inverse mass, σ = −1 at end A and +1 at end B). M is J W Jᵀ, symmetric and
''' positive definite while no tie is redundant, so it is solved by Cholesky's method. Which ties share
''' which bodies never changes, so those sums are worked out once; the buffers are reused, so one instance
''' serves one motion at a time.
''' </summary>
Friend NotInheritable Class ChainConstraints
    Private ReadOnly _ties As ChainTie()
    Private ReadOnly _inverseMass As Double()
    ' Σ σ_i σ_j w_p over the shared bodies, for i ≥ j; zero where ties i and j share none.
    Private ReadOnly _shared As Double()()
    Private ReadOnly _nx As Double(), _ny As Double(), _factor As Double()()

    ''' <summary>The ties of a chain whose bodies have the given inverse masses (1/kg, 0 for a body that cannot move).</summary>
    Friend Sub New(ties As ChainTie(), inverseMass As Double())
        _ties = ties
        _inverseMass = inverseMass
        Dim m = ties.Length
        _nx = New Double(m - 1) {}
        _ny = New Double(m - 1) {}
        _shared = New Double(m - 1)() {}
        _factor = New Double(m - 1)() {}
        For i = 0 To m - 1
            _shared(i) = New Double(i) {}
            _factor(i) = New Double(i) {}
            For j = 0 To i
                _shared(i)(j) = SharedInverseMass(ties(i), ties(j))
            Next
        Next
    End Sub

    ''' <summary>
    ''' The ties' tensions (N) for <paramref name="state"/>, with <paramref name="accelerations"/> holding the
    ''' free accelerations (gravity, springs) on entry and, on return, those plus the ties' forces ÷ mass.
    ''' </summary>
    Friend Function Tensions(state As Double(), accelerations As Double()) As Double()
        Dim m = _ties.Length
        Dim lambda(m - 1) As Double
        If m = 0 Then Return lambda
        For i = 0 To m - 1
            Dim t = _ties(i)
            Dim r = EndB(state, t) - Position(state, t.A)
            Dim d = r.Length
            Dim n = r / d
            _nx(i) = n.X
            _ny(i) = n.Y
            Dim w = VelocityB(state, t) - Velocity(state, t.A)
            Dim along = Vector.Dot(n, w)
            Dim relative = AccelerationB(accelerations, t) - Acceleration(accelerations, t.A)
            lambda(i) = Vector.Dot(n, relative) + (w.LengthSquared - along * along) / d
        Next
        Factor()
        Solve(lambda)
        Apply(accelerations, lambda, 2)
        Return lambda
    End Function

    ''' <summary>
    ''' Moves the bodies back onto the ties' lengths and takes away their speeds along the ties, each by the
    ''' least mass-weighted change (a Gauss–Newton step on d − L, repeated until within a few roundings; then
    ''' one linear solve for the stretch rates). The centre of mass is not moved by ties between bodies.
    ''' </summary>
    Friend Sub Project(state As Double())
        Dim m = _ties.Length
        If m = 0 Then Return
        Dim c(m - 1) As Double
        For iteration = 1 To 4
            Dim worst = 0.0
            For i = 0 To m - 1
                Dim t = _ties(i)
                Dim r = EndB(state, t) - Position(state, t.A)
                Dim d = r.Length
                _nx(i) = r.X / d
                _ny(i) = r.Y / d
                ' Moving the ends by μ along n (A towards B, B towards A, each by its inverse mass) shortens the
                ' ties by M μ: so M μ = d − L.
                c(i) = d - t.Length
                worst = Math.Max(worst, Math.Abs(c(i)) / t.Length)
            Next
            ' Gauss–Newton converges quadratically: from the integrator's drift one step reaches rounding.
            If worst <= 0.000000000000001 Then Exit For
            Factor()
            Solve(c)
            Apply(state, c, 0)
        Next
        For i = 0 To m - 1
            Dim t = _ties(i)
            Dim r = EndB(state, t) - Position(state, t.A)
            Dim d = r.Length
            _nx(i) = r.X / d
            _ny(i) = r.Y / d
            c(i) = Vector.Dot(New Vector(_nx(i), _ny(i)), VelocityB(state, t) - Velocity(state, t.A))
        Next
        Factor()
        Solve(c)
        Apply(state, c, 2)
    End Sub

    ''' <summary>The largest |d − L| ÷ L over the ties, and the largest |ḋ| (m/s).</summary>
    Friend Sub Drift(state As Double(), ByRef lengthError As Double, ByRef rateError As Double)
        lengthError = 0
        rateError = 0
        For Each t In _ties
            Dim r = EndB(state, t) - Position(state, t.A)
            Dim d = r.Length
            lengthError = Math.Max(lengthError, Math.Abs(d - t.Length) / t.Length)
            rateError = Math.Max(rateError, Math.Abs(Vector.Dot(r, VelocityB(state, t) - Velocity(state, t.A)) / d))
        Next
    End Sub

    Private Function SharedInverseMass(p As ChainTie, q As ChainTie) As Double
        Dim s = 0.0
        If p.A = q.A Then s += _inverseMass(p.A)
        If p.B >= 0 AndAlso p.B = q.B Then s += _inverseMass(p.B)
        If p.A = q.B Then s -= _inverseMass(p.A)
        If p.B >= 0 AndAlso p.B = q.A Then s -= _inverseMass(p.B)
        Return s
    End Function

    ''' <summary>Adds Σ_j λ_j × (tie j's direction at each end) × w to the values at <paramref name="offset"/> (0 positions, 2 velocities or accelerations).</summary>
    Private Sub Apply(values As Double(), lambda As Double(), offset As Integer)
        For j = 0 To _ties.Length - 1
            Dim t = _ties(j)
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

    ''' <summary>Cholesky's factor L (M = L Lᵀ, lower triangle) of M for the directions in _nx, _ny.</summary>
    Private Sub Factor()
        Dim m = _ties.Length
        For j = 0 To m - 1
            Dim lj = _factor(j)
            Dim diagonal = _shared(j)(j)
            For p = 0 To j - 1
                diagonal -= lj(p) * lj(p)
            Next
            If Not (diagonal > 0.000000000001 * _shared(j)(j)) Then Throw New InvalidOperationException("the rods and strings of a chain hold its bodies in more ways than they can move (a tie is redundant)")
            Dim root = Math.Sqrt(diagonal)
            lj(j) = root
            For i = j + 1 To m - 1
                Dim li = _factor(i)
                Dim s = _shared(i)(j)
                If s <> 0 Then s *= _nx(i) * _nx(j) + _ny(i) * _ny(j)
                For p = 0 To j - 1
                    s -= li(p) * lj(p)
                Next
                li(j) = s / root
            Next
        Next
    End Sub

    ''' <summary>Solves M x = b in place with the factor.</summary>
    Private Sub Solve(b As Double())
        Dim m = b.Length
        For i = 0 To m - 1
            Dim li = _factor(i)
            Dim s = b(i)
            For p = 0 To i - 1
                s -= li(p) * b(p)
            Next
            b(i) = s / li(i)
        Next
        For i = m - 1 To 0 Step -1
            Dim s = b(i)
            For p = i + 1 To m - 1
                s -= _factor(p)(i) * b(p)
            Next
            b(i) = s / _factor(i)(i)
        Next
    End Sub

    Private Shared Function Position(state As Double(), k As Integer) As Vector
        Return New Vector(state(4 * k), state(4 * k + 1))
    End Function

    Private Shared Function Velocity(state As Double(), k As Integer) As Vector
        Return New Vector(state(4 * k + 2), state(4 * k + 3))
    End Function

    Private Shared Function Acceleration(accelerations As Double(), k As Integer) As Vector
        Return New Vector(accelerations(4 * k + 2), accelerations(4 * k + 3))
    End Function

    Private Shared Function EndB(state As Double(), t As ChainTie) As Vector
        Return If(t.B >= 0, Position(state, t.B), t.Anchor)
    End Function

    Private Shared Function VelocityB(state As Double(), t As ChainTie) As Vector
        Return If(t.B >= 0, Velocity(state, t.B), Vector.Zero)
    End Function

    Private Shared Function AccelerationB(accelerations As Double(), t As ChainTie) As Vector
        Return If(t.B >= 0, Acceleration(accelerations, t.B), Vector.Zero)
    End Function
End Class
