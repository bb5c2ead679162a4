Option Strict On

''' <summary>
''' Finds the overlapping pairs of movable circles without testing every pair: a uniform grid whose
''' cells are one largest diameter wide, so two circles that touch have centres in the same or
''' neighbouring cells. Each cell is checked against itself and four of its neighbours (right, and the
''' three above), so every pair is met once. Cost grows with N, not N², for circles of similar size.
''' </summary>
Friend NotInheritable Class BroadPhase
    Private _movable As Integer() = Array.Empty(Of Integer)()
    Private _cellOf As Integer() = Array.Empty(Of Integer)()
    Private _sorted As Integer() = Array.Empty(Of Integer)()
    Private _start As Integer() = Array.Empty(Of Integer)()
    Private _fill As Integer() = Array.Empty(Of Integer)()

    ''' <summary>
    ''' Pairs are kept when their gap is under this fraction of their radii's sum: the later contact phases
    ''' of the same step (the floor pushing a ball up into the one resting on it, say) may close a gap that
    ''' was a rounding error wide when the pairs were found.
    ''' </summary>
    Friend Const Margin As Double = 0.05

    ''' <summary>
    ''' Fills <paramref name="pairs"/> with the index pairs (into <paramref name="circles"/>, smaller first)
    ''' of movable circles that overlap, touch, or nearly touch (see <see cref="Margin"/>) now.
    ''' </summary>
    Friend Sub FindOverlaps(circles As IReadOnlyList(Of Circle), pairs As List(Of (A As Integer, B As Integer)))
        pairs.Clear()
        If _movable.Length < circles.Count Then
            _movable = New Integer(circles.Count - 1) {}
            _cellOf = New Integer(circles.Count - 1) {}
            _sorted = New Integer(circles.Count - 1) {}
        End If
        Dim m = 0
        Dim minX = Double.MaxValue, minY = Double.MaxValue, maxX = Double.MinValue, maxY = Double.MinValue, maxR = 0.0
        For i = 0 To circles.Count - 1
            Dim c = circles(i)
            If c.IsFixed OrElse Not c.Position.IsFinite Then Continue For
            _movable(m) = i
            m += 1
            minX = Math.Min(minX, c.Position.X) : maxX = Math.Max(maxX, c.Position.X)
            minY = Math.Min(minY, c.Position.Y) : maxY = Math.Max(maxY, c.Position.Y)
            maxR = Math.Max(maxR, c.Radius)
        Next
        If m < 2 Then Return

        ' A sparse scene (a few circles far apart) would need a huge grid: widen the cells instead, which
        ' stays correct because wider cells still hold every touching pair in neighbouring cells.
        Dim cell = 2 * maxR * (1 + Margin)
        Dim maxCells = 4.0 * m + 16
        Do While (Math.Floor((maxX - minX) / cell) + 1) * (Math.Floor((maxY - minY) / cell) + 1) > maxCells
            cell *= 2
        Loop
        Dim cols = CInt(Math.Floor((maxX - minX) / cell)) + 1
        Dim rows = CInt(Math.Floor((maxY - minY) / cell)) + 1
        Dim cellCount = cols * rows
        If _start.Length < cellCount + 1 Then
            _start = New Integer(cellCount) {}
            _fill = New Integer(cellCount) {}
        End If
        Array.Clear(_start, 0, cellCount + 1)

        ' Counting sort of the movable circles by cell.
        For k = 0 To m - 1
            Dim p = circles(_movable(k)).Position
            Dim cx = Math.Min(cols - 1, CInt(Math.Floor((p.X - minX) / cell)))
            Dim cy = Math.Min(rows - 1, CInt(Math.Floor((p.Y - minY) / cell)))
            Dim key = cy * cols + cx
            _cellOf(k) = key
            _start(key + 1) += 1
        Next
        For key = 0 To cellCount - 1
            _start(key + 1) += _start(key)
        Next
        Array.Copy(_start, _fill, cellCount)
        For k = 0 To m - 1
            Dim key = _cellOf(k)
            _sorted(_fill(key)) = _movable(k)
            _fill(key) += 1
        Next

        For cy = 0 To rows - 1
            For cx = 0 To cols - 1
                Dim key = cy * cols + cx
                For s = _start(key) To _start(key + 1) - 1
                    Dim i = _sorted(s)
                    For t = s + 1 To _start(key + 1) - 1
                        Test(circles, i, _sorted(t), pairs)
                    Next
                    If cx + 1 < cols Then TestCell(circles, i, key + 1, pairs)
                    If cy + 1 < rows Then
                        If cx > 0 Then TestCell(circles, i, key + cols - 1, pairs)
                        TestCell(circles, i, key + cols, pairs)
                        If cx + 1 < cols Then TestCell(circles, i, key + cols + 1, pairs)
                    End If
                Next
            Next
        Next
    End Sub

    Private Sub TestCell(circles As IReadOnlyList(Of Circle), i As Integer, key As Integer, pairs As List(Of (A As Integer, B As Integer)))
        For t = _start(key) To _start(key + 1) - 1
            Test(circles, i, _sorted(t), pairs)
        Next
    End Sub

    Private Shared Sub Test(circles As IReadOnlyList(Of Circle), i As Integer, j As Integer, pairs As List(Of (A As Integer, B As Integer)))
        Dim a = circles(i), b = circles(j)
        Dim dx = a.Position.X - b.Position.X
        Dim dy = a.Position.Y - b.Position.Y
        Dim reach = (a.Radius + b.Radius) * (1 + Margin)
        If dx * dx + dy * dy <= reach * reach Then pairs.Add(If(i < j, (i, j), (j, i)))
    End Sub
End Class
