Option Strict On

''' <summary>
''' Which constraints of a group are independent of one another. Each constraint is a row J (its direction u on
''' body A's two slots, −u on body B's); the forces' matrix of a set of rows is M = J W Jᵀ, W the inverse masses,
''' and it can be solved only if no row lies in the span of the others in the metric W. This keeps an orthonormal
''' basis (Gram–Schmidt in that metric) of the rows accepted so far, and accepts a row when what it adds to their
''' span is at least a given fraction of its own size, squared: the test <see cref="ConstraintSet"/>'s
''' factorization makes, with a margin.
''' <para>
''' A box in a corner pressed into both faces with friction at both: the floor's sticking row (along the floor)
''' repeats the wall's contact row, and is not added; the wall holds the box along the floor already.
''' </para>
''' </summary>
Friend NotInheritable Class RowBasis
    Private ReadOnly _inverseMass As Double()
    Private ReadOnly _fraction As Double
    Private ReadOnly _basis As New List(Of Double())

    ''' <summary>A basis for rows on bodies with <paramref name="inverseMass"/> (1/kg); a row must add <paramref name="fraction"/> of its size squared to count as independent.</summary>
    Friend Sub New(inverseMass As Double(), fraction As Double)
        _inverseMass = inverseMass
        _fraction = fraction
    End Sub

    ''' <summary>Adds <paramref name="c"/>'s row at <paramref name="state"/> if it is independent of those added; returns whether it was.</summary>
    Friend Function TryAdd(c As Constraint, state As Double()) As Boolean
        Dim u As Vector, value As Double, rate As Double, curvature As Double
        c.Measure(state, u, value, rate, curvature)
        Dim j(2 * _inverseMass.Length - 1) As Double
        j(2 * c.A) = u.X
        j(2 * c.A + 1) = u.Y
        If c.B >= 0 Then
            j(2 * c.B) -= u.X
            j(2 * c.B + 1) -= u.Y
        End If
        Dim size = MassMetric.Weighted(_inverseMass, j, j)
        If Not (size > 0) Then Return False
        ' Twice over: one pass of Gram–Schmidt can leave rounding's part of the span behind.
        For pass = 1 To 2
            For Each e In _basis
                Dim p = MassMetric.Weighted(_inverseMass, j, e)
                If p = 0 Then Continue For
                For k = 0 To j.Length - 1
                    j(k) -= p * e(k)
                Next
            Next
        Next
        Dim rest = MassMetric.Weighted(_inverseMass, j, j)
        If Not (rest > _fraction * size) Then Return False
        Dim norm = Math.Sqrt(rest)
        For k = 0 To j.Length - 1
            j(k) /= norm
        Next
        _basis.Add(j)
        Return True
    End Function
End Class
