Option Strict On

''' <summary>
''' The convex hull of clicked corners (the outline a rubber band stretched round them would take),
''' and the measures the corner tool checks a polygon by. Pure functions of points in metres.
''' </summary>
Public Module ConvexHull
    ''' <summary>
    ''' A corner whose two sides turn by less than this (radians) is taken as lying on a straight
    ''' side: it cannot be seen, and the engine would refuse a corner that does not turn at all.
    ''' </summary>
    Public Const StraightTurn As Double = 0.000000001

    ''' <summary>
    ''' The indices of the points that are corners of their convex hull, anticlockwise, starting from
    ''' the lowest-left one. Points inside the hull, on one of its sides or repeating another are
    ''' left out. Fewer than 3 indices means the points enclose no area (all on one line, or fewer
    ''' than 3 distinct). Andrew's monotone chain: O(n log n).
    ''' </summary>
    Public Function Corners(points As IReadOnlyList(Of Vector)) As Integer()
        If points Is Nothing Then Throw New ArgumentNullException(NameOf(points))
        For Each p In points
            If Not p.IsFinite Then Throw New ArgumentException("corners must be finite", NameOf(points))
        Next
        Dim order = Enumerable.Range(0, points.Count).
            OrderBy(Function(i) points(i).X).ThenBy(Function(i) points(i).Y).ThenBy(Function(i) i).ToArray()
        If order.Length < 3 Then Return DistinctOf(points, order)
        ' The lower chain left to right, then the upper chain right to left; a point that does not
        ' turn left from the last two is popped, so collinear and repeated points never stay.
        Dim hull As New List(Of Integer)(order.Length + 1)
        For Each i In order
            Push(hull, points, i, 2)
        Next
        Dim upperFrom = hull.Count + 1
        For k = order.Length - 2 To 0 Step -1
            Push(hull, points, order(k), upperFrom)
        Next
        hull.RemoveAt(hull.Count - 1) ' the first point again
        DropStraightCorners(hull, points)
        Return hull.ToArray()
    End Function

    ''' <summary>Adds point i to a chain, first popping its last points (while it holds at least minCount) from which i does not turn left.</summary>
    Private Sub Push(hull As List(Of Integer), points As IReadOnlyList(Of Vector), i As Integer, minCount As Integer)
        While hull.Count >= minCount
            Dim a = points(hull(hull.Count - 2)), b = points(hull(hull.Count - 1))
            If Vector.Cross(b - a, points(i) - b) > 0 Then Exit While
            hull.RemoveAt(hull.Count - 1)
        End While
        hull.Add(i)
    End Sub

    ''' <summary>Removes corners that turn by less than <see cref="StraightTurn"/>, as the engine measures a turn (side into side).</summary>
    Private Sub DropStraightCorners(hull As List(Of Integer), points As IReadOnlyList(Of Vector))
        Dim changed = True
        While changed AndAlso hull.Count >= 3
            changed = False
            For k = 0 To hull.Count - 1
                Dim prev = points(hull((k + hull.Count - 1) Mod hull.Count)), here = points(hull(k)), nxt = points(hull((k + 1) Mod hull.Count))
                Dim e1 = here - prev, e2 = nxt - here
                If Vector.Cross(e1, e2) <= StraightTurn * e1.Length * e2.Length Then
                    hull.RemoveAt(k)
                    changed = True
                    Exit For
                End If
            Next
        End While
        If hull.Count < 3 Then hull.Clear()
    End Sub

    ''' <summary>Up to two indices of distinct points (too few for a hull).</summary>
    Private Function DistinctOf(points As IReadOnlyList(Of Vector), order As Integer()) As Integer()
        Dim result As New List(Of Integer)
        For Each i In order
            If result.All(Function(j) points(j) <> points(i)) Then result.Add(i)
        Next
        Return result.ToArray()
    End Function

    ''' <summary>The signed area of a polygon through the points in order, m²: positive when they turn anticlockwise (the shoelace formula).</summary>
    Public Function SignedArea(points As IReadOnlyList(Of Vector)) As Double
        If points Is Nothing Then Throw New ArgumentNullException(NameOf(points))
        Dim twice = 0.0
        For i = 0 To points.Count - 1
            twice += Vector.Cross(points(i), points((i + 1) Mod points.Count))
        Next
        Return twice / 2
    End Function

    ''' <summary>
    ''' Whether the points, in the order given, already go round a convex polygon (either way round):
    ''' every corner turns the same way, by at least <see cref="StraightTurn"/>, and once round in all.
    ''' </summary>
    Public Function IsConvexInOrder(points As IReadOnlyList(Of Vector)) As Boolean
        If points Is Nothing Then Throw New ArgumentNullException(NameOf(points))
        Dim n = points.Count
        If n < 3 Then Return False
        Dim sign = 0
        Dim turning = 0.0
        For i = 0 To n - 1
            Dim prev = points((i + n - 1) Mod n), here = points(i), nxt = points((i + 1) Mod n)
            Dim e1 = here - prev, e2 = nxt - here
            Dim c = Vector.Cross(e1, e2)
            If Math.Abs(c) <= StraightTurn * e1.Length * e2.Length Then Return False
            Dim s = Math.Sign(c)
            If sign = 0 Then sign = s
            If s <> sign Then Return False
            turning += Math.Atan2(Math.Abs(c), Vector.Dot(e1, e2))
        Next
        ' A star turns the same way at every corner but goes round twice.
        Return turning < 3 * Math.PI
    End Function

    ''' <summary>
    ''' The least width of a convex polygon, m: the narrowest gap between two parallel lines that hold
    ''' it (for a convex polygon one of them lies along a side, so each side is tried).
    ''' </summary>
    Public Function LeastWidth(corners As IReadOnlyList(Of Vector)) As Double
        If corners Is Nothing Then Throw New ArgumentNullException(NameOf(corners))
        Dim n = corners.Count
        If n < 3 Then Return 0
        Dim least = Double.PositiveInfinity
        For i = 0 To n - 1
            Dim a = corners(i), b = corners((i + 1) Mod n)
            Dim side = b - a
            Dim length = side.Length
            If Not (length > 0) Then Continue For
            Dim farthest = 0.0
            For Each c In corners
                farthest = Math.Max(farthest, Math.Abs(Vector.Cross(side, c - a)) / length)
            Next
            least = Math.Min(least, farthest)
        Next
        Return If(Double.IsPositiveInfinity(least), 0, least)
    End Function
End Module
