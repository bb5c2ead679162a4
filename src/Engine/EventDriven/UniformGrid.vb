Option Strict On

''' <summary>
''' A uniform grid over the container for the event-driven solver. Each cell is at least as wide as
''' the largest gridded circle's diameter, so two gridded circles can touch only when their cells are
''' neighbours (3 × 3). Movable circles are kept in per-cell linked lists (arrays, O(1) moves); the
''' static obstacles (fixed circles, rectangles) are listed in every cell they can be touched from.
''' The outermost cells extend to infinity, so a circle outside the container still has a cell.
''' Fields are Friend so the solver's hot loop reads them directly.
''' </summary>
Friend NotInheritable Class UniformGrid
    Friend Nx As Integer
    Friend Ny As Integer
    ''' <summary>Cell width and height, m.</summary>
    Friend CellWidth As Double
    Friend CellHeight As Double
    ''' <summary>First movable body in each cell, −1 when none.</summary>
    Friend Head As Integer() = Array.Empty(Of Integer)()
    Friend NextInCell As Integer() = Array.Empty(Of Integer)()
    Friend PrevInCell As Integer() = Array.Empty(Of Integer)()
    ''' <summary>Static obstacles of cell c are StaticItems(StaticStart(c)) … StaticItems(StaticStart(c + 1) − 1).</summary>
    Friend StaticStart As Integer() = Array.Empty(Of Integer)()
    Friend StaticItems As Integer() = Array.Empty(Of Integer)()

    ''' <summary>Lays out cells of at least <paramref name="minCell"/> metres over width × height.</summary>
    Friend Sub Layout(width As Double, height As Double, minCell As Double, bodyCount As Integer, maxCells As Integer)
        Nx = CInt(Math.Max(1, Math.Min(4096, Math.Floor(width / minCell))))
        Ny = CInt(Math.Max(1, Math.Min(4096, Math.Floor(height / minCell))))
        While CLng(Nx) * Ny > maxCells AndAlso (Nx > 1 OrElse Ny > 1)
            If Nx >= Ny Then Nx = Math.Max(1, Nx \ 2) Else Ny = Math.Max(1, Ny \ 2)
        End While
        CellWidth = width / Nx
        CellHeight = height / Ny
        Dim cells = Nx * Ny
        If Head.Length < cells Then Head = New Integer(cells - 1) {}
        For c = 0 To cells - 1
            Head(c) = -1
        Next
        If NextInCell.Length < bodyCount Then
            NextInCell = New Integer(bodyCount - 1) {}
            PrevInCell = New Integer(bodyCount - 1) {}
        End If
    End Sub

    Friend Function ColumnOf(x As Double) As Integer
        Dim c = Math.Floor(x / CellWidth)
        If Not (c >= 0) Then Return 0 ' also NaN
        If c >= Nx Then Return Nx - 1
        Return CInt(c)
    End Function

    Friend Function RowOf(y As Double) As Integer
        Dim r = Math.Floor(y / CellHeight)
        If Not (r >= 0) Then Return 0
        If r >= Ny Then Return Ny - 1
        Return CInt(r)
    End Function

    Friend Function CellOf(x As Double, y As Double) As Integer
        Return RowOf(y) * Nx + ColumnOf(x)
    End Function

    Friend Sub Insert(i As Integer, cell As Integer)
        Dim h = Head(cell)
        NextInCell(i) = h
        PrevInCell(i) = -1
        If h >= 0 Then PrevInCell(h) = i
        Head(cell) = i
    End Sub

    Friend Sub Remove(i As Integer, cell As Integer)
        Dim p = PrevInCell(i), n = NextInCell(i)
        If p >= 0 Then NextInCell(p) = n Else Head(cell) = n
        If n >= 0 Then PrevInCell(n) = p
    End Sub

    ''' <summary>
    ''' Lists static obstacle k (bounding box xmin … ymax, m) in every cell from which a gridded circle
    ''' (radius ≤ half a cell) could touch it. Call with all boxes at once.
    ''' </summary>
    Friend Sub SetStatics(xmin As Double(), ymin As Double(), xmax As Double(), ymax As Double(), count As Integer)
        Dim cells = Nx * Ny
        If StaticStart.Length < cells + 1 Then StaticStart = New Integer(cells) {}
        Array.Clear(StaticStart, 0, cells + 1)
        Dim mx = 0.5 * CellWidth, my = 0.5 * CellHeight
        For pass = 0 To 1
            Dim fill As Integer() = Nothing
            If pass = 1 Then
                For c = 1 To cells
                    StaticStart(c) += StaticStart(c - 1)
                Next
                If StaticItems.Length < StaticStart(cells) Then StaticItems = New Integer(StaticStart(cells) - 1) {}
                fill = New Integer(cells - 1) {}
            End If
            For k = 0 To count - 1
                Dim c0 = ColumnOf(xmin(k) - mx), c1 = ColumnOf(xmax(k) + mx)
                Dim r0 = RowOf(ymin(k) - my), r1 = RowOf(ymax(k) + my)
                For row = r0 To r1
                    For col = c0 To c1
                        Dim c = row * Nx + col
                        If pass = 0 Then
                            StaticStart(c + 1) += 1
                        Else
                            StaticItems(StaticStart(c) + fill(c)) = k
                            fill(c) += 1
                        End If
                    Next
                Next
            Next
        Next
    End Sub
End Class
