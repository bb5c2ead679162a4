Option Strict On

''' <summary>
''' The one place that says, for each pair of body kinds, which time-of-impact function finds their
''' contact and what the contact normal is when they touch (docs/event-driven.md §2–3). The solver's
''' other parts ask here and never look at a body's shape themselves.
''' </summary>
Friend Module ContactRules
    ''' <summary>
    ''' Two movable circles whose centres are (dx, dy) apart (A − B), with relative velocity (dvx, dvy)
    ''' and relative acceleration (dax, day): when they touch (s from now; +∞ if not before <paramref name="horizon"/> s), see <see cref="TimeOfImpact.CircleCircle(Double, Double, Double, Double, Double, Double, Double, Double, Double)"/>.
    ''' </summary>
    Friend Function TimeBetweenBodies(dx As Double, dy As Double, dvx As Double, dvy As Double, dax As Double, day As Double,
                                      sumRadii As Double, slop As Double, speedScale As Double, horizon As Double) As Double
        ' Relative to B, A's centre must come within R of the origin: not before the horizon, no root finding.
        If (dax <> 0 OrElse day <> 0) AndAlso
           Not PathBox.MayReach(dx, dy, dvx, dvy, dax, day, horizon, 0, 0, 0, 0, sumRadii + slop) Then Return Double.PositiveInfinity
        Return TimeOfImpact.CircleCircle(dx, dy, dvx, dvy, dax, day, sumRadii, slop, speedScale)
    End Function

    ''' <summary>
    ''' A movable circle of radius r (centre p, velocity v, vertical acceleration ay) against obstacle s:
    ''' when it touches (s from now, +∞ if never or not within <paramref name="horizon"/> s), and which
    ''' feature (face or corner) it touches.
    ''' </summary>
    Friend Function TimeToObstacle(o As Obstacles, s As Integer, px As Double, py As Double, vx As Double, vy As Double,
                                   ay As Double, r As Double, slop As Double, horizon As Double, ByRef feature As Integer) As Double
        ' Most obstacles in a body's cell are out of its reach before its next event or cell crossing:
        ' a box test spares the root finding (quartics, for corners under gravity).
        Dim xmin, ymin, xmax, ymax As Double
        o.Bounds(s, xmin, ymin, xmax, ymax)
        If Not PathBox.MayReach(px, py, vx, vy, 0, ay, horizon, xmin, ymin, xmax, ymax, r + slop) Then Return Double.PositiveInfinity
        Select Case o.Kind(s)
            Case ObstacleKind.Circle
                feature = 0
                Return TimeOfImpact.CircleCircle(px - o.X0(s), py - o.Y0(s), vx, vy, ay, r + o.Radius(s), slop)
            Case Else
                Return TimeOfImpact.CircleRectangle(px, py, vx, vy, ay, r, o.X0(s), o.Y0(s), o.X1(s), o.Y1(s), slop, horizon, feature)
        End Select
    End Function

    ''' <summary>
    ''' The contact of a circle of radius r, centre (px, py), touching <paramref name="feature"/> of
    ''' obstacle s: the unit normal from the obstacle towards the circle. A face contact snaps the
    ''' centre onto the face (the contact is exact, so rounding never accumulates over many bounces).
    ''' <paramref name="upwardFace"/> is True for the top face of a rectangle: something can rest on it.
    ''' </summary>
    Friend Function ObstacleNormal(o As Obstacles, s As Integer, feature As Integer, r As Double,
                                   ByRef px As Double, ByRef py As Double, ByRef upwardFace As Boolean) As Vector
        upwardFace = False
        If o.Kind(s) = ObstacleKind.Circle Then
            Return New Vector(px - o.X0(s), py - o.Y0(s)).Normalized(New Vector(0, 1))
        End If
        Select Case feature
            Case 0 : px = Math.Min(px, o.X0(s) - r) : Return New Vector(-1, 0)
            Case 1 : px = Math.Max(px, o.X1(s) + r) : Return New Vector(1, 0)
            Case 2 : py = Math.Min(py, o.Y0(s) - r) : Return New Vector(0, -1)
            Case 3 : py = Math.Max(py, o.Y1(s) + r) : upwardFace = True : Return New Vector(0, 1)
            Case Else
                Dim cx = If(((feature - 4) And 1) = 0, o.X0(s), o.X1(s))
                Dim cy = If(((feature - 4) And 2) = 0, o.Y0(s), o.Y1(s))
                Return New Vector(px - cx, py - cy).Normalized(New Vector(0, 1))
        End Select
    End Function

    ''' <summary>How the outputs name a collision with obstacle s.</summary>
    Friend Function KindOfObstacle(o As Obstacles, s As Integer) As CollisionKind
        Return If(o.Kind(s) = ObstacleKind.Circle, CollisionKind.CircleFixed, CollisionKind.CircleRectangle)
    End Function

    ''' <summary>
    ''' A body resting on top of obstacle s, its reference point at x (m) moving at vx (m/s) along the
    ''' top: when it reaches the end of the top (s from now; negative if already past it).
    ''' </summary>
    Friend Function TimeToLeaveTop(o As Obstacles, s As Integer, x As Double, vx As Double) As Double
        Return If(vx > 0, (o.X1(s) - x) / vx, (o.X0(s) - x) / vx)
    End Function

    ''' <summary>The point (m) of obstacle s's top edge where a body leaving it in direction sign(vx) goes over: the corner it may slide round.</summary>
    Friend Function TopCorner(o As Obstacles, s As Integer, vx As Double) As Vector
        Return New Vector(If(vx > 0, o.X1(s), o.X0(s)), o.Y1(s))
    End Function

    ''' <summary>How much body i overlaps obstacle s (m; ≤ 0 when apart), with the normal towards the body.</summary>
    Friend Function Overlap(o As Obstacles, s As Integer, p As Vector, r As Double) As Contact
        If o.Kind(s) = ObstacleKind.Circle Then
            Return Collider.CircleCircle(p, r, New Vector(o.X0(s), o.Y0(s)), o.Radius(s))
        End If
        Return Collider.CircleRectangle(p, r, New Vector(o.X0(s), o.Y0(s)), New Vector(o.X1(s), o.Y1(s)))
    End Function
End Module
