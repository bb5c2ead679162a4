Option Strict On

Imports Xunit

''' <summary>
''' <see cref="HouseholderQr.Append"/>: a factorization grown column by column solves the same least-squares problems as
''' one made anew from all the columns, and <see cref="HouseholderQr.RemoveLast"/> undoes an append.
''' </summary>
Public Class HouseholderQrTests
    ''' <summary>A rows × columns column-major matrix with entries in [−1, 1), rows scaled by up to 10⁶ as bodies' 1/√m are.</summary>
    Private Shared Function RandomMatrix(random As Random, rows As Integer, columns As Integer) As Double()
        Dim rowScale(rows - 1) As Double
        For i = 0 To rows - 1
            rowScale(i) = 10 ^ (6 * random.NextDouble())
        Next
        Dim m(rows * columns - 1) As Double
        For j = 0 To columns - 1
            For i = 0 To rows - 1
                m(j * rows + i) = (2 * random.NextDouble() - 1) * rowScale(i)
            Next
        Next
        Return m
    End Function

    ''' <summary>The least-squares solution per matrix column (not pivot order) and the residual, from a factorization.</summary>
    Private Shared Sub Solve(qr As HouseholderQr, rows As Integer, columns As Integer, rhs As Double(), ByRef x As Double(), ByRef residual As Double())
        Dim pivoted(qr.Count - 1) As Double
        residual = New Double(rows - 1) {}
        qr.LeastSquares(rhs, pivoted, residual)
        x = New Double(columns - 1) {}
        For s = 0 To qr.Count - 1
            x(qr.Column(s)) = pivoted(s)
        Next
    End Sub

    <Theory>
    <InlineData(1, 12, 6)>
    <InlineData(2, 20, 20)>
    <InlineData(3, 40, 25)>
    Public Sub Appending_SolvesAsFactoringAnew(seed As Integer, rows As Integer, columns As Integer)
        Dim random As New Random(seed)
        Dim matrix = RandomMatrix(random, rows, columns)
        Dim rhs(rows - 1) As Double
        For i = 0 To rows - 1
            rhs(i) = 2 * random.NextDouble() - 1
        Next
        Dim order = Enumerable.Range(0, columns).ToArray()

        Dim whole As New HouseholderQr()
        whole.Factor(matrix, rows, order, columns)
        Dim grown As New HouseholderQr()
        grown.Factor(matrix, rows, order, 0)
        For j = 0 To columns - 1
            grown.Append(matrix, j)
        Next
        Assert.Equal(columns, grown.Count)

        Dim x1 As Double() = Nothing, r1 As Double() = Nothing, x2 As Double() = Nothing, r2 As Double() = Nothing
        Solve(whole, rows, columns, rhs, x1, r1)
        Solve(grown, rows, columns, rhs, x2, r2)
        Dim xScale = x1.Max(Function(v) Math.Abs(v))
        For j = 0 To columns - 1
            Assert.True(Math.Abs(x1(j) - x2(j)) <= 0.000000001 * xScale, $"column {j}: {x1(j)} anew, {x2(j)} grown")
        Next
        For i = 0 To rows - 1
            Assert.True(Math.Abs(r1(i) - r2(i)) <= 0.000000001, $"row {i} of the residual: {r1(i)} anew, {r2(i)} grown")
        Next
    End Sub

    <Fact>
    Public Sub RemoveLast_UndoesTheLastAppend()
        Dim random As New Random(7)
        Const rows = 10, columns = 5
        Dim matrix = RandomMatrix(random, rows, columns)
        Dim rhs(rows - 1) As Double
        For i = 0 To rows - 1
            rhs(i) = 2 * random.NextDouble() - 1
        Next
        Dim columnsFactored = Enumerable.Range(0, 3).ToArray()
        Dim firstThree As New HouseholderQr()
        firstThree.Factor(matrix, rows, columnsFactored, 3)
        Dim qr As New HouseholderQr()
        qr.Factor(matrix, rows, columnsFactored, 3)
        qr.Append(matrix, 4)
        qr.RemoveLast()
        Assert.Equal(3, qr.Count)
        Dim x1 As Double() = Nothing, r1 As Double() = Nothing, x2 As Double() = Nothing, r2 As Double() = Nothing
        Solve(firstThree, rows, columns, rhs, x1, r1)
        Solve(qr, rows, columns, rhs, x2, r2)
        For j = 0 To columns - 1
            Assert.True(Math.Abs(x1(j) - x2(j)) <= 0.000000000001 * (1 + Math.Abs(x1(j))), $"column {j}: {x1(j)} and {x2(j)}")
        Next
        Assert.Equal(0.0, x2(4))
    End Sub
End Class
