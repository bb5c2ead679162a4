Option Strict On

''' <summary>
''' Cholesky's factor of a group's M = J W Jᵀ (see <see cref="ConstraintSet"/>) grown one constraint at a time,
''' for asking which rows of a list each add something to those kept before them. Each row is factored by
''' <see cref="ConstraintSet.FactorRow"/>, as <see cref="ConstraintSet"/> factors its own, so the answer is the same
''' to the last bit as that of a full factorization of the kept rows and the new one; asking costs k² per row
''' instead of a new factorization's k³.
''' </summary>
Friend NotInheritable Class GrowingFactor
    Private ReadOnly _inverseMass As Double()
    Private ReadOnly _independence As Double
    Private ReadOnly _rows As New List(Of Constraint)
    Private ReadOnly _directions As New List(Of Vector)
    ' Row k of L for each kept row k (the rows beyond the count are spare).
    Private _factor As Double()() = Array.Empty(Of Double())()

    ''' <param name="inverseMass">per body, 1/kg (0 for a body that cannot move)</param>
    ''' <param name="independence">a row is refused when its pivot is not above this fraction of its own M_kk, as <see cref="ConstraintSet"/> refuses it</param>
    Friend Sub New(inverseMass As Double(), independence As Double)
        _inverseMass = inverseMass
        _independence = independence
    End Sub

    ''' <summary>
    ''' Keeps constraint <paramref name="row"/>, pointing along <paramref name="direction"/> at the state being asked
    ''' about, and returns True, if it is independent of the rows kept so far; otherwise leaves the factor as it was.
    ''' </summary>
    Friend Function TryAdd(row As Constraint, direction As Vector) As Boolean
        Dim k = _rows.Count
        Dim lk(k) As Double
        For j = 0 To k - 1
            Dim s = ConstraintSet.SharedInverseMass(row, _rows(j), _inverseMass)
            If s <> 0 Then s *= direction.X * _directions(j).X + direction.Y * _directions(j).Y
            lk(j) = s
        Next
        If Not ConstraintSet.FactorRow(_factor, lk, k, ConstraintSet.SharedInverseMass(row, row, _inverseMass), _independence) Then Return False
        If _factor.Length <= k Then Array.Resize(_factor, 2 * (k + 1))
        _factor(k) = lk
        _rows.Add(row)
        _directions.Add(direction)
        Return True
    End Function

    ''' <summary>Forgets the row kept last.</summary>
    Friend Sub RemoveLast()
        Dim last = _rows.Count - 1
        _rows.RemoveAt(last)
        _directions.RemoveAt(last)
        _factor(last) = Nothing
    End Sub
End Class
