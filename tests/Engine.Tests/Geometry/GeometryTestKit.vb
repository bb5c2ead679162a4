Option Strict On
Imports PhysicsEngine

Namespace Geometry
    ''' <summary>
    ''' Random shapes and brute-force references for the outline tests. The references work from corner
    ''' lists alone (no normals, no edge lengths, nothing cached by <see cref="Outline"/>), so they do not
    ''' share the code under test. Metres and seconds throughout.
    ''' </summary>
    Public Module GeometryTestKit
        ''' <summary>The convex hull of the points, anticlockwise (Andrew's monotone chain), without collinear points.</summary>
        Public Function ConvexHull(points As IEnumerable(Of Vector)) As List(Of Vector)
            Dim pts = points.Distinct().OrderBy(Function(p) p.X).ThenBy(Function(p) p.Y).ToList()
            If pts.Count < 3 Then Return pts
            Dim hull As New List(Of Vector)
            For pass = 0 To 1
                Dim start = hull.Count
                For Each p In If(pass = 0, pts, Enumerable.Reverse(pts))
                    While hull.Count >= start + 2 AndAlso Vector.Cross(hull(hull.Count - 1) - hull(hull.Count - 2), p - hull(hull.Count - 1)) <= 0
                        hull.RemoveAt(hull.Count - 1)
                    End While
                    hull.Add(p)
                Next
                hull.RemoveAt(hull.Count - 1)
            Next
            Return hull
        End Function

        ''' <summary>A random convex polygon (≥ 3 corners, anticlockwise) about centre, within radius size (m).</summary>
        Public Function RandomConvex(rng As Random, centre As Vector, size As Double) As List(Of Vector)
            Do
                Dim n = rng.Next(3, 13)
                Dim stretch = 0.3 + rng.NextDouble()
                Dim pts As New List(Of Vector)
                For k = 1 To n
                    Dim angle = rng.NextDouble() * 2 * Math.PI
                    Dim r = size * Math.Sqrt(rng.NextDouble())
                    pts.Add(centre + New Vector(r * Math.Cos(angle) * stretch, r * Math.Sin(angle)))
                Next
                Dim hull = ConvexHull(pts)
                If hull.Count >= 3 AndAlso Math.Abs(SignedArea(hull)) > 0.01 * size * size Then Return hull
            Loop
        End Function

        ''' <summary>Twice the signed area of a closed polygon (positive anticlockwise).</summary>
        Public Function SignedArea(pts As IReadOnlyList(Of Vector)) As Double
            Dim a = 0.0
            For i = 0 To pts.Count - 1
                a += Vector.Cross(pts(i), pts((i + 1) Mod pts.Count))
            Next
            Return 0.5 * a
        End Function

        ''' <summary>
        ''' A random outline of any kind: a point with a radius, a segment, a box, a polygon, or a Minkowski
        ''' difference of two of those (which may be rounded). Its core lies within a few metres of the origin.
        ''' </summary>
        Public Function RandomOutline(rng As Random) As Outline
            Select Case rng.Next(6)
                Case 0 : Return Outline.Point(0.05 + 0.5 * rng.NextDouble())
                Case 1 : Return Outline.Segment(RandomPoint(rng, 1), RandomPoint(rng, 1))
                Case 2 : Return Outline.Box(0.1 + rng.NextDouble(), 0.1 + rng.NextDouble()).Translated(RandomPoint(rng, 0.5))
                Case 3 : Return Outline.Polygon(RandomConvex(rng, RandomPoint(rng, 0.5), 0.3 + rng.NextDouble()))
                Case Else : Return Outline.MinkowskiDifference(RandomBody(rng), RandomBody(rng))
            End Select
        End Function

        ''' <summary>A random body outline: point (radius &gt; 0), segment, box or polygon.</summary>
        Public Function RandomBody(rng As Random) As Outline
            Select Case rng.Next(4)
                Case 0 : Return Outline.Point(0.02 + 0.3 * rng.NextDouble()).Translated(RandomPoint(rng, 0.3))
                Case 1 : Return Outline.Segment(RandomPoint(rng, 0.7), RandomPoint(rng, 0.7))
                Case 2 : Return Outline.Box(0.1 + 0.6 * rng.NextDouble(), 0.1 + 0.6 * rng.NextDouble()).Translated(RandomPoint(rng, 0.3))
                Case Else : Return Outline.Polygon(RandomConvex(rng, RandomPoint(rng, 0.3), 0.2 + 0.5 * rng.NextDouble()))
            End Select
        End Function

        ''' <summary>A uniformly random point in the square [−size, size]² (m).</summary>
        Public Function RandomPoint(rng As Random, size As Double) As Vector
            Return New Vector(size * (2 * rng.NextDouble() - 1), size * (2 * rng.NextDouble() - 1))
        End Function

        ''' <summary>Distance (m) from d to the segment a–b.</summary>
        Public Function DistanceToSegment(d As Vector, a As Vector, b As Vector) As Double
            Dim e = b - a
            Dim s = Vector.Dot(d - a, e) / e.LengthSquared
            s = Math.Max(0, Math.Min(1, s))
            Return (d - (a + s * e)).Length
        End Function

        ''' <summary>
        ''' Signed distance (m) from d to a core given by its corners: positive outside, negative inside a
        ''' polygon (minus the distance to its boundary). The inside test uses the corners' cross products
        ''' directly, whatever their turning direction.
        ''' </summary>
        Public Function SignedDistanceToCore(corners As IReadOnlyList(Of Vector), d As Vector) As Double
            If corners.Count = 1 Then Return (d - corners(0)).Length
            If corners.Count = 2 Then Return DistanceToSegment(d, corners(0), corners(1))
            Dim dist = Double.PositiveInfinity
            Dim positive = 0, negative = 0
            For i = 0 To corners.Count - 1
                Dim a = corners(i), b = corners((i + 1) Mod corners.Count)
                dist = Math.Min(dist, DistanceToSegment(d, a, b))
                Dim c = Vector.Cross(b - a, d - a)
                If c > 0 Then positive += 1
                If c < 0 Then negative += 1
            Next
            Dim inside = positive = 0 OrElse negative = 0
            Return If(inside, -dist, dist)
        End Function

        ''' <summary>The gap (m) between d and the rounded shape: signed distance to the core minus R.</summary>
        Public Function Gap(k As Outline, d As Vector) As Double
            Return SignedDistanceToCore(k.Vertices, d) - k.Radius
        End Function

        ''' <summary>d(t) = d0 + dv t + ½ da t² (m).</summary>
        Public Function PathAt(d0 As Vector, dv As Vector, da As Vector, t As Double) As Vector
            Return d0 + t * dv + (0.5 * t * t) * da
        End Function

        ''' <summary>
        ''' Brute-force first entry of d(t) into the rounded shape over [0, tMax] s, by conservative
        ''' advancement: from a point with gap g the path cannot reach the shape in less than g / (its
        ''' fastest speed on the window), so stepping by that never steps over an entry. The step never
        ''' falls below tMax × 10⁻⁷ (so an entry shallower than that step's travel can be missed: a graze).
        ''' An entry is refined by bisection. A zero-thickness segment (R = 0) is entered when the path
        ''' crosses it. Returns +∞ when there is no entry in the window.
        ''' </summary>
        Public Function BruteEntry(k As Outline, d0 As Vector, dv As Vector, da As Vector, tMax As Double) As Double
            Dim speed = dv.Length + da.Length * tMax
            Dim minStep = tMax * 0.0000001
            Dim flat = k.VertexCount = 2 AndAlso k.Radius = 0
            Dim t = 0.0
            Dim g = Gap(k, d0)
            While t < tMax
                Dim t2 = Math.Min(tMax, t + Math.Max(g / speed, minStep))
                Dim g2 = Gap(k, PathAt(d0, dv, da, t2))
                If g2 <= 0 Then
                    Dim lo = t, hi = t2
                    For i = 1 To 200
                        Dim mid = 0.5 * (lo + hi)
                        If mid <= lo OrElse mid >= hi Then Exit For
                        If Gap(k, PathAt(d0, dv, da, mid)) > 0 Then lo = mid Else hi = mid
                    Next
                    Return lo
                End If
                If flat Then
                    Dim crossing = SegmentCrossing(k, d0, dv, da, t, t2)
                    If crossing < Double.PositiveInfinity Then Return crossing
                End If
                t = t2
                g = g2
            End While
            Return Double.PositiveInfinity
        End Function

        ''' <summary>Where the path crosses a zero-thickness segment between t and t2, if it does (bisection on the side).</summary>
        Private Function SegmentCrossing(k As Outline, d0 As Vector, dv As Vector, da As Vector, t As Double, t2 As Double) As Double
            Dim a = k.Vertices(0), b = k.Vertices(1)
            Dim e = b - a
            Dim side = Function(time As Double) Vector.Cross(e, PathAt(d0, dv, da, time) - a)
            Dim s1 = side(t), s2 = side(t2)
            If Math.Sign(s1) * Math.Sign(s2) > 0 OrElse s1 = 0 Then Return Double.PositiveInfinity
            Dim lo = t, hi = t2
            For i = 1 To 200
                Dim mid = 0.5 * (lo + hi)
                If mid <= lo OrElse mid >= hi Then Exit For
                If Math.Sign(side(mid)) = Math.Sign(s1) Then lo = mid Else hi = mid
            Next
            Dim along = Vector.Dot(PathAt(d0, dv, da, lo) - a, e) / e.LengthSquared
            Return If(along >= 0 AndAlso along <= 1, lo, Double.PositiveInfinity)
        End Function
    End Module
End Namespace
