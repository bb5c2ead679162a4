Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Geometry
    ''' <summary>The outline factories, their validation, and the area, centroid and extents against closed forms and brute force.</summary>
    Public Class OutlineTests
        <Fact>
        Public Sub Box_HasItsCornersAnticlockwise_FromTheLowerLeft_WithExactNormals()
            Dim b = Outline.Box(2, 1)
            Assert.Equal({New Vector(0, 0), New Vector(2, 0), New Vector(2, 1), New Vector(0, 1)}, b.Vertices.ToArray())
            Assert.Equal({New Vector(0, -1), New Vector(1, 0), New Vector(0, 1), New Vector(-1, 0)}, b.Normals.ToArray())
            Assert.Equal(0.0, b.Radius)
            Assert.Equal(2.0, b.Area, 15)
            Assert.Equal(New Vector(1, 0.5), b.Centroid)
            Assert.Equal(0.0, b.MinX) : Assert.Equal(2.0, b.MaxX) : Assert.Equal(0.0, b.MinY) : Assert.Equal(1.0, b.MaxY)
        End Sub

        <Fact>
        Public Sub Point_IsACircle()
            Dim p = Outline.Point(0.25)
            Assert.Equal(1, p.VertexCount)
            Assert.Equal(0, p.EdgeCount)
            Assert.Equal(Math.PI * 0.0625, p.Area, 15)
            Assert.Equal(Vector.Zero, p.Centroid)
            Assert.Equal(-0.25, p.MinX) : Assert.Equal(0.25, p.MaxX) : Assert.Equal(-0.25, p.MinY) : Assert.Equal(0.25, p.MaxY)
            Dim moved = p.Translated(New Vector(1, 2))
            Assert.Equal(New Vector(1, 2), moved.Centroid)
            Assert.Equal(0.75, moved.MinX)
        End Sub

        <Fact>
        Public Sub Segment_HasTwoOppositeSides_AndItsMidpointAsCentroid()
            Dim s = Outline.Segment(New Vector(0, 0), New Vector(3, 4))
            Assert.Equal(2, s.VertexCount)
            Assert.Equal(2, s.EdgeCount)
            ' Edge 0 faces the right of a → b, edge 1 the left.
            Assert.Equal(0.8, s.Normals(0).X, 15) : Assert.Equal(-0.6, s.Normals(0).Y, 15)
            Assert.Equal(-0.8, s.Normals(1).X, 15) : Assert.Equal(0.6, s.Normals(1).Y, 15)
            Assert.Equal(New Vector(1.5, 2), s.Centroid)
            Assert.Equal(0.0, s.Area)
        End Sub

        <Fact>
        Public Sub Polygon_ClockwiseInput_ComesOutAnticlockwise_WithOutwardUnitNormals()
            Dim cw = {New Vector(0, 0), New Vector(0, 2), New Vector(3, 2), New Vector(3, 0)}
            Dim p = Outline.Polygon(cw)
            Assert.True(GeometryTestKit.SignedArea(p.Vertices) > 0)
            Assert.Equal(6.0, p.Area, 14)
            For i = 0 To p.EdgeCount - 1
                Dim a = p.Vertices(i), b = p.Vertices((i + 1) Mod p.VertexCount)
                Dim n = p.Normals(i)
                Assert.Equal(1.0, n.Length, 15)
                Assert.Equal(0.0, Vector.Dot(n, b - a), 14)
                ' Outward: the centre is behind every edge.
                Assert.True(Vector.Dot(n, p.Centroid - a) < 0)
            Next
        End Sub

        <Fact>
        Public Sub Polygon_DropsDuplicates_AndCollinearMiddleCorners()
            Dim p = Outline.Polygon({New Vector(0, 0), New Vector(0, 0), New Vector(1, 0), New Vector(2, 0),
                                     New Vector(2, 2), New Vector(1, 2), New Vector(0, 2), New Vector(0, 0)})
            Assert.Equal(4, p.VertexCount)
            Assert.Equal(4.0, p.Area, 15)
            Assert.DoesNotContain(New Vector(1, 0), p.Vertices)
            Assert.DoesNotContain(New Vector(1, 2), p.Vertices)
        End Sub

        <Fact>
        Public Sub Polygon_RejectsBadInput()
            ' Too few corners, all on a line, not convex, a star that turns left everywhere, a spike, NaN.
            Assert.Throws(Of ArgumentException)(Function() Outline.Polygon({New Vector(0, 0), New Vector(1, 0)}))
            Assert.Throws(Of ArgumentException)(Function() Outline.Polygon({New Vector(0, 0), New Vector(1, 0), New Vector(1, 0)}))
            Assert.Throws(Of ArgumentException)(Function() Outline.Polygon({New Vector(0, 0), New Vector(1, 1), New Vector(2, 2)}))
            Assert.Throws(Of ArgumentException)(Function() Outline.Polygon({New Vector(0, 0), New Vector(2, 0), New Vector(1, 0.5), New Vector(2, 2), New Vector(0, 2)}))
            Dim star = Enumerable.Range(0, 5).Select(Function(k) New Vector(Math.Cos(k * 4 * Math.PI / 5), Math.Sin(k * 4 * Math.PI / 5))).ToArray()
            Assert.Throws(Of ArgumentException)(Function() Outline.Polygon(star))
            Assert.Throws(Of ArgumentException)(Function() Outline.Polygon({New Vector(0, 0), New Vector(2, 0), New Vector(1, 0), New Vector(1, 1)}))
            Assert.Throws(Of ArgumentException)(Function() Outline.Polygon({New Vector(0, 0), New Vector(Double.NaN, 0), New Vector(1, 1)}))
            Assert.Throws(Of ArgumentException)(Function() Outline.Segment(New Vector(1, 1), New Vector(1, 1)))
            Assert.Throws(Of ArgumentOutOfRangeException)(Function() Outline.Box(0, 1))
            Assert.Throws(Of ArgumentOutOfRangeException)(Function() Outline.Point(-1))
        End Sub

        <Fact>
        Public Sub Triangle_CentroidIsTheMeanOfItsCorners()
            Dim a = New Vector(1, 1), b = New Vector(4, 1.5), c = New Vector(2, 5)
            Dim p = Outline.Polygon({a, b, c})
            Dim expected = (a + b + c) / 3
            Assert.Equal(expected.X, p.Centroid.X, 14)
            Assert.Equal(expected.Y, p.Centroid.Y, 14)
            Assert.Equal(0.5 * Math.Abs(Vector.Cross(b - a, c - a)), p.Area, 14)
            ' Relative to its centroid, the centroid is the origin.
            Dim centred = p.Translated(-p.Centroid)
            Assert.Equal(0.0, centred.Centroid.X, 14)
            Assert.Equal(0.0, centred.Centroid.Y, 14)
        End Sub

        <Fact>
        Public Sub RoundedShapes_AreaCentroidAndExtents_MatchAGridCount()
            ' Count grid cells whose centres lie within R of the core (an independent distance function).
            Dim rng As New Random(11)
            For trial = 0 To 11
                Dim k = Outline.MinkowskiDifference(GeometryTestKit.RandomBody(rng), GeometryTestKit.RandomBody(rng))
                Const Cells = 700
                Dim w = k.MaxX - k.MinX, h = k.MaxY - k.MinY
                ' A sliver (two nearly parallel segments) is too thin for the grid to measure.
                If k.Area < 0.05 * w * h Then Continue For
                Dim cellArea = w * h / (Cells * Cells)
                Dim count = 0
                Dim sx = 0.0, sy = 0.0
                Dim xlo = Double.PositiveInfinity, xhi = Double.NegativeInfinity, ylo = Double.PositiveInfinity, yhi = Double.NegativeInfinity
                For i = 0 To Cells - 1
                    For j = 0 To Cells - 1
                        Dim p = New Vector(k.MinX + (i + 0.5) * w / Cells, k.MinY + (j + 0.5) * h / Cells)
                        If GeometryTestKit.Gap(k, p) <= 0 Then
                            count += 1 : sx += p.X : sy += p.Y
                            xlo = Math.Min(xlo, p.X) : xhi = Math.Max(xhi, p.X) : ylo = Math.Min(ylo, p.Y) : yhi = Math.Max(yhi, p.Y)
                        End If
                    Next
                Next
                Dim area = count * cellArea
                Dim size = Math.Max(w, h)
                Assert.True(Math.Abs(area - k.Area) <= 0.01 * k.Area, $"trial {trial}: area {k.Area} vs grid {area}")
                Assert.True(Math.Abs(sx / count - k.Centroid.X) <= 0.003 * size, $"trial {trial}: centroid x {k.Centroid.X} vs grid {sx / count}")
                Assert.True(Math.Abs(sy / count - k.Centroid.Y) <= 0.003 * size, $"trial {trial}: centroid y {k.Centroid.Y} vs grid {sy / count}")
                ' The extents are tight: the shape reaches within a cell of each side.
                Dim cell = size / Cells
                Assert.True(xlo - k.MinX <= cell AndAlso k.MaxX - xhi <= cell AndAlso ylo - k.MinY <= cell AndAlso k.MaxY - yhi <= cell)
            Next
        End Sub
    End Class
End Namespace
