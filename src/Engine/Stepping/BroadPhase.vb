Option Strict On

''' <summary>
''' Finds the overlapping pairs of movable bodies without testing every pair, on a
''' <see cref="BoundsGrid"/> keyed by the centres of their bounding boxes: two bodies that touch have
''' centres in the same or neighbouring cells, so each cell is checked against itself and four of its
''' neighbours (right, and the three above) and every pair is met once. Bodies much larger than most
''' (a big crate among marbles) are met through box queries over the cells they cover instead of
''' widening every cell. Cost grows with N, not N², however different the sizes.
''' </summary>
Friend NotInheritable Class BroadPhase
    Private ReadOnly _grid As New BoundsGrid()
    Private ReadOnly _near As New List(Of Integer)
    ' Per body: its radius when it is a circle, else 0 (a box test is used).
    Private _radius As Double() = Array.Empty(Of Double)()
    Private _rank As Integer() = Array.Empty(Of Integer)()
    Private _isLarge As Boolean() = Array.Empty(Of Boolean)()

    ''' <summary>
    ''' Pairs are kept when their gap is under this fraction of their sizes' sum (radii for two circles,
    ''' half-sizes otherwise): the later contact phases of the same step (the floor pushing a ball up into
    ''' the one resting on it, say) may close a gap that was a rounding error wide when the pairs were found.
    ''' </summary>
    Friend Const Margin As Double = 0.05

    ''' <summary>
    ''' Fills <paramref name="pairs"/> with the index pairs (into <paramref name="bodies"/>, the movable
    ''' bodies) that overlap, touch, or nearly touch (see <see cref="Margin"/>) now. In each pair A is the
    ''' body whose kind comes first (circle, then rectangle, then polygon), or the earlier one of two of a
    ''' kind, so a pair is always named the same way (circle-polygon, never polygon-circle).
    ''' </summary>
    Friend Sub FindOverlaps(bodies As IReadOnlyList(Of Shape), pairs As List(Of (A As Integer, B As Integer)))
        pairs.Clear()
        Dim n = bodies.Count
        If n < 2 Then Return
        If _radius.Length < n Then
            _radius = New Double(n - 1) {}
            _rank = New Integer(n - 1) {}
        End If
        _grid.Reset(n)
        For i = 0 To n - 1
            Dim b = bodies(i)
            Dim o = b.Outline
            Dim c = TryCast(b, Circle)
            If c IsNot Nothing Then
                ' A circle's box is centred on its centre: exactly, so circles keep their cells.
                _radius(i) = c.Radius
                _grid.SetItem(i, c.Position, c.Radius, c.Radius)
            Else
                _radius(i) = 0
                _grid.SetItem(i, New Vector(b.Position.X + 0.5 * (o.MinX + o.MaxX), b.Position.Y + 0.5 * (o.MinY + o.MaxY)),
                              0.5 * (o.MaxX - o.MinX), 0.5 * (o.MaxY - o.MinY))
            End If
            _rank(i) = KindRank(b)
        Next
        _grid.Build(Margin)

        Dim g = _grid
        Dim sorted = g.Sorted, start = g.CellStart
        Dim cols = g.Columns, rows = g.Rows
        For cy = 0 To rows - 1
            For cx = 0 To cols - 1
                Dim key = cy * cols + cx
                For s = start(key) To start(key + 1) - 1
                    Dim i = sorted(s)
                    For t = s + 1 To start(key + 1) - 1
                        Test(i, sorted(t), pairs)
                    Next
                    If cx + 1 < cols Then TestCell(i, key + 1, pairs)
                    If cy + 1 < rows Then
                        If cx > 0 Then TestCell(i, key + cols - 1, pairs)
                        TestCell(i, key + cols, pairs)
                        If cx + 1 < cols Then TestCell(i, key + cols + 1, pairs)
                    End If
                Next
            Next
        Next

        ' Large bodies: against the small ones near them, then against each other (they are few).
        If g.LargeCount = 0 Then Return
        If _isLarge.Length < n Then _isLarge = New Boolean(n - 1) {}
        Array.Clear(_isLarge, 0, n)
        For k = 0 To g.LargeCount - 1
            _isLarge(g.Large(k)) = True
        Next
        For k = 0 To g.LargeCount - 1
            Dim i = g.Large(k)
            Dim reachX = g.HalfWidth(i) + Margin * (Half(i) + g.SmallHalf)
            Dim reachY = g.HalfHeight(i) + Margin * (Half(i) + g.SmallHalf)
            g.Query(New Vector(g.CentreX(i) - reachX, g.CentreY(i) - reachY), New Vector(g.CentreX(i) + reachX, g.CentreY(i) + reachY), _near)
            For Each j In _near
                If Not _isLarge(j) Then Test(i, j, pairs)
            Next
        Next
        For k = 0 To g.LargeCount - 1
            For k2 = k + 1 To g.LargeCount - 1
                Test(g.Large(k), g.Large(k2), pairs)
            Next
        Next
    End Sub

    Private Function Half(i As Integer) As Double
        Return Math.Max(_grid.HalfWidth(i), _grid.HalfHeight(i))
    End Function

    Private Sub TestCell(i As Integer, key As Integer, pairs As List(Of (A As Integer, B As Integer)))
        Dim sorted = _grid.Sorted, start = _grid.CellStart
        For t = start(key) To start(key + 1) - 1
            Test(i, sorted(t), pairs)
        Next
    End Sub

    Private Sub Test(i As Integer, j As Integer, pairs As List(Of (A As Integer, B As Integer)))
        Dim g = _grid
        Dim dx = g.CentreX(i) - g.CentreX(j)
        Dim dy = g.CentreY(i) - g.CentreY(j)
        Dim ri = _radius(i), rj = _radius(j)
        If ri > 0 AndAlso rj > 0 Then
            Dim reach = (ri + rj) * (1 + Margin)
            If dx * dx + dy * dy > reach * reach Then Return
        Else
            Dim slack = Margin * (Half(i) + Half(j))
            If Math.Abs(dx) > g.HalfWidth(i) + g.HalfWidth(j) + slack OrElse Math.Abs(dy) > g.HalfHeight(i) + g.HalfHeight(j) + slack Then Return
        End If
        If _rank(i) < _rank(j) OrElse (_rank(i) = _rank(j) AndAlso i < j) Then
            pairs.Add((i, j))
        Else
            pairs.Add((j, i))
        End If
    End Sub

    ''' <summary>The order of kinds in a pair's name: circle, rectangle, polygon.</summary>
    Private Shared Function KindRank(b As Shape) As Integer
        Select Case b.Kind
            Case ShapeKind.Circle : Return 0
            Case ShapeKind.Rectangle : Return 1
            Case Else : Return 2
        End Select
    End Function
End Class
