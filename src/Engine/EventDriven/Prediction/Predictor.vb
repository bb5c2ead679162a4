Option Strict On

Imports System.Runtime.CompilerServices

#If NET Then
Imports System.Numerics
Imports System.Runtime.Intrinsics
#End If

''' <summary>
''' Prediction: the earliest event of one body against the walls, the obstacles and the movable
''' bodies near it, and its next grid-cell crossing, filed in the queue. Only the cells around it
''' that are within reach of its path are searched (see <see cref="ReachOfPath"/>), so the cost per
''' event stays flat as the number of bodies grows. Which time-of-impact function a pair uses is
''' decided in one place, <see cref="ContactRules"/>; this class only decides whom to ask.
''' </summary>
Friend NotInheritable Class Predictor
    Private ReadOnly _s As SolverState
    ' The state's body table and grid (each made once with it), held here too: one load fewer on every read.
    Private ReadOnly _bodies As BodyTable
    Private ReadOnly _grid As UniformGrid
    Private ReadOnly _slides As CornerSlides
    ''' <summary>Scratch list of the bodies of one cell being tested one by one.</summary>
    Private _scanList As Integer() = Array.Empty(Of Integer)()
    ''' <summary>Pairs a scan left to <see cref="CheckDeferred"/>, and the earliest each could touch, s.</summary>
    Private _deferred As Integer() = Array.Empty(Of Integer)()
    Private _deferredBound As Double() = Array.Empty(Of Double)()
    Private _deferredCount As Integer
    ' The cells of one lane scan whose overflow is still to be tested (see ScanLanesVector).
    Private _crowdedCells As Integer() = Array.Empty(Of Integer)()

#If NET Then
    ''' <summary>Whether pair tests run four lanes at a time (256-bit vectors, when the processor has them).</summary>
    Friend VectorScan As Boolean = Vector256.IsHardwareAccelerated
