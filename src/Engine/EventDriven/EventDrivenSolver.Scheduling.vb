Option Strict On

' Prediction: the earliest event of one body against the walls, the static obstacles and the
' movable circles near it, and its next grid-cell crossing. Only the 3 × 3 cells around it are
' searched, so the cost per event stays flat as the number of bodies grows.
Partial Public NotInheritable Class EventDrivenSolver
    ''' <summary>Recomputes body i's next event at the solver's clock and files it in the queue.</summary>
    Private Sub Reschedule(i As Integer)
        Dim best = Double.PositiveInfinity
        Dim kind = EventKind.None
        Dim other = -1
        Dim feature = 0
        Dim m = _mode(i)
        If m = BodyMode.Sliding Then
            best = CornerSlide.Duration(_slideV0(i), _g, _r(i), 0, _slideAngle(i)) - (_now - _slideStart(i))
            FileEvent(i, Math.Max(0, best), EventKind.SlideEnd, -1, 0)
            Return
        End If
        Dim tau = _now - _t0(i)
        Dim ay = _ay(i)
        Dim px = _px(i) + _vx(i) * tau
        Dim py = _py(i) + (_vy(i) + 0.5 * ay * tau) * tau
        Dim vx = _vx(i)
        Dim vy = _vy(i) + ay * tau
        Dim r = _r(i)
        Dim slop = _slop
        Dim t As Double
        Dim moving = m = BodyMode.Free OrElse m = BodyMode.Resting
        If moving Then
            If _walls Then
                t = TimeOfImpact.GapCloses(px - r, vx, 0, slop)
                If t < best Then best = t : kind = EventKind.Wall : feature = WallSide.Left
                t = TimeOfImpact.GapCloses(_width - r - px, -vx, 0, slop)
                If t < best Then best = t : kind = EventKind.Wall : feature = WallSide.Right
                If m = BodyMode.Free Then
                    t = TimeOfImpact.GapCloses(py - r, vy, ay, slop)
                    If t < best Then best = t : kind = EventKind.Wall : feature = WallSide.Bottom
                    t = TimeOfImpact.GapCloses(_height - r - py, -vy, -ay, slop)
                    If t < best Then best = t : kind = EventKind.Wall : feature = WallSide.Top
                End If
            End If
            Dim cell = _cell(i)
            If cell >= 0 Then
                Dim col = cell Mod _grid.Nx, row = cell \ _grid.Nx
                For rr = Math.Max(0, row - 1) To Math.Min(_grid.Ny - 1, row + 1)
                    For cc = Math.Max(0, col - 1) To Math.Min(_grid.Nx - 1, col + 1)
                        Dim c = rr * _grid.Nx + cc
                        For s = _grid.StaticStart(c) To _grid.StaticStart(c + 1) - 1
                            CheckStatic(_grid.StaticItems(s), px, py, vx, vy, ay, r, best, kind, other, feature)
                        Next
                    Next
                Next
            Else
                For s = 0 To _nFixed + _nRect - 1
                    CheckStatic(s, px, py, vx, vy, ay, r, best, kind, other, feature)
                Next
            End If
        End If
        ' Movable neighbours.
        Dim asleep = m = BodyMode.Sleeping
        If _cell(i) >= 0 Then
            Dim cell = _cell(i)
            Dim col = cell Mod _grid.Nx, row = cell \ _grid.Nx
            For rr = Math.Max(0, row - 1) To Math.Min(_grid.Ny - 1, row + 1)
                For cc = Math.Max(0, col - 1) To Math.Min(_grid.Nx - 1, col + 1)
                    Dim j = _grid.Head(rr * _grid.Nx + cc)
                    While j >= 0
                        If j <> i Then CheckPair(i, j, asleep, px, py, vx, vy, ay, r, best, kind, other)
                        j = _grid.NextInCell(j)
                    End While
                Next
            Next
            For k = 0 To _nOversized - 1
                CheckPair(i, _oversized(k), asleep, px, py, vx, vy, ay, r, best, kind, other)
            Next
        Else
            For j = 0 To _n - 1
                If j <> i Then CheckPair(i, j, asleep, px, py, vx, vy, ay, r, best, kind, other)
            Next
        End If
        ' Leaving the grid cell, and a resting body reaching the edge of its rectangle.
        If _cell(i) >= 0 AndAlso Not asleep AndAlso (vx <> 0 OrElse vy <> 0 OrElse ay <> 0) Then
            Dim dir As Integer
            t = CellExit(_cell(i), px, py, vx, vy, ay, dir)
            If t < best Then best = t : kind = EventKind.Cell : feature = dir
        End If
        If m = BodyMode.Resting AndAlso _support(i) >= 0 AndAlso vx <> 0 Then
            Dim k = _support(i)
            t = If(vx > 0, (_rx1(k) - px) / vx, (_rx0(k) - px) / vx)
            If t < best Then best = Math.Max(0, t) : kind = EventKind.EdgeLeave : other = k : feature = 0
        End If
        FileEvent(i, best, kind, other, feature)
    End Sub

    Private Sub FileEvent(i As Integer, dt As Double, kind As EventKind, other As Integer, feature As Integer)
        _evKind(i) = kind
        _evOther(i) = other
        _evOtherCount(i) = If(kind = EventKind.Circle, _count(other), 0)
        _evFeature(i) = feature
        _evTime(i) = If(dt < Double.PositiveInfinity, _now + dt, Double.PositiveInfinity)
        _queue.Update(i)
    End Sub

    Private Sub CheckStatic(s As Integer, px As Double, py As Double, vx As Double, vy As Double, ay As Double, r As Double,
                            ByRef best As Double, ByRef kind As EventKind, ByRef other As Integer, ByRef feature As Integer)
        Dim t As Double
        If s < _nFixed Then
            t = TimeOfImpact.CircleCircle(px - _fx(s), py - _fy(s), vx, vy, ay, r + _fr(s), _slop)
            If t < best Then best = t : kind = EventKind.FixedCircle : other = s : feature = 0
        Else
            Dim k = s - _nFixed
            ' Quick rejection: the Minkowski box cannot be reached if it lies behind and the motion leads away.
            Dim f As Integer
            t = TimeOfImpact.CircleRectangle(px, py, vx, vy, ay, r, _rx0(k), _ry0(k), _rx1(k), _ry1(k), _slop, f)
            If t < best Then best = t : kind = EventKind.Rectangle : other = k : feature = f
        End If
    End Sub

    Private Sub CheckPair(i As Integer, j As Integer, asleep As Boolean, px As Double, py As Double, vx As Double, vy As Double,
                          ay As Double, r As Double, ByRef best As Double, ByRef kind As EventKind, ByRef other As Integer)
        Dim mj = _mode(j)
        If mj = BodyMode.Sliding Then Return
        If asleep AndAlso mj = BodyMode.Sleeping Then Return
        Dim tj = _now - _t0(j)
        Dim ayj = _ay(j)
        Dim dx = px - (_px(j) + _vx(j) * tj)
        Dim dy = py - (_py(j) + (_vy(j) + 0.5 * ayj * tj) * tj)
        Dim t = TimeOfImpact.CircleCircle(dx, dy, vx - _vx(j), vy - (_vy(j) + ayj * tj), ay - ayj, r + _r(j), _slop)
        If t < best Then
            best = t
            kind = EventKind.Circle
            other = j
        End If
    End Sub

    ''' <summary>
    ''' When the centre leaves its cell: x is linear and y quadratic in t, each against the cell's two
    ''' boundaries (the outermost cells have no outer boundary). <paramref name="dir"/>: 0 −x, 1 +x, 2 −y, 3 +y.
    ''' </summary>
    Private Function CellExit(cell As Integer, px As Double, py As Double, vx As Double, vy As Double, ay As Double,
                              ByRef dir As Integer) As Double
        Dim col = cell Mod _grid.Nx, row = cell \ _grid.Nx
        Dim best = Double.PositiveInfinity
        Dim t As Double
        dir = -1
        If col > 0 Then
            t = TimeOfImpact.GapCloses(px - col * _grid.CellWidth, vx, 0, 0)
            If t < best Then best = t : dir = 0
        End If
        If col < _grid.Nx - 1 Then
            t = TimeOfImpact.GapCloses((col + 1) * _grid.CellWidth - px, -vx, 0, 0)
            If t < best Then best = t : dir = 1
        End If
        If row > 0 Then
            t = TimeOfImpact.GapCloses(py - row * _grid.CellHeight, vy, ay, 0)
            If t < best Then best = t : dir = 2
        End If
        If row < _grid.Ny - 1 Then
            t = TimeOfImpact.GapCloses((row + 1) * _grid.CellHeight - py, -vy, -ay, 0)
            If t < best Then best = t : dir = 3
        End If
        Return best
    End Function
End Class
