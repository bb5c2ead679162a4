Option Strict On

''' <summary>
''' A collision of linked bodies, resolved with the links' own impulses in the same solve. Each row is one
''' condition on the speed at which two points separate along a unit vector u (from end A to end B), after
''' the blow: the contact's row asks for −e times the speed it arrived at (Newton's experimental law), each
''' rod and taut string touching these bodies for 0 (it keeps its length). Row i's impulse λᵢ acts on its
''' ends equally and oppositely (v_A −= λ u/m_A, v_B += λ u/m_B), so momentum is conserved between bodies
''' (a fixed point takes what acts on it); a contact can only push (λ ≥ 0), a string only pull (λ ≤ 0),
''' a rod both. The rows are solved by projected Gauss–Seidel sweeps, which converge for these small,
''' well-conditioned systems. With e = 1 no energy is lost: every link's impulse does no work (its ends'
''' separation speed is 0 before and after), and the contact's does none either (the speed is reversed).
''' </summary>
Friend NotInheritable Class LinkedImpulse
    Private Const MaxSweeps As Integer = 10000

    Private ReadOnly _bodies As New List(Of Shape)
    Private ReadOnly _velocities As New List(Of Vector)
    Private ReadOnly _rows As New List(Of Row)

    Private Structure Row
        Public A As Integer
        Public B As Integer
        Public U As Vector
        Public Target As Double
        Public Lower As Double
        Public Upper As Double
        Public Impulse As Double
        ''' <summary>A contact (it pushes only), not a link.</summary>
        Public IsContact As Boolean
    End Structure

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
        Dim row As New Row With {.A = IndexOf(a), .B = If(b Is Nothing, -1, IndexOf(b)), .U = normal, .Lower = 0, .Upper = Double.PositiveInfinity, .IsContact = True}
        row.Target = -restitution * Math.Min(SeparationSpeed(row), 0)
        _rows.Add(row)
    End Sub

    ''' <summary>A rod or a taut string that holds its length through the blow.</summary>
    Friend Sub AddLink(link As Link)
        Dim r = link.EndB - link.EndA
        Dim row As New Row With {.A = IndexOf(link.A), .B = IndexOf(link.B), .U = r.Normalized(Vector.Zero), .Target = 0,
                                 .Lower = Double.NegativeInfinity,
                                 .Upper = If(link.Kind = LinkKind.String, 0, Double.PositiveInfinity)}
        _rows.Add(row)
    End Sub

    Private Function SeparationSpeed(row As Row) As Double
        Dim va = If(row.A >= 0, _velocities(row.A), Vector.Zero)
        Dim vb = If(row.B >= 0, _velocities(row.B), Vector.Zero)
        Return Vector.Dot(vb - va, row.U)
    End Function

    Private Function InverseMass(i As Integer) As Double
        Return If(i >= 0, _bodies(i).InverseMass, 0)
    End Function

    ''' <summary>Solves the rows and writes the new velocities to the bodies.</summary>
    Friend Sub Resolve()
        Sweep()
        WriteVelocities()
    End Sub

    ''' <summary>
    ''' Solves the rows as one blow in two phases (Poisson's hypothesis), for bodies wedged among contacts that
    ''' pairwise blows pass back and forth for ever (a ball caged with no room between the ends of a rod): first
    ''' every contact only stops its approach (target 0), which projects the velocities onto those that approach
    ''' nowhere; then each contact gives back <paramref name="restitution"/> times the impulse it took, and what
    ''' that sends into another contact is stopped again. The projection is orthogonal in the kinetic-energy
    ''' metric, so the energy after the first phase is the energy before less that of the change; giving back
    ''' at most all of the change (e ≤ 1) gains nothing, and stopping again only loses.
    ''' </summary>
    Friend Sub ResolveWedged(restitution As Double)
        For i = 0 To _rows.Count - 1
            Dim row = _rows(i)
            If row.IsContact Then row.Target = 0
            _rows(i) = row
        Next
        Sweep()
        For i = 0 To _rows.Count - 1
            Dim row = _rows(i)
            If row.IsContact AndAlso row.Impulse > 0 Then
                Dim give = restitution * row.Impulse
                If row.A >= 0 Then _velocities(row.A) -= row.U * (give * InverseMass(row.A))
                If row.B >= 0 Then _velocities(row.B) += row.U * (give * InverseMass(row.B))
            End If
            row.Impulse = 0
            _rows(i) = row
        Next
        Sweep()
        WriteVelocities()
    End Sub

    ''' <summary>Projected Gauss–Seidel sweeps over the rows, from the impulses they hold, until nothing changes.</summary>
    Private Sub Sweep()
        Dim scale = 0.0
        For Each v In _velocities
            scale = Math.Max(scale, v.Length)
        Next
        For pass = 1 To MaxSweeps
            Dim change = 0.0
            For i = 0 To _rows.Count - 1
                Dim row = _rows(i)
                Dim w = InverseMass(row.A) + InverseMass(row.B)
                If w = 0 OrElse row.U = Vector.Zero Then Continue For
                Dim wanted = row.Impulse + (row.Target - SeparationSpeed(row)) / w
                wanted = Math.Min(Math.Max(wanted, row.Lower), row.Upper)
                Dim delta = wanted - row.Impulse
                If delta = 0 Then Continue For
                row.Impulse = wanted
                _rows(i) = row
                If row.A >= 0 Then _velocities(row.A) -= row.U * (delta * InverseMass(row.A))
                If row.B >= 0 Then _velocities(row.B) += row.U * (delta * InverseMass(row.B))
                change = Math.Max(change, Math.Abs(delta) * w)
            Next
            If change <= 0.000000000000001 * scale Then Exit For
        Next
    End Sub

    Private Sub WriteVelocities()
        For i = 0 To _bodies.Count - 1
            _bodies(i).Velocity = _velocities(i)
        Next
    End Sub
End Class
