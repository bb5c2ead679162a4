Option Strict On

''' <summary>
''' The complementarity problem of frictionless contact (docs/contact.md): given each body's free value x₀ (its
''' velocity before a blow, or its acceleration under gravity and springs alone) and rows
''' (<see cref="ContactRow"/>), find forces λ and values x = x₀ + M⁻¹ Jᵀ λ such that every pushing row has
''' value ≥ 0 and force ≥ 0 and not both &gt; 0, and every holding row has value 0. Equivalently x is the point
''' closest to x₀ in the kinetic-energy metric (Σ m |x − x₀|²) that meets every row: a convex problem, so x is
''' unique whatever the rows, even when the forces are not (a box on two tables side by side can rest on
''' either). Solved exactly by Lawson and Hanson's active-set method on its dual (<see cref="ContactProjection"/>),
''' holding rows first: the forces of pushing rows that another row already implies are left at 0. A pure
''' function of its arguments; the instance only keeps buffers between calls.
''' </summary>
Friend NotInheritable Class ContactSolve
    ''' <summary>A row counts as met when its value is above −this × the scale of the values given.</summary>
    Friend Const ApproachTolerance As Double = 0.000000000001

    Private ReadOnly _projection As New ContactProjection()
    Private _contacts As ClusterContact() = Array.Empty(Of ClusterContact)()

    ''' <summary>
    ''' Solves the problem for bodies with <paramref name="inverseMasses"/> (1/kg; 0 for a body nothing moves, whose
    ''' value stays its free one) and free values <paramref name="free"/>. Writes each body's value to
    ''' <paramref name="result"/> and each row's force to <paramref name="forces"/>. A row counts as met within
    ''' <paramref name="tolerance"/> (m/s or m/s²). Returns False if the method's guard against cycling stopped it
    ''' (the result is then the last point it accepted).
    ''' </summary>
    Friend Function Solve(inverseMasses As IReadOnlyList(Of Double), free As IReadOnlyList(Of Vector), rows As IReadOnlyList(Of ContactRow),
                          tolerance As Double, result As Vector(), forces As Double()) As Boolean
        Dim n = free.Count
        For i = 0 To n - 1
            result(i) = free(i)
        Next
        Dim m = rows.Count
        Array.Clear(forces, 0, m)
        If m = 0 Then Return True
        If _contacts.Length < m Then _contacts = New ClusterContact(m - 1) {}
        Dim offsets(m - 1) As Double, holds(m - 1) As Boolean
        For k = 0 To m - 1
            Dim r = rows(k)
            ' The projection wants a body at A: a row with none there is the same row seen from B, along −u.
            If r.A = ContactRow.None Then
                _contacts(k) = New ClusterContact(r.B, ClusterContact.World, -r.Direction)
            Else
                _contacts(k) = New ClusterContact(r.A, If(r.B = ContactRow.None, ClusterContact.World, r.B), r.Direction)
            End If
            offsets(k) = r.Offset
            holds(k) = r.Holds
        Next
        _projection.Load(inverseMasses, free, New ArraySegment(Of ClusterContact)(_contacts, 0, m), offsets, holds)
        Dim slots = _projection.SlotCount
        Dim start(2 * slots - 1) As Double, projected(2 * slots - 1) As Double
        For s = 0 To slots - 1
            Dim v = free(_projection.BodyOfSlot(s))
            start(2 * s) = v.X
            start(2 * s + 1) = v.Y
        Next
        Dim converged = _projection.Project(start, tolerance, projected, forces)
        For s = 0 To slots - 1
            result(_projection.BodyOfSlot(s)) = New Vector(projected(2 * s), projected(2 * s + 1))
        Next
        Return converged
    End Function
End Class
