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
''' positive definite while no tie is redundant, so it is solved by Cholesky's method.
''' </summary>
Friend Module ChainConstraints
    ''' <summary>
    ''' The ties' tensions (N) for <paramref name="state"/>, with <paramref name="accelerations"/> holding the
    ''' free accelerations (gravity, springs) on entry and, on return, those plus the ties' forces ÷ mass.
    ''' </summary>
    Friend Function Tensions(state As Double(), accelerations As Double(), ties As ChainTie(), inverseMass As Double()) As Double()
        Dim m = ties.Length
        Dim lambda(m - 1) As Double
        If m = 0 Then Return lambda
        Dim nx(m - 1) As Double, ny(m - 1) As Double
        For i = 0 To m - 1
            Dim t = ties(i)
            Dim r = EndB(state, t) - Position(state, t.A)
            Dim d = r.Length
            Dim n = r / d
            nx(i) = n.X
            ny(i) = n.Y
            Dim w = VelocityB(state, t) - Velocity(state, t.A)
            Dim along = Vector.Dot(n, w)
            Dim relative = AccelerationB(accelerations, t) - Acceleration(accelerations, t.A)
            lambda(i) = Vector.Dot(n, relative) + (w.LengthSquared - along * along) / d
        Next
        Solve(Coupling(ties, inverseMass, nx, ny), lambda)
        Apply(accelerations, ties, inverseMass, nx, ny, lambda)
        Return lambda
    End Function

    ''' <summary>
    ''' Moves the bodies back onto the ties' lengths and takes away their speeds along the ties, each by the
    ''' least mass-weighted change (a Gauss–Newton step on d − L, repeated until within a few roundings; then
    ''' one linear solve for the stretch rates). The centre of mass is not moved by ties between bodies.
    ''' </summary>
    Friend Sub Project(state As Double(), ties As ChainTie(), inverseMass As Double())
        Dim m = ties.Length
        If m = 0 Then Return
        Dim nx(m - 1) As Double, ny(m - 1) As Double, c(m - 1) As Double
        For iteration = 1 To 8
            Dim worst = 0.0
            For i = 0 To m - 1
                Dim t = ties(i)
                Dim r = EndB(state, t) - Position(state, t.A)
                Dim d = r.Length
                nx(i) = r.X / d
                ny(i) = r.Y / d
                ' Moving the ends by μ along n (A towards B, B towards A, each by its inverse mass) shortens the
                ' ties by M μ: so M μ = d − L.
                c(i) = d - t.Length
                worst = Math.Max(worst, Math.Abs(c(i)) / t.Length)
            Next
            If worst <= 0.0000000000000004 Then Exit For
            Solve(Coupling(ties, inverseMass, nx, ny), c)
            Apply(state, ties, inverseMass, nx, ny, c, 0)
        Next
        For i = 0 To m - 1
            Dim t = ties(i)
            Dim r = EndB(state, t) - Position(state, t.A)
            Dim d = r.Length
            nx(i) = r.X / d
            ny(i) = r.Y / d
            c(i) = Vector.Dot(New Vector(nx(i), ny(i)), VelocityB(state, t) - Velocity(state, t.A))
        Next
        Solve(Coupling(ties, inverseMass, nx, ny), c)
        Apply(state, ties, inverseMass, nx, ny, c, 2)
    End Sub

    ''' <summary>The largest |d − L| ÷ L over the ties, and the largest |ḋ| (m/s).</summary>
    Friend Sub Drift(state As Double(), ties As ChainTie(), ByRef lengthError As Double, ByRef rateError As Double)
        lengthError = 0
        rateError = 0
        For Each t In ties
            Dim r = EndB(state, t) - Position(state, t.A)
            Dim d = r.Length
            lengthError = Math.Max(lengthError, Math.Abs(d - t.Length) / t.Length)
            rateError = Math.Max(rateError, Math.Abs(Vector.Dot(r, VelocityB(state, t) - Velocity(state, t.A)) / d))
        Next
    End Sub

    ''' <summary>M_ij = (n_i·n_j) Σ σ_i σ_j w_p over the bodies p that ties i and j share.</summary>
    Private Function Coupling(ties As ChainTie(), inverseMass As Double(), nx As Double(), ny As Double()) As Double(,)
        Dim m = ties.Length
        Dim k(m - 1, m - 1) As Double
        For i = 0 To m - 1
            For j = i To m - 1
                Dim s = SharedInverseMass(ties(i), ties(j), inverseMass)
                If s = 0 Then Continue For
                Dim v = s * (nx(i) * nx(j) + ny(i) * ny(j))
                k(i, j) = v
                k(j, i) = v
            Next
        Next
        Return k
    End Function

    Private Function SharedInverseMass(p As ChainTie, q As ChainTie, inverseMass As Double()) As Double
        Dim s = 0.0
        If p.A = q.A Then s += inverseMass(p.A)
        If p.B >= 0 AndAlso p.B = q.B Then s += inverseMass(p.B)
        If p.A = q.B Then s -= inverseMass(p.A)
        If p.B >= 0 AndAlso p.B = q.A Then s -= inverseMass(p.B)
        Return s
    End Function

    ''' <summary>Adds Σ_j λ_j × (force direction of tie j on each end) × w to the values at <paramref name="offset"/> (0 positions, 2 velocities or accelerations).</summary>
    Private Sub Apply(values As Double(), ties As ChainTie(), inverseMass As Double(), nx As Double(), ny As Double(), lambda As Double(), Optional offset As Integer = 2)
        For j = 0 To ties.Length - 1
            Dim t = ties(j)
            Dim wa = inverseMass(t.A) * lambda(j)
            values(4 * t.A + offset) += wa * nx(j)
            values(4 * t.A + offset + 1) += wa * ny(j)
            If t.B >= 0 Then
                Dim wb = inverseMass(t.B) * lambda(j)
                values(4 * t.B + offset) -= wb * nx(j)
                values(4 * t.B + offset + 1) -= wb * ny(j)
            End If
        Next
    End Sub

    ''' <summary>Solves k x = b in place by Cholesky's method (k symmetric positive definite; it is overwritten).</summary>
    Private Sub Solve(k As Double(,), b As Double())
        Dim m = b.Length
        For j = 0 To m - 1
            Dim diagonal = k(j, j)
            For p = 0 To j - 1
                diagonal -= k(j, p) * k(j, p)
            Next
            If Not (diagonal > 0.000000000001 * Math.Abs(k(j, j))) Then Throw New InvalidOperationException("the rods and strings of a chain hold its bodies in more ways than they can move (a tie is redundant)")
            Dim root = Math.Sqrt(diagonal)
            k(j, j) = root
            For i = j + 1 To m - 1
                Dim s = k(i, j)
                For p = 0 To j - 1
                    s -= k(i, p) * k(j, p)
                Next
                k(i, j) = s / root
            Next
        Next
        For i = 0 To m - 1
            Dim s = b(i)
            For p = 0 To i - 1
                s -= k(i, p) * b(p)
            Next
            b(i) = s / k(i, i)
        Next
        For i = m - 1 To 0 Step -1
            Dim s = b(i)
            For p = i + 1 To m - 1
                s -= k(p, i) * b(p)
            Next
            b(i) = s / k(i, i)
        Next
    End Sub

    Private Function Position(state As Double(), k As Integer) As Vector
        Return New Vector(state(4 * k), state(4 * k + 1))
    End Function

    Private Function Velocity(state As Double(), k As Integer) As Vector
        Return New Vector(state(4 * k + 2), state(4 * k + 3))
    End Function

    Private Function Acceleration(accelerations As Double(), k As Integer) As Vector
        Return New Vector(accelerations(4 * k + 2), accelerations(4 * k + 3))
    End Function

    Private Function EndB(state As Double(), t As ChainTie) As Vector
        Return If(t.B >= 0, Position(state, t.B), t.Anchor)
    End Function

    Private Function VelocityB(state As Double(), t As ChainTie) As Vector
        Return If(t.B >= 0, Velocity(state, t.B), Vector.Zero)
    End Function

    Private Function AccelerationB(accelerations As Double(), t As ChainTie) As Vector
        Return If(t.B >= 0, Acceleration(accelerations, t.B), Vector.Zero)
    End Function
End Module
