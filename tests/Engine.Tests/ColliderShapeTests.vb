Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' The general contact of any two shapes (<see cref="Collider.OutlineOutline(Outline, Vector, Outline, Vector)"/>),
''' its path-aware form against a fixed body (<see cref="Collider.OutlineOutlineFrom(Outline, Vector, Outline, Vector, Vector)"/>)
''' and the walls, against closed forms and against the circle functions they generalise.
''' </summary>
Public Class ColliderShapeTests
    <Fact>
    Public Sub GeneralContact_AgreesWithTheCircleFunctions_OutsideTheCore()
        ' Circle–circle and circle–rectangle in closed form, against the Minkowski difference, at random points.
        Dim rng As New Random(5)
        Dim disc = Outline.Point(0.3)
        Dim box = Outline.Box(2.0, 1.0)
        For k = 1 To 2000
            Dim p = New Vector(6 * rng.NextDouble() - 2, 4 * rng.NextDouble() - 1.5)
            Dim r = 0.05 + 0.5 * rng.NextDouble()
            Dim ball = Outline.Point(r)
            Dim cc = Collider.CircleCircle(p, r, New Vector(0.4, 0.2), 0.3)
            Dim general = Collider.OutlineOutline(ball, p, disc, New Vector(0.4, 0.2))
            Assert.Equal(cc.Depth, general.Depth, 12)
            Assert.True((cc.Normal - general.Normal).Length < 1.0E-12)
            ' Against the rectangle [0, 2] × [0, 1], with the centre outside it (inside, the closed form
            ' and the general one may pick different faces at equal depth only on the diagonals).
            If p.X > 0 AndAlso p.X < 2 AndAlso p.Y > 0 AndAlso p.Y < 1 Then Continue For
            Dim cr = Collider.CircleRectangle(p, r, Vector.Zero, New Vector(2, 1))
            Dim g = Collider.OutlineOutline(ball, p, box, Vector.Zero)
            Assert.Equal(cr.Depth, g.Depth, 12)
            Assert.True((cr.Normal - g.Normal).Length < 1.0E-12, $"at {p}: {cr.Normal} and {g.Normal}")
        Next
    End Sub

    <Fact>
    Public Sub TwoBoxes_TouchFaceToFace_WithTheFaceNormal_AndTheOverlapAsDepth()
        ' Box A (0.4 × 0.2) at x = 1.95 overlaps box B ([1, 2] × [0, 1]) by 0.05 from the right.
        Dim a = Outline.Box(0.4, 0.2), b = Outline.Box(1.0, 1.0)
        Dim c = Collider.OutlineOutline(a, New Vector(1.95, 0.3), b, New Vector(1, 0))
        Assert.Equal(New Vector(1, 0), c.Normal)
        Assert.Equal(0.05, c.Depth, 12)
        ' Apart by 0.1 above: a negative depth, the top face's normal.
        Dim apart = Collider.OutlineOutline(a, New Vector(1.2, 1.1), b, New Vector(1, 0))
        Assert.Equal(New Vector(0, 1), apart.Normal)
        Assert.Equal(-0.1, apart.Depth, 12)
    End Sub

    <Fact>
    Public Sub CircleOnASlopeSegment_GetsTheSlopeNormal_AndAtItsEnd_TheLineFromTheEnd()
        Dim theta = Math.PI / 6
        Dim segment = Outline.Segment(Vector.Zero, 3 * New Vector(Math.Cos(theta), -Math.Sin(theta)))
        Dim normal = New Vector(Math.Sin(theta), Math.Cos(theta))
        Dim ball = Outline.Point(0.1)
        Dim c = Collider.OutlineOutline(ball, 1.0 * New Vector(Math.Cos(theta), -Math.Sin(theta)) + 0.08 * normal, segment, Vector.Zero)
        Assert.Equal(0.02, c.Depth, 12)
        Assert.True((c.Normal - normal).Length < 1.0E-12)
        ' Beyond the upper end, off-centre: the normal runs from the end to the centre.
        Dim p = New Vector(-0.06, 0.05)
        Dim atEnd = Collider.OutlineOutline(ball, p, segment, Vector.Zero)
        Assert.Equal(0.1 - p.Length, atEnd.Depth, 12)
        Assert.True((atEnd.Normal - p / p.Length).Length < 1.0E-12)
    End Sub

    <Fact>
    Public Sub CircleWhoseCentreCrossedASegment_LeavesByTheSideItCameFrom()
        ' A horizontal segment; the centre came down from above and is now 0.03 below it.
        Dim segment = Outline.Segment(Vector.Zero, New Vector(2, 0))
        Dim ball = Outline.Point(0.05)
        Dim p = New Vector(1, -0.03)
        Dim nearest = Collider.OutlineOutline(ball, p, segment, Vector.Zero)
        Assert.Equal(New Vector(0, -1), nearest.Normal)
        Dim fromAbove = Collider.OutlineOutlineFrom(ball, p, segment, Vector.Zero, New Vector(1, 0.2))
        Assert.Equal(0.0, fromAbove.Normal.X, 12)
        Assert.Equal(1.0, fromAbove.Normal.Y, 12)
        Assert.Equal(0.05 + 0.03, fromAbove.Depth, 12)
        ' Right through and far beyond (10 m in one step): still back to the side it came from.
        Dim through = Collider.OutlineOutlineFrom(ball, New Vector(1, -10), segment, Vector.Zero, New Vector(1, 0.2))
        Assert.Equal(1.0, through.Normal.Y, 12)
        Assert.Equal(10.05, through.Depth, 9)
        ' A path that never reached the segment itself: the nearest point, as without a path.
        Dim grazing = Collider.OutlineOutlineFrom(ball, New Vector(1, 0.04), segment, Vector.Zero, New Vector(1, 0.2))
        Assert.Equal(0.01, grazing.Depth, 12)
        Assert.Equal(1.0, grazing.Normal.Y, 12)
    End Sub

    <Fact>
    Public Sub BoxThatEnteredAThinPlateFromAbove_LeavesUpwards_NotByTheNearestFace()
        ' A 0.1 m thick plate [0, 2] × [0, 0.1]; a 0.2 m box came down from above and is now at
        ' y ∈ [−0.15, 0.05]: out through the bottom is 0.05 away, but it came in through the top, 0.25 up.
        Dim plate = Outline.Box(2.0, 0.1)
        Dim box = Outline.Box(0.2, 0.2)
        Dim p = New Vector(0.9, -0.15)
        Dim nearest = Collider.OutlineOutline(box, p, plate, Vector.Zero)
        Assert.Equal(New Vector(0, -1), nearest.Normal)
        Assert.Equal(0.05, nearest.Depth, 12)
        Dim fromAbove = Collider.OutlineOutlineFrom(box, p, plate, Vector.Zero, New Vector(0.9, 0.3))
        Assert.Equal(New Vector(0, 1), fromAbove.Normal)
        Assert.Equal(0.25, fromAbove.Depth, 12)
        ' At x ∈ [0.1, 0.3], y ∈ [−0.05, 0.15], having come in through the left face: 0.15 up or down
        ' would be nearer, but it goes back out to the left, 0.3.
        Dim q = New Vector(0.1, -0.05)
        Assert.Equal(0.15, Collider.OutlineOutline(box, q, plate, Vector.Zero).Depth, 12)
        Dim fromLeft = Collider.OutlineOutlineFrom(box, q, plate, Vector.Zero, New Vector(-0.5, -0.05))
        Assert.Equal(New Vector(-1, 0), fromLeft.Normal)
        Assert.Equal(0.3, fromLeft.Depth, 12)
    End Sub

    <Fact>
    Public Sub PathThatStartedInside_GetsTheNearestWayOut()
        Dim plate = Outline.Box(2.0, 0.1)
        Dim box = Outline.Box(0.2, 0.2)
        Dim p = New Vector(0.9, -0.15)
        Dim startedInside = Collider.OutlineOutlineFrom(box, p, plate, Vector.Zero, New Vector(0.9, -0.12))
        Dim nearest = Collider.OutlineOutline(box, p, plate, Vector.Zero)
        Assert.Equal(nearest.Normal, startedInside.Normal)
        Assert.Equal(nearest.Depth, startedInside.Depth, 15)
    End Sub

    <Fact>
    Public Sub ContactFrom_ForCirclesAgainstRectanglesAndCircles_MatchesTheClosedForms()
        ' The general rule reduces to CircleRectangleFrom and CircleCircleFrom: random paths, sometimes
        ' right through.
        Dim rng As New Random(8)
        Dim rect = Outline.Box(1.0, 0.2)
        Dim disc = Outline.Point(0.4)
        Dim compared = 0
        For k = 1 To 3000
            Dim r = 0.02 + 0.1 * rng.NextDouble()
            Dim ball = Outline.Point(r)
            Dim from = New Vector(3 * rng.NextDouble() - 1, 2 * rng.NextDouble() - 0.9)
            Dim p = from + New Vector(2 * rng.NextDouble() - 1, 2 * rng.NextDouble() - 1)
            Dim closed = Collider.CircleRectangleFrom(p, r, Vector.Zero, New Vector(1, 0.2), from)
            Dim general = Collider.OutlineOutlineFrom(ball, p, rect, Vector.Zero, from)
            If closed.Depth > 0 Then
                compared += 1
                Assert.Equal(closed.Depth, general.Depth, 9)
                Assert.True((closed.Normal - general.Normal).Length < 1.0E-9, $"from {from} to {p}: {closed.Normal} and {general.Normal}")
            End If
            Dim closedDisc = Collider.CircleCircleFrom(p, r, New Vector(0.5, 0.1), 0.4, from)
            Dim generalDisc = Collider.OutlineOutlineFrom(ball, p, disc, New Vector(0.5, 0.1), from)
            If closedDisc.Depth > 0 Then
                Assert.Equal(closedDisc.Depth, generalDisc.Depth, 9)
                Assert.True((closedDisc.Normal - generalDisc.Normal).Length < 1.0E-9, $"from {from} to {p}: {closedDisc.Normal} and {generalDisc.Normal}")
            End If
        Next
        Assert.True(compared > 300, $"only {compared} contacts")
    End Sub

    <Fact>
    Public Sub OutlineWall_UsesTheOutlinesExtents()
        ' A triangle with corners (0, 0), (0.3, 0), (0.1, 0.4) about its centroid.
        Dim tri = Outline.Polygon({New Vector(0, 0), New Vector(0.3, 0), New Vector(0.1, 0.4)})
        Dim centred = tri.Translated(-tri.Centroid)
        Dim p = New Vector(0.05, 0.1)
        Dim left = Collider.OutlineWall(p, centred, WallSide.Left, 2, 1)
        Assert.Equal(New Vector(1, 0), left.Normal)
        Assert.Equal(-(p.X + centred.MinX), left.Depth, 15)
        Dim bottom = Collider.OutlineWall(p, centred, WallSide.Bottom, 2, 1)
        Assert.Equal(New Vector(0, 1), bottom.Normal)
        Assert.Equal(-(p.Y + centred.MinY), bottom.Depth, 15)
        Dim right = Collider.OutlineWall(New Vector(1.9, 0.5), centred, WallSide.Right, 2, 1)
        Assert.Equal(New Vector(-1, 0), right.Normal)
        Assert.Equal(1.9 + centred.MaxX - 2, right.Depth, 15)
        Dim top = Collider.OutlineWall(New Vector(1, 0.8), centred, WallSide.Top, 2, 1)
        Assert.Equal(New Vector(0, -1), top.Normal)
        Assert.Equal(0.8 + centred.MaxY - 1, top.Depth, 15)
        ' A circle: the same as CircleWall.
        Dim ball = Outline.Point(0.1)
        For Each side In {WallSide.Left, WallSide.Right, WallSide.Bottom, WallSide.Top}
            Assert.Equal(Collider.CircleWall(New Vector(0.05, 0.93), 0.1, side, 2, 1).Depth, Collider.OutlineWall(New Vector(0.05, 0.93), ball, side, 2, 1).Depth, 15)
        Next
    End Sub

    <Fact>
    Public Sub OutlineCore_DropsTheRounding()
        Dim c = Collider.OutlineCore(Outline.Point(0.3))
        Assert.Equal(0.0, c.Radius)
        Assert.Equal(1, c.VertexCount)
        Dim box = Outline.Box(1, 2)
        Assert.Same(box, Collider.OutlineCore(box))
        Dim rounded = Outline.MinkowskiDifference(box, Outline.Point(0.1))
        Dim core = Collider.OutlineCore(rounded)
        Assert.Equal(0.0, core.Radius)
        Assert.Equal(rounded.Vertices, core.Vertices)
    End Sub

    <Fact>
    Public Sub BoxBoxDepth_IsTheSmallerOverlap_ZeroWhenTouching_NegativeWhenApart()
        Assert.Equal(0.1, Collider.BoxBoxDepth(New Vector(0, 0), New Vector(1, 1), New Vector(0.9, 0.5), New Vector(2, 2)), 12)
        Assert.Equal(0.0, Collider.BoxBoxDepth(New Vector(0, 0), New Vector(1, 1), New Vector(1, 0.2), New Vector(2, 0.8)), 12)
        Assert.Equal(-0.5, Collider.BoxBoxDepth(New Vector(0, 0), New Vector(1, 1), New Vector(1.5, 0), New Vector(2, 1)), 12)
        ' Symmetric in the two boxes.
        Assert.Equal(Collider.BoxBoxDepth(New Vector(0.9, 0.5), New Vector(2, 2), New Vector(0, 0), New Vector(1, 1)),
                     Collider.BoxBoxDepth(New Vector(0, 0), New Vector(1, 1), New Vector(0.9, 0.5), New Vector(2, 2)))
    End Sub
End Class
