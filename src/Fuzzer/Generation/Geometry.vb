Option Strict On

Namespace Generation
    ''' <summary>Distances and depths for placing bodies, by the scene reader's own formulas.</summary>
    Friend Module Geometry
        ''' <summary>
        ''' How deep a circle (centre x, y, radius r) reaches into the box [x0, x1] × [y0, y1], m (≤ 0 when
        ''' apart). A centre inside must travel to the nearest side and a radius more. The same formula as
        ''' the scene reader's overlap check, so what passes here passes there.
        ''' </summary>
        Friend Function CircleBoxDepth(x As Double, y As Double, r As Double, x0 As Double, y0 As Double, x1 As Double, y1 As Double) As Double
            If x > x0 AndAlso x < x1 AndAlso y > y0 AndAlso y < y1 Then
                Return r + Math.Min(Math.Min(x - x0, x1 - x), Math.Min(y - y0, y1 - y))
            End If
            Dim qx = Math.Min(Math.Max(x, x0), x1)
            Dim qy = Math.Min(Math.Max(y, y0), y1)
            Return r - Vector.Hypot(x - qx, y - qy)
        End Function

        ''' <summary>Distance from point p to the segment from a to b, m.</summary>
        Friend Function PointSegmentDistance(p As Vector, a As Vector, b As Vector) As Double
            Dim ab = b - a
            Dim len2 = ab.LengthSquared
            Dim u = If(len2 > 0, Math.Min(Math.Max(Vector.Dot(p - a, ab) / len2, 0.0), 1.0), 0.0)
            Return (p - (a + ab * u)).Length
        End Function

        ''' <summary>
        ''' The centre of area of a convex polygon, m, as the engine finds it (a polygon body's reference point): a rod's
        ''' "length" written as the distance between its ends must be the distance the reader measures, to 10⁻⁹ m. The
        ''' shoelace formula from the origin, 1 km out, was 1.6·10⁻⁶ m off the engine's.
        ''' </summary>
        Friend Function Centroid(vertices As IReadOnlyList(Of Vector)) As Vector
            Return Polygon.CreateFixed(vertices).CentreOfMass
        End Function

        ''' <summary>True when every turn of the closed polygon goes the same way and none is straight (strictly convex, area &gt; 0).</summary>
        Friend Function IsStrictlyConvex(vertices As IReadOnlyList(Of Vector)) As Boolean
            If vertices.Count < 3 Then Return False
            Dim sign = 0
            For i = 0 To vertices.Count - 1
                Dim a = vertices(i)
                Dim b = vertices((i + 1) Mod vertices.Count)
                Dim c = vertices((i + 2) Mod vertices.Count)
                Dim turn = Vector.Cross(b - a, c - b)
                If turn = 0 Then Return False
                Dim s = Math.Sign(turn)
                If sign = 0 Then sign = s
                If s <> sign Then Return False
            Next
            Return True
        End Function
    End Module
End Namespace
