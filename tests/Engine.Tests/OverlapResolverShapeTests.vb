Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' The overlap resolver on pairs of every kind: after it no pair that collides overlaps by more than the
''' tolerance, fixed bodies and the dragged body have not moved, a pair is pushed apart in proportion to
''' inverse mass (its centre of mass stays put), and the result is deterministic and finite.
''' </summary>
Public Class OverlapResolverShapeTests
    Private Const Tolerance As Double = 1.0E-12

    Private Shared Function Deepest(w As World) As Double
        Dim worst = Double.NegativeInfinity
        Dim bodies = w.Bodies
        For i = 0 To bodies.Count - 1
            For j = i + 1 To bodies.Count - 1
                If bodies(i).IsFixed AndAlso bodies(j).IsFixed Then Continue For
                worst = Math.Max(worst, Collider.OutlineOutline(bodies(i).Outline, bodies(i).Position, bodies(j).Outline, bodies(j).Position).Depth)
            Next
        Next
        Return worst
    End Function

    ''' <summary>Every kind overlapping every other, and two bodies on the very same spot.</summary>
    Private Shared Function Tangle() As World
        Dim w As New World(4.0, 3.0, 9.81, 0.5)
        w.Add(New Segment(New Vector(0.5, 0.5), New Vector(2.0, 1.0), "ramp"))
        w.Add(Polygon.CreateFixed({New Vector(2.5, 0), New Vector(3.5, 0), New Vector(3.0, 0.8)}, "wedge"))
        w.Add(New Rectangle(New Vector(0, 2.0), 1.0, 0.2, "shelf"))
        w.Add(Circle.CreateFixed(New Vector(3.5, 2.0), 0.2, "peg"))
        w.Add(New Circle(New Vector(1.2, 0.76), 0.1, 1.0, id:="ball"))                    ' across the ramp
        w.Add(Rectangle.CreateMovable(New Vector(2.9, 0.5), 0.3, 0.3, 2.0, id:="box"))    ' in the wedge
        w.Add(New Polygon({New Vector(2.8, 0.6), New Vector(3.2, 0.6), New Vector(3.0, 1.0)}, 3.0, id:="tri")) ' in both
        w.Add(Rectangle.CreateMovable(New Vector(0.4, 1.95), 0.2, 0.2, 1.0, id:="crate")) ' in the shelf
        w.Add(New Circle(New Vector(3.4, 1.9), 0.15, 0.5, id:="pegged"))                  ' in the peg
        ' A box and a polygon whose reference points coincide.
        w.Add(Rectangle.CreateMovable(New Vector(1.9, 2.4), 0.2, 0.2, 1.0, id:="same1"))
        w.Add(New Polygon({New Vector(1.9, 2.4), New Vector(2.1, 2.4), New Vector(2.1, 2.6), New Vector(1.9, 2.6)}, 1.0, id:="same2"))
        Return w
    End Function

    <Fact>
    Public Sub MixedPairs_AreSeparated_FixedBodiesStay_AndEverythingStaysInside()
        Dim w = Tangle()
        Assert.True(Deepest(w) > 0.05)
        Dim fixedBefore = w.Bodies.Where(Function(b) b.IsFixed).Select(Function(b) b.Position).ToList()
        Dim left = OverlapResolver.Resolve(w, Tolerance)
        Assert.True(left <= Tolerance, $"{left} m left")
        Assert.True(Deepest(w) <= Tolerance, $"deepest overlap {Deepest(w)} m")
        Assert.Equal(fixedBefore, w.Bodies.Where(Function(b) b.IsFixed).Select(Function(b) b.Position).ToList())
        For Each b In w.Movables
            Assert.True(b.Position.IsFinite)
            Assert.True(b.BoundsMin.X >= 0 AndAlso b.BoundsMin.Y >= 0 AndAlso b.BoundsMax.X <= w.Width AndAlso b.BoundsMax.Y <= w.Height, $"{b.Id} is outside")
        Next
    End Sub

    <Fact>
    Public Sub TheSameTangleTwice_GivesTheSamePositions_ToTheBit()
        Dim first = Tangle(), second = Tangle()
        OverlapResolver.Resolve(first, Tolerance)
        OverlapResolver.Resolve(second, Tolerance)
        Assert.Equal(first.Bodies.Select(Function(b) b.Position).ToList(), second.Bodies.Select(Function(b) b.Position).ToList())
    End Sub

    <Fact>
    Public Sub ABoxAndAPolygonOverlapping_ArePushedApartInProportionToInverseMass()
        ' Masses 1 and 3, walls far away and no gravity: the pair's centre of mass must not move, and the
        ' light one moves three times as far.
        Dim w As New World(10.0, 10.0, 0, 1.0, walls:=False)
        Dim box = Rectangle.CreateMovable(New Vector(4.0, 5.0), 1.0, 0.5, 1.0, id:="box")
        Dim hex As New Polygon(Enumerable.Range(0, 6).Select(Function(k) New Vector(5.3 + 0.4 * Math.Cos(k * Math.PI / 3), 5.2 + 0.4 * Math.Sin(k * Math.PI / 3))).ToList(), 3.0, id:="hex")
        w.Add(box)
        w.Add(hex)
        Dim com = w.CentreOfMass()
        Dim box0 = box.Position, hex0 = hex.Position
        OverlapResolver.Resolve(w, Tolerance)
        Assert.True(Deepest(w) <= Tolerance)
        Assert.True((w.CentreOfMass() - com).Length < 1.0E-12)
        Assert.Equal(3.0 * (hex.Position - hex0).Length, (box.Position - box0).Length, 12)
        ' Along the contact normal: the hexagon's nearest way out of the box is its left side's face.
        Assert.Equal(0.0, box.Position.Y - box0.Y, 12)
    End Sub

    <Fact>
    Public Sub TheDraggedBody_IsNeverMoved_ItPushesTheOther()
        Dim w As New World(4.0, 3.0, 9.81, 0.5)
        Dim dragged = Rectangle.CreateMovable(New Vector(1, 1), 0.5, 0.5, 1.0, id:="dragged")
        Dim tri As New Polygon({New Vector(1.3, 1.3), New Vector(1.8, 1.3), New Vector(1.5, 1.7)}, 1.0, id:="tri")
        w.Add(dragged)
        w.Add(tri)
        w.BeginDrag(dragged)
        Dim at = dragged.Position
        OverlapResolver.Resolve(w, Tolerance)
        Assert.Equal(at, dragged.Position)
        Assert.True(Deepest(w) <= Tolerance)
    End Sub

    <Fact>
    Public Sub CirclesAndFixedRectanglesAlone_AreResolvedAsBefore()
        ' The circle-only path: two circles on one spot and one in a rectangle.
        Dim w As New World(4.0, 3.0, 9.81, 0.5)
        w.Add(New Rectangle(New Vector(1, 0), 1, 0.5, "table"))
        Dim a As New Circle(New Vector(2.5, 1.5), 0.2, 1.0)
        Dim b As New Circle(New Vector(2.5, 1.5), 0.2, 1.0)
        Dim c As New Circle(New Vector(1.5, 0.45), 0.1, 1.0)
        w.Add(a)
        w.Add(b)
        w.Add(c)
        OverlapResolver.Resolve(w, Tolerance)
        Assert.True(Deepest(w) <= Tolerance)
        Assert.True((a.Position - b.Position).Length >= 0.4 - Tolerance)
        ' The centre was inside the table near its top: out through the top, straight up.
        Assert.Equal(1.5, c.Position.X, 12)
        Assert.True(c.Position.Y >= 0.6 - Tolerance)
    End Sub
End Class
