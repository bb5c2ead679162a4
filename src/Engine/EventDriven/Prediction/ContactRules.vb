Option Strict On

''' <summary>
''' The one place that says, for each pair of body kinds, which maths finds their contact and its
''' normal (docs/event-driven.md §2–3): <see cref="RuleFor"/> is the dispatch, and a new pair of kinds
''' is a new <see cref="IContactRule"/> registered there. The solver's other parts ask here and never
''' look at a body's shape themselves. Also here: the container's walls, which every body meets by
''' the extents of its outline, and the contact geometry the resting rules need.
''' </summary>
Friend Module ContactRules
    Private ReadOnly CirclePair As New CircleCircleRule()
    Private ReadOnly CircleBox As New CircleBoxRule()
    Private ReadOnly AnyPair As New OutlineRule()

    ''' <summary>The rule for a moving body A (a circle or not) against a body B of the given kind.</summary>
    Friend Function RuleFor(aIsCircle As Boolean, b As ShapeKind) As IContactRule
        If aIsCircle Then
            If b = ShapeKind.Circle Then Return CirclePair
            If b = ShapeKind.Rectangle Then Return CircleBox
        End If
        Return AnyPair
    End Function

    ''' <summary>The query for movable body i against movable body j at the clock (both not sliding round a corner).</summary>
    Friend Function BodyQuery(s As SolverState, i As Integer, j As Integer, slop As Double, horizon As Double) As ContactQuery
        Dim b = s.Bodies
        Dim xi, yi, vxi, vyi, xj, yj, vxj, vyj As Double
        b.Motion(i).StateAt(s.Now, xi, yi, vxi, vyi)
        b.Motion(j).StateAt(s.Now, xj, yj, vxj, vyj)
        Return New ContactQuery With {
            .A = b.Outlines(i), .B = b.Outlines(j), .D = New Vector(xi - xj, yi - yj), .Dv = New Vector(vxi - vxj, vyi - vyj),
            .Da = New Vector(b.Motion(i).Ax - b.Motion(j).Ax, b.Motion(i).Ay - b.Motion(j).Ay), .Slop = slop,
            .SpeedScale = Math.Abs(vxi) + Math.Abs(vyi) + Math.Abs(vxj) + Math.Abs(vyj), .Horizon = horizon, .Shapes = s.Shapes}
    End Function

    ''' <summary>The query for movable body i (at (px, py), velocity, acceleration) against obstacle k.</summary>
    Friend Function ObstacleQuery(s As SolverState, i As Integer, k As Integer, px As Double, py As Double, vx As Double, vy As Double,
                                  ax As Double, ay As Double, slop As Double, horizon As Double) As ContactQuery
        Dim o = s.Obstacles
        Return New ContactQuery With {
            .A = s.Bodies.Outlines(i), .B = o.Outlines(k), .D = New Vector(px - o.X0(k), py - o.Y0(k)), .Dv = New Vector(vx, vy),
            .Da = New Vector(ax, ay), .Slop = slop, .SpeedScale = 0, .Horizon = horizon, .Shapes = s.Shapes}
    End Function

    ''' <summary>Movable bodies i and j: when they touch (s from now; +∞ if not before <paramref name="horizon"/> s), and which feature.</summary>
    Friend Function TimeBetweenBodies(s As SolverState, i As Integer, j As Integer, slop As Double, horizon As Double, ByRef feature As Integer) As Double
        Dim q = BodyQuery(s, i, j, slop, horizon)
        Return RuleFor(s.Bodies.Info(i).IsCircle, s.Bodies.Info(j).Kind).TimeOfImpact(q, feature)
    End Function

    ''' <summary>Movable body i, at (px, py) with the given velocity and acceleration, against obstacle k.</summary>
    Friend Function TimeToObstacle(s As SolverState, i As Integer, k As Integer, px As Double, py As Double, vx As Double, vy As Double,
                                   ax As Double, ay As Double, slop As Double, horizon As Double, ByRef feature As Integer) As Double
        Dim o = s.Obstacles
        ' Most obstacles in a body's cell are out of its reach before its next event or cell crossing:
        ' a box test spares the root finding (quartics, for corners under gravity).
        Dim xmin, ymin, xmax, ymax As Double
        o.Bounds(k, xmin, ymin, xmax, ymax)
        If Not PathBox.MayReach(px, py, vx, vy, ax, ay, horizon, xmin, ymin, xmax, ymax, s.Bodies.Size(i).Reach + slop) Then Return Double.PositiveInfinity
        Dim q = ObstacleQuery(s, i, k, px, py, vx, vy, ax, ay, slop, horizon)
        Return RuleFor(s.Bodies.Info(i).IsCircle, o.Kind(k)).TimeOfImpact(q, feature)
    End Function

    ''' <summary>
    ''' The unit normal from obstacle k towards body i (its reference point at (px, py)), touching the
    ''' given feature. A face contact moves the body onto the face exactly (the contact is exact, so
    ''' rounding never accumulates over many bounces).
    ''' </summary>
    Friend Function NormalAtObstacle(s As SolverState, i As Integer, k As Integer, feature As Integer, ByRef px As Double, ByRef py As Double) As Vector
        Dim q = ObstacleQuery(s, i, k, px, py, 0, 0, 0, 0, SolverState.SlopAt(px, py), Double.PositiveInfinity)
        Dim correction As Double
        Dim n = RuleFor(s.Bodies.Info(i).IsCircle, s.Obstacles.Kind(k)).Normal(q, feature, correction)
        px += n.X * correction
        py += n.Y * correction
        Return n
    End Function

    ''' <summary>
    ''' The unit normal from body j towards body i where they touch now. Two circles: the line between
    ''' their centres. Otherwise the face of their pair shape that i's reference point lies on (the
    ''' corner-on-corner rule where it lies on two), or the line from its nearest rounded corner.
    ''' </summary>
    Friend Function NormalBetweenBodies(s As SolverState, i As Integer, j As Integer) As Vector
        Dim b = s.Bodies
        Dim pi = b.PositionAt(i, s.Now), pj = b.PositionAt(j, s.Now)
        Dim k = s.Shapes.Difference(b.Outlines(j), b.Outlines(i))
        Dim d = pi - pj
        Dim slop = SolverState.SlopAt(pi.X, pi.Y)
        Dim first, second As Integer
        If OutlineContact.TouchingEdges(k, d, 4 * slop, first, second) > 0 Then Return OutlineContact.ContactNormal(k, d, first, 4 * slop)
        Return OutlineContact.Penetration(k, d).Normal
    End Function

    ''' <summary>The face (an edge of the pair shape of body i and obstacle k) that a contact feature is, or −1 for a corner.</summary>
    Friend Function FaceOf(s As SolverState, i As Integer, k As Integer, feature As Integer) As Integer
        Dim shape = s.Shapes.Difference(s.Obstacles.Outlines(k), s.Bodies.Outlines(i))
        Return If(feature >= 0 AndAlso feature < shape.EdgeCount, feature, -1)
    End Function

    ''' <summary>
    ''' When a contact feature of body i and obstacle k is a rounded corner, the curve it is: the corner
    ''' (the arc's centre), the pair's rounding radius, and the normals of the faces it joins (none for a
    ''' point: a fixed circle). Nothing for a face or a sharp corner.
    ''' </summary>
    Friend Function CurveAt(s As SolverState, i As Integer, k As Integer, feature As Integer) As CurvedSupport?
        Dim shape = s.Shapes.Difference(s.Obstacles.Outlines(k), s.Bodies.Outlines(i))
        If Not (shape.Radius > 0 AndAlso feature >= shape.EdgeCount AndAlso feature < shape.EdgeCount + shape.VertexCount) Then Return Nothing
        Dim v = feature - shape.EdgeCount
        Dim curve As New CurvedSupport With {.Centre = New Vector(s.Obstacles.X0(k), s.Obstacles.Y0(k)) + shape.Corners(v), .Radius = shape.Radius}
        ' Corner v joins edge v − 1 (ending there) and edge v (starting there).
        If shape.EdgeCount > 0 Then curve.Cone = (shape.EdgeNormals((v - 1 + shape.EdgeCount) Mod shape.EdgeCount), shape.EdgeNormals(v Mod shape.EdgeCount))
        Return curve
    End Function

    ''' <summary>How much body i (its reference point at p) overlaps obstacle k (m; ≤ 0 when apart), with the normal towards the body.</summary>
    Friend Function OverlapWithObstacle(s As SolverState, i As Integer, k As Integer, p As Vector) As Contact
        Dim o = s.Obstacles
        Return OutlineContact.Penetration(s.Shapes.Difference(o.Outlines(k), s.Bodies.Outlines(i)), p - New Vector(o.X0(k), o.Y0(k)))
    End Function

    ''' <summary>How much body i (at pi) overlaps body j (at pj) (m; ≤ 0 when apart), with the normal from j towards i.</summary>
    Friend Function OverlapWithBody(s As SolverState, i As Integer, j As Integer, pi As Vector, pj As Vector) As Contact
        Dim b = s.Bodies
        If b.Info(i).IsCircle AndAlso b.Info(j).IsCircle Then Return Collider.CircleCircle(pi, b.Motion(i).R, pj, b.Motion(j).R)
        Return OutlineContact.Penetration(s.Shapes.Difference(b.Outlines(j), b.Outlines(i)), pi - pj)
    End Function

    ''' <summary>
    ''' A body supported on face e of obstacle k's pair shape, its reference point at p (m) moving with
    ''' v (m/s) and a (m/s²) along the face: when it reaches an end of the face (s from now; +∞ if it
    ''' never does), and which end (True: the far end, where face e meets face e + 1).
    ''' </summary>
    Friend Function TimeToLeaveFace(s As SolverState, i As Integer, k As Integer, e As Integer, p As Vector, v As Vector, a As Vector,
                                    ByRef farEnd As Boolean) As Double
        Dim shape = s.Shapes.Difference(s.Obstacles.Outlines(k), s.Bodies.Outlines(i))
        Dim c0 = shape.Corners(e), c1 = shape.Corners((e + 1) Mod shape.VertexCount)
        Dim length = shape.EdgeLengths(e)
        Dim tangent = (c1 - c0) / length
        ' Along the face: q(t) = q0 + u t + ½ w t², from 0 at the near end to L at the far end.
        Dim d = p - New Vector(s.Obstacles.X0(k), s.Obstacles.Y0(k))
        Dim q0 = Vector.Dot(d - c0, tangent), u = Vector.Dot(v, tangent), w = Vector.Dot(a, tangent)
        Dim toFar = RootFinding.EarliestEntryQuadratic(-0.5 * w, -u, length - q0, 0)
        Dim toNear = RootFinding.EarliestEntryQuadratic(0.5 * w, u, q0, 0)
        farEnd = toFar <= toNear
        Return Math.Min(toFar, toNear)
    End Function
End Module