#Else
    ''' <summary>.NET Framework has no 256-bit vectors: pair tests run one body at a time.</summary>
    Friend ReadOnly VectorScan As Boolean
#End If

    Friend Sub New(state As SolverState, slides As CornerSlides)
        _s = state
        _bodies = state.Bodies
        _grid = state.Grid
        _slides = slides
    End Sub

    ''' <summary>Room for n bodies in the scratch lists.</summary>
    Friend Sub Reset(n As Integer)
        If _scanList.Length < n Then _scanList = New Integer(n - 1) {}
        ' A cell overflows only when it holds more bodies than it has lanes: fewer such cells than bodies.
        If _crowdedCells.Length < n Then _crowdedCells = New Integer(n - 1) {}
        If _deferred.Length < n Then
            _deferred = New Integer(n - 1) {}
            _deferredBound = New Double(n - 1) {}
        End If
    End Sub

    ''' <summary>Recomputes body i's next event at the solver's clock and files it in the queue.</summary>
    Friend Sub Reschedule(i As Integer)
        Dim b = _bodies
        Dim m = b.Slot(i).Mode
        If m = BodyMode.Rounding Then
            RescheduleSlide(i)
            Return
        End If
        Dim p As Probe
        p.Body = i
        b.Motion(i).StateAt(_s.Now, p.Px, p.Py, p.Vx, p.Vy)
        p.Ax = b.Motion(i).Ax
        p.Ay = b.Motion(i).Ay
        p.R = b.Motion(i).R
        p.Slop = SolverState.SlopAt(p.Px, p.Py)
        p.Asleep = m = BodyMode.Sleeping
        p.Best = Double.PositiveInfinity
        p.Kind = EventKind.None
        p.Other = -1
        Dim dir = 0
        p.ExitTime = CellExit(p, dir)
        Dim moving = m = BodyMode.Free OrElse m = BodyMode.Supported
        If moving Then
            If _s.Walls AndAlso AlongWall(i) Then CheckWalls(p, m = BodyMode.Free OrElse (m = BodyMode.Supported AndAlso b.Support(i) >= 0))
            If b.Slot(i).Cell >= 0 Then
                ' An obstacle is listed in every cell within half a cell of it, so the body's own cell
                ' suffices, and only until it leaves the cell: the next cell's obstacles are tested then.
                Dim c = b.Slot(i).Cell
                For s = _grid.StaticStart(c) To _grid.StaticStart(c + 1) - 1
                    CheckObstacle(p, _grid.StaticItems(s))
                Next
            Else
                For s = 0 To _s.Obstacles.Count - 1
                    CheckObstacle(p, s)
                Next
            End If
        End If
        ' Movable neighbours: those in the cells within reach of its path (see ReachOfPath).
        If b.Slot(i).Cell >= 0 Then
            Dim c0, c1, r0, r1 As Integer
            ReachOfPath(p, Math.Min(p.ExitTime, p.Best), c0, c1, r0, r1)
            ScanCells(p, c0, c1, r0, r1, -1)
            If _deferredCount > 0 Then CheckDeferred(p)
            If _s.OversizedCount > 0 Then CheckOversized(p)
        Else
            For j = 0 To b.Count - 1
                If j <> i Then CheckPair(p, j, Double.PositiveInfinity)
            Next
        End If
        If m = BodyMode.Supported AndAlso b.Support(i) >= 0 Then CheckLeaveFace(p)
        File(i, p.Best, p.Kind, p.Other, p.Feature, p.ExitTime, dir)
    End Sub

    ''' <summary>
    ''' Body i slides round a corner: its slide ends, or a neighbour reaches the disc the sliding ball
    ''' sweeps round the corner. Apart from <see cref="Reschedule"/> (which runs at every collision) because it is rare.
    ''' </summary>
    <MethodImpl(MethodImplOptions.NoInlining)>
    Private Sub RescheduleSlide(i As Integer)
        Dim best = _slides.TimeToEnd(i)
        Dim kind = EventKind.CornerEnd
        Dim other = -1
        Dim count = _slides.Neighbours(i)
        For q = 0 To count - 1
            Dim k = _slides.Neighbour(q)
            Dim ts = _slides.TimeToReach(i, k, best)
            If ts < best Then best = ts : kind = EventKind.Body : other = k
        Next
        File(i, best, kind, other, 0, Double.PositiveInfinity, 0)
    End Sub

    ''' <summary>The probe's body, supported, reaching an end of the face it rests on.</summary>
    <MethodImpl(MethodImplOptions.NoInlining)>
    Private Sub CheckLeaveFace(ByRef p As Probe)
        Dim b = _bodies
        Dim i = p.Body
        Dim farEnd As Boolean
        Dim t = ContactRules.TimeToLeaveFace(_s, i, b.Support(i), b.SupportEdge(i), New Vector(p.Px, p.Py), New Vector(p.Vx, p.Vy), New Vector(p.Ax, p.Ay), farEnd)
        If t < p.Best Then
            p.Best = Math.Max(0, t)
            p.Kind = EventKind.LeaveSupport
            p.Other = b.Support(i)
            p.Feature = If(farEnd, 1, 0)
        End If
    End Sub

    ''' <summary>
    ''' Body i's reference point enters the next cell. Its collision prediction stays valid (its own
    ''' motion did not change); the walls and obstacles of the new cell, and the cells within reach of
    ''' its new stretch of path except the one it came from, are searched (docs/event-driven.md §4).
    ''' </summary>
    Friend Sub CrossCell(i As Integer)
        Dim b = _bodies
        Dim dir = b.Slot(i).CellDir
        Dim col = b.Slot(i).Col, row = b.Slot(i).Row
        Select Case dir
            Case 0 : col -= 1
            Case 1 : col += 1
            Case 2 : row -= 1
            Case Else : row += 1
        End Select
        Dim previous = b.Slot(i).Cell
        _s.MoveToCell(i, col, row)
        Dim target = b.Slot(i).Cell
        If b.Slot(i).Kind = EventKind.Body AndAlso b.Slot(b.Slot(i).Other).Count <> b.Slot(i).OtherCount Then
            Reschedule(i) ' the kept prediction went stale: start afresh
            Return
        End If
        ' The kept prediction is the best so far.
        Dim p As Probe
        p.Body = i
        p.Best = b.Slot(i).ColTime - _s.Now
        p.Kind = b.Slot(i).Kind
        p.Other = b.Slot(i).Other
        p.Feature = b.Slot(i).Feature
        Dim m = b.Slot(i).Mode
        b.Motion(i).StateAt(_s.Now, p.Px, p.Py, p.Vx, p.Vy)
        p.Ax = b.Motion(i).Ax
        p.Ay = b.Motion(i).Ay
        p.R = b.Motion(i).R
        p.Slop = SolverState.SlopAt(p.Px, p.Py)
        p.Asleep = m = BodyMode.Sleeping
        Dim exitDir = 0
        p.ExitTime = CellExit(p, exitDir)
        If m = BodyMode.Free OrElse m = BodyMode.Supported Then
            If _s.Walls AndAlso AlongWall(i) Then CheckWalls(p, m = BodyMode.Free OrElse (m = BodyMode.Supported AndAlso b.Support(i) >= 0))
            For s = _grid.StaticStart(target) To _grid.StaticStart(target + 1) - 1
                CheckObstacle(p, _grid.StaticItems(s))
            Next
        End If
        Dim c0, c1, r0, r1 As Integer
        ReachOfPath(p, Math.Min(p.ExitTime, p.Best), c0, c1, r0, r1)
        ScanCells(p, c0, c1, r0, r1, previous)
        If _deferredCount > 0 Then CheckDeferred(p)
        If _s.OversizedCount > 0 Then CheckOversized(p)
        File(i, p.Best, p.Kind, p.Other, p.Feature, p.ExitTime, exitDir)
    End Sub

    ''' <summary>
    ''' The probe's body against the movable bodies in cells col0 … col1 × row0 … row1: in each cell, any
    ''' overflow one by one, then the lanes, four at a time where the processor has 256-bit vectors.
    ''' </summary>
    Private Sub ScanCells(ByRef p As Probe, col0 As Integer, col1 As Integer, row0 As Integer, row1 As Integer, skip As Integer)
        Dim grid = _grid
        Dim c0 = Math.Max(0, col0), c1 = Math.Min(grid.Nx - 1, col1)
        Dim r0 = Math.Max(0, row0), r1 = Math.Min(grid.Ny - 1, row1)
        _s.CellsSearched += (c1 - c0 + 1) * (r1 - r0 + 1)
        If skip >= 0 Then
            Dim sr = skip \ grid.Nx, sc = skip - sr * grid.Nx
            If sc >= c0 AndAlso sc <= c1 AndAlso sr >= r0 AndAlso sr <= r1 Then _s.CellsSearched -= 1
        End If
        ' A body asleep, not a circle (R = 0: only a circle has a rounding radius), or whose acceleration is
        ' not vertical (sliding down a slope), takes no hot path.
        Dim slowOnly = p.Asleep OrElse p.Ax <> 0 OrElse p.R = 0
        _deferredCount = 0
        ' The scan is the last call (a tail call: nothing kept across it); the caller then tests what it
        ' deferred, with CheckDeferred.
#If NET Then
        If VectorScan Then
            ScanLanesVector(p, c0, c1, r0, r1, skip, slowOnly)
            Return
        End If
#End If
        ScanBodies(p, c0, c1, r0, r1, skip, True, slowOnly)
    End Sub

    ''' <summary>A pair the scan leaves to <see cref="CheckPair"/>: tested after the scan, nearest first.</summary>
    Private Sub Defer(j As Integer)
        _deferred(_deferredCount) = j
        _deferredCount += 1
    End Sub

    ''' <summary>
    ''' The pairs the scan deferred (their relative motion is not a straight line, so each costs a quartic,
    ''' or they touch), tested in order of the earliest time they could possibly touch: a lower bound from
    ''' the gap between their bounding circles, closed at most at their relative speed plus the relative
    ''' acceleration's ½|Δa|t². Once that bound reaches the best time found, no later pair can come earlier,
    ''' and the rest are not solved for. In a pile a falling ball has many sleeping neighbours; the nearest
    ''' one is usually the one it meets, and the others then cost a bound each instead of a quartic. Pairs
    ''' of equal bound keep the scan's order, so ties are broken as the scan would.
    ''' </summary>
    Private Sub CheckDeferred(ByRef p As Probe)
        If _deferredCount = 0 Then Return
        Dim b = _bodies
        Dim i = p.Body
        Dim px = p.Px, py = p.Py, vx = p.Vx, vy = p.Vy, ax = p.Ax, ay = p.Ay
        Dim reachI = b.Size(i).Reach
        Dim gapSlop = 4 * p.Slop
        Dim now = _s.Now
        Dim n = 0
        For q = 0 To _deferredCount - 1
            Dim j = _deferred(q)
            Dim bound = 0.0
            Dim mj = b.Slot(j).Mode
            If mj = BodyMode.Sleeping AndAlso p.Asleep Then Continue For ' two sleepers never meet
            If mj = BodyMode.Free OrElse mj = BodyMode.Sleeping OrElse mj = BodyMode.Supported Then
                Dim xj, yj, vxj, vyj As Double
                b.Motion(j).StateAt(now, xj, yj, vxj, vyj)
                Dim dx = px - xj, dy = py - yj
                Dim gap = Math.Sqrt(dx * dx + dy * dy) - reachI - b.Size(j).Reach - gapSlop
                If gap > 0 Then
                    Dim dvx = vx - vxj, dvy = vy - vyj
                    Dim daX = ax - b.Motion(j).Ax, daY = ay - b.Motion(j).Ay
                    Dim speed = Math.Sqrt(dvx * dvx + dvy * dvy)
                    Dim halfAccel = 0.5 * Math.Sqrt(daX * daX + daY * daY)
                    ' The smaller root of ½|Δa| t² + |Δv| t = gap, shrunk by a part in 10⁶ against rounding.
                    bound = 0.999999 * 2 * gap / (speed + Math.Sqrt(speed * speed + 4 * halfAccel * gap))
                    If bound >= p.Best Then Continue For
                End If
            End If
            _deferred(n) = j
            _deferredBound(n) = bound
            n += 1
        Next
        ' Nearest first: pick the smallest bound left (the first of equal ones, as the scan met them) until it reaches the best.
        Do While n > 0
            Dim pick = 0
            For q = 1 To n - 1
                If _deferredBound(q) < _deferredBound(pick) Then pick = q
            Next
            If _deferredBound(pick) >= p.Best Then Exit Do
            Dim j = _deferred(pick)
            For q = pick To n - 2
                _deferred(q) = _deferred(q + 1)
                _deferredBound(q) = _deferredBound(q + 1)
            Next
            n -= 1
            CheckPair(p, j, Double.PositiveInfinity)
        Loop
    End Sub

    ''' <summary>
    ''' Cells c0 … c1 × r0 … r1, one body at a time, from the bodies' own state. With
    ''' <paramref name="withLanes"/>, each cell's lanes, then the overflow lists of the cells that have
    ''' one (the order of the vector scan); without, only the cells' overflow lists.
    ''' <paramref name="slowOnly"/>: the scanning body takes no hot path (asleep, or not falling freely).
    ''' </summary>
    Private Sub ScanBodies(ByRef p As Probe, c0 As Integer, c1 As Integer, r0 As Integer, r1 As Integer, skip As Integer, withLanes As Boolean,
                           slowOnly As Boolean)
        Dim grid = _grid
        Dim count = grid.Count, laneBody = grid.LaneBody, nx = grid.Nx, listed = _scanList
        Dim motion = _bodies.Motion, slot = _bodies.Slot
        Dim now = _s.Now
        ' The probe's numbers in locals, which the loop keeps in registers; a hit is written through.
        Dim i = p.Body
        Dim px = p.Px, py = p.Py, vx = p.Vx, vy = p.Vy, ay = p.Ay, r = p.R, slop = p.Slop
        Dim best = p.Best
        Dim crowded = _crowdedCells, crowdedCount = 0
        For rr = r0 To r1
            For cell = rr * nx + c0 To rr * nx + c1
                If cell = skip Then Continue For
                Dim n = 0
                If withLanes Then
                    If grid.OverflowHead(cell) >= 0 Then
                        crowded(crowdedCount) = cell
                        crowdedCount += 1
                    End If
                    For lane = cell * UniformGrid.Lanes To cell * UniformGrid.Lanes + count(cell) - 1
                        listed(n) = laneBody(lane)
                        n += 1
                    Next
                Else
                    Dim o = grid.OverflowHead(cell)
                    While o >= 0
                        listed(n) = o
                        n += 1
                        o = grid.OverflowNext(o)
                    End While
                End If
                For q = 0 To n - 1
                    Dim j = listed(q)
                    If motion(j).Ay = ay AndAlso motion(j).Ax = 0 AndAlso motion(j).R > 0 AndAlso Not slowOnly Then
                        ' Hot path (the elastic gas): the same acceleration, so the relative motion is a
                        ' straight line and the contact time is the smaller root of a quadratic. The root
                        ' is computed for every candidate and the tests combined into one condition: which
                        ' pairs meet is random, and a mispredicted branch costs more than the square root.
                        Dim xj, yj, vxj, vyj As Double
                        motion(j).StateAt(now, xj, yj, vxj, vyj)
                        Dim dx = px - xj
                        Dim dy = py - yj
                        Dim dvx = vx - vxj
                        Dim dvy = vy - vyj
                        Dim b = dx * dvx + dy * dvy
                        Dim sumR = r + motion(j).R
                        Dim c = dx * dx + dy * dy - sumR * sumR
                        If c <= 2 * sumR * slop Then
                            ' Touching (common in a pile): only an approach can be a collision now.
                            If b < 0 AndAlso j <> i Then Defer(j)
                        Else
                            Dim a = dvx * dvx + dvy * dvy
                            Dim disc = b * b - a * c
                            Dim t = c / (Math.Sqrt(disc) - b)
                            ' Approaching, not a graze, earlier than the best so far, and not after the
                            ' partner's own next collision (it is rescheduled then and finds this pair
                            ' again, so filing it here would only go stale).
                            Dim hit = (b < 0) And (disc > TimeOfImpact.GrazeFraction * b * b) And (t < best)
                            If hit AndAlso now + t <= slot(j).ColTime Then
                                best = t
                                p.OfferBody(t, j)
                            End If
                        End If
                    ElseIf j <> i Then
                        Defer(j)
                    End If
                Next
            Next
        Next
        For k = 0 To crowdedCount - 1
            Dim row = crowded(k) \ nx, col = crowded(k) - row * nx
            ScanBodies(p, col, col, row, row, -1, False, slowOnly)
        Next
    End Sub

#If NET Then
    ''' <summary>
    ''' Cells c0 … c1 × r0 … r1, four lanes at a time, from the published copies (then any overflow,
    ''' one by one, as in <see cref="ScanBodies"/>): the pair test of <see cref="ScanBodies"/> with
    ''' the same arithmetic, lane by lane. Lanes whose body does not share the scanning body's
    ''' acceleration, and touching pairs, go to <see cref="CheckPair"/>; a hit earlier than the best
    ''' so far is taken in lane order, as the scalar loop would.
    ''' </summary>
    Private Sub ScanLanesVector(ByRef p As Probe, c0 As Integer, c1 As Integer, r0 As Integer, r1 As Integer, skip As Integer, slowOnly As Boolean)
        Dim grid = _grid
        Dim blocks = grid.Blocks, shift = grid.BlockShift, count = grid.Count, laneBody = grid.LaneBody, overflow = grid.OverflowHead
        Dim nx = grid.Nx
        Dim now = _s.Now
        Dim i = p.Body
        Dim ay = p.Ay
        Dim vNow = Vector256.Create(now)
        Dim vPx = Vector256.Create(p.Px), vPy = Vector256.Create(p.Py)
        Dim vVx = Vector256.Create(p.Vx), vVy = Vector256.Create(p.Vy)
        Dim vAy = Vector256.Create(ay), vHalfAy = Vector256.Create(0.5 * ay)
        ' A body that takes no hot path matches no lane: NaN equals nothing.
        Dim vMatch = Vector256.Create(If(slowOnly, Double.NaN, ay))
        Dim vR = Vector256.Create(p.R), vTwo = Vector256.Create(2.0), vSlop = Vector256.Create(p.Slop)
        Dim vGraze = Vector256.Create(TimeOfImpact.GrazeFraction)
        Dim vZero = Vector256(Of Double).Zero
        Dim laneIndex = Vector256.Create(0.0, 1.0, 2.0, 3.0)
        Dim vMargin = Vector256.Create(1 + 1.0E-6)
        ' The best so far in a local, which the loop keeps in a register; a hit is written through.
        Dim best = p.Best
        Dim bestSeen = best, vInvBest = Vector256.Create(1 / best)
        ' Cells with an overflow are listed and their overflow tested after the lanes: the loop then
        ' calls nothing, so its constants stay in registers.
        Dim crowded = _crowdedCells, crowdedCount = 0
        For rr = r0 To r1
            For cell = rr * nx + c0 To rr * nx + c1
                If cell = skip Then Continue For
                If overflow(cell) >= 0 Then
                    crowded(crowdedCount) = cell
                    crowdedCount += 1
                End If
                Dim valid = Vector256.LessThan(laneIndex, Vector256.Create(CDbl(count(cell))))
                Dim hot = valid And Vector256.Equals(Unsafe.AddByteOffset(blocks(cell), shift).Ay, vMatch)
                Dim tj = vNow - Unsafe.AddByteOffset(blocks(cell), shift).T0
                Dim jvx = Unsafe.AddByteOffset(blocks(cell), shift).Vx
                Dim jvy = Unsafe.AddByteOffset(blocks(cell), shift).Vy
                Dim dx = vPx - (Unsafe.AddByteOffset(blocks(cell), shift).Px + jvx * tj)
                Dim dy = vPy - (Unsafe.AddByteOffset(blocks(cell), shift).Py + (jvy + vHalfAy * tj) * tj)
                Dim dvx = vVx - jvx
                Dim dvy = vVy - (jvy + vAy * tj)
                Dim b = dx * dvx + dy * dvy
                Dim sumR = vR + Unsafe.AddByteOffset(blocks(cell), shift).R
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
                Dim hit = candidate And Vector256.LessThanOrEqual(vNow + t, Unsafe.AddByteOffset(blocks(cell), shift).ColTime) And
                          Vector256.LessThan(t, Vector256.Create(best))
                ' Only the lanes that need a look, in lane order (as the one-at-a-time loop takes them).
                Dim look = special Or Vector256.ExtractMostSignificantBits(hit)
                While look <> 0
                    Dim k = BitOperations.TrailingZeroCount(look)
                    look = look And (look - 1UI)
                    Dim j = laneBody(cell * UniformGrid.Lanes + k)
                    If ((special >> k) And 1UI) <> 0 Then
                        If j <> i Then Defer(j)
                    ElseIf t.GetElement(k) < best Then
                        best = t.GetElement(k)
                        p.OfferBody(best, j)
                    End If
                End While
            Next
        Next
        For k = 0 To crowdedCount - 1
            Dim rr = crowded(k) \ nx, col = crowded(k) - rr * nx
            ScanBodies(p, col, col, rr, rr, -1, False, slowOnly)
        Next
    End Sub
