Option Strict On

''' <summary>
''' Householder QR with row and column pivoting of a few chosen columns of a dense column-major matrix:
''' P C[:, cols] Π = Q R. It is what <see cref="ContactProjection"/> solves its least-squares problems
''' with. Orthogonal transformations, never the normal equations: the contact matrices have condition
''' numbers up to √(mass ratio) ≈ 10⁶, which the normal equations would square to 10¹².
''' </summary>
''' <remarks>
''' The rows differ in scale by as much as the bodies' 1/√m (10⁶ across a cluster). Householder QR is
''' row-wise backward stable in that case when the columns are pivoted by norm and, at each step, the
''' pivot row is the remaining row with the largest entry in the pivot column (Powell and Reid, 1969;
''' Cox and Higham, 1998). Row pivoting matters here for a second reason: a reflector only mixes its
''' pivot row with rows where its column is non-zero, so a body that no factored contact touches keeps
''' its rows exactly, instead of picking up rounding from heavy bodies that 1/√m then magnifies.
''' The buffers are kept between calls, so refactoring costs no allocation.
''' </remarks>
Friend NotInheritable Class HouseholderQr
    ' Column-major rows × Count. Column s holds R(i, s) at row _rowOrder(i) for i ≤ s and the
    ' Householder vector of step s at rows _rowOrder(s + 1 …); rows are never moved.
    Private _f As Double() = Array.Empty(Of Double)()
    ' The pivot entry of each Householder vector (the slot for it holds R's diagonal).
    Private _pivotPart As Double() = Array.Empty(Of Double)()
    Private _columnOrder As Integer() = Array.Empty(Of Integer)()
    Private _rowOrder As Integer() = Array.Empty(Of Integer)()
    Private _scratch As Double() = Array.Empty(Of Double)()
    Private _rows As Integer

    ''' <summary>Number of columns factored.</summary>
    Friend Property Count As Integer

    ''' <summary>The matrix column at pivot position s (0 ≤ s &lt; Count).</summary>
    Friend ReadOnly Property Column(s As Integer) As Integer
        Get
            Return _columnOrder(s)
        End Get
    End Property

    ''' <summary>
    ''' Factors the columns <paramref name="cols"/>(0 … count − 1) of the rows × (any) column-major matrix
    ''' <paramref name="matrix"/>. Ties in either pivot choice go to the earlier column or row, so the
    ''' result depends only on the input.
    ''' </summary>
    Friend Sub Factor(matrix As Double(), rows As Integer, cols As Integer(), count As Integer)
        _rows = rows
        Me.Count = count
        Grow(_f, rows * count)
        Grow(_pivotPart, count)
        Grow(_scratch, rows)
        If _columnOrder.Length < count Then _columnOrder = New Integer(count - 1) {}
        If _rowOrder.Length < rows Then _rowOrder = New Integer(rows - 1) {}
        For i = 0 To rows - 1
            _rowOrder(i) = i
        Next
        For j = 0 To count - 1
            _columnOrder(j) = cols(j)
            Array.Copy(matrix, cols(j) * rows, _f, j * rows, rows)
        Next
        For s = 0 To count - 1
            ' Sums of squares suffice to compare the columns (the entries, at most 1/√m, cannot overflow
            ' when squared for any mass above 10⁻³⁰⁰ kg); the reflector itself uses the scaled norm.
            Dim best = s
            Dim bestSquares = RemainingSquares(s * rows, s)
            For j = s + 1 To count - 1
                Dim squares = RemainingSquares(j * rows, s)
                If squares > bestSquares Then
                    best = j
                    bestSquares = squares
                End If
            Next
            If best <> s Then SwapColumns(s, best)
            ChoosePivotRow(s)
            MakeReflector(s, RemainingNorm(_f, s * rows, s))
            For j = s + 1 To count - 1
                Reflect(s, _f, j * rows)
            Next
        Next
    End Sub

    ''' <summary>
    ''' Extends the factorization by column <paramref name="col"/> of the same <paramref name="matrix"/> as the last
    ''' <see cref="Factor"/>: the reflectors so far are applied to it and one more is made, at a cost of rows × Count
    ''' instead of a new factorization's rows × Count². The earlier columns keep their pivot order (the new one
    ''' comes last whatever its norm); the pivot row is chosen as in <see cref="Factor"/>. Rows already used as
    ''' pivots are untouched by the new reflector, so the earlier ones still describe the same Q.
    ''' </summary>
    Friend Sub Append(matrix As Double(), col As Integer)
        Dim s = Count
        If _f.Length < _rows * (s + 1) Then Array.Resize(_f, 2 * _rows * (s + 1))
        If _pivotPart.Length < s + 1 Then Array.Resize(_pivotPart, 2 * (s + 1))
        If _columnOrder.Length < s + 1 Then Array.Resize(_columnOrder, 2 * (s + 1))
        _columnOrder(s) = col
        Dim at = s * _rows
        Array.Copy(matrix, col * _rows, _f, at, _rows)
        For r = 0 To s - 1
            Reflect(r, _f, at)
        Next
        ChoosePivotRow(s)
        MakeReflector(s, RemainingNorm(_f, at, s))
        Count = s + 1
    End Sub

    ''' <summary>Drops the column appended last (<see cref="Append"/>, or the last of <see cref="Factor"/>).</summary>
    Friend Sub RemoveLast()
        Count -= 1
    End Sub

    ''' <summary>
    ''' The least-squares solution of C[:, cols] x ≈ <paramref name="rhs"/>: x in pivot order (Count entries)
    ''' into <paramref name="solution"/>, and the residual rhs − C x (one entry per row) into
    ''' <paramref name="residual"/>, computed as Q [0; (Qᵀ rhs) below row Count], which is accurate in
    ''' every row however large x is.
    ''' </summary>
    Friend Sub LeastSquares(rhs As Double(), solution As Double(), residual As Double())
        Array.Copy(rhs, residual, _rows)
        ApplyQTranspose(residual)
        For i = 0 To Count - 1
            solution(i) = residual(_rowOrder(i))
            residual(_rowOrder(i)) = 0
        Next
        SolveR(solution)
        ApplyQ(residual)
    End Sub

    ''' <summary>
    ''' For G = C[:, cols]: the smallest step δ (one entry per row) with Gᵀ δ = <paramref name="target"/>
    ''' (pivot order), which is δ = G μ with μ = (GᵀG)⁻¹ target. Writes δ to <paramref name="stepOut"/> and μ
    ''' (pivot order) over <paramref name="target"/>. Uses R only (RᵀR = Πᵀ GᵀG Π), so its error grows with
    ''' the square of G's condition number: meant for small corrections.
    ''' </summary>
    Friend Sub MinimalStep(target As Double(), stepOut As Double())
        SolveRTranspose(target)
        Array.Clear(stepOut, 0, _rows)
        For i = 0 To Count - 1
            stepOut(_rowOrder(i)) = target(i)
        Next
        ApplyQ(stepOut)
        SolveR(target)
    End Sub

    ''' <summary>
    ''' ‖(Qᵀ c) below row Count‖: the length of the part of column <paramref name="col"/> of
    ''' <paramref name="matrix"/> that the factored columns cannot make. Zero (to rounding) when the
    ''' column depends linearly on them.
    ''' </summary>
    Friend Function IndependentPart(matrix As Double(), col As Integer) As Double
        Array.Copy(matrix, col * _rows, _scratch, 0, _rows)
        ApplyQTranspose(_scratch)
        Return RemainingNorm(_scratch, 0, Count)
    End Function

    ''' <summary>‖v(offset + i)‖ over all rows i, scaled so that it cannot overflow.</summary>
    Friend Shared Function Norm(v As Double(), offset As Integer, rows As Integer) As Double
        Dim biggest = 0.0
        For i = 0 To rows - 1
            biggest = Math.Max(biggest, Math.Abs(v(offset + i)))
        Next
        If biggest = 0 Then Return 0
        Dim sum = 0.0
        For i = 0 To rows - 1
            Dim t = v(offset + i) / biggest
            sum += t * t
        Next
        Return biggest * Math.Sqrt(sum)
    End Function

    ''' <summary>Makes <paramref name="buffer"/> hold at least <paramref name="length"/> entries (contents not kept).</summary>
    Friend Shared Sub Grow(ByRef buffer As Double(), length As Integer)
        If buffer.Length < length Then buffer = New Double(length - 1) {}
    End Sub

    Private Sub ApplyQTranspose(v As Double())
        For s = 0 To Count - 1
            Reflect(s, v, 0)
        Next
    End Sub

    Private Sub ApplyQ(v As Double())
        ' Each reflector is its own inverse, so Q = H₀ H₁ … applies them in reverse order.
        For s = Count - 1 To 0 Step -1
            Reflect(s, v, 0)
        Next
    End Sub

    ' R x = b in place (pivot order).
    Private Sub SolveR(x As Double())
        For i = Count - 1 To 0 Step -1
            Dim row = _rowOrder(i)
            Dim sum = x(i)
            For j = i + 1 To Count - 1
                sum -= _f(j * _rows + row) * x(j)
            Next
            x(i) = sum / _f(i * _rows + row)
        Next
    End Sub

    ' Rᵀ y = b in place (pivot order).
    Private Sub SolveRTranspose(y As Double())
        For i = 0 To Count - 1
            Dim col = i * _rows
            Dim sum = y(i)
            For j = 0 To i - 1
                sum -= _f(col + _rowOrder(j)) * y(j)
            Next
            y(i) = sum / _f(col + _rowOrder(i))
        Next
    End Sub

    ' ‖ entries of the vector at v(offset) in the rows not yet used as pivots (positions from … of the row order) ‖, scaled.
    Private Function RemainingNorm(v As Double(), offset As Integer, from As Integer) As Double
        Dim biggest = 0.0
        For i = from To _rows - 1
            biggest = Math.Max(biggest, Math.Abs(v(offset + _rowOrder(i))))
        Next
        If biggest = 0 Then Return 0
        Dim sum = 0.0
        For i = from To _rows - 1
            Dim t = v(offset + _rowOrder(i)) / biggest
            sum += t * t
        Next
        Return biggest * Math.Sqrt(sum)
    End Function

    Private Function RemainingSquares(offset As Integer, from As Integer) As Double
        Dim sum = 0.0
        For i = from To _rows - 1
            Dim t = _f(offset + _rowOrder(i))
            sum += t * t
        Next
        Return sum
    End Function

    Private Sub SwapColumns(a As Integer, b As Integer)
        For i = 0 To _rows - 1
            Dim t = _f(a * _rows + i)
            _f(a * _rows + i) = _f(b * _rows + i)
            _f(b * _rows + i) = t
        Next
        Dim o = _columnOrder(a)
        _columnOrder(a) = _columnOrder(b)
        _columnOrder(b) = o
    End Sub

    ' The remaining row with the largest entry in column s becomes row position s.
    Private Sub ChoosePivotRow(s As Integer)
        Dim col = s * _rows
        Dim best = s
        Dim biggest = Math.Abs(_f(col + _rowOrder(s)))
        For i = s + 1 To _rows - 1
            Dim a = Math.Abs(_f(col + _rowOrder(i)))
            If a > biggest Then
                best = i
                biggest = a
            End If
        Next
        Dim t = _rowOrder(s)
        _rowOrder(s) = _rowOrder(best)
        _rowOrder(best) = t
    End Sub

    ' Lawson and Hanson's H1: the reflector that zeroes column s in the remaining rows below the pivot.
    ' R(s, s) = ∓‖x‖ with the sign opposite to the pivot entry, so that pivot − R(s, s) adds two numbers of
    ' one sign and never cancels.
    Private Sub MakeReflector(s As Integer, norm As Double)
        Dim pivot = s * _rows + _rowOrder(s)
        If norm = 0 Then
            ' Cannot happen for the independent columns the projection factors; kept harmless anyway.
            _pivotPart(s) = 0
            Return
        End If
        Dim diagonal = If(_f(pivot) > 0, -norm, norm)
        _pivotPart(s) = _f(pivot) - diagonal
        _f(pivot) = diagonal
    End Sub

    ' Lawson and Hanson's H2: applies reflector s, I + u uᵀ / (u_pivot R(s, s)), to the vector at v(offset).
    Private Sub Reflect(s As Integer, v As Double(), offset As Integer)
        Dim up = _pivotPart(s)
        Dim col = s * _rows
        Dim pivotRow = _rowOrder(s)
        Dim b = up * _f(col + pivotRow)
        If b >= 0 Then Return
        Dim sum = v(offset + pivotRow) * up
        For i = s + 1 To _rows - 1
            Dim row = _rowOrder(i)
            sum += v(offset + row) * _f(col + row)
        Next
        If sum = 0 Then Return
        sum /= b
        v(offset + pivotRow) += sum * up
        For i = s + 1 To _rows - 1
            Dim row = _rowOrder(i)
            v(offset + row) += sum * _f(col + row)
        Next
    End Sub
End Class
