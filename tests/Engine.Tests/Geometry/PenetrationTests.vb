Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Geometry
    ''' <summary>Penetration depth and normal against brute-force distances to the boundary.</summary>
    Public Class PenetrationTests
        ''' <summary>Points spaced at most <paramref name="spacing"/> m apart along the core's boundary (its corners included).</summary>
        Private Shared Function BoundarySamples(k As Outline, spacing As Double) As List(Of Vector)
            Dim samples As New List(Of Vector)
            Dim m = k.VertexCount
            If m = 1 Then
                samples.Add(k.Vertices(0))
                Return samples
            End If
            For i = 0 To m - 1
                Dim a = k.Vertices(i), b = k.Vertices((i + 1) Mod m)
                Dim n = CInt(Math.Ceiling((b - a).Length / spacing))
                For s = 0 To n - 1
                    samples.Add(a + (s / n) * (b - a))
                Next
            Next
            Return samples
        End Function

        <Fact>
        Public Sub RandomPoints_DepthAndNormal_MatchTheNearestBoundarySample()
            Dim rng As New Random(5)
            Const Spacing = 0.0005
            For trial = 0 To 59
                Dim k = GeometryTestKit.RandomOutline(rng)
                Dim samples = BoundarySamples(k, Spacing)
                For q = 0 To 99
                    Dim d = New Vector(k.MinX - 0.5 + (k.MaxX - k.MinX + 1) * rng.NextDouble(), k.MinY - 0.5 + (k.MaxY - k.MinY + 1) * rng.NextDouble())
                    Dim c = OutlineContact.Penetration(k, d)
                    ' Nearest boundary sample, by brute force.
                    Dim nearest = samples(0), bestDist = Double.PositiveInfinity
                    For Each s In samples
                        Dim dist = (d - s).Length
                        If dist < bestDist Then bestDist = dist : nearest = s
                    Next
                    Dim inside = GeometryTestKit.SignedDistanceToCore(k.Vertices, d) < 0
                    Dim expectedDepth = k.Radius + If(inside, bestDist, -bestDist)
                    Assert.True(Math.Abs(c.Depth - expectedDepth) <= Spacing, $"trial {trial}: depth {c.Depth} vs sampled {expectedDepth}")
                    ' The same against the exact, independent distance function.
                    Assert.True(Math.Abs(c.Depth + GeometryTestKit.Gap(k, d)) <= 1.0E-12, $"trial {trial}: depth {c.Depth} vs exact {-GeometryTestKit.Gap(k, d)}")
                    Assert.True(Math.Abs(c.Normal.Length - 1) <= 1.0E-14)
                    ' Stepping from d back along the normal by the distance to the core lands on the core's boundary.
                    Dim onBoundary = d - (k.Radius - c.Depth) * c.Normal
                    Assert.True(Math.Abs(GeometryTestKit.SignedDistanceToCore(k.Vertices, onBoundary)) <= 1.0E-12, $"trial {trial}: foot of the normal is off the boundary")
                    ' Outside, the normal points from the nearest boundary point towards d.
                    If Not inside AndAlso bestDist > 0.05 Then
                        Dim sampled = (d - nearest) / bestDist
                        Assert.True((c.Normal - sampled).Length <= 0.02, $"trial {trial}: normal {c.Normal} vs sampled {sampled}")
                    End If
                Next
            Next
        End Sub

        <Fact>
        Public Sub InsideABox_LeavesThroughTheNearestFace()
            Dim k = Outline.Box(4, 2)
            Dim c = OutlineContact.Penetration(k, New Vector(3.5, 0.8))
            Assert.Equal(New Vector(1, 0), c.Normal)
            Assert.Equal(0.5, c.Depth, 15)
            c = OutlineContact.Penetration(k, New Vector(1.5, 1.7))
            Assert.Equal(New Vector(0, 1), c.Normal)
            Assert.Equal(2 - 1.7, c.Depth, 15)
        End Sub

        <Fact>
        Public Sub EquallyDeepBehindTwoEdgesOfACorner_TakesTheCornersBisector_InTheMirrorToo()
            ' Two unit boxes overlapping corner to corner by 0.1 m each way, and the mirror image.
            Dim k = Outline.MinkowskiDifference(Outline.Box(1, 1), Outline.Box(1, 1))
            Dim c = OutlineContact.Penetration(k, New Vector(-0.9, 0.9))
            Dim cm = OutlineContact.Penetration(k, New Vector(0.9, 0.9))
            Assert.Equal(-Math.Sqrt(0.5), c.Normal.X, 15)
            Assert.Equal(Math.Sqrt(0.5), c.Normal.Y, 15)
            Assert.Equal(-c.Normal.X, cm.Normal.X)
            Assert.Equal(c.Normal.Y, cm.Normal.Y)
            Assert.Equal(c.Depth, cm.Depth)
            Assert.Equal(0.1, c.Depth, 15)
            ' Exactly on the corner: touching, with the same normal.
            c = OutlineContact.Penetration(k, New Vector(-1, 1))
            Assert.Equal(0.0, c.Depth)
            Assert.Equal(-Math.Sqrt(0.5), c.Normal.X, 15)
            ' Not a tie: the nearer face.
            Assert.Equal(New Vector(0, 1), OutlineContact.Penetration(k, New Vector(-0.8, 0.9)).Normal)
        End Sub

        <Fact>
        Public Sub CircleOnCircle_MatchesCollider()
            Dim k = Outline.MinkowskiDifference(Outline.Point(0.3), Outline.Point(0.2))
            Dim d = New Vector(0.3, 0.2)
            Dim c = OutlineContact.Penetration(k, d)
            Dim reference = Collider.CircleCircle(d, 0.2, Vector.Zero, 0.3)
            Assert.Equal(reference.Depth, c.Depth, 15)
            Assert.Equal(reference.Normal.X, c.Normal.X, 15)
            Assert.Equal(reference.Normal.Y, c.Normal.Y, 15)
            ' Coincident: a fixed direction, no NaN.
            c = OutlineContact.Penetration(k, Vector.Zero)
            Assert.Equal(New Vector(0, 1), c.Normal)
            Assert.Equal(0.5, c.Depth, 15)
        End Sub

        <Fact>
        Public Sub OnASegment_EitherSide_AndBeyondItsEnds()
            Dim k = Outline.Segment(New Vector(0, 0), New Vector(2, 0))
            Assert.Equal(New Vector(0, 1), OutlineContact.Penetration(k, New Vector(1, 0.5)).Normal)
            Assert.Equal(New Vector(0, -1), OutlineContact.Penetration(k, New Vector(1, -0.5)).Normal)
            Dim beyond = OutlineContact.Penetration(k, New Vector(3, 0))
            Assert.Equal(New Vector(1, 0), beyond.Normal)
            Assert.Equal(-1.0, beyond.Depth, 15)
            ' Exactly on an end: the normal points straight out along the segment.
            Assert.Equal(New Vector(-1, 0), OutlineContact.Penetration(k, New Vector(0, 0)).Normal)
        End Sub
    End Class
End Namespace
