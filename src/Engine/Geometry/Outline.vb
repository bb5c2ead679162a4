Option Strict On

Imports System.Collections.ObjectModel

''' <summary>
''' A rounded convex outline: every point within <see cref="Radius"/> (m) of a convex core. The core is
''' one point (a circle's centre), two points (a segment, solid on both sides) or a convex polygon, given
''' as offsets (m) from the body's reference point in anticlockwise order. Nothing in the engine
''' rotates, so a body's outline never changes: only its reference point moves. Edge i runs from vertex
''' i to vertex i + 1 (cyclically) and has the outward unit normal <see cref="Normals"/>(i); a point
''' has no edges, a segment two (one for each side, with opposite normals).
''' </summary>
Public NotInheritable Class Outline
    ' Friend arrays, read directly by the contact maths on the hot path; never written after construction.
    Friend ReadOnly Corners As Vector()
    Friend ReadOnly EdgeNormals As Vector()
    Friend ReadOnly EdgeLengths As Double()
    Private ReadOnly _vertexView As ReadOnlyCollection(Of Vector)
    Private ReadOnly _normalView As ReadOnlyCollection(Of Vector)

    ''' <summary>Builds an outline from a core that is already valid: anticlockwise, convex, with its normals.</summary>
    Private Sub New(corners As Vector(), normals As Vector(), radius As Double)
        Me.Corners = corners
        EdgeNormals = normals
        Me.Radius = radius
        EdgeLengths = New Double(normals.Length - 1) {}
        For i = 0 To normals.Length - 1
            Dim e = corners((i + 1) Mod corners.Length) - corners(i)
            EdgeLengths(i) = e.Length
        Next
        Dim xlo = corners(0).X, xhi = corners(0).X, ylo = corners(0).Y, yhi = corners(0).Y
        For Each c In corners
            xlo = Math.Min(xlo, c.X) : xhi = Math.Max(xhi, c.X)
            ylo = Math.Min(ylo, c.Y) : yhi = Math.Max(yhi, c.Y)
        Next
        MinX = xlo - radius : MaxX = xhi + radius
        MinY = ylo - radius : MaxY = yhi + radius
        _vertexView = Array.AsReadOnly(corners)
        _normalView = Array.AsReadOnly(normals)
    End Sub

    ''' <summary>The core's vertices (offsets from the reference point, m), anticlockwise.</summary>
    Public ReadOnly Property Vertices As IReadOnlyList(Of Vector)
        Get
            Return _vertexView
        End Get
    End Property

    ''' <summary>The outward unit normal of each edge; edge i runs from vertex i to vertex i + 1.</summary>
    Public ReadOnly Property Normals As IReadOnlyList(Of Vector)
        Get
            Return _normalView
        End Get
    End Property

    ''' <summary>How far the shape reaches beyond its core, m (a circle's radius; 0 for polygons and segments).</summary>
    Public ReadOnly Property Radius As Double

    ''' <summary>1 for a point, 2 for a segment, the number of corners for a polygon.</summary>
    Public ReadOnly Property VertexCount As Integer
        Get
            Return Corners.Length
        End Get
    End Property

    ''' <summary>0 for a point, 2 for a segment (one per side), the number of sides for a polygon.</summary>
    Public ReadOnly Property EdgeCount As Integer
        Get
            Return EdgeNormals.Length
        End Get
    End Property

    ''' <summary>Leftmost x of the rounded shape, m (relative to the reference point).</summary>
    Public ReadOnly Property MinX As Double
    ''' <summary>Rightmost x of the rounded shape, m.</summary>
    Public ReadOnly Property MaxX As Double
    ''' <summary>Lowest y of the rounded shape, m.</summary>
    Public ReadOnly Property MinY As Double
    ''' <summary>Highest y of the rounded shape, m.</summary>
    Public ReadOnly Property MaxY As Double

    ''' <summary>A circle of the given radius (m, ≥ 0) centred on the reference point.</summary>
    Public Shared Function Point(radius As Double) As Outline
        If Not (radius >= 0) OrElse Double.IsInfinity(radius) Then Throw New ArgumentOutOfRangeException(NameOf(radius), "radius must be a finite number of at least 0")
        Return New Outline({Vector.Zero}, Array.Empty(Of Vector)(), radius)
    End Function

    ''' <summary>
    ''' A fixed line segment from a to b (offsets, m) of zero thickness, solid on both sides: edge 0 is
    ''' the side on the right of a → b, edge 1 the side on its left. Its ends act as corners.
    ''' </summary>
    Public Shared Function Segment(a As Vector, b As Vector) As Outline
        If Not a.IsFinite OrElse Not b.IsFinite Then Throw New ArgumentException("segment ends must be finite")
        If a = b Then Throw New ArgumentException("a segment needs two different ends")
        Return New Outline({a, b}, {EdgeNormal(a, b), EdgeNormal(b, a)}, 0)
    End Function

    ''' <summary>An axis-aligned box width × height (m, &gt; 0) with its lower-left corner on the reference point.</summary>
    Public Shared Function Box(width As Double, height As Double) As Outline
        If Not (width > 0) OrElse Double.IsInfinity(width) Then Throw New ArgumentOutOfRangeException(NameOf(width), "width must be a finite number greater than 0")
        If Not (height > 0) OrElse Double.IsInfinity(height) Then Throw New ArgumentOutOfRangeException(NameOf(height), "height must be a finite number greater than 0")
        Dim corners = {New Vector(0, 0), New Vector(width, 0), New Vector(width, height), New Vector(0, height)}
        Return New Outline(corners, {New Vector(0, -1), New Vector(1, 0), New Vector(0, 1), New Vector(-1, 0)}, 0)
    End Function

    ''' <summary>
    ''' A convex polygon from its corners (offsets, m) in either turning direction; the outline holds
    ''' them anticlockwise. Exact duplicates and exactly collinear middle corners are dropped.
    ''' </summary>
    ''' <exception cref="ArgumentException">fewer than 3 distinct corners, zero area, not convex, or self-intersecting.</exception>
    Public Shared Function Polygon(vertices As IReadOnlyList(Of Vector)) As Outline
        If vertices Is Nothing Then Throw New ArgumentNullException(NameOf(vertices))
        Dim pts As New List(Of Vector)(vertices.Count)
        For Each v In vertices
            If Not v.IsFinite Then Throw New ArgumentException("polygon corners must be finite", NameOf(vertices))
            If pts.Count = 0 OrElse pts(pts.Count - 1) <> v Then pts.Add(v)
        Next
        While pts.Count > 1 AndAlso pts(0) = pts(pts.Count - 1)
            pts.RemoveAt(pts.Count - 1)
        End While
        If pts.Count < 3 Then Throw New ArgumentException("a polygon needs at least 3 distinct corners", NameOf(vertices))
        Dim twiceArea = 0.0
        For i = 1 To pts.Count - 2
            twiceArea += Vector.Cross(pts(i) - pts(0), pts(i + 1) - pts(0))
        Next
        If twiceArea = 0 Then Throw New ArgumentException("the polygon has zero area", NameOf(vertices))
        If twiceArea < 0 Then pts.Reverse()
        ' Collinear middle corners would make zero-angle corners; a corner that turns straight back is a spike.
        Dim changed = True
        While changed AndAlso pts.Count >= 3
            changed = False
            For i = 0 To pts.Count - 1
                Dim prev = pts((i + pts.Count - 1) Mod pts.Count), nxt = pts((i + 1) Mod pts.Count)
                Dim e1 = pts(i) - prev, e2 = nxt - pts(i)
                If Vector.Cross(e1, e2) = 0 Then
                    If Vector.Dot(e1, e2) < 0 Then Throw New ArgumentException("the polygon is not convex (it folds back on itself)", NameOf(vertices))
                    pts.RemoveAt(i)
                    changed = True
                    Exit For
                End If
            Next
        End While
        If pts.Count < 3 Then Throw New ArgumentException("the polygon has zero area", NameOf(vertices))
        ' Every corner must turn left, and the turns must add up to one full turn (a star pentagon
        ' turns left everywhere but goes round twice).
        Dim turning = 0.0
        For i = 0 To pts.Count - 1
            Dim prev = pts((i + pts.Count - 1) Mod pts.Count), nxt = pts((i + 1) Mod pts.Count)
            Dim e1 = pts(i) - prev, e2 = nxt - pts(i)
            Dim c = Vector.Cross(e1, e2)
            If c <= 0 Then Throw New ArgumentException("the polygon is not convex", NameOf(vertices))
            turning += Math.Atan2(c, Vector.Dot(e1, e2))
        Next
        If turning > 3 * Math.PI Then Throw New ArgumentException("the polygon intersects itself", NameOf(vertices))
        Dim corners = pts.ToArray()
        Dim normals(corners.Length - 1) As Vector
        For i = 0 To corners.Length - 1
            normals(i) = EdgeNormal(corners(i), corners((i + 1) Mod corners.Length))
        Next
        Return New Outline(corners, normals, 0)
    End Function

    ''' <summary>
    ''' The same shape with its core moved by <paramref name="offset"/> (m): for example
    ''' <c>p.Translated(-p.Centroid)</c> expresses a polygon relative to its centre of area.
    ''' </summary>
    Public Function Translated(offset As Vector) As Outline
        If Not offset.IsFinite Then Throw New ArgumentException("the offset must be finite", NameOf(offset))
        Dim moved(Corners.Length - 1) As Vector
        For i = 0 To moved.Length - 1
            moved(i) = Corners(i) + offset
        Next
        Return New Outline(moved, EdgeNormals, Radius)
    End Function

    ''' <summary>
    ''' Area of the rounded shape, m²: the core's area, plus a strip of width R along every edge, plus
    ''' the corner sectors that together make one disc of radius R. A polygon: its area; a circle: πR².
    ''' </summary>
    Public ReadOnly Property Area As Double
        Get
            Dim perimeter = 0.0
            For Each l In EdgeLengths
                perimeter += l
            Next
            Return CoreArea() + perimeter * Radius + Math.PI * Radius * Radius
        End Get
    End Property

    ''' <summary>
    ''' Centre of area of the rounded shape (offset, m): a polygon's centroid, a circle's centre, a
    ''' segment's midpoint. (With R &gt; 0 around a polygon the strips and corner sectors are included.)
    ''' </summary>
    Public ReadOnly Property Centroid As Vector
        Get
            ' An outline never changes: its centroid is worked out once (a spring to a box asks for it at every step).
            If Not _centroidKnown Then
                _centroid = CentroidOfArea()
                _centroidKnown = True
            End If
            Return _centroid
        End Get
    End Property

    Private _centroid As Vector
    Private _centroidKnown As Boolean

    Private Function CentroidOfArea() As Vector
        If Corners.Length = 1 Then Return Corners(0)
        If Corners.Length = 2 Then Return 0.5 * (Corners(0) + Corners(1))
        ' Core: fan of triangles from corner 0, measured from corner 0 so large offsets cancel less.
        Dim o = Corners(0)
        Dim a2 = 0.0, mx = 0.0, my = 0.0
        For i = 1 To Corners.Length - 2
            Dim p = Corners(i) - o, q = Corners(i + 1) - o
            Dim c = Vector.Cross(p, q)
            a2 += c
            mx += c * (p.X + q.X) / 3
            my += c * (p.Y + q.Y) / 3
        Next
        Dim area = 0.5 * a2
        Dim moment = New Vector(0.5 * mx, 0.5 * my)
        Dim r = Radius
        If r > 0 Then
            For i = 0 To Corners.Length - 1
                ' The strip along edge i: a rectangle L × R centred half a radius out from the edge's middle.
                Dim stripArea = EdgeLengths(i) * r
                Dim stripCentre = 0.5 * (Corners(i) + Corners((i + 1) Mod Corners.Length)) + (0.5 * r) * EdgeNormals(i) - o
                area += stripArea
                moment += stripArea * stripCentre
                ' The sector at corner i, between the normals of the edges that meet there: its
                ' centre of area lies on the bisector at 4R sin(θ/2) / (3θ) from the corner.
                Dim n1 = EdgeNormals((i + Corners.Length - 1) Mod Corners.Length), n2 = EdgeNormals(i)
                Dim theta = Math.Atan2(Vector.Cross(n1, n2), Vector.Dot(n1, n2))
                Dim sectorArea = 0.5 * r * r * theta
                Dim reach = 4 * r * Math.Sin(0.5 * theta) / (3 * theta)
                area += sectorArea
                moment += sectorArea * (Corners(i) - o + reach * (n1 + n2).Normalized(n2))
            Next
        End If
        Return o + moment / area
    End Function

    ''' <summary>
    ''' The set of differences core_b − core_a grown by r_a + r_b: body A (outline a, reference point p_A)
    ''' touches body B exactly when p_A − p_B lies in this outline. Built in O(n + m) by merging the two
    ''' cores' edges in order of direction; parallel edges merge into one. Two points give a point, a
    ''' point and anything a translated copy, two parallel segments a segment, two other segments a
    ''' parallelogram.
    ''' </summary>
    Public Shared Function MinkowskiDifference(b As Outline, a As Outline) As Outline
        If b Is Nothing Then Throw New ArgumentNullException(NameOf(b))
        If a Is Nothing Then Throw New ArgumentNullException(NameOf(a))
        Dim radius = a.Radius + b.Radius
        Dim p = b.Corners, pn = b.EdgeNormals
        Dim q(a.Corners.Length - 1) As Vector, qn(a.EdgeNormals.Length - 1) As Vector
        ' −core_a: a half turn keeps the anticlockwise order and the edge numbering.
        For k = 0 To q.Length - 1
            q(k) = -a.Corners(k)
        Next
        For k = 0 To qn.Length - 1
            qn(k) = -a.EdgeNormals(k)
        Next
        If q.Length = 1 Then Return New Outline(Shift(p, q(0)), pn, radius)
        If p.Length = 1 Then Return New Outline(Shift(q, p(0)), qn, radius)
        ' Both cores have edges. From its lowest (then leftmost) corner each core's edge directions
        ' rise through [0, 2π); merging the two sequences by direction walks round the sum.
        Dim i0 = LowestCorner(p), j0 = LowestCorner(q)
        Dim n = p.Length, m = q.Length
        Dim corners As New List(Of Vector)(n + m)
        Dim normals As New List(Of Vector)(n + m)
        Dim i = 0, j = 0
        While i < n OrElse j < m
            Dim ip = (i0 + i) Mod n, jq = (j0 + j) Mod m
            corners.Add(p(ip) + q(jq))
            Dim order As Integer
            If i = n Then
                order = 1
            ElseIf j = m Then
                order = -1
            Else
                order = CompareDirection(p((ip + 1) Mod n) - p(ip), q((jq + 1) Mod m) - q(jq))
            End If
            If order <= 0 Then
                normals.Add(pn(ip))
                i += 1
                If order = 0 Then j += 1
            Else
                normals.Add(qn(jq))
                j += 1
            End If
        End While
        Return FromMerged(corners, normals, radius)
    End Function

    ''' <summary>
    ''' The unit vector that points out of the shape at corner k along the bisector of its normal cone
    ''' (between the normals of the two edges that meet there). At a segment's end, whose two normals are
    ''' opposite, it points along the segment away from it; for a point core it is +y.
    ''' </summary>
    Friend Function CornerBisector(k As Integer) As Vector
        If EdgeNormals.Length = 0 Then Return New Vector(0, 1)
        Dim m = Corners.Length
        Dim before = EdgeNormals((k + m - 1) Mod m), after = EdgeNormals(k)
        Dim sum = before + after
        ' A segment's end: the normals cancel (or nearly, by rounding); the edge arriving at the end,
        ' continued, points straight out.
        If sum.LengthSquared <= 1.0E-20 Then Return New Vector(-before.Y, before.X)
        Return sum.Normalized(after)
    End Function

    Private Function CoreArea() As Double
        If Corners.Length < 3 Then Return 0
        Dim o = Corners(0)
        Dim a2 = 0.0
        For i = 1 To Corners.Length - 2
            a2 += Vector.Cross(Corners(i) - o, Corners(i + 1) - o)
        Next
        Return 0.5 * a2
    End Function

    ''' <summary>The outward normal of an edge from a to b of an anticlockwise core: a → b turned a quarter turn clockwise.</summary>
    Private Shared Function EdgeNormal(a As Vector, b As Vector) As Vector
        Dim e = b - a
        Dim len = e.Length
        Return New Vector(e.Y / len, -e.X / len)
    End Function

    Private Shared Function Shift(points As Vector(), offset As Vector) As Vector()
        Dim moved(points.Length - 1) As Vector
        For i = 0 To points.Length - 1
            moved(i) = points(i) + offset
        Next
        Return moved
    End Function

    ''' <summary>The corner with the lowest y, the leftmost of those on a tie.</summary>
    Private Shared Function LowestCorner(points As Vector()) As Integer
        Dim best = 0
        For i = 1 To points.Length - 1
            If points(i).Y < points(best).Y OrElse (points(i).Y = points(best).Y AndAlso points(i).X < points(best).X) Then best = i
        Next
        Return best
    End Function

    ''' <summary>
    ''' −1 when direction e comes before f on a turn anticlockwise from +x (angles in [0, 2π)), +1 when
    ''' after, 0 when they point the same way. Exact: a half-plane test, then the sign of a cross product.
    ''' </summary>
    Private Shared Function CompareDirection(e As Vector, f As Vector) As Integer
        Dim he = If(e.Y > 0 OrElse (e.Y = 0 AndAlso e.X > 0), 0, 1)
        Dim hf = If(f.Y > 0 OrElse (f.Y = 0 AndAlso f.X > 0), 0, 1)
        If he <> hf Then Return If(he < hf, -1, 1)
        Dim c = Vector.Cross(e, f)
        If c > 0 Then Return -1
        If c < 0 Then Return 1
        Return 0
    End Function

    ''' <summary>
    ''' The merged corners and edge normals as an outline. A sum corner can round onto its neighbour
    ''' when one edge is tiny next to the offsets: that zero-length edge is dropped.
    ''' </summary>
    Private Shared Function FromMerged(corners As List(Of Vector), normals As List(Of Vector), radius As Double) As Outline
        Dim keptCorners As New List(Of Vector)(corners.Count)
        Dim keptNormals As New List(Of Vector)(corners.Count)
        For k = 0 To corners.Count - 1
            If corners(k) <> corners((k + 1) Mod corners.Count) OrElse corners.Count = 1 Then
                keptCorners.Add(corners(k))
                keptNormals.Add(normals(k))
            End If
        Next
        If keptCorners.Count <= 1 Then Return New Outline({corners(0)}, Array.Empty(Of Vector)(), radius)
        If keptCorners.Count = 2 Then
            Dim a = keptCorners(0), b = keptCorners(1)
            Return New Outline({a, b}, {EdgeNormal(a, b), EdgeNormal(b, a)}, radius)
        End If
        Return New Outline(keptCorners.ToArray(), keptNormals.ToArray(), radius)
    End Function
End Class
