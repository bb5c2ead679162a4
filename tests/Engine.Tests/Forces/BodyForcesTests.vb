Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Forces
    ''' <summary>
    ''' The free-body diagram (<see cref="BodyForces"/>) against the textbook: the contact pushes, friction and
    ''' tensions the complementarity solve finds, and the sum of the forces equal to m a.
    ''' </summary>
    Public Class BodyForcesTests
        Private Const G As Double = 9.81

        Private Shared Function OfKind(d As FreeBodyDiagram, kind As ForceKind) As List(Of BodyForce)
            Return d.Forces.Where(Function(f) f.Kind = kind).ToList()
        End Function

        Private Shared Sub AssertClose(expected As Vector, actual As Vector, tolerance As Double)
            Assert.True((expected - actual).Length <= tolerance, $"expected {expected}, got {actual}")
        End Sub

        ''' <summary>ΣF = m a, to rounding.</summary>
        Private Shared Sub AssertNewton(d As FreeBodyDiagram)
            AssertClose(d.MassTimesAcceleration, d.Sum, 0.000000001 * (1 + d.Forces.Sum(Function(f) f.Magnitude)))
        End Sub

        <Fact>
        Public Sub BoxRestingOnATable_IsPushedUpByMg_AndNothingAddsUp()
            Dim w As New World(10, 10, G, 0.5)
            w.Add(New Rectangle(New Vector(2, 0), 4, 1, "table"))
            Dim box = Rectangle.CreateMovable(New Vector(3, 1), 0.5, 0.5, 2, Vector.Zero, "box")
            w.Add(box)
            Dim d = BodyForces.Diagram(w, box)
            AssertClose(New Vector(0, -2 * G), OfKind(d, ForceKind.Weight).Single().Force, 0.000000000001)
            Dim n = OfKind(d, ForceKind.Normal).Single()
            Assert.Equal("table", n.Source)
            AssertClose(New Vector(0, 2 * G), n.Force, 0.000000001)
            ' It acts in the middle of the box's bottom face.
            AssertClose(New Vector(3.25, 1), n.Point, 0.000000001)
            AssertClose(Vector.Zero, d.Sum, 0.000000001)
            AssertClose(Vector.Zero, d.Acceleration, 0.000000001)
            AssertNewton(d)
        End Sub

        <Theory>
        <InlineData(0.3)>
        <InlineData(0.7)>
        Public Sub BallInAV_IsPushedByEachFaceWithMgOverTwoCosAlpha(alpha As Double)
            Dim w As New World(10, 10, G, 0.5)
            Dim vertex = New Vector(5, 1)
            w.Add(New Segment(vertex, vertex + New Vector(-Math.Cos(alpha), Math.Sin(alpha)) * 3, "left"))
            w.Add(New Segment(vertex, vertex + New Vector(Math.Cos(alpha), Math.Sin(alpha)) * 3, "right"))
            Dim r = 0.2
            Dim ball As New Circle(vertex + New Vector(0, r / Math.Cos(alpha)), r, 1.5, Vector.Zero, "ball")
            w.Add(ball)
            Dim d = BodyForces.Diagram(w, ball)
            Dim normals = OfKind(d, ForceKind.Normal)
            Assert.Equal(2, normals.Count)
            Dim expected = 1.5 * G / (2 * Math.Cos(alpha))
            For Each n In normals
                Assert.Equal(expected, n.Magnitude, 9)
            Next
            Assert.Empty(OfKind(d, ForceKind.Friction))
            AssertClose(Vector.Zero, d.Sum, 0.000000001)
            AssertNewton(d)
        End Sub

        <Fact>
        Public Sub StackOfTwoBoxes_TheFloorCarriesBoth_AndTheUpperPressesOnTheLower()
            Dim w As New World(10, 10, G, 0.5)
            Dim lower = Rectangle.CreateMovable(New Vector(3, 0), 1, 0.5, 3, Vector.Zero, "lower")
            Dim upper = Rectangle.CreateMovable(New Vector(3.2, 0.5), 0.5, 0.5, 2, Vector.Zero, "upper")
            w.Add(lower)
            w.Add(upper)
            Dim d = BodyForces.Diagram(w, lower)
            Dim normals = OfKind(d, ForceKind.Normal)
            Assert.Equal(2, normals.Count)
            AssertClose(New Vector(0, 5 * G), normals.Single(Function(f) f.Source = "floor").Force, 0.000000001)
            AssertClose(New Vector(0, -2 * G), normals.Single(Function(f) f.Source = "upper").Force, 0.000000001)
            AssertNewton(d)
            Dim top = BodyForces.Diagram(w, upper)
            AssertClose(New Vector(0, 2 * G), OfKind(top, ForceKind.Normal).Single(Function(f) f.Source = "lower").Force, 0.000000001)
        End Sub

        <Fact>
        Public Sub BobHangingOnAStringAtRest_IsPulledUpByMg()
            Dim w As New World(10, 10, G, 0.5)
            Dim anchor = New Vector(5, 8)
            Dim bob As New Circle(anchor - New Vector(0, 2), 0.1, 0.7, Vector.Zero, "bob")
            w.Add(bob)
            w.Add(Link.CreateTie(LinkKind.String, bob, anchor, 2, "thread"))
            Dim d = BodyForces.Diagram(w, bob)
            Dim t = OfKind(d, ForceKind.Tension).Single()
            Assert.Equal("thread", t.Source)
            AssertClose(New Vector(0, 0.7 * G), t.Force, 0.000000001)
            AssertClose(Vector.Zero, d.Sum, 0.000000001)
            AssertNewton(d)
        End Sub

        <Fact>
        Public Sub BobOnASlackString_FeelsNoTension()
            Dim w As New World(10, 10, G, 0.5)
            Dim anchor = New Vector(5, 8)
            Dim bob As New Circle(anchor - New Vector(0, 1.5), 0.1, 0.7, Vector.Zero, "bob")
            w.Add(bob)
            w.Add(Link.CreateTie(LinkKind.String, bob, anchor, 2, "thread"))
            Dim d = BodyForces.Diagram(w, bob)
            Assert.Empty(OfKind(d, ForceKind.Tension))
            AssertClose(New Vector(0, -G), d.Acceleration, 0.000000000001)
        End Sub

        <Theory>
        <InlineData(0.3, 0.5)>
        <InlineData(0.45, 0.5)>
        Public Sub BlockOnARoughRampBelowTheAngleOfRepose_FrictionIsMgSinTheta_NormalMgCosTheta(theta As Double, muS As Double)
            Dim w As New World(10, 10, G, 0.2) With {.Friction = 0.3, .StaticFriction = muS}
            Dim start = New Vector(2, 1), along = New Vector(Math.Cos(theta), Math.Sin(theta))
            w.Add(New Segment(start, start + along * 6, "ramp"))
            Dim corner = start + along * 1
            Dim m = 1.5
            Dim box = Rectangle.CreateMovable(corner - New Vector(0.4, 0), 0.4, 0.4, m, Vector.Zero, "box")
            w.Add(box)
            Dim d = BodyForces.Diagram(w, box)
            Dim n = OfKind(d, ForceKind.Normal).Single()
            Dim f = OfKind(d, ForceKind.Friction).Single()
            Assert.Equal("ramp", n.Source)
            Assert.Equal(m * G * Math.Cos(theta), n.Magnitude, 9)
            Assert.Equal(m * G * Math.Sin(theta), f.Magnitude, 9)
            ' Friction holds it up the slope.
            Assert.True(Vector.Dot(f.Force, along) > 0)
            AssertClose(Vector.Zero, d.Sum, 0.000000001)
            AssertNewton(d)
        End Sub

        <Theory>
        <InlineData(2.0, 0.4)>
        <InlineData(-3.5, 0.25)>
        Public Sub BlockSlidingOnARoughFloor_FrictionIsMuKMgAgainstTheSliding(speed As Double, mu As Double)
            Dim w As New World(10, 10, G, 0.2) With {.Friction = mu, .StaticFriction = mu + 0.1}
            Dim box = Rectangle.CreateMovable(New Vector(4, 0), 0.5, 0.3, 2, New Vector(speed, 0), "box")
            w.Add(box)
            Dim d = BodyForces.Diagram(w, box)
            Dim f = OfKind(d, ForceKind.Friction).Single()
            Assert.Equal("floor", f.Source)
            AssertClose(New Vector(-Math.Sign(speed) * mu * 2 * G, 0), f.Force, 0.000000001)
            AssertClose(New Vector(0, 2 * G), OfKind(d, ForceKind.Normal).Single().Force, 0.000000001)
            AssertClose(New Vector(-Math.Sign(speed) * mu * G, 0), d.Acceleration, 0.000000001)
            AssertNewton(d)
        End Sub

        <Fact>
        Public Sub FallingBallWithLinearDrag_DragIsMinusBV_AndTheSumIsMA()
            Dim w As New World(10, 10, G, 0.5)
            Dim v = New Vector(1.5, -4)
            Dim ball As New Circle(New Vector(5, 5), 0.2, 0.5, v, "ball")
            w.Add(ball)
            w.SetDrag(ball, 0, 0.3)
            Dim d = BodyForces.Diagram(w, ball)
            Dim drag = OfKind(d, ForceKind.Drag).Single()
            AssertClose(v * -0.3, drag.Force, 0.000000000001)
            Assert.Empty(OfKind(d, ForceKind.Normal))
            AssertClose(New Vector(0, -G) - v * (0.3 / 0.5), d.Acceleration, 0.000000000001)
            AssertNewton(d)
        End Sub

        <Fact>
        Public Sub BoxOnASmoothFloorPulledByASpring_FeelsKTimesTheStretch()
            Dim w As New World(10, 10, G, 0.5)
            Dim box = Rectangle.CreateMovable(New Vector(4, 0), 0.5, 0.5, 2, Vector.Zero, "box")
            w.Add(box)
            ' The spring from the box's centre (4.25, 0.25) to (7.25, 0.25), rest length 2: stretched 1 m.
            w.Add(Link.CreateSpring(box, New Vector(7.25, 0.25), 30, 2, 0, "spring"))
            Dim d = BodyForces.Diagram(w, box)
            AssertClose(New Vector(30, 0), OfKind(d, ForceKind.Spring).Single().Force, 0.000000001)
            AssertClose(New Vector(15, 0), d.Acceleration, 0.000000001)
            AssertNewton(d)
        End Sub

        <Fact>
        Public Sub BobOnARodLeaningOnAWall_RodPullsMgOverCosTheta_WallPushesMgTanTheta()
            Dim w As New World(10, 10, G, 0.5)
            ' Anchored beyond the left wall: the bob would swing through it to hang below, and leans on it instead.
            Dim anchor = New Vector(-0.8, 8)
            Dim r = 0.1, l = 2.0, m = 0.6
            Dim sinTheta = (r - anchor.X) / l
            Dim theta = Math.Asin(sinTheta)
            Dim bob As New Circle(New Vector(r, anchor.Y - l * Math.Cos(theta)), r, m, Vector.Zero, "bob")
            w.Add(bob)
            w.Add(Link.CreateTie(LinkKind.Rod, bob, anchor, l, "arm"))
            Dim d = BodyForces.Diagram(w, bob)
            Dim t = OfKind(d, ForceKind.Tension).Single()
            Assert.Equal(m * G / Math.Cos(theta), t.Magnitude, 9)
            ' It pulls towards the anchor.
            Assert.True(Vector.Dot(t.Force, anchor - bob.CentreOfMass) > 0)
            Dim n = OfKind(d, ForceKind.Normal).Single()
            Assert.Equal("left wall", n.Source)
            AssertClose(New Vector(m * G * Math.Tan(theta), 0), n.Force, 0.000000001)
            AssertClose(Vector.Zero, d.Sum, 0.000000001)
            AssertNewton(d)
        End Sub

        <Fact>
        Public Sub BoxFloatingAtItsDepth_UpthrustIsItsWeight()
            Dim w As New World(10, 10, G, 0.5)
            w.Add(New Liquid(New Vector(0, 0), 10, 4, 1000, "water"))
            Dim m = 200.0, width = 0.8
            Dim depth = Buoyancy.FloatingDepth(m, width, 1000)
            Dim box = Rectangle.CreateMovable(New Vector(4, 4 - depth), width, 0.6, m, Vector.Zero, "box")
            w.Add(box)
            Dim d = BodyForces.Diagram(w, box)
            Dim u = OfKind(d, ForceKind.Buoyancy).Single()
            Assert.Equal("water", u.Source)
            AssertClose(New Vector(0, m * G), u.Force, 0.000000001)
            Assert.Empty(OfKind(d, ForceKind.Drag))
            AssertClose(Vector.Zero, d.Sum, 0.000000001)
            AssertNewton(d)
        End Sub

        <Fact>
        Public Sub FixedBody_HasNoDiagram()
            Dim w As New World(10, 10, G, 0.5)
            Dim table As New Rectangle(New Vector(2, 0), 4, 1, "table")
            w.Add(table)
            Assert.Throws(Of ArgumentException)(Sub() BodyForces.Diagram(w, table))
        End Sub
    End Class
End Namespace
