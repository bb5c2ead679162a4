Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Geometry
    ''' <summary>
    ''' core_b ⊕ (−core_a) checked through its support function h(u) = max over the set of u·x, which for a
    ''' Minkowski sum is the sum of the parts' support functions: h_K(u) = h_B(u) + h_A(−u). Two convex
    ''' sets with the same support function in every direction are the same set.
    ''' </summary>
    Public Class MinkowskiDifferenceTests
        Private Shared Function Support(points As IEnumerable(Of Vector), u As Vector) As Double
            Return points.Max(Function(p) Vector.Dot(p, u))
        End Function

        <Fact>
        Public Sub RandomPairs_HaveTheSupportOfTheSum_AndAreConvexAnticlockwise_WithFewCorners()
            Dim rng As New Random(2024)
            Dim parallelogramsSeen = 0
            For trial = 0 To 1999
                Dim a = GeometryTestKit.RandomBody(rng), b = GeometryTestKit.RandomBody(rng)
                If trial Mod 7 = 0 Then
                    ' Two boxes: every edge of one is parallel to an edge of the other, and they merge.
                    a = Outline.Box(0.1 + rng.NextDouble(), 0.1 + rng.NextDouble()).Translated(GeometryTestKit.RandomPoint(rng, 1))
                    b = Outline.Box(0.1 + rng.NextDouble(), 0.1 + rng.NextDouble()).Translated(GeometryTestKit.RandomPoint(rng, 1))
                End If
                Dim k = Outline.MinkowskiDifference(b, a)
                Assert.Equal(a.Radius + b.Radius, k.Radius)
                Assert.True(k.VertexCount <= a.VertexCount + b.VertexCount, $"trial {trial}: {k.VertexCount} corners from {a.VertexCount} + {b.VertexCount}")
                ' Directions: a fan, plus every edge normal of both parts (where parallel edges merge).
                Dim dirs As New List(Of Vector)
                For s = 0 To 359
                    dirs.Add(New Vector(Math.Cos(s * Math.PI / 180 + 0.001), Math.Sin(s * Math.PI / 180 + 0.001)))
                Next
                For Each n In a.Normals.Concat(b.Normals)
                    dirs.Add(n) : dirs.Add(-n)
                Next
                For Each u In dirs
                    Dim expected = Support(b.Vertices, u) + Support(a.Vertices.Select(Function(v) -v), u)
                    Assert.True(Math.Abs(Support(k.Vertices, u) - expected) <= 1.0E-13, $"trial {trial}: support along {u}: {Support(k.Vertices, u)} vs {expected}")
                Next
                CheckConvexAnticlockwise(k, trial)
                If a.VertexCount = 2 AndAlso b.VertexCount = 2 AndAlso k.VertexCount = 4 Then parallelogramsSeen += 1
                If trial Mod 7 = 0 Then Assert.Equal(4, k.VertexCount)
            Next
            Assert.True(parallelogramsSeen > 10)
        End Sub

        ''' <summary>Corners anticlockwise and strictly convex; normals unit, along the edges' outward sides.</summary>
        Private Shared Sub CheckConvexAnticlockwise(k As Outline, trial As Integer)
            Dim m = k.VertexCount
            If m = 1 Then
                Assert.Equal(0, k.EdgeCount)
                Return
            End If
            Assert.Equal(m, k.EdgeCount)
            For i = 0 To m - 1
                Dim a = k.Vertices(i), b = k.Vertices((i + 1) Mod m), c = k.Vertices((i + 2) Mod m)
                Dim n = k.Normals(i)
                Assert.True(Math.Abs(n.Length - 1) <= 1.0E-15)
                Assert.True(Math.Abs(Vector.Dot(n, b - a)) <= 1.0E-13 * (b - a).Length, $"trial {trial}: normal {i} not across its edge")
                If m >= 3 Then
                    Assert.True(Vector.Cross(b - a, c - b) > 0, $"trial {trial}: corner {(i + 1) Mod m} does not turn left")
                    For Each v In k.Vertices
                        Assert.True(Vector.Dot(n, v - a) <= 1.0E-13, $"trial {trial}: a corner lies outside edge {i}")
                    Next
                End If
            Next
            If m = 2 Then Assert.Equal(-k.Normals(0), k.Normals(1))
        End Sub

        <Fact>
        Public Sub TwoBoxes_GiveTheBoxOfSummedSizes_WithMergedEdges()
            ' B = [0, 2] × [0, 1], A = [0, 1] × [0, 1]: B ⊕ (−A) = [−1, 2] × [−1, 1].
            Dim k = Outline.MinkowskiDifference(Outline.Box(2, 1), Outline.Box(1, 1))
            Assert.Equal({New Vector(-1, -1), New Vector(2, -1), New Vector(2, 1), New Vector(-1, 1)}, k.Vertices.ToArray())
            Assert.Equal({New Vector(0, -1), New Vector(1, 0), New Vector(0, 1), New Vector(-1, 0)}, k.Normals.ToArray())
            Assert.Equal(0.0, k.Radius)
        End Sub

        <Fact>
        Public Sub DegenerateSums_PointPointSegmentParallelogram()
            Dim p = Outline.MinkowskiDifference(Outline.Point(0.1).Translated(New Vector(1, 2)), Outline.Point(0.2).Translated(New Vector(0.5, 0.5)))
            Assert.Equal({New Vector(0.5, 1.5)}, p.Vertices.ToArray())
            Assert.Equal(0.2 + 0.1, p.Radius)

            ' A circle against a segment: the segment moved by −centre, rounded by the radius (a capsule).
            Dim capsule = Outline.MinkowskiDifference(Outline.Segment(New Vector(0, 0), New Vector(2, 0)), Outline.Point(0.1).Translated(New Vector(1, 1)))
            Assert.Equal(2, capsule.VertexCount)
            Assert.Equal(0.1, capsule.Radius)
            Assert.Contains(New Vector(-1, -1), capsule.Vertices)
            Assert.Contains(New Vector(1, -1), capsule.Vertices)

            ' Two parallel segments: a longer segment.
            Dim longer = Outline.MinkowskiDifference(Outline.Segment(New Vector(0, 0), New Vector(2, 0)), Outline.Segment(New Vector(0, 0), New Vector(1, 0)))
            Assert.Equal(2, longer.VertexCount)
            Assert.Contains(New Vector(-1, 0), longer.Vertices)
            Assert.Contains(New Vector(2, 0), longer.Vertices)

            ' Two crossing segments: a parallelogram.
            Dim para = Outline.MinkowskiDifference(Outline.Segment(New Vector(0, 0), New Vector(2, 0)), Outline.Segment(New Vector(0, 0), New Vector(1, 1)))
            Assert.Equal(4, para.VertexCount)
            Assert.Equal(2.0, para.Area, 14)
        End Sub
    End Class
End Namespace
