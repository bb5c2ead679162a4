Option Strict On

''' <summary>
''' Phase 1 of <see cref="ContactCluster"/>: the velocities closest to given ones, in the kinetic-energy
''' metric, at which no contact of the cluster approaches. Solved through its dual, a non-negative
''' least-squares problem, by Lawson and Hanson's active-set method.
''' </summary>
''' <remarks>
''' <para>
''' The primal: minimise ½ (u − u₀)ᵀ M (u − u₀) over the velocities u of the movable bodies, subject to
''' g = J u + c ≥ 0, where row k of J gives the normal relative velocity of contact k and c_k is what
''' the immovable bodies' own velocities add to it (a dragged body moves; walls do not). Its optimum is
''' u = u₀ + M⁻¹ Jᵀ λ with impulses λ ≥ 0 (N·s), g ≥ 0 and λ_k g_k = 0.
''' </para>
''' <para>
''' In scaled velocities r = M^(1/2) u (the unit is √kg · m/s, so ½‖r‖² is the kinetic energy) the
''' dual is: minimise ‖C λ − d‖² over λ ≥ 0 with C = M^(−1/2) Jᵀ and d = −M^(1/2) u₀, and the residual
''' C λ − d is r itself. Lawson–Hanson keeps a "passive" set P of contacts that push, solves the
''' unconstrained least-squares problem on P by Householder QR, steps back towards the last point if
''' some impulse would turn negative (dropping that contact), and adds the most approaching contact
''' while one approaches. Each step lowers the dual objective, so no set repeats and it terminates.
''' A contact that enters extends the factorization by one column (rows × |P| work); only a drop
''' refactors (rows × |P|²), so a cluster whose contacts all end up pushing costs rows × |P|² in all,
''' not rows × |P|³.
''' </para>
''' <para>
''' Accuracy at mass ratios of 10¹²: the velocities are read from the QR residual, not from
''' u₀ + M⁻¹ Jᵀ λ. A 4·10⁻¹³ kg ball squeezed by a 0.4 kg one feels impulses of 0.4 N·s that cancel
''' to a net of 10⁻¹³ N·s; rounding λ alone would give it 10⁻⁴ of the speed. The QR pivots rows as
''' well as columns (see <see cref="HouseholderQr"/>), so a light body that no pushing contact touches
''' keeps its velocity exactly. Each solve ends with two steps of refinement that drive the pushing
''' contacts' normal velocities to zero directly (seminormal equations on the same R). The first step
''' is also what brings in the constant c when an immovable body moves; on the random clusters of the
''' tests, without refinement a contact is left approaching at up to 9·10⁻¹³ of the speed, with it at
''' most 4·10⁻¹⁵.
''' </para>
''' </remarks>
Friend NotInheritable Class ContactProjection
    ' A column whose part outside the passive columns' span is below this fraction of its length is
    ' taken as linearly dependent on them (Lawson and Hanson use about 100 ε; this leaves more room).
    Private Const DependenceTolerance As Double = 0.000000000001
    Private Const RefinementSteps As Integer = 2

    ' The problem, set by Load. Slots are the movable bodies that touch something, in the order their
    ' first contact names them; rows 2s and 2s + 1 are slot s's x and y.
    Private _rows As Integer
    Private _contacts As Integer
    Private _slotCount As Integer
    Private _bodyOfSlot As Integer() = Array.Empty(Of Integer)()
    Private _slotOfBody As Integer() = Array.Empty(Of Integer)()
    Private _sqrtInverseMass As Double() = Array.Empty(Of Double)() ' per slot, 1/√kg
    Private _slotA As Integer() = Array.Empty(Of Integer)()         ' per contact: slot, or −1 if immovable
    Private _slotB As Integer() = Array.Empty(Of Integer)()
    Private _nx As Double() = Array.Empty(Of Double)()
    Private _ny As Double() = Array.Empty(Of Double)()
    Private _offset As Double() = Array.Empty(Of Double)()          ' c_k, m/s
    Private _columnNorm As Double() = Array.Empty(Of Double)()      ' ‖C_k‖, 1/√kg; 0 when nothing in it moves
    Private _holds As Boolean() = Array.Empty(Of Boolean)()        ' per contact: a two-sided row (g = 0, impulse of either sign)
    Private _anyHolds As Boolean
    Private _matrix As Double() = Array.Empty(Of Double)()          ' C, rows × contacts, column-major

    ' The solve.
    Private ReadOnly _qr As New HouseholderQr()
    Private _d As Double() = Array.Empty(Of Double)()
    Private _r As Double() = Array.Empty(Of Double)()       ' scaled velocities of the accepted point
    Private _trial As Double() = Array.Empty(Of Double)()   ' scaled velocities of the last solve
    Private _work As Double() = Array.Empty(Of Double)()
    Private _pivoted As Double() = Array.Empty(Of Double)()
    Private _lambda As Double() = Array.Empty(Of Double)()  ' accepted impulses, N·s
    Private _x As Double() = Array.Empty(Of Double)()       ' Lawson–Hanson's current point
    Private _z As Double() = Array.Empty(Of Double)()       ' impulses of the last solve
    Private _approach As Double() = Array.Empty(Of Double)() ' g at the accepted point, m/s
    Private _passive As Integer() = Array.Empty(Of Integer)()
    Private _passiveCount As Integer
    Private _inPassive As Boolean() = Array.Empty(Of Boolean)()
    Private _rejected As Boolean() = Array.Empty(Of Boolean)()

    ''' <summary>Number of movable bodies that touch something; velocities are passed per slot (x, y).</summary>
    Friend ReadOnly Property SlotCount As Integer
        Get
            Return _slotCount
        End Get
    End Property

    ''' <summary>The body in slot <paramref name="slot"/>.</summary>
    Friend ReadOnly Property BodyOfSlot(slot As Integer) As Integer
        Get
            Return _bodyOfSlot(slot)
        End Get
    End Property

    ''' <summary>For tests of the guard: a cap on least-squares solves below the normal 5 m + 10 (0 = the normal one).</summary>
    Friend Property SolveCapOverride As Integer

    ''' <summary>Sets up C, c and the slots for a validated cluster.</summary>
    Friend Sub Load(inverseMasses As IReadOnlyList(Of Double), velocities As IReadOnlyList(Of Vector),
                    contacts As IReadOnlyList(Of ClusterContact))
        Load(inverseMasses, velocities, contacts, Nothing, Nothing)
    End Sub

    ''' <summary>
    ''' Sets up C, c and the slots, with <paramref name="offsets"/> (m/s, or Nothing) added to each contact's c, and
    ''' <paramref name="holds"/> (or Nothing) marking two-sided rows: those are kept at g = 0 with an impulse of
    ''' either sign (a rod), and enter the passive set first, in order, unless they depend on those before them.
    ''' </summary>
    Friend Sub Load(inverseMasses As IReadOnlyList(Of Double), velocities As IReadOnlyList(Of Vector),
                    contacts As IReadOnlyList(Of ClusterContact), offsets As IReadOnlyList(Of Double), holds As IReadOnlyList(Of Boolean))
        Dim n = inverseMasses.Count
        _contacts = contacts.Count
        If _slotOfBody.Length < n Then _slotOfBody = New Integer(n - 1) {}
        If _bodyOfSlot.Length < n Then _bodyOfSlot = New Integer(n - 1) {}
        For i = 0 To n - 1
            _slotOfBody(i) = -1
        Next
        _slotCount = 0
        For Each contact In contacts
            AddSlot(contact.BodyA, inverseMasses)
            If contact.BodyB <> ClusterContact.World Then AddSlot(contact.BodyB, inverseMasses)
        Next
        _rows = 2 * _slotCount

        HouseholderQr.Grow(_sqrtInverseMass, _slotCount)
        For s = 0 To _slotCount - 1
            _sqrtInverseMass(s) = Math.Sqrt(inverseMasses(_bodyOfSlot(s)))
        Next
        GrowPerContact()
        _anyHolds = False
        HouseholderQr.Grow(_matrix, _rows * _contacts)
        Array.Clear(_matrix, 0, _rows * _contacts)
        For k = 0 To _contacts - 1
            Dim contact = contacts(k)
            Dim a = contact.BodyA
            Dim b = contact.BodyB
            Dim nrm = contact.Normal
            _nx(k) = nrm.X
            _ny(k) = nrm.Y
            _slotA(k) = _slotOfBody(a)
            _slotB(k) = If(b = ClusterContact.World, -1, _slotOfBody(b))
            ' An immovable body keeps its velocity, so its share of the normal velocity is a constant.
            Dim offset = 0.0
            If _slotA(k) < 0 Then offset += Vector.Dot(nrm, velocities(a))
            If b <> ClusterContact.World AndAlso _slotB(k) < 0 Then offset -= Vector.Dot(nrm, velocities(b))
            If offsets IsNot Nothing Then offset += offsets(k)
            _offset(k) = offset
            _holds(k) = holds IsNot Nothing AndAlso holds(k)
            If _holds(k) Then _anyHolds = True
            Dim col = k * _rows
            If _slotA(k) >= 0 Then
                Dim s = _slotA(k)
                _matrix(col + 2 * s) += nrm.X * _sqrtInverseMass(s)
                _matrix(col + 2 * s + 1) += nrm.Y * _sqrtInverseMass(s)
            End If
            If _slotB(k) >= 0 Then
                Dim s = _slotB(k)
                _matrix(col + 2 * s) -= nrm.X * _sqrtInverseMass(s)
                _matrix(col + 2 * s + 1) -= nrm.Y * _sqrtInverseMass(s)
            End If
            _columnNorm(k) = HouseholderQr.Norm(_matrix, col, _rows)
        Next
    End Sub

    ''' <summary>
    ''' Normal relative velocity of contact <paramref name="k"/> (m/s; negative = approaching) when the
    ''' slots move at <paramref name="velocities"/> (x, y per slot, m/s).
    ''' </summary>
    Friend Function NormalVelocity(velocities As Double(), k As Integer) As Double
        Return NormalVelocityOf(velocities, k, scaled:=False)
    End Function

    ''' <summary>The smallest normal velocity over all contacts (m/s); +∞ when there are none.</summary>
    Friend Function SlowestSeparation(velocities As Double()) As Double
        Dim least = Double.PositiveInfinity
        For k = 0 To _contacts - 1
            least = Math.Min(least, NormalVelocity(velocities, k))
        Next
        Return least
    End Function

    ''' <summary>
    ''' Projects <paramref name="start"/> (x, y per slot, m/s) onto the velocities at which no contact
    ''' approaches by more than <paramref name="tolerance"/> (m/s). Writes the result to
    ''' <paramref name="result"/> and each contact's impulse (N·s, ≥ 0) to <paramref name="impulses"/>.
    ''' Returns False if the solve cap was reached: the result is then the last point the method accepted
    ''' (impulses ≥ 0, kinetic energy not above the start's when the immovable bodies are at rest), but
    ''' some contact may still approach.
    ''' </summary>
    Friend Function Project(start As Double(), tolerance As Double, result As Double(), impulses As Double()) As Boolean
        Dim converged = Solve(start, tolerance)
        For s = 0 To _slotCount - 1
            result(2 * s) = _r(2 * s) * _sqrtInverseMass(s)
            result(2 * s + 1) = _r(2 * s + 1) * _sqrtInverseMass(s)
        Next
        Array.Copy(_lambda, impulses, _contacts)
        Return converged
    End Function

    Private Function Solve(start As Double(), tolerance As Double) As Boolean
        HouseholderQr.Grow(_d, _rows)
        HouseholderQr.Grow(_r, _rows)
        HouseholderQr.Grow(_trial, _rows)
        HouseholderQr.Grow(_work, _rows)
        For s = 0 To _slotCount - 1
            For axis = 0 To 1
                Dim i = 2 * s + axis
                _r(i) = start(i) / _sqrtInverseMass(s)
                _d(i) = -_r(i)
            Next
        Next
        For k = 0 To _contacts - 1
            _lambda(k) = 0
            _x(k) = 0
            _inPassive(k) = False
        Next
        _passiveCount = 0
        _qr.Factor(_matrix, _rows, _passive, 0)
        If _anyHolds Then SeedHolds()
        UpdateApproaches()

        ' Lawson–Hanson terminates after finitely many solves, typically about one per contact that ends
        ' up pushing; the cap only guards against rounding making it cycle.
        Dim solveCap = If(SolveCapOverride > 0, SolveCapOverride, 5 * _contacts + 10)
        Dim solves = 0
        Do
            ' Outer step: bring in the most approaching contact that the passive ones cannot already hold.
            Array.Clear(_rejected, 0, _contacts)
            Do
                Dim t = MostApproaching(tolerance)
                If t < 0 Then Return True
                If _passiveCount > 0 AndAlso
                    _qr.IndependentPart(_matrix, t) <= DependenceTolerance * _columnNorm(t) Then
                    ' Redundant (a third support of a ball in a corner, a duplicate): the others hold it,
                    ' or nothing can (immovable bodies closing in), and the method would divide by zero.
                    _rejected(t) = True
                    Continue Do
                End If
                AddPassive(t)
                _qr.Append(_matrix, t)
                SolvePassive()
                solves += 1
                If _z(t) > 0 Then Exit Do
                ' Only rounding can make a newly added, approaching contact pull; Lawson and Hanson reject it.
                RemovePassive(t)
                _rejected(t) = True
                _qr.RemoveLast()
                If solves >= solveCap Then Return False
            Loop

            ' Inner steps: while some passive contact would pull, move towards the new solution only until
            ' its impulse reaches zero, drop it, and solve again.
            Do
                If AllPassivePush() Then
                    For p = 0 To _passiveCount - 1
                        Dim k = _passive(p)
                        _x(k) = _z(k)
                    Next
                    Array.Copy(_x, _lambda, _contacts)
                    Array.Copy(_trial, _r, _rows)
                    UpdateApproaches()
                    Exit Do
                End If
                If solves >= solveCap Then Return False
                StepBackAndDrop()
                _qr.Factor(_matrix, _rows, _passive, _passiveCount)
                SolvePassive()
                solves += 1
            Loop
            If solves >= solveCap Then Return MostApproaching(tolerance) < 0
        Loop
    End Function

    ' The unconstrained least-squares solution on the passive set, as factored: impulses in _z, scaled velocities in _trial.
    Private Sub SolvePassive()
        Dim count = _passiveCount
        HouseholderQr.Grow(_pivoted, count)
        ' The residual d − C z comes out of the QR; the scaled velocities are r = C z − d.
        _qr.LeastSquares(_d, _pivoted, _work)
        For s = 0 To count - 1
            _z(_qr.Column(s)) = _pivoted(s)
        Next
        For i = 0 To _rows - 1
            _trial(i) = -_work(i)
        Next

        ' Refinement: the passive contacts' normal velocities g_P should be zero. The smallest change of
        ' r (in the energy metric) that makes them so is −C_P μ with C_Pᵀ C_P μ = g_P, and it changes the
        ' impulses by −μ. The first step also brings in the immovable bodies' share c of g.
        For stepIndex = 1 To RefinementSteps
            For s = 0 To count - 1
                _pivoted(s) = NormalVelocityOf(_trial, _qr.Column(s), scaled:=True)
            Next
            _qr.MinimalStep(_pivoted, _work)
            For i = 0 To _rows - 1
                _trial(i) -= _work(i)
            Next
            For s = 0 To count - 1
                _z(_qr.Column(s)) -= _pivoted(s)
            Next
        Next
    End Sub

    ' Lawson–Hanson's interpolation: x ← x + α (z − x) with the largest α ≤ 1 that keeps every impulse
    ' ≥ 0; the contacts whose impulse reaches zero leave the passive set.
    Private Sub StepBackAndDrop()
        Dim alpha = 1.0
        Dim limiting = -1
        For p = 0 To _passiveCount - 1
            Dim k = _passive(p)
            If _z(k) <= 0 AndAlso Not _holds(k) Then
                Dim a = _x(k) / (_x(k) - _z(k))
                If limiting < 0 OrElse a < alpha Then
                    alpha = a
                    limiting = k
                End If
            End If
        Next
        For p = 0 To _passiveCount - 1
            Dim k = _passive(p)
            _x(k) += alpha * (_z(k) - _x(k))
        Next
        _x(limiting) = 0
        Dim kept = 0
        For p = 0 To _passiveCount - 1
            Dim k = _passive(p)
            If _x(k) > 0 OrElse _holds(k) Then
                _passive(kept) = k
                kept += 1
            Else
                _x(k) = 0
                _inPassive(k) = False
            End If
        Next
        _passiveCount = kept
    End Sub

    Private Function AllPassivePush() As Boolean
        For p = 0 To _passiveCount - 1
            If _z(_passive(p)) <= 0 AndAlso Not _holds(_passive(p)) Then Return False
        Next
        Return True
    End Function

    ' The two-sided rows first, each unless it depends on those before it (a second rod between the same two
    ' balls): the least-squares point on them alone is where Lawson–Hanson starts, their impulses of any sign.
    Private Sub SeedHolds()
        For k = 0 To _contacts - 1
            If Not _holds(k) OrElse _columnNorm(k) = 0 Then Continue For
            If _passiveCount > 0 AndAlso _qr.IndependentPart(_matrix, k) <= DependenceTolerance * _columnNorm(k) Then Continue For
            AddPassive(k)
            _qr.Append(_matrix, k)
        Next
        If _passiveCount = 0 Then Return
        SolvePassive()
        For p = 0 To _passiveCount - 1
            Dim k = _passive(p)
            _x(k) = _z(k)
        Next
        Array.Copy(_x, _lambda, _contacts)
        Array.Copy(_trial, _r, _rows)
    End Sub

    ' The contact outside the passive set that approaches fastest (beyond the tolerance), or −1.
    ' Ties go to the lower index, so the path depends only on the input.
    Private Function MostApproaching(tolerance As Double) As Integer
        Dim best = -1
        Dim fastest = tolerance
        For k = 0 To _contacts - 1
            If _inPassive(k) OrElse _rejected(k) OrElse _columnNorm(k) = 0 Then Continue For
            If -_approach(k) > fastest Then
                fastest = -_approach(k)
                best = k
            End If
        Next
        Return best
    End Function

    Private Sub UpdateApproaches()
        For k = 0 To _contacts - 1
            _approach(k) = NormalVelocityOf(_r, k, scaled:=True)
        Next
    End Sub

    ' g_k from slot velocities, or from scaled velocities r = M^(1/2) u when scaled is True.
    Private Function NormalVelocityOf(v As Double(), k As Integer, scaled As Boolean) As Double
        Dim dvx = 0.0
        Dim dvy = 0.0
        Dim a = _slotA(k)
        If a >= 0 Then
            Dim f = If(scaled, _sqrtInverseMass(a), 1.0)
            dvx += v(2 * a) * f
            dvy += v(2 * a + 1) * f
        End If
        Dim b = _slotB(k)
        If b >= 0 Then
            Dim f = If(scaled, _sqrtInverseMass(b), 1.0)
            dvx -= v(2 * b) * f
            dvy -= v(2 * b + 1) * f
        End If
        Return _nx(k) * dvx + _ny(k) * dvy + _offset(k)
    End Function

    Private Sub AddPassive(k As Integer)
        _passive(_passiveCount) = k
        _passiveCount += 1
        _inPassive(k) = True
    End Sub

    Private Sub RemovePassive(k As Integer)
        Dim kept = 0
        For p = 0 To _passiveCount - 1
            If _passive(p) <> k Then
                _passive(kept) = _passive(p)
                kept += 1
            End If
        Next
        _passiveCount = kept
        _inPassive(k) = False
        _x(k) = 0
    End Sub

    Private Sub AddSlot(body As Integer, inverseMasses As IReadOnlyList(Of Double))
        If inverseMasses(body) > 0 AndAlso _slotOfBody(body) < 0 Then
            _slotOfBody(body) = _slotCount
            _bodyOfSlot(_slotCount) = body
            _slotCount += 1
        End If
    End Sub

    Private Sub GrowPerContact()
        Dim m = _contacts
        If _slotA.Length < m Then
            _slotA = New Integer(m - 1) {}
            _slotB = New Integer(m - 1) {}
            _passive = New Integer(m - 1) {}
            _inPassive = New Boolean(m - 1) {}
            _rejected = New Boolean(m - 1) {}
            _holds = New Boolean(m - 1) {}
        End If
        HouseholderQr.Grow(_nx, m)
        HouseholderQr.Grow(_ny, m)
        HouseholderQr.Grow(_offset, m)
        HouseholderQr.Grow(_columnNorm, m)
        HouseholderQr.Grow(_lambda, m)
        HouseholderQr.Grow(_x, m)
        HouseholderQr.Grow(_z, m)
        HouseholderQr.Grow(_approach, m)
    End Sub
End Class
