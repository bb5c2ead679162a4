Option Strict On

''' <summary>
''' The simulated world: a container of width × height metres, gravity g pulling towards −y, one
''' coefficient of restitution e for every contact, optional walls, and the bodies. A solver
''' (<see cref="ISolver"/>) moves it forward; every change made here is passed to the solver so its
''' predictions stay valid.
''' </summary>
Partial Public NotInheritable Class World
    Private ReadOnly _bodies As New List(Of Shape)
    Private ReadOnly _circles As New List(Of Circle)
    Private ReadOnly _rectangles As New List(Of Rectangle)
    Private ReadOnly _segments As New List(Of Segment)
    Private ReadOnly _polygons As New List(Of Polygon)
    Private ReadOnly _movables As New List(Of Shape)
    Private ReadOnly _links As New List(Of Link)
    Private ReadOnly _linkIds As New HashSet(Of String)(StringComparer.Ordinal)
    Private _nextLinkId As Integer = 1
    Private ReadOnly _ids As New HashSet(Of String)(StringComparer.Ordinal)
    Private _width As Double
    Private _height As Double
    Private _gravity As Double
    Private _restitution As Double
    Private _walls As Boolean
    Private _solver As ISolver
    Private _nextId As Integer = 1

    ''' <param name="width">container width, m, &gt; 0</param>
    ''' <param name="height">container height, m, &gt; 0</param>
    ''' <param name="gravity">g, m/s², ≥ 0, pulling towards −y</param>
    ''' <param name="restitution">e in [0, 1], for every contact</param>
    ''' <param name="walls">whether the container's sides reflect circles</param>
    Public Sub New(width As Double, height As Double, Optional gravity As Double = 9.81,
                   Optional restitution As Double = 1.0, Optional walls As Boolean = True)
        CheckSize(width, height)
        _width = width
        _height = height
        Me.Gravity = gravity
        Me.Restitution = restitution
        _walls = walls
    End Sub

    ''' <summary>Inner width of the container, m.</summary>
    Public ReadOnly Property Width As Double
        Get
            Return _width
        End Get
    End Property

    ''' <summary>Inner height of the container, m.</summary>
    Public ReadOnly Property Height As Double
        Get
            Return _height
        End Get
    End Property

    ''' <summary>Magnitude of g, m/s², pulling towards −y. Can change while running.</summary>
    Public Property Gravity As Double
        Get
            Return _gravity
        End Get
        Set(value As Double)
            If Not (value >= 0) OrElse Double.IsInfinity(value) Then Throw New ArgumentOutOfRangeException(NameOf(Gravity), "gravity must be a finite number ≥ 0")
            _gravity = value
            _solver?.Invalidate(Nothing)
        End Set
    End Property

    ''' <summary>Coefficient of restitution e in [0, 1], used for every contact. Can change while running.</summary>
    Public Property Restitution As Double
        Get
            Return _restitution
        End Get
        Set(value As Double)
            If Not (value >= 0 AndAlso value <= 1) Then Throw New ArgumentOutOfRangeException(NameOf(Restitution), "restitution must be between 0 and 1")
            _restitution = value
            _solver?.Invalidate(Nothing)
        End Set
    End Property

    ''' <summary>Whether the four sides of the container reflect circles.</summary>
    Public Property Walls As Boolean
        Get
            Return _walls
        End Get
        Set(value As Boolean)
            If value Then CheckEveryBodyFits(_width, _height)
            _walls = value
            If value Then BringBodiesInside()
            _solver?.Invalidate(Nothing)
        End Set
    End Property

    ''' <summary>Simulated time, s.</summary>
    Public ReadOnly Property Time As Double

    ''' <summary>Every body, in the order it was added.</summary>
    Public ReadOnly Property Bodies As IReadOnlyList(Of Shape)
        Get
            Return _bodies
        End Get
    End Property

    ''' <summary>Every circle, movable and fixed, in the order added.</summary>
    Public ReadOnly Property Circles As IReadOnlyList(Of Circle)
        Get
            Return _circles
        End Get
    End Property

    ''' <summary>Every rectangle, fixed and movable, in the order added.</summary>
    Public ReadOnly Property Rectangles As IReadOnlyList(Of Rectangle)
        Get
            Return _rectangles
        End Get
    End Property

    ''' <summary>Every segment, in the order added.</summary>
    Public ReadOnly Property Segments As IReadOnlyList(Of Segment)
        Get
            Return _segments
        End Get
    End Property

    ''' <summary>Every polygon, fixed and movable, in the order added.</summary>
    Public ReadOnly Property Polygons As IReadOnlyList(Of Polygon)
        Get
            Return _polygons
        End Get
    End Property

    ''' <summary>Every movable body (circles, boxes, polygons), in the order added.</summary>
    Public ReadOnly Property Movables As IReadOnlyList(Of Shape)
        Get
            Return _movables
        End Get
    End Property

    ''' <summary>The springs, rods and strings, in the order they were added.</summary>
    Public ReadOnly Property Links As IReadOnlyList(Of Link)
        Get
            Return _links
        End Get
    End Property

    ''' <summary>Collisions reported since the world was made.</summary>
    Public ReadOnly Property CollisionCount As Long

    ''' <summary>Called for every collision, in time order. Must not change the world.</summary>
    Public Property CollisionListener As Action(Of CollisionRecord)

    ''' <summary>The body being dragged, or Nothing.</summary>
    Public ReadOnly Property DraggedBody As Shape

    ''' <summary>The body being dragged if it is a circle, or Nothing.</summary>
    Public ReadOnly Property DraggedCircle As Circle
        Get
            Return TryCast(_DraggedBody, Circle)
        End Get
    End Property

    ''' <summary>Where the dragged body's reference point is heading, m. It reaches it at the end of the next <see cref="Advance"/>.</summary>
    Public ReadOnly Property DragTarget As Vector

    ''' <summary>The solver that moves this world. Setting it attaches it.</summary>
    Public Property Solver As ISolver
        Get
            Return _solver
        End Get
        Set(value As ISolver)
            If value Is Nothing Then Throw New ArgumentNullException(NameOf(value))
            _solver = value
            value.Attach(Me)
        End Set
    End Property

    ''' <summary>
    ''' Adds a body. An empty id is given the next free number. A movable body outside a walled
    ''' container is brought inside. Overlaps are allowed: the solver pushes them apart.
    ''' </summary>
    Public Sub Add(body As Shape)
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        ' Only a body without an id, or whose id is taken, can already be here: checking that first keeps
        ' Add O(1) for bodies with fresh ids, so loading a scene of 100 000 circles is not O(N²).
        If (String.IsNullOrEmpty(body.Id) OrElse _ids.Contains(body.Id)) AndAlso _bodies.Contains(body) Then Throw New ArgumentException("this body is already in the world", NameOf(body))
        If String.IsNullOrEmpty(body.Id) Then
            Do
                body.Id = _nextId.ToString(Globalization.CultureInfo.InvariantCulture)
                _nextId += 1
            Loop While _ids.Contains(body.Id)
        ElseIf _ids.Contains(body.Id) Then
            Throw New ArgumentException("id '" & body.Id & "' is already used", NameOf(body))
        End If
        Admit(body, NameOf(body))
        KindList(body).Add(body)
        If Not body.IsFixed Then _movables.Add(body)
        _ids.Add(body.Id)
        _bodies.Add(body)
        _solver?.Invalidate(body)
    End Sub

    ''' <summary>The list of the body's own kind, as a list of shapes (the same list object).</summary>
    Private Function KindList(body As Shape) As Collections.IList
        Select Case body.Kind
            Case ShapeKind.Circle : Return _circles
            Case ShapeKind.Rectangle : Return _rectangles
            Case ShapeKind.Segment : Return _segments
            Case Else : Return _polygons
        End Select
    End Function

    ''' <summary>
    ''' Puts <paramref name="replacement"/> where <paramref name="body"/> was, in the same place in
    ''' every list (so tables and outputs keep their order), with the same id: how a fixed body, which
    ''' the engine never moves, is moved by the user. Both must be the same kind of shape.
    ''' </summary>
    Public Sub Replace(body As Shape, replacement As Shape)
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        If replacement Is Nothing Then Throw New ArgumentNullException(NameOf(replacement))
        Dim index = _bodies.IndexOf(body)
        If index < 0 Then Throw New ArgumentException("this body is not in the world", NameOf(body))
        If replacement.GetType() IsNot body.GetType() Then Throw New ArgumentException("a body can only be replaced by one of the same kind", NameOf(replacement))
        If replacement IsNot body AndAlso _bodies.Contains(replacement) Then Throw New ArgumentException("the replacement is already in the world", NameOf(replacement))
        If replacement.Id <> body.Id Then Throw New ArgumentException("the replacement must keep the id '" & body.Id & "'", NameOf(replacement))
        If replacement.IsFixed <> body.IsFixed Then Throw New ArgumentException("a body can only be replaced by one that is fixed or movable as it was", NameOf(replacement))
        Admit(replacement, NameOf(replacement))
        Dim list = KindList(body)
        list(list.IndexOf(body)) = replacement
        If Not body.IsFixed Then _movables(_movables.IndexOf(body)) = replacement
        If body Is _DraggedBody Then _DraggedBody = Nothing
        For k = 0 To _links.Count - 1
            If _links(k).A Is body OrElse _links(k).B Is body Then _links(k) = _links(k).WithBody(body, replacement)
        Next
        _bodies(index) = replacement
        _solver?.Invalidate(body)
        _solver?.Invalidate(replacement)
    End Sub

    ''' <summary>
    ''' Readies a body that is joining the world: its position and velocity must be finite, a fixed
    ''' one is at rest, and a movable one in a walled container is brought inside.
    ''' </summary>
    Private Sub Admit(b As Shape, paramName As String)
        If Not b.Position.IsFinite OrElse Not b.Velocity.IsFinite Then Throw New ArgumentException("position and velocity must be finite", paramName)
        If b.IsFixed Then b.Velocity = Vector.Zero
        If _walls AndAlso Not b.IsFixed Then
            CheckFits(b, _width, _height)
            b.Position = InsideFor(b, b.Position)
        End If
    End Sub

    ''' <summary>Removes a body; returns False when it was not in the world.</summary>
    Public Function Remove(body As Shape) As Boolean
        If body Is Nothing OrElse Not _bodies.Remove(body) Then Return False
        _ids.Remove(body.Id)
        KindList(body).Remove(body)
        _movables.Remove(body)
        If body Is _DraggedBody Then _DraggedBody = Nothing
        Dim linked = _links.RemoveAll(Function(l) l.A Is body OrElse l.B Is body)
        If linked > 0 Then
            _linkIds.Clear()
            For Each l In _links
                _linkIds.Add(l.Id)
            Next
        End If
        _solver?.Invalidate(If(linked > 0, Nothing, body))
        Return True
    End Function

    ''' <summary>
    ''' Adds a link between bodies already in the world. An empty id is given the next free "link" number.
    ''' Rods and strings keep the length they are given: a rod whose ends are not that far apart, or a string
    ''' whose ends are farther apart, is pulled to it by the solver's first step.
    ''' </summary>
    Public Sub Add(link As Link)
        If link Is Nothing Then Throw New ArgumentNullException(NameOf(link))
        If _links.Contains(link) Then Throw New ArgumentException("this link is already in the world", NameOf(link))
        If Not _bodies.Contains(link.A) OrElse (link.B IsNot Nothing AndAlso Not _bodies.Contains(link.B)) Then Throw New ArgumentException("a link's bodies must be in the world", NameOf(link))
        If String.IsNullOrEmpty(link.Id) Then
            Do
                link.Id = "link" & _nextLinkId.ToString(Globalization.CultureInfo.InvariantCulture)
                _nextLinkId += 1
            Loop While _linkIds.Contains(link.Id)
        ElseIf _linkIds.Contains(link.Id) Then
            Throw New ArgumentException("link id '" & link.Id & "' is already used", NameOf(link))
        End If
        _links.Add(link)
        _linkIds.Add(link.Id)
        _solver?.Invalidate(Nothing)
    End Sub

    ''' <summary>Removes a link; returns False when it was not in the world.</summary>
    Public Function Remove(link As Link) As Boolean
        If link Is Nothing OrElse Not _links.Remove(link) Then Return False
        _linkIds.Remove(link.Id)
        _solver?.Invalidate(Nothing)
        Return True
    End Function

    ''' <summary>The link with this id, or Nothing.</summary>
    Public Function FindLink(id As String) As Link
        For Each l In _links
            If String.Equals(l.Id, id, StringComparison.Ordinal) Then Return l
        Next
        Return Nothing
    End Function

    ''' <summary>Removes every body and sets the clock to zero.</summary>
    Public Sub Clear()
        _bodies.Clear()
        _circles.Clear()
        _rectangles.Clear()
        _segments.Clear()
        _polygons.Clear()
        _movables.Clear()
        _ids.Clear()
        _nextId = 1
        _links.Clear()
        _linkIds.Clear()
        _nextLinkId = 1
        _DraggedBody = Nothing
        _Time = 0
        _liquids.Clear()
        _dissipated = 0
        _solver?.Invalidate(Nothing)
    End Sub

    ''' <summary>The body with this id, or Nothing.</summary>
    Public Function Find(id As String) As Shape
        For Each b In _bodies
            If String.Equals(b.Id, id, StringComparison.Ordinal) Then Return b
        Next
        Return Nothing
    End Function

    ''' <summary>Advances the world by exactly <paramref name="duration"/> seconds (≥ 0).</summary>
    Public Sub Advance(duration As Double)
        If Not (duration >= 0) OrElse Double.IsInfinity(duration) Then Throw New ArgumentOutOfRangeException(NameOf(duration), "duration must be a finite number ≥ 0")
        If _solver Is Nothing Then Throw New InvalidOperationException("the world has no solver")
        If duration = 0 Then Return
        CheckSpeeds()
        Dim start = _Time
        _solver.Advance(duration)
        _Time = start + duration
    End Sub

    ''' <summary>
    ''' Advances by at most <paramref name="duration"/> seconds, stopping early once
    ''' <paramref name="wallSeconds"/> of wall-clock time have passed (between two events or steps, so
    ''' the state is exact and the run is the same as without the limit). Returns the simulated
    ''' seconds advanced. For a window that must stay responsive on a scene that needs millions of
    ''' collisions per simulated second: it shows slower time instead of freezing.
    ''' </summary>
    Public Function AdvanceWithin(duration As Double, wallSeconds As Double) As Double
        If Not (duration >= 0) OrElse Double.IsInfinity(duration) Then Throw New ArgumentOutOfRangeException(NameOf(duration), "duration must be a finite number ≥ 0")
        If Not (wallSeconds >= 0) Then Throw New ArgumentOutOfRangeException(NameOf(wallSeconds), "the wall-clock budget must be a number ≥ 0")
        If _solver Is Nothing Then Throw New InvalidOperationException("the world has no solver")
        If duration = 0 Then Return 0
        CheckSpeeds()
        Dim start = _Time
        Dim ticks = Math.Min(wallSeconds * Diagnostics.Stopwatch.Frequency, Long.MaxValue / 4.0)
        Dim reached = _solver.AdvanceWithin(duration, Diagnostics.Stopwatch.GetTimestamp() + CLng(ticks))
        _Time = reached
        Return reached - start
    End Function

    ''' <summary>
    ''' The fastest a movable circle may move when the world advances, m/s. Every solver squares speeds
    ''' (kinetic energy; the quadratics that give contact times multiply speeds by speeds and by
    ''' distances), and the square of about 1.3e154 overflows a double: the stepping solvers then produce
    ''' NaN, and the event solver times every contact at the same instant and stops the ball dead.
    ''' 1e150 leaves room for those products (a test runs every solver just below it).
    ''' </summary>
    Public Const MaxSpeed As Double = 1.0E+150

    ''' <summary>
    ''' Throws <see cref="SpeedLimitException"/> for the first movable body faster than <see cref="MaxSpeed"/>.
    ''' <see cref="Advance"/> checks this first; a caller can check before it starts anything.
    ''' </summary>
    Public Sub CheckSpeeds()
        For Each b In _movables
            Dim v = b.Velocity
            If Math.Abs(v.X) + Math.Abs(v.Y) > MaxSpeed AndAlso v.Length > MaxSpeed Then Throw New SpeedLimitException(b, v.Length)
        Next
    End Sub

    ''' <summary>Sets a movable body's velocity, m/s.</summary>
    Public Sub SetVelocity(body As Shape, velocity As Vector)
        CheckMovable(body)
        If Not velocity.IsFinite Then Throw New ArgumentException("velocity must be finite", NameOf(velocity))
        body.Velocity = velocity
        _solver?.Invalidate(body)
    End Sub

    ''' <summary>Moves a movable body's reference point to a new place, m (kept inside a walled container).</summary>
    Public Sub SetPosition(body As Shape, position As Vector)
        CheckMovable(body)
        If Not position.IsFinite Then Throw New ArgumentException("position must be finite", NameOf(position))
        body.Position = If(_walls, InsideFor(body, position), position)
        _solver?.Invalidate(body)
    End Sub

    ''' <summary>
    ''' Applies an impulse J (N·s) to a movable body: Δv = J / m, so the same push moves a heavy
    ''' body less (F = ma integrated over the push).
    ''' </summary>
    Public Sub ApplyImpulse(body As Shape, impulse As Vector)
        CheckMovable(body)
        If Not impulse.IsFinite Then Throw New ArgumentException("impulse must be finite", NameOf(impulse))
        body.Velocity += impulse * body.InverseMass
        _solver?.Invalidate(body)
    End Sub

    ''' <summary>
    ''' Starts dragging a movable body. While dragged it follows <see cref="DragTarget"/>, feels no
    ''' gravity, pushes what it touches and is not pushed back (it acts as if of infinite mass).
    ''' </summary>
    Public Sub BeginDrag(body As Shape)
        CheckMovable(body)
        If _DraggedBody IsNot Nothing Then EndDrag(Vector.Zero)
        _DraggedBody = body
        _DragTarget = body.Position
        body.Velocity = Vector.Zero
        _solver?.Invalidate(body)
    End Sub

    ''' <summary>
    ''' Sets where the dragged body's reference point is heading, m: kept inside a walled container, and within reach of
    ''' the rods and strings that tie it to fixed points (<see cref="WithinLinks"/>).
    ''' </summary>
    Public Sub DragTo(target As Vector)
        If _DraggedBody Is Nothing Then Return
        If Not target.IsFinite Then Throw New ArgumentException("target must be finite", NameOf(target))
        target = WithinLinks(_DraggedBody, target)
        _DragTarget = If(_walls, InsideFor(_DraggedBody, target), target)
        _solver?.Invalidate(_DraggedBody)
    End Sub

    ''' <summary>Drops the dragged body back into the simulation with the given velocity, m/s.</summary>
    Public Sub EndDrag(releaseVelocity As Vector)
        Dim b = _DraggedBody
        If b Is Nothing Then Return
        _DraggedBody = Nothing
        b.Velocity = If(releaseVelocity.IsFinite, releaseVelocity, Vector.Zero)
        ' What the hand did to the links (a rod a little off its length after stepping) is put right before anything moves.
        HoldLinks()
        _solver?.Invalidate(b)
    End Sub

    ''' <summary>
    ''' Changes the container's size while running. With walls on, a movable body that the smaller
    ''' container leaves outside is brought back inside; a size too small for the largest movable body
    ''' is refused (ArgumentException) and nothing changes.
    ''' </summary>
    Public Sub Resize(width As Double, height As Double)
        CheckSize(width, height)
        If _walls Then CheckEveryBodyFits(width, height)
        _width = width
        _height = height
        If _walls Then BringBodiesInside()
        If _DraggedBody IsNot Nothing AndAlso _walls Then _DragTarget = InsideFor(_DraggedBody, _DragTarget)
        _solver?.Invalidate(Nothing)
    End Sub

    ''' <summary>Called by solvers for each collision, in time order.</summary>
    Friend Sub ReportCollision(record As CollisionRecord)
        CountCollision()
        _CollisionListener?.Invoke(record)
    End Sub

    ''' <summary>
    ''' Whether anything listens for collisions. Where a collision is frequent (the event solver's
    ''' pairs and walls) the solver builds its record only then, and otherwise only counts it
    ''' (<see cref="CountCollision"/>): a record is about a hundred bytes, built and copied for nothing.
    ''' </summary>
    Friend ReadOnly Property ListensForCollisions As Boolean
        Get
            Return _CollisionListener IsNot Nothing
        End Get
    End Property

    ''' <summary>Counts a collision that nothing listens for (see <see cref="ListensForCollisions"/>).</summary>
    Friend Sub CountCollision()
        _CollisionCount += 1
    End Sub

    ''' <summary>The nearest centre to <paramref name="p"/> that keeps a circle of radius r inside the container.</summary>
    Public Function Inside(p As Vector, radius As Double) As Vector
        Return New Vector(Clamp(p.X, radius, _width - radius, _width / 2), Clamp(p.Y, radius, _height - radius, _height / 2))
    End Function

    ''' <summary>The nearest reference point to <paramref name="p"/> that keeps <paramref name="body"/>'s outline inside the container.</summary>
    Public Function InsideFor(body As Shape, p As Vector) As Vector
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        Dim o = body.Outline
        Return New Vector(Clamp(p.X, -o.MinX, _width - o.MaxX, (_width - o.MinX - o.MaxX) / 2),
                          Clamp(p.Y, -o.MinY, _height - o.MaxY, (_height - o.MinY - o.MaxY) / 2))
    End Function

    Private Shared Function Clamp(v As Double, lo As Double, hi As Double, middle As Double) As Double
        If lo > hi Then Return middle ' wider than the container: centre it
        Return Math.Min(Math.Max(v, lo), hi)
    End Function

    ''' <summary>
    ''' After the container shrank (or its walls came on): every movable circle left outside is folded
    ''' back in, as far inside the wall as it was beyond it (reflected again off the far wall if it
    ''' was further out than the container is wide). Clamping them onto the wall instead would stack
    ''' a whole strip of circles on one line, overlapping along it, and pushing overlaps apart along
    ''' that line can never make room; folded, they keep their spread, and the overlaps with the
    ''' circles already inside are left to the solver (the event solver pushes them apart before it
    ''' predicts anything).
    ''' </summary>
    Private Sub BringBodiesInside()
        For Each b In _movables
            Dim o = b.Outline
            b.Position = New Vector(Fold(b.Position.X, -o.MinX, _width - o.MaxX, (_width - o.MinX - o.MaxX) / 2),
                                    Fold(b.Position.Y, -o.MinY, _height - o.MaxY, (_height - o.MinY - o.MaxY) / 2))
        Next
    End Sub

    ''' <summary>v reflected back and forth between lo and hi until it lies between them (a triangle wave).</summary>
    Private Shared Function Fold(v As Double, lo As Double, hi As Double, middle As Double) As Double
        If lo > hi Then Return middle ' wider than the container: centre it
        If v >= lo AndAlso v <= hi Then Return v
        Dim span = hi - lo
        If Not (span > 0) OrElse Double.IsNaN(v) OrElse Double.IsInfinity(v) Then Return Math.Min(Math.Max(v, lo), hi)
        Dim m = (v - lo) Mod (2 * span)
        If m < 0 Then m += 2 * span
        Return Math.Min(Math.Max(lo + span - Math.Abs(m - span), lo), hi)
    End Function

    ' A movable body wider than a walled container could touch both of two opposite walls at once
    ' and be pushed through one of them: such a world is refused at the boundary, with a message.
    Private Shared Sub CheckFits(b As Shape, width As Double, height As Double)
        Dim w = b.Outline.MaxX - b.Outline.MinX, h = b.Outline.MaxY - b.Outline.MinY
        If w > width OrElse h > height Then
            Dim inv = Globalization.CultureInfo.InvariantCulture
            Dim what = If(b.Kind = ShapeKind.Circle, "a circle of diameter " & w.ToString("G4", inv) & " m",
                          "a " & b.KindName & " " & w.ToString("G4", inv) & " m × " & h.ToString("G4", inv) & " m")
            Throw New ArgumentException(what & " does not fit in a container of " & width.ToString("G4", inv) & " m × " &
                height.ToString("G4", inv) & " m")
        End If
    End Sub

    Private Sub CheckEveryBodyFits(width As Double, height As Double)
        For Each b In _movables
            CheckFits(b, width, height)
        Next
    End Sub

    Private Sub CheckMovable(body As Shape)
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        If body.IsFixed Then Throw New ArgumentException("a fixed " & body.KindName & " never moves", NameOf(body))
        If Not _movables.Contains(body) Then Throw New ArgumentException("the body is not in this world", NameOf(body))
    End Sub

    Private Shared Sub CheckSize(width As Double, height As Double)
        If Not (width > 0) OrElse Double.IsInfinity(width) Then Throw New ArgumentOutOfRangeException(NameOf(width), "width must be a finite number greater than 0")
        If Not (height > 0) OrElse Double.IsInfinity(height) Then Throw New ArgumentOutOfRangeException(NameOf(height), "height must be a finite number greater than 0")
    End Sub
End Class
