Option Strict On

''' <summary>
''' A baseline for the benchmark, not part of the engine: the elastic gas simulated event by event
''' the way the textbooks do it (Alder and Wainwright 1959; Rapaport, The Art of Molecular Dynamics
''' Simulation, ch. 14). Free discs (g = 0, e = 1) in a walled box; a uniform grid of cell lists
''' with about one disc per cell; for each disc one next event (its earliest collision, wall bounce
''' or cell exit) in a binary heap; and a counter per disc, bumped when its course changes, which
''' makes the events predicted against its old course stale. It has none of the engine's features
''' (gravity, obstacles, rest, the user's changes mid-run) and none of its tuning (pairs tested
''' four at a time, searches limited to the reach of a path, the calendar queue). Timed beside the
''' event-driven solver on the same gas, it shows what this machine gives for the same work done
''' plainly: a speed target that it misses by as much as the engine does is a target for the
''' machine, not for the engine's design.
''' </summary>
Friend NotInheritable Class TextbookGas
    ''' <summary>A disc's course: at time T0 (s) at (X, Y) m with velocity (Vx, Vy) m/s; radius R m; 1/mass, 1/kg.</summary>
    Private Structure Disc
        Friend T0 As Double
        Friend X As Double
        Friend Y As Double
        Friend Vx As Double
        Friend Vy As Double
        Friend R As Double
        Friend InvMass As Double
    End Structure

    ''' <summary>A disc's next event and its place in the grid.</summary>
    Private Structure NextEvent
        ''' <summary>Time (s) of its next collision or wall bounce, +∞ if none.</summary>
        Friend HitTime As Double
        ''' <summary>Time (s) its centre leaves its cell, +∞ if never.</summary>
        Friend ExitTime As Double
        ''' <summary>The other disc (≥ 0) or the wall (−1 left, −2 right, −3 bottom, −4 top) it hits.</summary>
        Friend Partner As Integer
        ''' <summary>The partner's counter when the hit was predicted.</summary>
        Friend PartnerCount As Integer
        ''' <summary>Which way it leaves the cell: 0 −x, 1 +x, 2 −y, 3 +y.</summary>
        Friend ExitSide As Integer
        ''' <summary>Bumped whenever its course changes.</summary>
        Friend Count As Integer
        Friend Col As Integer
        Friend Row As Integer
        ''' <summary>Its index in its cell's list.</summary>
        Friend Slot As Integer
    End Structure

    Private Const NoPartner As Integer = Integer.MinValue

    Private ReadOnly _n As Integer
    Private ReadOnly _width As Double
    Private ReadOnly _height As Double
    Private ReadOnly _disc As Disc()
    Private ReadOnly _next As NextEvent()

    ' The grid: Nx × Ny cells; cell c lists its discs in _cellItems(c · _capacity …), _cellCount(c) of them.
    Private ReadOnly _nx As Integer
    Private ReadOnly _ny As Integer
    Private ReadOnly _cellWidth As Double
    Private ReadOnly _cellHeight As Double
    Private _capacity As Integer = 8
    Private ReadOnly _cellCount As Integer()
    Private _cellItems As Integer()

    ' The binary heap of the discs by the time of their next event: _heapTime(k) and _heapDisc(k) at
    ' place k, children at 2k + 1 and 2k + 2; _place(i) is where disc i is.
    Private ReadOnly _heapTime As Double()
    Private ReadOnly _heapDisc As Integer()
    Private ReadOnly _place As Integer()

    ''' <summary>The clock, s.</summary>
    Public ReadOnly Property Time As Double

    ''' <summary>Collisions so far, wall bounces included, as the engine counts them.</summary>
    Public ReadOnly Property CollisionCount As Long

    ''' <summary>Events processed so far: collisions, wall bounces, cell exits and stale predictions.</summary>
    Public ReadOnly Property EventCount As Long

    ''' <summary>
    ''' Takes the circles of <paramref name="world"/> (its time, positions, velocities, radii, masses)
    ''' and predicts every disc's first event. Only what the baseline models: movable circles, g = 0,
    ''' e = 1, walls on, no rectangles, no overlaps.
    ''' </summary>
    Public Sub New(world As World)
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If world.Gravity <> 0 OrElse world.Restitution <> 1 OrElse Not world.Walls OrElse world.Rectangles.Count > 0 OrElse
           world.Circles.Count = 0 OrElse world.Circles.Any(Function(c) c.IsFixed) Then
            Throw New ArgumentException("the textbook gas models only free circles in a walled box with g = 0, e = 1 and no rectangles", NameOf(world))
        End If
        _n = world.Circles.Count
        _width = world.Width
        _height = world.Height
        _Time = world.Time
        _disc = New Disc(_n - 1) {}
        _next = New NextEvent(_n - 1) {}
        Dim rMax = 0.0
        For i = 0 To _n - 1
            Dim c = world.Circles(i)
            _disc(i) = New Disc With {.T0 = _Time, .X = c.Position.X, .Y = c.Position.Y, .Vx = c.Velocity.X, .Vy = c.Velocity.Y,
                                      .R = c.Radius, .InvMass = c.InverseMass}
            rMax = Math.Max(rMax, c.Radius)
        Next
        ' About one disc per cell, and no narrower than the widest disc, so discs that touch are in neighbouring cells.
        Dim size = Math.Max(2 * rMax * (1 + 1.0E-9), Math.Sqrt(_width * _height / _n))
        _nx = Math.Max(1, CInt(Math.Min(4096, Math.Floor(_width / size))))
        _ny = Math.Max(1, CInt(Math.Min(4096, Math.Floor(_height / size))))
        _cellWidth = _width / _nx
        _cellHeight = _height / _ny
        _cellCount = New Integer(_nx * _ny - 1) {}
        _cellItems = New Integer(_nx * _ny * _capacity - 1) {}
        For i = 0 To _n - 1
            _next(i).Col = Math.Min(_nx - 1, Math.Max(0, CInt(Math.Floor(_disc(i).X / _cellWidth))))
            _next(i).Row = Math.Min(_ny - 1, Math.Max(0, CInt(Math.Floor(_disc(i).Y / _cellHeight))))
            AddToCell(i)
        Next
        _heapTime = New Double(_n - 1) {}
        _heapDisc = New Integer(_n - 1) {}
        _place = New Integer(_n - 1) {}
        For i = 0 To _n - 1
            _heapTime(i) = Double.PositiveInfinity
            _heapDisc(i) = i
            _place(i) = i
        Next
        For i = 0 To _n - 1
            _next(i).HitTime = Double.PositiveInfinity
        Next
        For i = 0 To _n - 1
            Predict(i)
        Next
    End Sub

    ''' <summary>Runs the gas for <paramref name="duration"/> seconds: take the earliest event, move the clock to it, carry it out; repeat.</summary>
    Public Sub Advance(duration As Double)
        Dim tEnd = _Time + duration
        Do
            Dim t = _heapTime(0)
            If Not (t <= tEnd) Then Exit Do
            _Time = t
            Carry(_heapDisc(0))
            _EventCount += 1
        Loop
        _Time = tEnd
    End Sub

    ''' <summary>Disc i's position at the clock, m.</summary>
    Public Function PositionOf(i As Integer) As Vector
        Dim tau = _Time - _disc(i).T0
        Return New Vector(_disc(i).X + _disc(i).Vx * tau, _disc(i).Y + _disc(i).Vy * tau)
    End Function

    ''' <summary>Disc i's velocity, m/s.</summary>
    Public Function VelocityOf(i As Integer) As Vector
        Return New Vector(_disc(i).Vx, _disc(i).Vy)
    End Function

    ''' <summary>Total kinetic energy, J.</summary>
    Public Function KineticEnergy() As Double
        Dim sum = 0.0
        For i = 0 To _n - 1
            sum += 0.5 * (_disc(i).Vx * _disc(i).Vx + _disc(i).Vy * _disc(i).Vy) / _disc(i).InvMass
        Next
        Return sum
    End Function

    Private Sub Carry(i As Integer)
        If _next(i).ExitTime <= _next(i).HitTime Then
            CrossCell(i)
            Return
        End If
        Dim j = _next(i).Partner
        If j >= 0 Then
            If _next(j).Count <> _next(i).PartnerCount Then
                Predict(i) ' stale: j's course changed since
                Return
            End If
            Collide(i, j)
        Else
            MoveToClock(i)
            If j >= -2 Then _disc(i).Vx = -_disc(i).Vx Else _disc(i).Vy = -_disc(i).Vy
            _CollisionCount += 1
            _next(i).Count += 1
            Predict(i)
        End If
    End Sub

    ''' <summary>An elastic collision: the impulse along the line of centres that reverses the approach.</summary>
    Private Sub Collide(i As Integer, j As Integer)
        MoveToClock(i)
        MoveToClock(j)
        Dim dx = _disc(i).X - _disc(j).X, dy = _disc(i).Y - _disc(j).Y
        Dim d = Math.Sqrt(dx * dx + dy * dy)
        Dim nx = dx / d, ny = dy / d
        Dim approach = (_disc(i).Vx - _disc(j).Vx) * nx + (_disc(i).Vy - _disc(j).Vy) * ny
        If approach < 0 Then
            Dim impulse = -2 * approach / (_disc(i).InvMass + _disc(j).InvMass)
            _disc(i).Vx += impulse * _disc(i).InvMass * nx
            _disc(i).Vy += impulse * _disc(i).InvMass * ny
            _disc(j).Vx -= impulse * _disc(j).InvMass * nx
            _disc(j).Vy -= impulse * _disc(j).InvMass * ny
            _CollisionCount += 1
        End If
        _next(i).Count += 1
        _next(j).Count += 1
        Predict(i)
        Predict(j)
    End Sub

    Private Sub MoveToClock(i As Integer)
        Dim tau = _Time - _disc(i).T0
        _disc(i).X += _disc(i).Vx * tau
        _disc(i).Y += _disc(i).Vy * tau
        _disc(i).T0 = _Time
    End Sub

    ''' <summary>Disc i's next event from scratch: the walls of its cell, every disc in the 3 × 3 cells around it, its cell exit.</summary>
    Private Sub Predict(i As Integer)
        Dim x, y As Double
        PositionAtClock(i, x, y)
        Dim best = Double.PositiveInfinity, partner = NoPartner
        HitWalls(i, x, y, best, partner)
        Dim col = _next(i).Col, row = _next(i).Row
        HitDiscsIn(i, col - 1, col + 1, row - 1, row + 1, x, y, best, partner)
        File(i, x, y, best, partner)
    End Sub

    ''' <summary>
    ''' Disc i enters the next cell. Its predicted hit still holds (its course did not change) unless
    ''' the partner's did; the three cells that have just come next to it are searched, and the walls.
    ''' </summary>
    Private Sub CrossCell(i As Integer)
        RemoveFromCell(i)
        Dim side = _next(i).ExitSide
        Select Case side
            Case 0 : _next(i).Col -= 1
            Case 1 : _next(i).Col += 1
            Case 2 : _next(i).Row -= 1
            Case Else : _next(i).Row += 1
        End Select
        AddToCell(i)
        Dim partner = _next(i).Partner
        If partner >= 0 AndAlso _next(partner).Count <> _next(i).PartnerCount Then
            Predict(i)
            Return
        End If
        Dim x, y As Double
        PositionAtClock(i, x, y)
        Dim best = _next(i).HitTime - _Time
        HitWalls(i, x, y, best, partner)
        Dim col = _next(i).Col, row = _next(i).Row
        Select Case side
            Case 0 : HitDiscsIn(i, col - 1, col - 1, row - 1, row + 1, x, y, best, partner)
            Case 1 : HitDiscsIn(i, col + 1, col + 1, row - 1, row + 1, x, y, best, partner)
            Case 2 : HitDiscsIn(i, col - 1, col + 1, row - 1, row - 1, x, y, best, partner)
            Case Else : HitDiscsIn(i, col - 1, col + 1, row + 1, row + 1, x, y, best, partner)
        End Select
        File(i, x, y, best, partner)
    End Sub

    Private Sub PositionAtClock(i As Integer, ByRef x As Double, ByRef y As Double)
        Dim tau = _Time - _disc(i).T0
        x = _disc(i).X + _disc(i).Vx * tau
        y = _disc(i).Y + _disc(i).Vy * tau
    End Sub

    ''' <summary>Disc i against every disc in columns c0 … c1, rows r0 … r1 (those inside the grid).</summary>
    Private Sub HitDiscsIn(i As Integer, c0 As Integer, c1 As Integer, r0 As Integer, r1 As Integer, x As Double, y As Double,
                           ByRef best As Double, ByRef partner As Integer)
        For r = Math.Max(0, r0) To Math.Min(_ny - 1, r1)
            For c = Math.Max(0, c0) To Math.Min(_nx - 1, c1)
                HitDiscsInCell(i, r * _nx + c, x, y, best, partner)
            Next
        Next
    End Sub

    ''' <summary>
    ''' Disc i against every disc of one cell: their relative motion is a straight line, so they touch
    ''' at the smaller root of |d + v t| = r_i + r_j. A hit after the partner's own next hit is left
    ''' out (the partner is predicted again then and finds this pair if it still holds).
    ''' </summary>
    Private Sub HitDiscsInCell(i As Integer, cell As Integer, x As Double, y As Double, ByRef best As Double, ByRef partner As Integer)
        Dim vx = _disc(i).Vx, vy = _disc(i).Vy, ri = _disc(i).R
        Dim first = cell * _capacity
        For k = first To first + _cellCount(cell) - 1
            Dim j = _cellItems(k)
            If j = i Then Continue For
            Dim tau = _Time - _disc(j).T0
            Dim dx = x - (_disc(j).X + _disc(j).Vx * tau)
            Dim dy = y - (_disc(j).Y + _disc(j).Vy * tau)
            Dim dvx = vx - _disc(j).Vx
            Dim dvy = vy - _disc(j).Vy
            Dim b = dx * dvx + dy * dvy
            If b >= 0 Then Continue For ' moving apart
            Dim sumR = ri + _disc(j).R
            Dim c = dx * dx + dy * dy - sumR * sumR
            Dim a = dvx * dvx + dvy * dvy
            Dim disc = b * b - a * c
            If disc <= 0 Then Continue For ' they miss
            Dim t = If(c <= 0, 0.0, c / (Math.Sqrt(disc) - b))
            If t < best AndAlso _Time + t <= _next(j).HitTime Then
                best = t
                partner = j
            End If
        Next
    End Sub

    ''' <summary>The walls along disc i's cell: a gap closing at a constant speed.</summary>
    Private Sub HitWalls(i As Integer, x As Double, y As Double, ByRef best As Double, ByRef partner As Integer)
        Dim vx = _disc(i).Vx, vy = _disc(i).Vy, r = _disc(i).R
        If _next(i).Col = 0 Then Earlier(GapCloses(x - r, -vx), -1, best, partner)
        If _next(i).Col = _nx - 1 Then Earlier(GapCloses(_width - r - x, vx), -2, best, partner)
        If _next(i).Row = 0 Then Earlier(GapCloses(y - r, -vy), -3, best, partner)
        If _next(i).Row = _ny - 1 Then Earlier(GapCloses(_height - r - y, vy), -4, best, partner)
    End Sub

    ''' <summary>Takes <paramref name="t"/> (s) and what it is for when it is earlier than the best so far.</summary>
    Private Shared Sub Earlier(t As Double, what As Integer, ByRef best As Double, ByRef which As Integer)
        If t < best Then
            best = t
            which = what
        End If
    End Sub

    ''' <summary>When a gap (m) closing at <paramref name="speed"/> m/s is gone, s; +∞ if it is not closing.</summary>
    Private Shared Function GapCloses(gap As Double, speed As Double) As Double
        If speed <= 0 Then Return Double.PositiveInfinity
        Return Math.Max(0, gap) / speed
    End Function

    ''' <summary>Files disc i's next hit (<paramref name="best"/> s from now) and its next cell exit.</summary>
    Private Sub File(i As Integer, x As Double, y As Double, best As Double, partner As Integer)
        Dim vx = _disc(i).Vx, vy = _disc(i).Vy
        Dim col = _next(i).Col, row = _next(i).Row
        Dim exitTime = Double.PositiveInfinity, side = -1
        If col > 0 Then Earlier(GapCloses(x - col * _cellWidth, -vx), 0, exitTime, side)
        If col < _nx - 1 Then Earlier(GapCloses((col + 1) * _cellWidth - x, vx), 1, exitTime, side)
        If row > 0 Then Earlier(GapCloses(y - row * _cellHeight, -vy), 2, exitTime, side)
        If row < _ny - 1 Then Earlier(GapCloses((row + 1) * _cellHeight - y, vy), 3, exitTime, side)
        _next(i).HitTime = _Time + best
        _next(i).Partner = partner
        _next(i).PartnerCount = If(partner >= 0, _next(partner).Count, 0)
        _next(i).ExitTime = _Time + exitTime
        _next(i).ExitSide = side
        Reposition(i, Math.Min(_next(i).HitTime, _next(i).ExitTime))
    End Sub

    Private Sub AddToCell(i As Integer)
        Dim cell = _next(i).Row * _nx + _next(i).Col
        If _cellCount(cell) = _capacity Then Widen()
        _cellItems(cell * _capacity + _cellCount(cell)) = i
        _next(i).Slot = _cellCount(cell)
        _cellCount(cell) += 1
    End Sub

    Private Sub RemoveFromCell(i As Integer)
        Dim cell = _next(i).Row * _nx + _next(i).Col
        Dim last = _cellCount(cell) - 1
        Dim slot = _next(i).Slot
        If slot <> last Then
            Dim moved = _cellItems(cell * _capacity + last)
            _cellItems(cell * _capacity + slot) = moved
            _next(moved).Slot = slot
        End If
        _cellCount(cell) = last
    End Sub

    ''' <summary>A cell is full: every cell gets twice the room.</summary>
    Private Sub Widen()
        Dim wider = New Integer(_cellCount.Length * _capacity * 2 - 1) {}
        For cell = 0 To _cellCount.Length - 1
            Array.Copy(_cellItems, cell * _capacity, wider, cell * _capacity * 2, _cellCount(cell))
        Next
        _cellItems = wider
        _capacity *= 2
    End Sub

    ''' <summary>Moves disc i to its place in the heap for its new time <paramref name="t"/> (s).</summary>
    Private Sub Reposition(i As Integer, t As Double)
        Dim k = _place(i)
        If t < _heapTime(k) Then
            While k > 0
                Dim parent = (k - 1) \ 2
                If _heapTime(parent) <= t Then Exit While
                MoveInHeap(parent, k)
                k = parent
            End While
        Else
            Do
                Dim child = 2 * k + 1
                If child >= _n Then Exit Do
                If child + 1 < _n AndAlso _heapTime(child + 1) < _heapTime(child) Then child += 1
                If _heapTime(child) >= t Then Exit Do
                MoveInHeap(child, k)
                k = child
            Loop
        End If
        _heapTime(k) = t
        _heapDisc(k) = i
        _place(i) = k
    End Sub

    Private Sub MoveInHeap(source As Integer, target As Integer)
        _heapTime(target) = _heapTime(source)
        _heapDisc(target) = _heapDisc(source)
        _place(_heapDisc(target)) = target
    End Sub
End Class
