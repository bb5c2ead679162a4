Option Strict On

''' <summary>
''' Contact and time of impact of a point against a fixed rounded convex outline, as pure functions.
''' Bodies never rotate, so body A (outline a, reference point p_A) touches body B exactly when
''' d = p_A − p_B lies in K = <see cref="Outline.MinkowskiDifference"/>(b, a): every pair of shapes
''' becomes the point d(t) = d0 + dv t + ½ da t² against the fixed outline K. Distances in m, times in s,
''' velocities in m/s, accelerations in m/s².
''' Features of K: edge i is feature i (0 … EdgeCount − 1); the rounded corner at vertex k is feature
''' VertexCount + k.
''' </summary>
Public Module OutlineContact
    ''' <summary>
    ''' How deep the point d lies in the outline. Depth (m) = R − (distance from d to the core): positive
    ''' inside the rounded shape, 0 on its boundary, negative outside. Normal: the unit vector from the
    ''' core's nearest point towards d; for d inside a polygon core, the normal of the edge d is least
    ''' deep behind. As in <see cref="Contact"/>, it points from the other body (B) towards this one (A).
    ''' Ties, so that a mirrored scene gets the mirrored normal: exactly as deep behind both edges of a
    ''' corner (d on the corner's bisector, or on the corner itself) gives the corner's bisector (the
    ''' normalised sum of the two edges' normals), other ties the lowest-numbered edge. d on a segment core
    ''' takes edge 0's normal, d exactly on a segment's end the direction straight out along the segment,
    ''' d on a point core +y.
    ''' </summary>
    Public Function Penetration(outline As Outline, d As Vector) As Contact
        If outline Is Nothing Then Throw New ArgumentNullException(NameOf(outline))
        Dim corners = outline.Corners, normals = outline.EdgeNormals, lengths = outline.EdgeLengths
        Dim r = outline.Radius
        Dim m = corners.Length
        If m = 1 Then
            Dim rel = d - corners(0)
            Return New Contact(rel.Normalized(New Vector(0, 1)), r - rel.Length)
        End If
        If m >= 3 Then
            Dim leastDeep = Double.NegativeInfinity, face = 0
            Dim runnerUp = Double.NegativeInfinity, runnerFace = -1
            For i = 0 To m - 1
                Dim s = Vector.Dot(normals(i), d - corners(i))
                If s > leastDeep Then
                    runnerUp = leastDeep : runnerFace = face
                    leastDeep = s : face = i
                ElseIf s > runnerUp Then
                    runnerUp = s : runnerFace = i
                End If
            Next
            If leastDeep <= 0 Then
                ' Exactly as deep behind the two edges of one corner: that corner's bisector, which does
                ' not depend on how the edges are numbered, so a mirrored scene gets the mirrored normal.
                If runnerUp = leastDeep Then
                    If runnerFace = (face + 1) Mod m Then Return New Contact(outline.CornerBisector(runnerFace), r - leastDeep)
                    If face = (runnerFace + 1) Mod m Then Return New Contact(outline.CornerBisector(face), r - leastDeep)
                End If
                Return New Contact(normals(face), r - leastDeep)
            End If
        End If
        ' Outside the core (a segment has no inside): the nearest point of the boundary. Where that
        ' point is inside an edge, the normal is the edge's own (exact) rather than a rounded difference.
        Dim best = Double.PositiveInfinity
        Dim normal = New Vector(0, 1)
        For i = 0 To m - 1
            Dim n = normals(i)
            Dim rel = d - corners(i)
            Dim s = rel.X * -n.Y + rel.Y * n.X
            If s > 0 AndAlso s < lengths(i) Then
                ' An edge whose inner side faces d is never the nearest (d is outside), except on a
                ' segment, whose other edge is the same line seen from d's side.
                Dim dist = Vector.Dot(rel, n)
                If dist >= 0 AndAlso dist < best Then best = dist : normal = n
            Else
                Dim k = If(s <= 0, i, (i + 1) Mod m)
                Dim fromCorner = d - corners(k)
                Dim dist = fromCorner.Length
                If dist < best Then best = dist : normal = fromCorner.Normalized(outline.CornerBisector(k))
            End If
        Next
        Return New Contact(normal, r - best)
    End Function

    ''' <summary>
    ''' The first time t ≥ 0 (s) at which the point d(t) = d0 + dv t + ½ da t² (m, m/s, m/s²) enters the
    ''' rounded outline while the gap is closing; +∞ when it never does, or only after
    ''' <paramref name="horizon"/> s (which may be +∞). Touching now (gap within <paramref name="slop"/> m)
    ''' and approaching faster than <see cref="TimeOfImpact.ApproachFraction"/> × (|dv| +
    ''' <paramref name="speedScale"/>) is a contact now (0); touching and separating is none.
    ''' Each edge is a plane moved out by R, whose gap is a quadratic in t (linear when da is along the
    ''' edge), accepted only within the edge's extent; each rounded corner (R &gt; 0) is a circle of
    ''' radius R about the vertex, accepted only inside the vertex's normal cone. With R = 0 a corner is
    ''' no feature of its own: the edges' closed extents (with slop) take a hit on it, but only when the
    ''' point also closes on the other edge that meets there (it enters the corner's wedge rather than
    ''' passing the corner or sliding along that edge). A start deeper than slop inside the shape is an
    ''' overlap for the overlap resolver, not a contact: an edge then counts only a later crossing of its
    ''' plane from outside, and a rounded corner only a hit inside its cone.
    ''' <paramref name="feature"/> is the edge index, or VertexCount + k for the rounded corner at vertex
    ''' k, or −1 when there is no hit.
    ''' </summary>
    Public Function EarliestEntry(outline As Outline, d0 As Vector, dv As Vector, da As Vector, slop As Double,
                                  speedScale As Double, horizon As Double, ByRef feature As Integer) As Double
        feature = -1
        If outline Is Nothing Then Throw New ArgumentNullException(NameOf(outline))
        If Not (horizon >= 0) Then Return Double.PositiveInfinity
        ' When the path can be within the shape's extents: [0, horizon], cut down by the slab of each
        ' coordinate that moves in a straight line; then the box around the path over what is left.
        Dim tLo = 0.0, tHi = horizon
        If da.X = 0 AndAlso Not Slab(d0.X, dv.X, outline.MinX - slop, outline.MaxX + slop, tLo, tHi) Then Return Double.PositiveInfinity
        If da.Y = 0 AndAlso Not Slab(d0.Y, dv.Y, outline.MinY - slop, outline.MaxY + slop, tLo, tHi) Then Return Double.PositiveInfinity
        If tHi < Double.PositiveInfinity AndAlso PathMisses(outline, d0, dv, da, slop, tLo, tHi) Then Return Double.PositiveInfinity
        Dim corners = outline.Corners, normals = outline.EdgeNormals
        Dim r = outline.Radius
        Dim approachTol = TimeOfImpact.ApproachFraction * (dv.Length + speedScale)
        Dim best = Double.PositiveInfinity
        For i = 0 To normals.Length - 1
            Dim n = normals(i)
            Dim gap = Vector.Dot(n, d0 - corners(i)) - r
            Dim rate = Vector.Dot(n, dv)
            ' Touching and approaching at less than rounding can tell from zero is not approaching
            ' (what rounding leaves after a perfectly inelastic collision).
            If Math.Abs(gap) <= slop AndAlso Math.Abs(rate) <= approachTol Then rate = 0
            Dim t = TimeOfImpact.GapCloses(gap, rate, Vector.Dot(n, da), slop)
            If t < best AndAlso t <= horizon AndAlso FaceTakesHit(outline, i, d0, dv, da, t, slop, approachTol) Then
                best = t
                feature = i
            End If
        Next
        If r > 0 Then
            ' Corners are quartics under gravity, the dearest part: only those whose disc the path can
            ' reach before the earliest hit so far (or before it leaves the extents) are solved.
            Dim limit = Math.Min(best, tHi)
            Dim prune = limit < Double.PositiveInfinity
            Dim xlo, xhi, ylo, yhi As Double
            If prune Then PathBounds(d0, dv, da, Math.Min(tLo, limit), limit, xlo, xhi, ylo, yhi)
            Dim m = corners.Length
            For k = 0 To m - 1
                Dim c = corners(k)
                If prune AndAlso (c.X + r < xlo - slop OrElse c.X - r > xhi + slop OrElse c.Y + r < ylo - slop OrElse c.Y - r > yhi + slop) Then Continue For
                Dim rel = d0 - c
                Dim t = PolishCornerTime(rel, dv, da, r, CornerTime(rel, dv, da, r, slop, speedScale))
                If t < best AndAlso t <= horizon AndAlso InNormalCone(outline, k, rel + t * dv + (0.5 * t * t) * da, slop) Then
                    best = t
                    feature = m + k
                End If
            Next
        End If
        Return best
    End Function

    ''' <summary>
    ''' The unit contact normal (from K towards d) for a hit that <see cref="EarliestEntry"/> found on
    ''' <paramref name="feature"/> with the point at d (m):
    ''' an edge gives its outward normal; a rounded corner gives (d − vertex) normalised.
    ''' Corner on corner (R = 0, d within <paramref name="slop"/> m of a polygon vertex, so touching both
    ''' edges that meet there): the normalised sum of those two edges' normals, the bisector of the
    ''' corner. This rule is deterministic and mirror-symmetric: it does not depend on which of the two
    ''' edges the hit was found on, so a scene that is symmetric about a vertical line stays symmetric.
    ''' (At a segment's end the two normals are opposite and have no useful sum: the edge's own normal,
    ''' the side that was hit, is kept.) Any other feature value gives the normal of
    ''' <see cref="Penetration"/>.
    ''' </summary>
    Public Function ContactNormal(outline As Outline, d As Vector, feature As Integer, slop As Double) As Vector
        If outline Is Nothing Then Throw New ArgumentNullException(NameOf(outline))
        Dim corners = outline.Corners, normals = outline.EdgeNormals
        Dim m = corners.Length
        If feature >= m AndAlso feature < 2 * m Then
            Dim k = feature - m
            Return (d - corners(k)).Normalized(outline.CornerBisector(k))
        End If
        If feature >= 0 AndAlso feature < normals.Length Then
            If outline.Radius = 0 AndAlso m >= 3 Then
                Dim startCorner = feature, endCorner = (feature + 1) Mod m
                If (d - corners(startCorner)).Length <= slop Then Return outline.CornerBisector(startCorner)
                If (d - corners(endCorner)).Length <= slop Then Return outline.CornerBisector(endCorner)
            End If
            Return normals(feature)
        End If
        Return Penetration(outline, d).Normal
    End Function

    ''' <summary>
    ''' Which edges of the outline the point d (m) lies on, within <paramref name="slop"/> m: its gap to
    ''' the edge moved out by R is within ±slop and it projects within the edge's extent (± slop). Returns
    ''' how many; the first two (lowest-numbered) are in <paramref name="first"/> and
    ''' <paramref name="second"/> (−1 when absent). A point on a polygon's corner lies on both edges that
    ''' meet there; a point on a segment on both of its sides.
    ''' </summary>
    Public Function TouchingEdges(outline As Outline, d As Vector, slop As Double, ByRef first As Integer, ByRef second As Integer) As Integer
        If outline Is Nothing Then Throw New ArgumentNullException(NameOf(outline))
        first = -1
        second = -1
        Dim corners = outline.Corners, normals = outline.EdgeNormals, lengths = outline.EdgeLengths
        Dim count = 0
        For i = 0 To normals.Length - 1
            Dim n = normals(i)
            Dim rel = d - corners(i)
            Dim gap = Vector.Dot(rel, n) - outline.Radius
            Dim s = rel.X * -n.Y + rel.Y * n.X
            If Math.Abs(gap) <= slop AndAlso s >= -slop AndAlso s <= lengths(i) + slop Then
                If count = 0 Then first = i Else If count = 1 Then second = i
                count += 1
            End If
        Next
        Return count
    End Function

    ''' <summary>
    ''' Cuts the window [tLo, tHi] (s) down to the times when a coordinate p + v t (m, m/s) lies in
    ''' [lo, hi] (m); False when nothing of the window is left. A NaN anywhere leaves nothing.
    ''' </summary>
    Private Function Slab(p As Double, v As Double, lo As Double, hi As Double, ByRef tLo As Double, ByRef tHi As Double) As Boolean
        If v = 0 Then Return p >= lo AndAlso p <= hi
        Dim t1 = (lo - p) / v, t2 = (hi - p) / v
        If v < 0 Then
            Dim swap = t1 : t1 = t2 : t2 = swap
        End If
        If t1 > tLo Then tLo = t1
        If t2 < tHi Then tHi = t2
        Return tLo <= tHi
    End Function

    ''' <summary>
    ''' Whether the box around the path over [tFrom, tTo] (s) stays clear of the outline's extents: then
    ''' nothing can happen in that window. A NaN bound compares false everywhere and prunes nothing.
    ''' </summary>
    Private Function PathMisses(outline As Outline, d0 As Vector, dv As Vector, da As Vector, slop As Double, tFrom As Double, tTo As Double) As Boolean
        Dim xlo, xhi, ylo, yhi As Double
        PathBounds(d0, dv, da, tFrom, tTo, xlo, xhi, ylo, yhi)
        Return xhi < outline.MinX - slop OrElse xlo > outline.MaxX + slop OrElse
               yhi < outline.MinY - slop OrElse ylo > outline.MaxY + slop
    End Function

    ''' <summary>The box (m) that holds d(t) for tFrom ≤ t ≤ tTo (s).</summary>
    Private Sub PathBounds(d0 As Vector, dv As Vector, da As Vector, tFrom As Double, tTo As Double,
                          ByRef xlo As Double, ByRef xhi As Double, ByRef ylo As Double, ByRef yhi As Double)
        Dim p = d0 + tFrom * dv + (0.5 * tFrom * tFrom) * da
        Dim v = dv + tFrom * da
        Dim span = tTo - tFrom
        PathBox.Bounds(p.X, p.Y, v.X, v.Y, da.Y, span, xlo, xhi, ylo, yhi)
        If da.X <> 0 Then
            ' PathBox bends only y; a sideways acceleration bends x too: bound it as the y of a second call.
            Dim ignoredLo, ignoredHi As Double
            PathBox.Bounds(0, p.X, 0, v.X, da.X, span, ignoredLo, ignoredHi, xlo, xhi)
        End If
    End Sub

    ''' <summary>
    ''' Whether edge i takes a hit on its plane at time t: the hit point must lie within the edge's
    ''' extent (± slop). With R &gt; 0 (and on a segment) a hit exactly at an end while moving outwards
    ''' along the edge belongs to the rounded corner there (the rule of the rectangle faces). With R = 0
    ''' a hit within slop of a polygon's corner enters only if the point also closes on the other edge
    ''' that meets there (its velocity, or failing that its acceleration, points into the corner's
    ''' wedge); otherwise it passes the corner, or slides along that edge, without entering.
    ''' </summary>
    Private Function FaceTakesHit(outline As Outline, i As Integer, d0 As Vector, dv As Vector, da As Vector, t As Double,
                                  slop As Double, approachTol As Double) As Boolean
        Dim corners = outline.Corners, normals = outline.EdgeNormals
        Dim m = corners.Length
        Dim n = normals(i)
        Dim along = New Vector(-n.Y, n.X)
        Dim rel = (d0 - corners(i)) + t * dv + (0.5 * t * t) * da
        Dim velocity = dv + t * da
        Dim u = Vector.Dot(rel, along)
        Dim length = outline.EdgeLengths(i)
        If u < -slop OrElse u > length + slop Then Return False
        If outline.Radius > 0 OrElse m = 2 Then
            Dim uRate = Vector.Dot(velocity, along)
            If u >= length AndAlso uRate > 0 Then Return False
            If u <= 0 AndAlso uRate < 0 Then Return False
            Return True
        End If
        If u >= length - slop AndAlso Not ClosesOnEdge(outline, (i + 1) Mod m, velocity, da, approachTol) Then Return False
        If u <= slop AndAlso Not ClosesOnEdge(outline, (i + m - 1) Mod m, velocity, da, approachTol) Then Return False
        Return True
    End Function

    ''' <summary>
    ''' Whether a point on edge j's plane moving at velocity (m/s) with acceleration da (m/s²) is closing
    ''' on it: the first of its normal speed and normal acceleration that is not (nearly) zero is negative.
    ''' </summary>
    Private Function ClosesOnEdge(outline As Outline, j As Integer, velocity As Vector, da As Vector, approachTol As Double) As Boolean
        Dim n = outline.EdgeNormals(j)
        Dim rate = Vector.Dot(n, velocity)
        If rate < -approachTol Then Return True
        If rate > approachTol Then Return False
        Return Vector.Dot(n, da) < 0
    End Function

    ''' <summary>
    ''' Whether a hit at offset h (m) from vertex k lies in the vertex's normal cone: past the end of the
    ''' edge arriving at k and before the start of the edge leaving it (± slop). A point core's cone is
    ''' the whole plane; a segment end's cone is the half-plane beyond that end.
    ''' </summary>
    Private Function InNormalCone(outline As Outline, k As Integer, h As Vector, slop As Double) As Boolean
        Dim normals = outline.EdgeNormals
        If normals.Length = 0 Then Return True
        Dim m = outline.Corners.Length
        Dim before = normals((k + m - 1) Mod m), after = normals(k)
        ' Along-edge directions are the normals turned a quarter turn anticlockwise.
        Dim pastArriving = h.X * -before.Y + h.Y * before.X >= -slop
        Dim beforeLeaving = h.X * -after.Y + h.Y * after.X <= slop
        Return pastArriving AndAlso beforeLeaving
    End Function

    ''' <summary>
    ''' A corner time t (s) refined by Newton steps on the distance itself, |rel(t)| − r. The quartic in
    ''' |rel|² loses digits when the path starts far from the corner compared with r (terms of size |rel₀|²
    ''' cancel down to r²: a 1 mm ball arriving from 10 m at 10⁴ m/s would end up 10⁻¹¹ m inside), while
    ''' the distance is good to the rounding of the position. A step is taken only while it is small and
    ''' brings the distance closer to r; a touching contact (t = 0) and a miss are left alone.
    ''' </summary>
    Private Function PolishCornerTime(rel As Vector, dv As Vector, da As Vector, r As Double, t As Double) As Double
        If Not (t > 0) OrElse Double.IsInfinity(t) Then Return t
        Dim gap = (rel + t * dv + (0.5 * t * t) * da).Length - r
        For iteration = 1 To 3
            If gap = 0 Then Exit For
            Dim p = rel + t * dv + (0.5 * t * t) * da
            Dim closing = Vector.Dot(p, dv + t * da) / p.Length
            If Not (closing < 0) Then Exit For
            Dim nextT = t - gap / closing
            If Not (nextT > 0) OrElse Math.Abs(nextT - t) > 0.000001 * t Then Exit For
            Dim nextGap = (rel + nextT * dv + (0.5 * nextT * nextT) * da).Length - r
            If Math.Abs(nextGap) >= Math.Abs(gap) Then Exit For
            t = nextT
            gap = nextGap
        Next
        Return t
    End Function

    ''' <summary>
    ''' The first entry of the point, at offset rel (m) from a vertex, into the circle of radius r about
    ''' it: <see cref="TimeOfImpact.CircleCircle"/>, which bends the path only vertically. A distance does
    ''' not depend on the frame, so a sideways acceleration is handled by turning the frame until it
    ''' points along +y.
    ''' </summary>
    Private Function CornerTime(rel As Vector, dv As Vector, da As Vector, r As Double, slop As Double, speedScale As Double) As Double
        If da.X = 0 Then Return TimeOfImpact.CircleCircle(rel.X, rel.Y, dv.X, dv.Y, da.Y, r, slop, speedScale)
        Dim a = da.Length
        Dim up = da / a
        Dim across = New Vector(up.Y, -up.X)
        Return TimeOfImpact.CircleCircle(Vector.Dot(rel, across), Vector.Dot(rel, up), Vector.Dot(dv, across), Vector.Dot(dv, up),
                                         a, r, slop, speedScale)
    End Function
End Module
