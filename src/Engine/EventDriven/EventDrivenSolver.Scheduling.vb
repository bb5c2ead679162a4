Option Strict On

#If NET Then
Imports System.Numerics
Imports System.Runtime.Intrinsics
#End If

' Prediction: the earliest event of one body against the walls, the static obstacles and the
' movable circles near it, and its next grid-cell crossing. Only the cells around it that are within
' reach of its path are searched (see ReachOfPath), so the cost per event stays flat as the number
' of bodies grows.
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
        Dim ay = _body(i).Ay
        Dim px, py, vx, vy As Double
        _body(i).StateAt(_now, px, py, vx, vy)
        Dim r = _body(i).R
        Dim t As Double
        Dim moving = m = BodyMode.Free OrElse m = BodyMode.Resting
        If moving Then
            If _walls Then CheckWalls(i, m = BodyMode.Free, px, py, vx, vy, ay, r, best, kind, feature)
            If _ev(i).Cell >= 0 Then
                ' A static obstacle is listed in every cell within half a cell of it, so the own cell suffices.
                Dim c = _ev(i).Cell
                For s = _grid.StaticStart(c) To _grid.StaticStart(c + 1) - 1
                    CheckStatic(_grid.StaticItems(s), px, py, vx, vy, ay, r, best, kind, other, feature)
                Next
            Else
                For s = 0 To _nFixed + _nRect - 1
                    CheckStatic(s, px, py, vx, vy, ay, r, best, kind, other, feature)
                Next
            End If
        End If
        ' Movable neighbours: those in the cells within reach of its path (see ReachOfPath).
        Dim asleep = m = BodyMode.Sleeping
        Dim dir = 0
        Dim exitTime = CellExit(i, asleep, px, py, vx, vy, ay, dir)
        If _ev(i).Cell >= 0 Then
            Dim c0, c1, r0, r1 As Integer
            ReachOfPath(i, px, py, vx, vy, ay, r, Math.Min(exitTime, best), c0, c1, r0, r1)
            ScanCells(i, c0, c1, r0, r1, -1, asleep, px, py, vx, vy, ay, r, best, kind, other)
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
        FileEvent(i, best, kind, other, feature, exitTime, dir)
    End Sub

    ''' <summary>
    ''' Body i's centre enters the next cell. Its collision prediction stays valid (its own motion did
    ''' not change); the walls and statics of the new cell, and the cells within reach of its new
    ''' stretch of path except the one it came from, are searched (docs/event-driven.md §4).
    ''' </summary>
    Private Sub CrossCell(i As Integer)
        Dim dir = _ev(i).CellDir
        Dim col = _ev(i).Col, row = _ev(i).Row
        Select Case dir
            Case 0 : col -= 1
            Case 1 : col += 1
            Case 2 : row -= 1
            Case Else : row += 1
        End Select
        Dim previous = _ev(i).Cell
        MoveToCell(i, col, row)
        Dim target = _ev(i).Cell
        Dim kind = _ev(i).Kind
        If kind = EventKind.Circle AndAlso _ev(_ev(i).Other).Count <> _ev(i).OtherCount Then
            Reschedule(i) ' the kept prediction went stale: start afresh
            Return
        End If
        Dim best = _ev(i).ColTime - _now
        Dim other = _ev(i).Other
        Dim feature = _ev(i).Feature
        Dim m = _body(i).Mode
        Dim ay = _body(i).Ay
        Dim px, py, vx, vy As Double
        _body(i).StateAt(_now, px, py, vx, vy)
        Dim r = _body(i).R
        If m = BodyMode.Free OrElse m = BodyMode.Resting Then
            If _walls Then CheckWalls(i, m = BodyMode.Free, px, py, vx, vy, ay, r, best, kind, feature)
            For s = _grid.StaticStart(target) To _grid.StaticStart(target + 1) - 1
                CheckStatic(_grid.StaticItems(s), px, py, vx, vy, ay, r, best, kind, other, feature)
            Next
        End If
        Dim asleep = m = BodyMode.Sleeping
        Dim exitDir = 0
        Dim exitTime = CellExit(i, asleep, px, py, vx, vy, ay, exitDir)
        Dim c0, c1, r0, r1 As Integer
        ReachOfPath(i, px, py, vx, vy, ay, r, Math.Min(exitTime, best), c0, c1, r0, r1)
        ScanCells(i, c0, c1, r0, r1, previous, asleep, px, py, vx, vy, ay, r, best, kind, other)
        FileEvent(i, best, kind, other, feature, exitTime, exitDir)
    End Sub

    ''' <summary>
    ''' Body i against the movable bodies in cells col0 … col1 × row0 … row1: in each cell, any
    ''' overflow one by one, then the lanes, four at a time where the processor has 256-bit vectors.
    ''' </summary>
    Private Sub ScanCells(i As Integer, col0 As Integer, col1 As Integer, row0 As Integer, row1 As Integer, skip As Integer, asleep As Boolean,
                          px As Double, py As Double, vx As Double, vy As Double, ay As Double, r As Double,
                          ByRef best As Double, ByRef kind As EventKind, ByRef other As Integer)
        Dim c0 = Math.Max(0, col0), c1 = Math.Min(_grid.Nx - 1, col1)
        Dim r0 = Math.Max(0, row0), r1 = Math.Min(_grid.Ny - 1, row1)
        _CellsSearched += (c1 - c0 + 1) * (r1 - r0 + 1)
        If skip >= 0 Then
            Dim sr = skip \ _grid.Nx, sc = skip - sr * _grid.Nx
            If sc >= c0 AndAlso sc <= c1 AndAlso sr >= r0 AndAlso sr <= r1 Then _CellsSearched -= 1
        End If
#If NET Then
        If VectorScan Then
            ScanLanesVector(i, c0, c1, r0, r1, skip, asleep, px, py, vx, vy, ay, r, best, kind, other)
            Return
        End If
#End If
        ScanBodies(i, c0, c1, r0, r1, skip, True, asleep, px, py, vx, vy, ay, r, best, kind, other)
    End Sub

    ''' <summary>
    ''' Cells c0 … c1 × r0 … r1, one body at a time, from the bodies' own state: each cell's overflow
    ''' and then (when <paramref name="withLanes"/>) its lanes are listed, then tested in one loop.
    ''' </summary>
    Private Sub ScanBodies(i As Integer, c0 As Integer, c1 As Integer, r0 As Integer, r1 As Integer, skip As Integer, withLanes As Boolean,
                           asleep As Boolean, px As Double, py As Double, vx As Double, vy As Double, ay As Double, r As Double,
                           ByRef best As Double, ByRef kind As EventKind, ByRef other As Integer)
        Dim count = _grid.Count, laneBody = _grid.LaneBody, nx = _grid.Nx, listed = _scanList
        For rr = r0 To r1
            For cell = rr * nx + c0 To rr * nx + c1
                If cell = skip Then Continue For
                Dim n = 0
                Dim o = _grid.OverflowHead(cell)
                While o >= 0
                    listed(n) = o
                    n += 1
                    o = _grid.OverflowNext(o)
                End While
                If withLanes Then
                    For lane = cell * UniformGrid.Lanes To cell * UniformGrid.Lanes + count(cell) - 1
                        listed(n) = laneBody(lane)
                        n += 1
                    Next
                End If
                For q = 0 To n - 1
                    Dim j = listed(q)
                    If _body(j).Ay = ay AndAlso _body(j).Mode = BodyMode.Free AndAlso Not asleep Then
                        ' Hot path (the elastic gas): same gravity, so the relative motion is a straight
                        ' line and the contact time is the smaller root of a quadratic. The root is
                        ' computed for every candidate and the tests combined into one condition: which
                        ' pairs meet is random, and a mispredicted branch costs more than the square root.
                        Dim xj, yj, vxj, vyj As Double
                        _body(j).StateAt(_now, xj, yj, vxj, vyj)
                        Dim dx = px - xj
                        Dim dy = py - yj
                        Dim dvx = vx - vxj
                        Dim dvy = vy - vyj
                        Dim b = dx * dvx + dy * dvy
                        Dim sumR = r + _body(j).R
                        Dim c = dx * dx + dy * dy - sumR * sumR
                        If c <= 2 * sumR * _slop Then
                            ' Touching (common in a pile): only an approach can be a collision now.
                            If b < 0 AndAlso j <> i Then CheckPair(i, j, asleep, px, py, vx, vy, ay, r, best, kind, other)
                        Else
                            Dim a = dvx * dvx + dvy * dvy
                            Dim disc = b * b - a * c
                            Dim t = c / (Math.Sqrt(disc) - b)
                            ' Approaching, not a graze, earlier than the best so far, and not after the
                            ' partner's own next collision (it is rescheduled then and finds this pair
                            ' again, so filing it here would only go stale).
                            Dim hit = (b < 0) And (disc > TimeOfImpact.GrazeFraction * b * b) And (t < best)
                            If hit AndAlso _now + t <= _ev(j).ColTime Then
                                best = t
                                kind = EventKind.Circle
                                other = j
                            End If
                        End If
                    ElseIf j <> i Then
                        CheckPair(i, j, asleep, px, py, vx, vy, ay, r, best, kind, other)
                    End If
                Next
            Next
        Next
    End Sub

#If NET Then
    ''' <summary>
    ''' Cells c0 … c1 × r0 … r1, four lanes at a time, from the published copies (any overflow first,
    ''' one by one, as in <see cref="ScanBodies"/>): the pair test of <see cref="ScanBodies"/> with
    ''' the same arithmetic, lane by lane. Lanes whose body
    ''' is not free under the same gravity, and touching pairs, go to <see cref="CheckPair"/>; a hit
    ''' earlier than the best so far is taken in lane order, as the scalar loop would.
    ''' </summary>
    Private Sub ScanLanesVector(i As Integer, c0 As Integer, c1 As Integer, r0 As Integer, r1 As Integer, skip As Integer, asleep As Boolean,
                                px As Double, py As Double, vx As Double, vy As Double, ay As Double, r As Double,
                                ByRef best As Double, ByRef kind As EventKind, ByRef other As Integer)
        Dim blocks = _grid.Blocks, count = _grid.Count, laneBody = _grid.LaneBody, overflow = _grid.OverflowHead
        Dim nx = _grid.Nx
        Dim vNow = Vector256.Create(_now)
        Dim vPx = Vector256.Create(px), vPy = Vector256.Create(py)
        Dim vVx = Vector256.Create(vx), vVy = Vector256.Create(vy)
        Dim vAy = Vector256.Create(ay), vHalfAy = Vector256.Create(0.5 * ay)
        ' A sleeping body takes no hot path: its gravity matches nothing.
        Dim vMatch = Vector256.Create(If(asleep, Double.NaN, ay))
        Dim vR = Vector256.Create(r), vTwo = Vector256.Create(2.0), vSlop = Vector256.Create(_slop)
        Dim vGraze = Vector256.Create(TimeOfImpact.GrazeFraction)
        Dim vZero = Vector256(Of Double).Zero
        Dim laneIndex = Vector256.Create(0.0, 1.0, 2.0, 3.0)
        Dim vMargin = Vector256.Create(1 + 1.0E-6)
        Dim bestSeen = best, vInvBest = Vector256.Create(1 / best)
        For rr = r0 To r1
            For cell = rr * nx + c0 To rr * nx + c1
                If cell = skip Then Continue For
                If overflow(cell) >= 0 Then
                    Dim col = cell - rr * nx
                    ScanBodies(i, col, col, rr, rr, -1, False, asleep, px, py, vx, vy, ay, r, best, kind, other)
                End If
                Dim valid = Vector256.LessThan(laneIndex, Vector256.Create(CDbl(count(cell))))
                Dim hot = valid And Vector256.Equals(blocks(cell).Ay, vMatch)
                Dim tj = vNow - blocks(cell).T0
                Dim jvx = blocks(cell).Vx
                Dim jvy = blocks(cell).Vy
                Dim dx = vPx - (blocks(cell).Px + jvx * tj)
                Dim dy = vPy - (blocks(cell).Py + (jvy + vHalfAy * tj) * tj)
                Dim dvx = vVx - jvx
                Dim dvy = vVy - (jvy + vAy * tj)
                Dim b = dx * dvx + dy * dvy
                Dim sumR = vR + blocks(cell).R
                Dim c = dx * dx + dy * dy - sumR * sumR
                Dim touching = Vector256.LessThanOrEqual(c, vTwo * sumR * vSlop)
                Dim approaching = Vector256.LessThan(b, vZero)
                Dim a = dvx * dvx + dvy * dvy
                Dim disc = b * b - a * c
                If best <> bestSeen Then
                    bestSeen = best
                    vInvBest = Vector256.Create(1 / best)
                End If
                ' Which lanes can hit before the best so far, without the square root and the division
                ' (the slow part of the pair test): t = c / (√disc − b) < best exactly when
                ' √disc > u = c / best + b, that is u < 0 or disc > u². The margin makes it a filter
                ' that lets through every lane the exact test below accepts.
                Dim u = c * vInvBest + b
                Dim candidate = Vector256.AndNot(hot And approaching, touching) And
                                Vector256.GreaterThan(disc, vGraze * b * b) And
                                (Vector256.LessThan(u, vZero) Or Vector256.GreaterThan(disc * vMargin, u * u))
                Dim slow = Vector256.AndNot(valid, hot) Or (hot And touching And approaching)
                Dim special = Vector256.ExtractMostSignificantBits(slow)
                Dim maybe = Vector256.ExtractMostSignificantBits(candidate)
                If (maybe Or special) = 0 Then Continue For
                Dim t = c / (Vector256.Sqrt(disc) - b)
                Dim hit = candidate And Vector256.LessThanOrEqual(vNow + t, blocks(cell).ColTime) And
                          Vector256.LessThan(t, Vector256.Create(best))
                ' Only the lanes that need a look, in lane order (as the one-at-a-time loop takes them).
                Dim look = special Or Vector256.ExtractMostSignificantBits(hit)
                While look <> 0
                    Dim k = BitOperations.TrailingZeroCount(look)
                    look = look And (look - 1UI)
                    Dim j = laneBody(cell * UniformGrid.Lanes + k)
                    If ((special >> k) And 1UI) <> 0 Then
                        If j <> i Then CheckPair(i, j, asleep, px, py, vx, vy, ay, r, best, kind, other)
                    ElseIf t.GetElement(k) < best Then
                        best = t.GetElement(k)
                        kind = EventKind.Circle
                        other = j
                    End If
                End While
            Next
        Next
    End Sub
