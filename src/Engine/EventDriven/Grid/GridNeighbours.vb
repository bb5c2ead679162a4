Option Strict On

''' <summary>The movable bodies near one body: those in the 3 × 3 cells around it, and the oversized ones.</summary>
Friend Module GridNeighbours
    ''' <summary>
    ''' Fills <paramref name="list"/> with the movable bodies in the 3 × 3 cells around body i and the
    ''' bodies too large for the grid (every body, if i itself is one of those); returns how many.
    ''' </summary>
    Friend Function Collect(s As SolverState, i As Integer, list As Integer()) As Integer
        Dim count = 0
        Dim slot = s.Bodies.Slot
        Dim grid = s.Grid
        If slot(i).Cell < 0 Then
            For j = 0 To s.Bodies.Count - 1
                If j <> i Then list(count) = j : count += 1
            Next
            Return count
        End If
        Dim col = slot(i).Col, row = slot(i).Row
        For rr = Math.Max(0, row - 1) To Math.Min(grid.Ny - 1, row + 1)
            For cc = Math.Max(0, col - 1) To Math.Min(grid.Nx - 1, col + 1)
                Dim cell = rr * grid.Nx + cc
                For lane = cell * UniformGrid.Lanes To cell * UniformGrid.Lanes + grid.Count(cell) - 1
                    Dim j = grid.LaneBody(lane)
                    If j <> i AndAlso count < list.Length Then list(count) = j : count += 1
                Next
                Dim o = grid.OverflowHead(cell)
                While o >= 0
                    If o <> i AndAlso count < list.Length Then list(count) = o : count += 1
                    o = grid.OverflowNext(o)
                End While
            Next
        Next
        For k = 0 To s.OversizedCount - 1
            If s.Oversized(k) <> i AndAlso count < list.Length Then list(count) = s.Oversized(k) : count += 1
        Next
        Return count
    End Function
End Module
