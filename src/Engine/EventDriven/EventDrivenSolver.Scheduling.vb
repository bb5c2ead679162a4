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
        Dim m = _body(i).Mode
        If m = BodyMode.Sliding Then
            ' Its slide ends, or a neighbour reaches the disc the sliding ball sweeps round the corner.
            best = Math.Max(0, CornerSlide.Duration(_slideV0(i), _g, _body(i).R, 0, _slideAngle(i)) - (_now - _slideStart(i)))
            kind = EventKind.SlideEnd
            Dim count = Neighbours(i)
            For q = 0 To count - 1
                Dim k = _stack(q)
                Dim ts = SweptDiscContact(i, k)
                If ts < best Then best = ts : kind = EventKind.Circle : other = k
            Next
            FileEvent(i, best, kind, other, 0, Double.PositiveInfinity, 0)
            Return
        End If
        Dim tau = _now - _body(i).T0
        Dim ay = _body(i).Ay
        Dim px = _body(i).Px + _body(i).Vx * tau
        Dim py = _body(i).Py + (_body(i).Vy + 0.5 * ay * tau) * tau
        Dim vx = _body(i).Vx
        Dim vy = _body(i).Vy + ay * tau
        Dim r = _body(i).R
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
            If _cell(i) >= 0 Then
                ' A static obstacle is listed in every cell within half a cell of it, so the own cell suffices.
                Dim c = _cell(i)
                For s = _grid.StaticStart(c) To _grid.StaticStart(c + 1) - 1
                    CheckStatic(_grid.StaticItems(s), px, py, vx, vy, ay, r, best, kind, other, feature)
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
            ScanCells(i, col - 1, col + 1, row - 1, row + 1, asleep, px, py, vx, vy, ay, r, best, kind, other)
            For k = 0 To _nOversized - 1
                CheckPair(i, _oversized(k), asleep, px, py, vx, vy, ay, r, best, kind, other)
            Next
        Else
            For j = 0 To _n - 1
                If j <> i Then CheckPair(i, j, asleep, px, py, vx, vy, ay, r, best, kind, other)
            Next
        End If
        ' A resting body reaching the edge of its rectangle.
        If m = BodyMode.Resting AndAlso _support(i) >= 0 AndAlso vx <> 0 Then
            Dim k = _support(i)
            t = If(vx > 0, (_rx1(k) - px) / vx, (_rx0(k) - px) / vx)
            If t < best Then best = Math.Max(0, t) : kind = EventKind.EdgeLeave : other = k : feature = 0
        End If
        Dim dir = 0
        Dim exitTime = CellExit(i, asleep, px, py, vx, vy, ay, dir)
        FileEvent(i, best, kind, other, feature, exitTime, dir)
    End Sub

    ''' <summary>
    ''' Body i's centre enters the next cell. Its collision prediction stays valid (its own motion did
    ''' not change), so only the strip of three cells that just came into its 3 × 3 neighbourhood, and
    ''' the statics of the new cell, are searched.
    ''' </summary>
    Private Sub CrossCell(i As Integer)
        Dim cell = _cell(i)
        Dim dir = _cellDir(i)
        Dim target = cell
        Select Case dir
            Case 0 : target = cell - 1
            Case 1 : target = cell + 1
            Case 2 : target = cell - _grid.Nx
            Case Else : target = cell + _grid.Nx
        End Select
        _grid.Remove(i, cell)
        _grid.Insert(i, target)
        _cell(i) = target
        Dim kind = _evKind(i)
        If kind = EventKind.Circle AndAlso _count(_evOther(i)) <> _evOtherCount(i) Then
            Reschedule(i) ' the kept prediction went stale: start afresh
            Return
        End If
        Dim best = _colTime(i) - _now
        Dim other = _evOther(i)
        Dim feature = _evFeature(i)
        Dim m = _body(i).Mode
        Dim tau = _now - _body(i).T0
        Dim ay = _body(i).Ay
        Dim px = _body(i).Px + _body(i).Vx * tau
        Dim py = _body(i).Py + (_body(i).Vy + 0.5 * ay * tau) * tau
        Dim vx = _body(i).Vx
        Dim vy = _body(i).Vy + ay * tau
        Dim r = _body(i).R
        If m = BodyMode.Free OrElse m = BodyMode.Resting Then
            For s = _grid.StaticStart(target) To _grid.StaticStart(target + 1) - 1
                CheckStatic(_grid.StaticItems(s), px, py, vx, vy, ay, r, best, kind, other, feature)
            Next
        End If
        Dim asleep = m = BodyMode.Sleeping
        Dim col = target Mod _grid.Nx, row = target \ _grid.Nx
        Select Case dir
            Case 0 : ScanCells(i, col - 1, col - 1, row - 1, row + 1, asleep, px, py, vx, vy, ay, r, best, kind, other)
            Case 1 : ScanCells(i, col + 1, col + 1, row - 1, row + 1, asleep, px, py, vx, vy, ay, r, best, kind, other)
            Case 2 : ScanCells(i, col - 1, col + 1, row - 1, row - 1, asleep, px, py, vx, vy, ay, r, best, kind, other)
            Case Else : ScanCells(i, col - 1, col + 1, row + 1, row + 1, asleep, px, py, vx, vy, ay, r, best, kind, other)
        End Select
        Dim exitDir = 0
        Dim exitTime = CellExit(i, asleep, px, py, vx, vy, ay, exitDir)
        FileEvent(i, best, kind, other, feature, exitTime, exitDir)
    End Sub

    Private Sub ScanCells(i As Integer, col0 As Integer, col1 As Integer, row0 As Integer, row1 As Integer, asleep As Boolean,
                          px As Double, py As Double, vx As Double, vy As Double, ay As Double, r As Double,
                          ByRef best As Double, ByRef kind As EventKind, ByRef other As Integer)
        Dim nx = _grid.Nx
        Dim head = _grid.Head
        Dim nextInCell = _grid.NextInCell
        Dim bodies = _body
        Dim colTime = _colTime
        Dim now = _now
        Dim slop = _slop
        For rr = Math.Max(0, row0) To Math.Min(_grid.Ny - 1, row1)
            For cc = Math.Max(0, col0) To Math.Min(nx - 1, col1)
                Dim j = head(rr * nx + cc)
                While j >= 0
                    If bodies(j).Ay = ay AndAlso bodies(j).Mode = BodyMode.Free AndAlso Not asleep Then
                        ' Hot path (the elastic gas): same gravity, so the relative motion is a
                        ' straight line and the contact time is the smaller root of a quadratic.
                        ' The root is computed for every candidate and the tests combined into one
                        ' condition: which pairs meet is random, and a mispredicted branch costs
                        ' more than the square root it would save.
                        Dim tj = now - bodies(j).T0
                        Dim dx = px - (bodies(j).Px + bodies(j).Vx * tj)
                        Dim dy = py - (bodies(j).Py + (bodies(j).Vy + 0.5 * ay * tj) * tj)
                        Dim dvx = vx - bodies(j).Vx
                        Dim dvy = vy - (bodies(j).Vy + ay * tj)
                        Dim b = dx * dvx + dy * dvy
                        Dim sumR = r + bodies(j).R
                        Dim c = dx * dx + dy * dy - sumR * sumR
                        If c <= 2 * sumR * slop Then
                            ' Touching (common in a pile): only an approach can be a collision now.
                            If b < 0 AndAlso j <> i Then CheckPair(i, j, asleep, px, py, vx, vy, ay, r, best, kind, other)
                        Else
                            Dim a = dvx * dvx + dvy * dvy
                            Dim disc = b * b - a * c
                            Dim t = c / (-b + Math.Sqrt(disc))
                            ' Approaching, not a graze, earlier than the best so far, and not after the
                            ' partner's own next collision (it is rescheduled then and finds this pair
                            ' again, so filing it here would only go stale).
                            Dim hit = (b < 0) And (disc > TimeOfImpact.GrazeFraction * b * b) And (t < best)
                            If hit AndAlso now + t <= colTime(j) Then
                                best = t
                                kind = EventKind.Circle
                                other = j
                            End If
                        End If
                    ElseIf j <> i Then
                        CheckPair(i, j, asleep, px, py, vx, vy, ay, r, best, kind, other)
                    End If
                    j = nextInCell(j)
                End While
            Next
        Next
    End Sub

    ''' <summary>Files body i's next collision-type event and its next cell exit (times from now, s).</summary>
    Private Sub FileEvent(i As Integer, dt As Double, kind As EventKind, other As Integer, feature As Integer,
                          exitDt As Double, exitDir As Integer)
        _evKind(i) = kind
        _evOther(i) = other
        _evOtherCount(i) = If(kind = EventKind.Circle, _count(other), 0)
        _evFeature(i) = feature
        _colTime(i) = If(dt < Double.PositiveInfinity, _now + dt, Double.PositiveInfinity)
        _cellTime(i) = If(exitDt < Double.PositiveInfinity, _now + exitDt, Double.PositiveInfinity)
        _cellDir(i) = exitDir
        _evTime(i) = Math.Min(_colTime(i), _cellTime(i))
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
            Dim f As Integer
            t = TimeOfImpact.CircleRectangle(px, py, vx, vy, ay, r, _rx0(k), _ry0(k), _rx1(k), _ry1(k), _slop, f)
            If t < best Then best = t : kind = EventKind.Rectangle : other = k : feature = f
        End If
    End Sub

    Private Sub CheckPair(i As Integer, j As Integer, asleep As Boolean, px As Double, py As Double, vx As Double, vy As Double,
                          ay As Double, r As Double, ByRef best As Double, ByRef kind As EventKind, ByRef other As Integer)
        Dim mj = _body(j).Mode
        If mj = BodyMode.Sliding Then
            Dim ts = SweptDiscContact(j, i)
            If ts < best Then
                best = ts
                kind = EventKind.Circle
                other = j
            End If
            Return
        End If
        If asleep AndAlso mj = BodyMode.Sleeping Then Return
        Dim tj = _now - _body(j).T0
        Dim ayj = _body(j).Ay
        Dim dx = px - (_body(j).Px + _body(j).Vx * tj)
        Dim dy = py - (_body(j).Py + (_body(j).Vy + 0.5 * ayj * tj) * tj)
        Dim vyj = _body(j).Vy + ayj * tj
        Dim t = TimeOfImpact.CircleCircle(dx, dy, vx - _body(j).Vx, vy - vyj, ay - ayj, r + _body(j).R, _slop,
                                          Math.Abs(vx) + Math.Abs(vy) + Math.Abs(_body(j).Vx) + Math.Abs(vyj))
        If t < best Then
            best = t
            kind = EventKind.Circle
            other = j
        End If
    End Sub

    ''' <summary>
    ''' When body k first comes within reach of sliding body j: j's centre stays within r_j of its
    ''' corner, so k can touch it only inside the disc of radius r_k + 2 r_j about the corner. Reaching
    ''' that disc ends the exact slide early (see <c>Materialize</c>); +∞ if k never gets there.
    ''' </summary>
    Private Function SweptDiscContact(j As Integer, k As Integer) As Double
        Dim mk = _body(k).Mode
        If mk = BodyMode.Sliding OrElse mk = BodyMode.Sleeping Then Return Double.PositiveInfinity
        Dim tk = _now - _body(k).T0
        Dim ayk = _body(k).Ay
        Dim dx = _body(k).Px + _body(k).Vx * tk - _slideCx(j)
        Dim dy = _body(k).Py + (_body(k).Vy + 0.5 * ayk * tk) * tk - _slideCy(j)
        Return TimeOfImpact.CircleCircle(dx, dy, _body(k).Vx, _body(k).Vy + ayk * tk, ayk, _body(k).R + 2 * _body(j).R, _slop)
    End Function

    ''' <summary>
    ''' When the centre leaves its cell: x is linear and y quadratic in t, each against the cell's two
    ''' boundaries (the outermost cells have no outer boundary). <paramref name="dir"/>: 0 −x, 1 +x, 2 −y, 3 +y.
    ''' </summary>
    Private Function CellExit(i As Integer, asleep As Boolean, px As Double, py As Double, vx As Double, vy As Double, ay As Double,
                              ByRef dir As Integer) As Double
        Dim best = Double.PositiveInfinity
        Dim cell = _cell(i)
        If cell < 0 OrElse asleep OrElse (vx = 0 AndAlso vy = 0 AndAlso ay = 0) Then Return best
        Dim col = cell Mod _grid.Nx, row = cell \ _grid.Nx
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