#End If

    ''' <summary>Files body i's next collision-type event and its next cell exit (times from now, s).</summary>
    Private Sub File(i As Integer, dt As Double, kind As EventKind, other As Integer, feature As Integer,
                     exitDt As Double, exitDir As Integer)
        Dim slot = _bodies.Slot
        Dim now = _s.Now
        slot(i).Kind = kind
        slot(i).Other = other
        slot(i).OtherCount = If(kind = EventKind.Body, slot(other).Count, 0)
        slot(i).Feature = feature
        slot(i).ColTime = If(dt < Double.PositiveInfinity, now + dt, Double.PositiveInfinity)
        slot(i).CellTime = If(exitDt < Double.PositiveInfinity, now + exitDt, Double.PositiveInfinity)
        slot(i).CellDir = exitDir
        _s.Queue.Update(i, Math.Min(slot(i).ColTime, slot(i).CellTime))
        ' Only the time: its motion was published when it last changed (see SolverState.Changed).
        _grid.PublishColTime(i, slot(i).ColTime)
    End Sub

    ''' <summary>
    ''' Whether body i's cell lies along a wall of the container (or it is out of the grid): only then
    ''' can it reach a wall before it next crosses into another cell (see <see cref="CheckWalls"/>).
    ''' Tested before the call, which most bodies, far from the walls, are spared.
    ''' </summary>
    Private Function AlongWall(i As Integer) As Boolean
        Dim slot = _bodies.Slot
        Dim col = slot(i).Col, row = slot(i).Row
        Return slot(i).Cell < 0 OrElse col = 0 OrElse row = 0 OrElse col = _grid.Nx - 1 OrElse row = _grid.Ny - 1
    End Function

    ''' <summary>
    ''' The probe's body against the container's walls (the floor and the ceiling only when it is free or slides
    ''' on a fixed body: a ramp may end below the point where a ball sliding down it meets the floor;
    ''' one resting on the floor or on a body is held by what it rests on). The
    ''' cells tile the container and are wider than any gridded body, so a gridded body touches a wall
    ''' only from a cell along that wall, and it crosses into one (an event) before it gets there:
    ''' only the walls its own cell lies along are tested, on a prediction and on entering the cell.
    ''' </summary>
    Private Sub CheckWalls(ByRef p As Probe, vertical As Boolean)
        Dim b = _bodies
        Dim slot = b.Slot
        Dim i = p.Body
        Dim px = p.Px, py = p.Py, vx = p.Vx, vy = p.Vy, ax = p.Ax, ay = p.Ay, r = p.R
        Dim all = slot(i).Cell < 0
        Dim col = slot(i).Col, row = slot(i).Row
        Dim atLeft = all OrElse col = 0, atRight = all OrElse col = _grid.Nx - 1
        Dim atBottom = vertical AndAlso (all OrElse row = 0), atTop = vertical AndAlso (all OrElse row = _grid.Ny - 1)
        If Not (atLeft OrElse atRight OrElse atBottom OrElse atTop) Then Return
        ' The outline's extents; a circle's are its radius (read from the motion, not the outline object).
        Dim minX = -r, maxX = r, minY = -r, maxY = r
        If Not b.Info(i).IsCircle Then
            Dim o = b.Outlines(i)
            minX = o.MinX : maxX = o.MaxX : minY = o.MinY : maxY = o.MaxY
        End If
        ' Each wall's gap is measured along one axis (from the outline's extent on that side), so its
        ' tolerance follows that coordinate alone.
        Dim slop = SolverState.SlopAlong(px)
        Dim t As Double
        If atLeft Then
            t = TimeOfImpact.GapCloses(px + minX, vx, ax, slop)
            p.Offer(t, EventKind.Wall, p.Other, WallSide.Left)
        End If
        If atRight Then
            t = TimeOfImpact.GapCloses(_s.Width - maxX - px, -vx, -ax, slop)
            p.Offer(t, EventKind.Wall, p.Other, WallSide.Right)
        End If
        slop = SolverState.SlopAlong(py)
        If atBottom Then
            t = TimeOfImpact.GapCloses(py + minY, vy, ay, slop)
            p.Offer(t, EventKind.Wall, p.Other, WallSide.Bottom)
        End If
        If atTop Then
            t = TimeOfImpact.GapCloses(_s.Height - maxY - py, -vy, -ay, slop)
            p.Offer(t, EventKind.Wall, p.Other, WallSide.Top)
        End If
    End Sub

    ''' <summary>The probe's body against obstacle s, looking no further ahead than the best so far or its next cell exit.</summary>
    Private Sub CheckObstacle(ByRef p As Probe, s As Integer)
        ' Sliding on a face of a convex body, it can meet that body again only where the face ends,
        ' which is its own event (LeaveSupport).
        Dim i = p.Body
        If _bodies.Support(i) = s AndAlso _bodies.Slot(i).Mode = BodyMode.Supported Then Return
        Dim f As Integer
        Dim t = ContactRules.TimeToObstacle(_s, i, s, p.Px, p.Py, p.Vx, p.Vy, p.Ax, p.Ay, p.Slop, Math.Min(p.Best, p.ExitTime), f)
        p.Offer(t, EventKind.Obstacle, s, f)
    End Sub

    ''' <summary>
    ''' The probe's body (gridded) against the bodies too large for the grid, looking only as far ahead as its next
    ''' cell crossing: they are tested again on every crossing, and an oversized body that changes
    ''' course tests every body itself.
    ''' </summary>
    Private Sub CheckOversized(ByRef p As Probe)
        For k = 0 To _s.OversizedCount - 1
            CheckPair(p, _s.Oversized(k), p.ExitTime)
        Next
    End Sub

    ''' <summary>
    ''' The probe's body against movable body j, looking no further ahead than the best so far or
    ''' <paramref name="until"/> (s from now).
    ''' </summary>
    Private Sub CheckPair(ByRef p As Probe, j As Integer, until As Double)
        Dim b = _bodies
        Dim mj = b.Slot(j).Mode
        If mj = BodyMode.Rounding Then
            p.OfferBody(_slides.TimeToReach(j, p.Body, p.Best), j)
            Return
        End If
        If p.Asleep AndAlso mj = BodyMode.Sleeping Then Return
        Dim f As Integer
        p.OfferBody(ContactRules.TimeBetweenBodies(_s, p.Body, j, p.Slop, Math.Min(p.Best, until), f), j)
    End Sub

    ''' <summary>
    ''' The cells (columns c0 … c1, rows r0 … r1, within its 3 × 3 block) that a partner touching the probe's body
    ''' in the next <paramref name="span"/> seconds could be in. Until it leaves its cell, or meets what it
    ''' has already found, its reference point stays on the stretch of its path that follows; a partner
    ''' touching it there has its reference point within r + r_max of that stretch, so only cells that
    ''' near the stretch's bounding box can hold one. A body moving away from a side of its cell never
    ''' needs the cells beyond it. Every pair is still found: of the two bodies, the one that searched
    ''' last searched with both final courses and the other's cell (docs/event-driven.md §4).
    ''' </summary>
    Private Sub ReachOfPath(ByRef p As Probe, span As Double, ByRef c0 As Integer, ByRef c1 As Integer, ByRef r0 As Integer, ByRef r1 As Integer)
        Dim slot = _bodies.Slot
        Dim grid = _grid
        Dim i = p.Body
        Dim px = p.Px, py = p.Py, vx = p.Vx, vy = p.Vy, ax = p.Ax, ay = p.Ay, r = p.R, slop = p.Slop
        Dim col = slot(i).Col, row = slot(i).Row
        c0 = col - 1 : c1 = col + 1 : r0 = row - 1 : r1 = row + 1
        If vx = 0 AndAlso vy = 0 AndAlso ay = 0 AndAlso ax = 0 Then span = 0 ' at rest: its path is a point
        If Not (span < Double.PositiveInfinity) OrElse ax <> 0 Then Return
        Dim xlo, xhi, ylo, yhi As Double
        PathBox.Bounds(px, py, vx, vy, ay, span, xlo, xhi, ylo, yhi)
        ' A body sliding round a corner is listed where it started the slide but can reach 3 r_max
        ' beyond; the margin covers rounding and the touching tolerance.
        ' A circle's reach is its radius (R > 0 only for a circle), read from the motion already at hand.
        Dim reach = If(r > 0, r, _bodies.Size(i).Reach) + If(_bodies.Rounding > 0, 3, 1) * _s.RMax + 16 * slop + 1.0E-9 * (grid.CellWidth + grid.CellHeight)
        ' Written so that NaN keeps the neighbour.
        If xlo - reach >= col * grid.CellWidth Then c0 = col
        If xhi + reach <= (col + 1) * grid.CellWidth Then c1 = col
        If ylo - reach >= row * grid.CellHeight Then r0 = row
        If yhi + reach <= (row + 1) * grid.CellHeight Then r1 = row
    End Sub

    ''' <summary>
    ''' When the reference point leaves its cell: x is linear and y quadratic in t, each against the
    ''' cell's two boundaries (the outermost cells have no outer boundary). <paramref name="dir"/>: 0 −x,
    ''' 1 +x, 2 −y, 3 +y. A point that rounding left a hair beyond a boundary of its cell counts as on
    ''' it, so if it moves on outwards it leaves at once; otherwise it would never leave, and its
    ''' searches would be centred on the wrong cell.
    ''' </summary>
    Private Function CellExit(ByRef p As Probe, ByRef dir As Integer) As Double
        Dim best = Double.PositiveInfinity
        Dim slot = _bodies.Slot
        Dim grid = _grid
        Dim i = p.Body
        Dim px = p.Px, py = p.Py, vx = p.Vx, vy = p.Vy, ax = p.Ax, ay = p.Ay
        Dim cell = slot(i).Cell
        If cell < 0 OrElse p.Asleep OrElse (vx = 0 AndAlso vy = 0 AndAlso ay = 0 AndAlso ax = 0) Then Return best
        Dim col = slot(i).Col, row = slot(i).Row
        Dim t As Double
        dir = -1
        If col > 0 Then
            t = TimeOfImpact.GapCloses(Math.Max(0, px - col * grid.CellWidth), vx, ax, 0)
            If t < best Then best = t : dir = 0
        End If
        If col < grid.Nx - 1 Then
            t = TimeOfImpact.GapCloses(Math.Max(0, (col + 1) * grid.CellWidth - px), -vx, -ax, 0)
            If t < best Then best = t : dir = 1
        End If
        If row > 0 Then
            t = TimeOfImpact.GapCloses(Math.Max(0, py - row * grid.CellHeight), vy, ay, 0)
            If t < best Then best = t : dir = 2
        End If
        If row < grid.Ny - 1 Then
            t = TimeOfImpact.GapCloses(Math.Max(0, (row + 1) * grid.CellHeight - py), -vy, -ay, 0)
            If t < best Then best = t : dir = 3
        End If
        Return best
    End Function
End Class
