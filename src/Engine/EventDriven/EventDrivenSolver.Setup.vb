Option Strict On

' Building the solver's arrays, grid and first predictions from the world.
Partial Public NotInheritable Class EventDrivenSolver
    ''' <summary>Re-reads the whole world: after a global change, or when bodies were added or removed.</summary>
    Private Sub Rebuild()
        Dim w = _world
        OverlapResolver.Resolve(w)
        _g = w.Gravity
        _e = w.Restitution
        _walls = w.Walls
        _width = w.Width
        _height = w.Height
        _slop = 1.0E-12 * Math.Max(1.0, Math.Max(_width, _height))
        _now = w.Time
        LoadStatics(w)
        LoadMovables(w)
        _sliding = 0 ' every body was just loaded free or dragged
        For i = 0 To _n - 1
            _ev(i).ColTime = Double.PositiveInfinity
            _ev(i).CellTime = Double.PositiveInfinity
        Next
        LayoutGrid()
        _queue.Reset(Enumerable.Repeat(Double.PositiveInfinity, _n).ToArray(), _n)
        For i = 0 To _n - 1
            Reschedule(i)
        Next
        _dirty = False
    End Sub

    Private Sub LoadStatics(w As World)
        Dim fixedCount = 0
        For Each c In w.Circles
            If c.IsFixed Then fixedCount += 1
        Next
        _nFixed = fixedCount
        _nRect = w.Rectangles.Count
        _fixed = New Circle(fixedCount - 1) {}
        _fx = New Double(fixedCount - 1) {}
        _fy = New Double(fixedCount - 1) {}
        _fr = New Double(fixedCount - 1) {}
        Dim k = 0
        For Each c In w.Circles
            If Not c.IsFixed Then Continue For
            _fixed(k) = c
            _fx(k) = c.Position.X
            _fy(k) = c.Position.Y
            _fr(k) = c.Radius
            k += 1
        Next
        _rect = New Rectangle(_nRect - 1) {}
        _rx0 = New Double(_nRect - 1) {}
        _ry0 = New Double(_nRect - 1) {}
        _rx1 = New Double(_nRect - 1) {}
        _ry1 = New Double(_nRect - 1) {}
        For k = 0 To _nRect - 1
            Dim r = w.Rectangles(k)
            _rect(k) = r
            _rx0(k) = r.Min.X
            _ry0(k) = r.Min.Y
            _rx1(k) = r.Max.X
            _ry1(k) = r.Max.Y
        Next
    End Sub

    Private Sub LoadMovables(w As World)
        Dim n = 0
        For Each c In w.Circles
            If Not c.IsFixed Then n += 1
        Next
        _n = n
        If _circle.Length < n Then Allocate(Math.Max(n, 2 * _circle.Length))
        _index.Clear()
        Dim i = 0
        Dim stillResting As New HashSet(Of Circle)()
        For Each c In w.Circles
            If c.IsFixed Then Continue For
            _circle(i) = c
            _index(c) = i
            LoadBody(i, c)
            _ev(i).Count = 0
            _lastHit(i) = Double.NegativeInfinity
            _burstStart(i) = Double.NegativeInfinity
            _burstCount(i) = 0
            _sameTime(i) = Double.NaN
            _sameCount(i) = 0
            If _restTimes.ContainsKey(c) AndAlso _body(i).Mode = BodyMode.Free AndAlso c.Velocity.Y = 0 Then stillResting.Add(c)
            i += 1
        Next
        ' A rest time survives a rebuild only while the circle still sits still vertically.
        Dim stale As New List(Of Circle)()
        For Each c In _restTimes.Keys
            If Not stillResting.Contains(c) Then stale.Add(c)
        Next
        For Each c In stale
            _restTimes.Remove(c)
        Next
    End Sub

    ''' <summary>Reads circle c into slot i at the solver's clock, as a free body (or the dragged one).</summary>
    Private Sub LoadBody(i As Integer, c As Circle)
        _body(i).T0 = _now
        _body(i).Px = c.Position.X
        _body(i).Py = c.Position.Y
        _body(i).Vx = c.Velocity.X
        _body(i).Vy = c.Velocity.Y
        _body(i).R = c.Radius
        _support(i) = SupportNone
        If c Is _world.DraggedCircle Then
            SetMode(i, BodyMode.Dragged)
            _body(i).Ay = 0
            _invMass(i) = 0
        Else
            SetMode(i, BodyMode.Free)
            _body(i).Ay = -_g
            _invMass(i) = c.InverseMass
        End If
    End Sub

    Private Sub Allocate(capacity As Integer)
        ReDim _circle(capacity - 1)
        ReDim _body(capacity - 1)
        ReDim _invMass(capacity - 1)
        ReDim _support(capacity - 1)
        ReDim _lastHit(capacity - 1)
        ReDim _burstStart(capacity - 1)
        ReDim _burstCount(capacity - 1)
        ReDim _sameTime(capacity - 1)
        ReDim _sameCount(capacity - 1)
        ReDim _ev(capacity - 1)
        ReDim _slideCx(capacity - 1)
        ReDim _slideCy(capacity - 1)
        ReDim _slideDir(capacity - 1)
        ReDim _slideV0(capacity - 1)
        ReDim _slideAngle(capacity - 1)
        ReDim _slideStart(capacity - 1)
        ReDim _oversized(capacity - 1)
        ReDim _stack(capacity - 1)
        ReDim _wake(capacity - 1)
        ReDim _scanList(capacity - 1)
    End Sub

    ''' <summary>
    ''' Cells holding about 2 bodies each (few crossings, few neighbours), never narrower than the
    ''' largest gridded diameter. Circles more than four times the median radius are "oversized": kept
    ''' out of the grid and checked against every body, so one giant does not make every cell huge.
    ''' </summary>
    Private Sub LayoutGrid()
        Dim limit = Double.PositiveInfinity
        If _n > 0 Then
            Dim radii = New Double(_n - 1) {}
            For k = 0 To _n - 1
                radii(k) = _body(k).R
            Next
            Array.Sort(radii)
            limit = 4 * radii(_n \ 2)
        End If
        Dim rMax = 0.0
        _nOversized = 0
        For i = 0 To _n - 1
            If _body(i).R > limit Then
                _oversized(_nOversized) = i
                _nOversized += 1
            Else
                rMax = Math.Max(rMax, _body(i).R)
            End If
        Next
        _rMax = rMax
        Dim gridded = Math.Max(1, _n - _nOversized)
        Dim cell = Math.Max(2 * rMax * (1 + 1.0E-9), Math.Sqrt(BodiesPerCell() * _width * _height / gridded))
        _grid.Layout(_width, _height, cell, _n, 4 * _n + 64)
        For i = 0 To _n - 1
            If _body(i).R > limit Then
                _ev(i).Cell = -1
            Else
                _ev(i).Col = _grid.ColumnOf(_body(i).Px)
                _ev(i).Row = _grid.RowOf(_body(i).Py)
                _ev(i).Cell = _ev(i).Row * _grid.Nx + _ev(i).Col
                _grid.Insert(i, _ev(i).Cell)
                Publish(i)
            End If
        Next
        Dim count = _nFixed + _nRect
        Dim x0 = New Double(count - 1) {}, y0 = New Double(count - 1) {}, x1 = New Double(count - 1) {}, y1 = New Double(count - 1) {}
        For k = 0 To _nFixed - 1
            x0(k) = _fx(k) - _fr(k)
            x1(k) = _fx(k) + _fr(k)
            y0(k) = _fy(k) - _fr(k)
            y1(k) = _fy(k) + _fr(k)
        Next
        For k = 0 To _nRect - 1
            x0(_nFixed + k) = _rx0(k)
            x1(_nFixed + k) = _rx1(k)
            y0(_nFixed + k) = _ry0(k)
            y1(_nFixed + k) = _ry1(k)
        Next
        _grid.SetStatics(x0, y0, x1, y1, count)
    End Sub

    ''' <summary>
    ''' How many bodies a cell should hold on average: bigger cells mean fewer crossings but more
    ''' pairs to test. Testing a whole cell's lanes at once (vectors) makes pairs cheap, so about 2;
    ''' one at a time (.NET Framework, Mono), about 1.2. Both measured on the elastic gas.
    ''' </summary>
    Private Function BodiesPerCell() As Double
        If CellOccupancy > 0 Then Return CellOccupancy
        Return If(_vectorScan, 2.0, 1.2)
    End Function

    ''' <summary>Whether circle c (just moved or added by the user) overlaps anything beyond rounding.</summary>
    Private Function OverlapsSomething(c As Circle) As Boolean
        Dim tol = 1.0E-12 * Math.Max(1.0, Math.Max(_width, _height))
        For Each o In _world.Circles
            If o Is c Then Continue For
            If Collider.CircleCircle(c.Position, c.Radius, o.Position, o.Radius).Depth > tol Then Return True
        Next
        For Each r In _world.Rectangles
            If Collider.CircleRectangle(c.Position, c.Radius, r.Min, r.Max).Depth > tol Then Return True
        Next
        Return False
    End Function
End Class
