Option Strict On

''' <summary>
''' Pushes overlapping bodies apart before the event-driven solver predicts anything (new bodies,
''' moved bodies, spawn overlaps), for every pair of shapes that collide (any pair but two fixed bodies).
''' Iterative projection: each overlapping pair is separated along its contact normal, shared in
''' proportion to inverse mass (fixed bodies and the dragged body do not move), and movable bodies are
''' kept inside the walls, until no overlap exceeds the tolerance. Deterministic; coincident centres get
''' a fixed normal, never NaN.
''' </summary>
Public Module OverlapResolver
    ''' <summary>Separates overlaps in <paramref name="world"/>; returns the deepest overlap left (m).</summary>
    ''' <param name="tolerance">overlap (m) accepted as touching</param>
    ''' <param name="maxIterations">passes before giving up</param>
    Public Function Resolve(world As World, Optional tolerance As Double = 1.0E-12, Optional maxIterations As Integer = 500) As Double
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim bodies = world.Bodies
        If bodies.Count = 0 Then Return 0
        Dim circles = world.Circles
        Dim dragged = world.DraggedBody
        ' Bodies other than circles, by their place in world.Bodies; with none, only circle pairs can overlap.
        Dim others = bodies.Count - circles.Count
        Dim rMax = 0.0
        For Each c In circles
            rMax = Math.Max(rMax, c.Radius)
        Next
        Dim cell = 2 * rMax
        Dim grid = If(others > 0, New BoundsGrid(), Nothing)
        Dim differences = If(others > 0, New DifferenceCache(), Nothing)
        Dim near As New List(Of Integer)
        Dim worst = 0.0
        For iteration = 1 To maxIterations
            worst = 0
            If circles.Count > 0 Then worst = SeparateCircles(circles, cell, dragged, tolerance)
            If grid IsNot Nothing Then Place(bodies, grid)
            For index = 0 To bodies.Count - 1
                Dim a = bodies(index)
                If a.IsFixed Then Continue For
                If grid IsNot Nothing Then worst = Math.Max(worst, SeparateOthers(bodies, index, grid, near, differences, dragged, tolerance))
                If world.Walls AndAlso a IsNot dragged Then
                    Dim c = TryCast(a, Circle)
                    Dim inside = If(c IsNot Nothing, world.Inside(c.Position, c.Radius), world.InsideFor(a, a.Position))
                    If inside <> a.Position Then
                        worst = Math.Max(worst, (inside - a.Position).Length)
                        a.Position = inside
                    End If
                End If
            Next
            If worst <= tolerance Then Exit For
        Next
        Return worst
    End Function

    ''' <summary>One pass over the pairs of circles (movable with movable or fixed), bucketed in cells one largest diameter wide.</summary>
    Private Function SeparateCircles(circles As IReadOnlyList(Of Circle), cell As Double, dragged As Shape, tolerance As Double) As Double
        Dim worst = 0.0
        Dim n = circles.Count
        ' Bucket the circles; pairs are only looked for in neighbouring buckets.
        Dim buckets As New Dictionary(Of Long, List(Of Integer))()
        For i = 0 To n - 1
            Dim key = BucketKey(circles(i).Position, cell, 0, 0)
            Dim list As List(Of Integer) = Nothing
            If Not buckets.TryGetValue(key, list) Then
                list = New List(Of Integer)()
                buckets(key) = list
            End If
            list.Add(i)
        Next
        For i = 0 To n - 1
            Dim a = circles(i)
            For ox = -1 To 1
                For oy = -1 To 1
                    Dim list As List(Of Integer) = Nothing
                    If Not buckets.TryGetValue(BucketKey(a.Position, cell, ox, oy), list) Then Continue For
                    For Each j In list
                        If j <= i Then Continue For
                        worst = Math.Max(worst, SeparateCirclePair(a, circles(j), dragged, tolerance, i, j))
                    Next
                Next
            Next
        Next
        Return worst
    End Function

    ''' <summary>Puts every body's bounding box in the grid, indexed like world.Bodies.</summary>
    Private Sub Place(bodies As IReadOnlyList(Of Shape), grid As BoundsGrid)
        grid.Reset(bodies.Count)
        For i = 0 To bodies.Count - 1
            Dim b = bodies(i)
            Dim o = b.Outline
            grid.SetItem(i, New Vector(b.Position.X + 0.5 * (o.MinX + o.MaxX), b.Position.Y + 0.5 * (o.MinY + o.MaxY)),
                         0.5 * (o.MaxX - o.MinX), 0.5 * (o.MaxY - o.MinY))
        Next
        grid.Build(0)
    End Sub

    ''' <summary>
    ''' Separates movable body number <paramref name="index"/> (in world.Bodies) from every body near it
    ''' that is not a circle pair (those are <see cref="SeparateCircles"/>'s), each pair once: a movable
    ''' partner earlier in the list has already met it. After a push the partners still to come are found
    ''' again from where it is now, so they are met in order as if every body were tried. Returns the
    ''' deepest overlap found (m).
    ''' </summary>
    Private Function SeparateOthers(bodies As IReadOnlyList(Of Shape), index As Integer, grid As BoundsGrid, near As List(Of Integer),
                                    differences As DifferenceCache, dragged As Shape, tolerance As Double) As Double
        Dim a = bodies(index)
        Dim aCircle = a.Kind = ShapeKind.Circle
        Dim worst = 0.0
        Query(a, grid, near, -1)
        Dim k = 0
        While k < near.Count
            Dim j = near(k)
            Dim b = bodies(j)
            k += 1
            If j = index OrElse (aCircle AndAlso b.Kind = ShapeKind.Circle) OrElse (Not b.IsFixed AndAlso j < index) Then Continue While
            Dim before = a.Position
            Dim depth = SeparatePair(a, b, differences, dragged, tolerance)
            worst = Math.Max(worst, depth)
            If a.Position <> before Then
                Query(a, grid, near, j)
                k = 0
            End If
        End While
        Return worst
    End Function

    ''' <summary>Fills <paramref name="near"/> with the bodies whose boxes meet body a's, keeping those after <paramref name="after"/>.</summary>
    Private Sub Query(a As Shape, grid As BoundsGrid, near As List(Of Integer), after As Integer)
        grid.Query(a.BoundsMin, a.BoundsMax, near)
        If after >= 0 Then near.RemoveAll(Function(j) j <= after)
    End Sub

    ''' <summary>
    ''' Pushes A and B apart along their contact normal when they overlap by more than the tolerance,
    ''' by the depth and half the tolerance, shared in proportion to inverse mass. Returns the depth (m),
    ''' or 0 when neither can move or they do not overlap by more than the tolerance.
    ''' </summary>
    Private Function SeparatePair(a As Shape, b As Shape, differences As DifferenceCache, dragged As Shape, tolerance As Double) As Double
        Dim wa = If(a.IsFixed OrElse a Is dragged, 0.0, a.InverseMass)
        Dim wb = If(b.IsFixed OrElse b Is dragged, 0.0, b.InverseMass)
        If wa + wb = 0 Then Return 0
        Dim contact As Contact
        Dim ca = TryCast(a, Circle), rb = TryCast(b, Rectangle)
        If ca IsNot Nothing AndAlso rb IsNot Nothing Then
            contact = Collider.CircleRectangle(ca.Position, ca.Radius, rb.Min, rb.Max)
        Else
            contact = Collider.OutlineOutline(differences.Get(b.Outline, a.Outline).Difference, a.Position, b.Position)
        End If
        If Not (contact.Depth > tolerance) Then Return 0
        Dim n = contact.Normal
        Dim push = contact.Depth + 0.5 * tolerance
        If wb = 0 Then
            a.Position += n * push
        ElseIf wa = 0 Then
            b.Position -= n * push
        Else
            a.Position += n * (push * wa / (wa + wb))
            b.Position -= n * (push * wb / (wa + wb))
        End If
        Return contact.Depth
    End Function

    Private Function BucketKey(p As Vector, cell As Double, ox As Integer, oy As Integer) As Long
        Dim ix = CellIndex(p.X, cell) + ox
        Dim iy = CellIndex(p.Y, cell) + oy
        ' Two 32-bit halves: no multiplication, so no overflow however far away a body is.
        Return (ix << 32) Or (iy And &HFFFFFFFFL)
    End Function

    ''' <summary>The cell index, clamped to ±10⁹ so a body 10¹² m away (walls off) cannot overflow it.</summary>
    Private Function CellIndex(v As Double, cell As Double) As Long
        Dim q = Math.Floor(v / cell)
        If Double.IsNaN(q) Then Return 0
        Return CLng(Math.Max(-1000000000.0, Math.Min(1000000000.0, q)))
    End Function

    Private Function SeparateCirclePair(a As Circle, b As Circle, dragged As Shape, tolerance As Double, i As Integer, j As Integer) As Double
        Dim wa = If(a.IsFixed OrElse a Is dragged, 0.0, a.InverseMass)
        Dim wb = If(b.IsFixed OrElse b Is dragged, 0.0, b.InverseMass)
        If wa + wb = 0 Then Return 0
        Dim d = a.Position - b.Position
        Dim dist = d.Length
        Dim depth = a.Radius + b.Radius - dist
        If depth <= tolerance Then Return 0
        ' Coincident centres: a fixed direction that depends only on the pair, so the result is deterministic.
        Dim n As Vector
        If dist > 0 Then
            n = d / dist
        Else
            Dim angle = 2.399963229728653 * (i + 7 * j)
            n = New Vector(Math.Cos(angle), Math.Sin(angle))
        End If
        Dim push = depth + 0.5 * tolerance
        a.Position += n * (push * wa / (wa + wb))
        b.Position -= n * (push * wb / (wa + wb))
        Return depth
    End Function
End Module