#End If

    ''' <summary>Files body i's next collision-type event and its next cell exit (times from now, s).</summary>
    Private Sub FileEvent(i As Integer, dt As Double, kind As EventKind, other As Integer, feature As Integer,
                          exitDt As Double, exitDir As Integer)
        _ev(i).Kind = kind
        _ev(i).Other = other
        _ev(i).OtherCount = If(kind = EventKind.Circle, _ev(other).Count, 0)
        _ev(i).Feature = feature
        _ev(i).ColTime = If(dt < Double.PositiveInfinity, _now + dt, Double.PositiveInfinity)
        _ev(i).CellTime = If(exitDt < Double.PositiveInfinity, _now + exitDt, Double.PositiveInfinity)
        _ev(i).CellDir = exitDir
        _queue.Update(i, Math.Min(_ev(i).ColTime, _ev(i).CellTime))
        ' Only the time: its motion was published when it last changed (see EventDrivenSolver.Lanes).
        _grid.PublishColTime(i, _ev(i).ColTime)
    End Sub

    ''' <summary>
    ''' Body i against the container's walls (the floor and the ceiling only when it is free). The
    ''' cells tile the container and are wider than any gridded ball, so a gridded ball touches a wall
    ''' only from a cell along that wall, and it crosses into one (an event) before it gets there:
    ''' only the walls its own cell lies along are tested, on a prediction and on entering the cell.
    ''' </summary>
    Private Sub CheckWalls(i As Integer, free As Boolean, px As Double, py As Double, vx As Double, vy As Double, ay As Double,
                           r As Double, ByRef best As Double, ByRef kind As EventKind, ByRef feature As Integer)
        Dim all = _ev(i).Cell < 0
        Dim col = _ev(i).Col, row = _ev(i).Row
        Dim slop = _slop
        Dim t As Double
        If all OrElse col = 0 Then
            t = TimeOfImpact.GapCloses(px - r, vx, 0, slop)
            If t < best Then best = t : kind = EventKind.Wall : feature = WallSide.Left
        End If
        If all OrElse col = _grid.Nx - 1 Then
            t = TimeOfImpact.GapCloses(_width - r - px, -vx, 0, slop)
            If t < best Then best = t : kind = EventKind.Wall : feature = WallSide.Right
        End If
        If Not free Then Return
        If all OrElse row = 0 Then
            t = TimeOfImpact.GapCloses(py - r, vy, ay, slop)
            If t < best Then best = t : kind = EventKind.Wall : feature = WallSide.Bottom
        End If
        If all OrElse row = _grid.Ny - 1 Then
            t = TimeOfImpact.GapCloses(_height - r - py, -vy, -ay, slop)
            If t < best Then best = t : kind = EventKind.Wall : feature = WallSide.Top
        End If
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
        Dim xj, yj, vxj, vyj As Double
        _body(j).StateAt(_now, xj, yj, vxj, vyj)
        Dim t = TimeOfImpact.CircleCircle(px - xj, py - yj, vx - vxj, vy - vyj, ay - _body(j).Ay, r + _body(j).R, _slop,
                                          Math.Abs(vx) + Math.Abs(vy) + Math.Abs(vxj) + Math.Abs(vyj))
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
        Dim xk, yk, vxk, vyk As Double
        _body(k).StateAt(_now, xk, yk, vxk, vyk)
        Return TimeOfImpact.CircleCircle(xk - _slideCx(j), yk - _slideCy(j), vxk, vyk, _body(k).Ay, _body(k).R + 2 * _body(j).R, _slop)
    End Function

    ''' <summary>
    ''' The cells (columns c0 … c1, rows r0 … r1, within its 3 × 3 block) that a partner touching body i
    ''' in the next <paramref name="span"/> seconds could be in. Until it leaves its cell, or meets what it
    ''' has already found, its centre stays on the stretch of its path that follows; a partner touching it
    ''' there has its centre within r + r_max of that stretch, so only cells that near the stretch's
    ''' bounding box can hold one. A ball moving away from a side of its cell never needs the cells
    ''' beyond it. Every pair is still found: of the two bodies, the one that searched last searched
    ''' with both final courses and the other's cell (docs/event-driven.md §4).
    ''' </summary>
    Private Sub ReachOfPath(i As Integer, px As Double, py As Double, vx As Double, vy As Double, ay As Double, r As Double,
                            span As Double, ByRef c0 As Integer, ByRef c1 As Integer, ByRef r0 As Integer, ByRef r1 As Integer)
        Dim col = _ev(i).Col, row = _ev(i).Row
        c0 = col - 1 : c1 = col + 1 : r0 = row - 1 : r1 = row + 1
        If vx = 0 AndAlso vy = 0 AndAlso ay = 0 Then span = 0 ' at rest: its path is a point
        If Not (span < Double.PositiveInfinity) Then Return
        Dim xlo, xhi, ylo, yhi As Double
        PathBox.Bounds(px, py, vx, vy, ay, span, xlo, xhi, ylo, yhi)
        ' A ball sliding round a corner is listed where it started the slide but can reach 3 r_max
        ' beyond; the margin covers rounding and the touching tolerance.
        Dim reach = r + If(_sliding > 0, 3, 1) * _rMax + 16 * _slop + 1.0E-9 * (_grid.CellWidth + _grid.CellHeight)
        ' Written so that NaN keeps the neighbour.
        If xlo - reach >= col * _grid.CellWidth Then c0 = col
        If xhi + reach <= (col + 1) * _grid.CellWidth Then c1 = col
        If ylo - reach >= row * _grid.CellHeight Then r0 = row
        If yhi + reach <= (row + 1) * _grid.CellHeight Then r1 = row
    End Sub

    ''' <summary>
    ''' When the centre leaves its cell: x is linear and y quadratic in t, each against the cell's two
    ''' boundaries (the outermost cells have no outer boundary). <paramref name="dir"/>: 0 −x, 1 +x, 2 −y, 3 +y.
    ''' A centre that rounding left a hair beyond a boundary of its cell counts as on it, so if it moves
    ''' on outwards it leaves at once; otherwise it would never leave, and its searches would be centred
    ''' on the wrong cell.
    ''' </summary>
    Private Function CellExit(i As Integer, asleep As Boolean, px As Double, py As Double, vx As Double, vy As Double, ay As Double,
                              ByRef dir As Integer) As Double
        Dim best = Double.PositiveInfinity
        Dim cell = _ev(i).Cell
        If cell < 0 OrElse asleep OrElse (vx = 0 AndAlso vy = 0 AndAlso ay = 0) Then Return best
        Dim col = _ev(i).Col, row = _ev(i).Row
        Dim t As Double
        dir = -1
        If col > 0 Then
            t = TimeOfImpact.GapCloses(Math.Max(0, px - col * _grid.CellWidth), vx, 0, 0)
            If t < best Then best = t : dir = 0
        End If
        If col < _grid.Nx - 1 Then
            t = TimeOfImpact.GapCloses(Math.Max(0, (col + 1) * _grid.CellWidth - px), -vx, 0, 0)
            If t < best Then best = t : dir = 1
        End If
        If row > 0 Then
            t = TimeOfImpact.GapCloses(Math.Max(0, py - row * _grid.CellHeight), vy, ay, 0)
            If t < best Then best = t : dir = 2
        End If
        If row < _grid.Ny - 1 Then
            t = TimeOfImpact.GapCloses(Math.Max(0, (row + 1) * _grid.CellHeight - py), -vy, -ay, 0)
            If t < best Then best = t : dir = 3
        End If
        Return best
    End Function
End Class
