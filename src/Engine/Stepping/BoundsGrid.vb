Option Strict On

''' <summary>
''' A uniform grid over the bounding boxes of bodies of any shape and size: the one broad phase of the
''' stepping solvers (movable pairs, and the fixed bodies each movable body may touch) and of the
''' <see cref="OverlapResolver"/>. Each item is keyed by the centre of its box into square cells at
''' least as wide as the largest item that is not "large", so two touching items have centres in the
''' same or neighbouring cells, and a box query only visits the cells within half a cell of the box.
''' When cells that wide would be crowded, items more than <see cref="LargeFactor"/> times the median
''' size (a 3 m ramp among 1 mm balls, a big crate among marbles), which would make every cell huge and
''' every test O(N²), are set apart: each is listed in every cell its box covers (or, covering more than
''' <see cref="MaxCellsPerLarge"/> cells, in one list that every query meets). A sparse scene (a few items
''' far apart) widens the cells rather than allocate a huge grid. Items whose centre is not finite are
''' left out.
''' </summary>
Friend NotInheritable Class BoundsGrid
    ''' <summary>An item whose half-size exceeds this many times the median half-size is large (see the class).</summary>
    Friend Const LargeFactor As Double = 4

    ''' <summary>
    ''' Items per cell, on average, above which cells as wide as the largest item are too crowded and
    ''' the large items are set apart; below it one cell size serves every item.
    ''' </summary>
    Friend Const CrowdLimit As Double = 8

    ''' <summary>A large item covering more cells than this is met by every query instead of listed in each cell.</summary>
    Friend Const MaxCellsPerLarge As Integer = 256

    ' Per item: the centre of its box and its half-width and half-height, m.
    Private _cx As Double() = Array.Empty(Of Double)()
    Private _cy As Double() = Array.Empty(Of Double)()
    Private _hx As Double() = Array.Empty(Of Double)()
    Private _hy As Double() = Array.Empty(Of Double)()
    Private _count As Integer
    Private _halves As Double() = Array.Empty(Of Double)()
    Private _smallItems As Integer() = Array.Empty(Of Integer)()
    Private _cellOf As Integer() = Array.Empty(Of Integer)()
    Private _largeItems As Integer() = Array.Empty(Of Integer)()
    Private _fill As Integer() = Array.Empty(Of Integer)()
    ' Large items by cell (CSR: cell k lists _largeInCell(_largeStart(k)) up to _largeStart(k + 1)), and those met everywhere.
    Private _largeStart As Integer() = Array.Empty(Of Integer)()
    Private _largeInCell As Integer() = Array.Empty(Of Integer)()
    Private _everywhere As New List(Of Integer)
    ' Per item: the query that last added it, so an item listed in several cells is added once.
    Private _stamp As Integer() = Array.Empty(Of Integer)()
    Private _query As Integer
    Private _originX As Double
    Private _originY As Double

    ''' <summary>How many items are small (in the cells by centre).</summary>
    Friend ReadOnly Property SmallCount As Integer
    ''' <summary>How many items are large (see the class).</summary>
    Friend ReadOnly Property LargeCount As Integer
    ''' <summary>The small items, sorted by cell (row by row, left to right) and by index within a cell.</summary>
    Friend ReadOnly Property Sorted As Integer() = Array.Empty(Of Integer)()
    ''' <summary>Cell k holds <see cref="Sorted"/>(CellStart(k)) up to but not including <see cref="Sorted"/>(CellStart(k + 1)).</summary>
    Friend ReadOnly Property CellStart As Integer() = Array.Empty(Of Integer)()
    ''' <summary>Columns of cells; cell (cx, cy) is number cy × Columns + cx.</summary>
    Friend ReadOnly Property Columns As Integer
    ''' <summary>Rows of cells.</summary>
    Friend ReadOnly Property Rows As Integer
    ''' <summary>The width of a cell, m.</summary>
    Friend ReadOnly Property Cell As Double
    ''' <summary>The largest half-size of a small item, m.</summary>
    Friend ReadOnly Property SmallHalf As Double

    ''' <summary>Starts a new set of <paramref name="count"/> items; give each one with <see cref="SetItem"/>, then <see cref="Build"/>.</summary>
    Friend Sub Reset(count As Integer)
        If _cx.Length < count Then
            Dim size = Math.Max(count, 2 * _cx.Length)
            _cx = New Double(size - 1) {}
            _cy = New Double(size - 1) {}
            _hx = New Double(size - 1) {}
            _hy = New Double(size - 1) {}
            _halves = New Double(size - 1) {}
            _smallItems = New Integer(size - 1) {}
            _cellOf = New Integer(size - 1) {}
            _largeItems = New Integer(size - 1) {}
            _stamp = New Integer(size - 1) {}
            _Sorted = New Integer(size - 1) {}
        End If
        _count = count
    End Sub

    ''' <summary>Item i's box: its centre (m) and half its width and height (m, ≥ 0).</summary>
    Friend Sub SetItem(i As Integer, centre As Vector, halfWidth As Double, halfHeight As Double)
        _cx(i) = centre.X
        _cy(i) = centre.Y
        _hx(i) = halfWidth
        _hy(i) = halfHeight
    End Sub

    ''' <summary>The x of the centre of item i's box, m.</summary>
    Friend Function CentreX(i As Integer) As Double
        Return _cx(i)
    End Function

    ''' <summary>The y of the centre of item i's box, m.</summary>
    Friend Function CentreY(i As Integer) As Double
        Return _cy(i)
    End Function

    ''' <summary>Half the width of item i's box, m.</summary>
    Friend Function HalfWidth(i As Integer) As Double
        Return _hx(i)
    End Function

    ''' <summary>Half the height of item i's box, m.</summary>
    Friend Function HalfHeight(i As Integer) As Double
        Return _hy(i)
    End Function

    ''' <summary>Large item number k (0 ≤ k &lt; <see cref="LargeCount"/>), in increasing item order.</summary>
    Friend Function Large(k As Integer) As Integer
        Return _largeItems(k)
    End Function

    ''' <summary>
    ''' Sorts the items into cells. Cells are 2 (1 + <paramref name="margin"/>) times the largest small
    ''' half-size wide, so items whose boxes are within <paramref name="margin"/> of their sizes of
    ''' touching are in neighbouring cells; then doubled until there are at most 4 cells per item (plus 16).
    ''' </summary>
    Friend Sub Build(margin As Double)
        Dim largeAbove = LargeThreshold(margin)
        Dim m = 0, l = 0
        Dim minX = Double.MaxValue, minY = Double.MaxValue, maxX = Double.MinValue, maxY = Double.MinValue, smallHalf = 0.0
        For i = 0 To _count - 1
            _stamp(i) = 0
            If Not IsFinite(_cx(i)) OrElse Not IsFinite(_cy(i)) Then Continue For
            Dim half = Math.Max(_hx(i), _hy(i))
            If half > largeAbove Then
                _largeItems(l) = i
                l += 1
                Continue For
            End If
            _smallItems(m) = i
            m += 1
            minX = Math.Min(minX, _cx(i)) : maxX = Math.Max(maxX, _cx(i))
            minY = Math.Min(minY, _cy(i)) : maxY = Math.Max(maxY, _cy(i))
            smallHalf = Math.Max(smallHalf, half)
        Next
        _query = 0
        _SmallCount = m
        _LargeCount = l
        _SmallHalf = smallHalf
        _everywhere.Clear()
        If m = 0 Then
            ' Every item is large (or there are none): one list for all.
            _Columns = 0
            _Rows = 0
            For k = 0 To l - 1
                _everywhere.Add(_largeItems(k))
            Next
            Return
        End If

        ' A sparse scene (a few items far apart) would need a huge grid: widen the cells instead, which
        ' stays correct because wider cells still hold every touching pair in neighbouring cells.
        Dim size = 2 * smallHalf * (1 + margin)
        If Not (size > 0) Then size = Math.Max(maxX - minX, maxY - minY) + 1 ' points only: one cell will do
        Dim maxCells = 4.0 * m + 16
        Do While (Math.Floor((maxX - minX) / size) + 1) * (Math.Floor((maxY - minY) / size) + 1) > maxCells
            size *= 2
        Loop
        _Cell = size
        _originX = minX
        _originY = minY
        _Columns = CInt(Math.Floor((maxX - minX) / size)) + 1
        _Rows = CInt(Math.Floor((maxY - minY) / size)) + 1
        Dim cellCount = _Columns * _Rows
        If _CellStart.Length < cellCount + 1 Then
            _CellStart = New Integer(cellCount) {}
            _largeStart = New Integer(cellCount) {}
            _fill = New Integer(cellCount) {}
        End If
        Array.Clear(_CellStart, 0, cellCount + 1)

        ' Counting sort of the small items by cell, keeping their order within a cell.
        For k = 0 To m - 1
            Dim i = _smallItems(k)
            Dim key = Row(_cy(i)) * _Columns + Column(_cx(i))
            _cellOf(k) = key
            _CellStart(key + 1) += 1
        Next
        For key = 0 To cellCount - 1
            _CellStart(key + 1) += _CellStart(key)
        Next
        Array.Copy(_CellStart, _fill, cellCount)
        For k = 0 To m - 1
            Dim key = _cellOf(k)
            _Sorted(_fill(key)) = _smallItems(k)
            _fill(key) += 1
        Next
        PlaceLarge(cellCount)
    End Sub

    ''' <summary>
    ''' The half-size (m) above which an item is large: +∞ (none is) unless cells as wide as the largest
    ''' item would hold more than <see cref="CrowdLimit"/> items each and the sizes differ by more than
    ''' <see cref="LargeFactor"/>; then <see cref="LargeFactor"/> times the median half-size.
    ''' </summary>
    Private Function LargeThreshold(margin As Double) As Double
        Dim finite = 0
        Dim minHalf = Double.MaxValue, maxHalf = 0.0
        Dim x0 = Double.MaxValue, y0 = Double.MaxValue, x1 = Double.MinValue, y1 = Double.MinValue
        For i = 0 To _count - 1
            If Not IsFinite(_cx(i)) OrElse Not IsFinite(_cy(i)) Then Continue For
            Dim half = Math.Max(_hx(i), _hy(i))
            _halves(finite) = half
            finite += 1
            minHalf = Math.Min(minHalf, half)
            maxHalf = Math.Max(maxHalf, half)
            x0 = Math.Min(x0, _cx(i)) : x1 = Math.Max(x1, _cx(i))
            y0 = Math.Min(y0, _cy(i)) : y1 = Math.Max(y1, _cy(i))
        Next
        If finite = 0 OrElse Not (maxHalf > LargeFactor * minHalf) Then Return Double.PositiveInfinity
        Dim widest = 2 * maxHalf * (1 + margin)
        Dim cells = (Math.Floor((x1 - x0) / widest) + 1) * (Math.Floor((y1 - y0) / widest) + 1)
        If Not (finite > CrowdLimit * cells) Then Return Double.PositiveInfinity
        Array.Sort(_halves, 0, finite)
        Return LargeFactor * _halves(finite \ 2)
    End Function

    ''' <summary>Lists each large item in every cell its box covers, or in the list every query meets.</summary>
    Private Sub PlaceLarge(cellCount As Integer)
        Array.Clear(_largeStart, 0, cellCount + 1)
        Dim entries = 0
        For pass = 1 To 2
            For k = 0 To _LargeCount - 1
                Dim i = _largeItems(k)
                Dim c0 = Column(_cx(i) - _hx(i)), c1 = Column(_cx(i) + _hx(i))
                Dim r0 = Row(_cy(i) - _hy(i)), r1 = Row(_cy(i) + _hy(i))
                If CLng(c1 - c0 + 1) * (r1 - r0 + 1) > MaxCellsPerLarge Then
                    If pass = 1 Then _everywhere.Add(i)
                    Continue For
                End If
                For r = r0 To r1
                    For c = c0 To c1
                        Dim key = r * _Columns + c
                        If pass = 1 Then
                            _largeStart(key + 1) += 1
                            entries += 1
                        Else
                            _largeInCell(_fill(key)) = i
                            _fill(key) += 1
                        End If
                    Next
                Next
            Next
            If pass = 1 Then
                For key = 0 To cellCount - 1
                    _largeStart(key + 1) += _largeStart(key)
                Next
                Array.Copy(_largeStart, _fill, cellCount)
                If _largeInCell.Length < entries Then _largeInCell = New Integer(entries - 1) {}
            End If
        Next
    End Sub

    ''' <summary>The column of an x (m), clamped to the grid.</summary>
    Private Function Column(x As Double) As Integer
        Return CInt(Math.Min(_Columns - 1, Math.Max(0.0, Math.Floor((x - _originX) / _Cell))))
    End Function

    ''' <summary>The row of a y (m), clamped to the grid.</summary>
    Private Function Row(y As Double) As Integer
        Return CInt(Math.Min(_Rows - 1, Math.Max(0.0, Math.Floor((y - _originY) / _Cell))))
    End Function

    ''' <summary>
    ''' Fills <paramref name="result"/> with every item, small or large, whose box meets the box
    ''' [lo, hi] (m; touching counts), in increasing item order. A box that is not finite meets everything.
    ''' </summary>
    Friend Sub Query(lo As Vector, hi As Vector, result As List(Of Integer))
        result.Clear()
        If Not lo.IsFinite OrElse Not hi.IsFinite Then
            For i = 0 To _count - 1
                If IsFinite(_cx(i)) AndAlso IsFinite(_cy(i)) Then result.Add(i)
            Next
            Return
        End If
        _query += 1
        If _query = Integer.MaxValue Then
            Array.Clear(_stamp, 0, _count)
            _query = 1
        End If
        If _SmallCount > 0 Then
            ' A small item's box reaches less than half a cell from its centre.
            Dim reach = 0.5 * _Cell
            Dim c0 = Column(lo.X - reach), c1 = Column(hi.X + reach)
            Dim r0 = Row(lo.Y - reach), r1 = Row(hi.Y + reach)
            If CLng(c1 - c0 + 1) * (r1 - r0 + 1) > _SmallCount + _LargeCount Then
                ' The box covers more cells than there are items: trying every item is cheaper.
                For k = 0 To _SmallCount - 1
                    AddIfMeets(_smallItems(k), lo, hi, result)
                Next
                For k = 0 To _LargeCount - 1
                    AddIfMeets(_largeItems(k), lo, hi, result)
                Next
            Else
                For r = r0 To r1
                    For c = c0 To c1
                        Dim key = r * _Columns + c
                        For s = _CellStart(key) To _CellStart(key + 1) - 1
                            AddIfMeets(_Sorted(s), lo, hi, result)
                        Next
                        For s = _largeStart(key) To _largeStart(key + 1) - 1
                            AddIfMeets(_largeInCell(s), lo, hi, result)
                        Next
                    Next
                Next
                For Each i In _everywhere
                    AddIfMeets(i, lo, hi, result)
                Next
            End If
        Else
            For Each i In _everywhere
                AddIfMeets(i, lo, hi, result)
            Next
        End If
        If result.Count > 1 Then result.Sort()
    End Sub

    Private Sub AddIfMeets(i As Integer, lo As Vector, hi As Vector, result As List(Of Integer))
        If _stamp(i) = _query Then Return
        If _cx(i) + _hx(i) >= lo.X AndAlso _cx(i) - _hx(i) <= hi.X AndAlso
           _cy(i) + _hy(i) >= lo.Y AndAlso _cy(i) - _hy(i) <= hi.Y Then
            _stamp(i) = _query
            result.Add(i)
        End If
    End Sub

    Private Shared Function IsFinite(v As Double) As Boolean
        Return Not Double.IsNaN(v) AndAlso Not Double.IsInfinity(v)
    End Function
End Class
