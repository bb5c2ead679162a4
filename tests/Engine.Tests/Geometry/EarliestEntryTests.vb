Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Geometry
    ''' <summary>
    ''' Time of impact of a point against a rounded convex outline, in cases with a closed form: falls,
    ''' slopes, segment ends, grazes, touching contacts, corner-on-corner symmetry, fast thin bodies, the horizon.
    ''' </summary>
    Public Class EarliestEntryTests
        Private Const Slop As Double = 1.0E-12
        Private Const G As Double = 9.81
        Private Shared ReadOnly Fall As New Vector(0, -G)
        Private Shared ReadOnly Infinity As Double = Double.PositiveInfinity

        Private Shared Function Entry(k As Outline, d0 As Vector, dv As Vector, da As Vector, ByRef feature As Integer,
                                      Optional horizon As Double = Double.PositiveInfinity, Optional speedScale As Double = 0) As Double
            Return OutlineContact.EarliestEntry(k, d0, dv, da, Slop, speedScale, horizon, feature)
        End Function

        <Fact>
        Public Sub PointFallingFromRest_OntoAHorizontalEdge_TakesSqrt2hOverG()
            Dim f As Integer
            ' Sharp box: the top face y = 1, dropped from 1.5 m above it.
            Dim t = Entry(Outline.Box(2, 1), New Vector(0.7, 2.5), Vector.Zero, Fall, f)
            Assert.Equal(Math.Sqrt(2 * 1.5 / G), t, 14)
            Assert.Equal(2, f)
            Assert.Equal(New Vector(0, 1), OutlineContact.ContactNormal(Outline.Box(2, 1), New Vector(0.7, 1), f, Slop))
            ' A ball of radius 0.1 onto the box: the face moves out by 0.1.
            Dim rounded = Outline.MinkowskiDifference(Outline.Box(2, 1), Outline.Point(0.1))
            t = Entry(rounded, New Vector(0.7, 2.5), Vector.Zero, Fall, f)
            Assert.Equal(Math.Sqrt(2 * 1.4 / G), t, 14)
            Assert.Equal(New Vector(0, 1), rounded.Normals(f))
        End Sub

        <Fact>
        Public Sub PointFallingOntoA30DegreeSlope_MatchesGeometry()
            Dim len = 2.0, height = len * Math.Tan(Math.PI / 6), r = 0.05
            Dim ramp = Outline.Polygon({New Vector(0, 0), New Vector(len, 0), New Vector(0, height)})
            Dim k = Outline.MinkowskiDifference(ramp, Outline.Point(r))
            Dim x0 = 0.8, y0 = 3.0
            ' The rounded slope lies r / cos 30° above the ramp's surface, measured vertically.
            Dim drop = y0 - (len - x0) * Math.Tan(Math.PI / 6) - r / Math.Cos(Math.PI / 6)
            Dim f As Integer
            Dim t = Entry(k, New Vector(x0, y0), Vector.Zero, Fall, f)
            Assert.Equal(Math.Sqrt(2 * drop / G), t, 13)
            Dim n = OutlineContact.ContactNormal(k, New Vector(x0, y0 - 0.5 * G * t * t), f, Slop)
            Assert.Equal(Math.Sin(Math.PI / 6), n.X, 15)
            Assert.Equal(Math.Cos(Math.PI / 6), n.Y, 15)
        End Sub

        <Fact>
        Public Sub BallHittingASegmentsEnd_OffCentre_NormalRunsFromTheEndToTheBall()
            Dim r = 0.2, b = 0.12, v = 3.0
            Dim k = Outline.MinkowskiDifference(Outline.Segment(New Vector(-1, 0), New Vector(0, 0)), Outline.Point(r))
            Dim f As Integer
            ' Moving left at height b towards the end (0, 0): contact when x² + b² = r².
            Dim t = Entry(k, New Vector(2, b), New Vector(-v, 0), Vector.Zero, f)
            Dim xHit = Math.Sqrt(r * r - b * b)
            Assert.Equal((2 - xHit) / v, t, 14)
            Assert.Equal(k.VertexCount + 1, f) ' the rounded corner at vertex 1, (0, 0)
            Dim n = OutlineContact.ContactNormal(k, New Vector(2 - v * t, b), f, Slop)
            Assert.Equal(xHit / r, n.X, 12)
            Assert.Equal(b / r, n.Y, 12)
            ' Dropped from rest beside the centre of the end cap: contact at height √(r² − x²).
            Dim x0 = 0.03
            t = Entry(k, New Vector(x0, 1), Vector.Zero, Fall, f)
            Dim yHit = Math.Sqrt(r * r - x0 * x0)
            Assert.Equal(Math.Sqrt(2 * (1 - yHit) / G), t, 13)
            n = OutlineContact.ContactNormal(k, New Vector(x0, 1 - 0.5 * G * t * t), f, Slop)
            Assert.Equal(x0 / r, n.X, 12)
            Assert.Equal(yHit / r, n.Y, 12)
        End Sub

        <Fact>
        Public Sub GrazeExactlyAlongAnEdge_IsNoHit()
            Dim f As Integer
            Assert.Equal(Infinity, Entry(Outline.Box(2, 1), New Vector(-1, 1), New Vector(1, 0), Vector.Zero, f))
            Assert.Equal(-1, f)
            ' Rounded: tangent to the top face and to both corner circles.
            Dim rounded = Outline.MinkowskiDifference(Outline.Box(2, 1), Outline.Point(0.1))
            Assert.Equal(Infinity, Entry(rounded, New Vector(-1, 1.1), New Vector(1, 0), Vector.Zero, f))
            ' Along a segment's line, beside it: touching both of its sides at the ends, entering neither.
            Assert.Equal(Infinity, Entry(Outline.Segment(New Vector(0, 0), New Vector(2, 0)), New Vector(-1, 0), New Vector(1, 0), Vector.Zero, f))
        End Sub

        <Fact>
        Public Sub Touching_Approaching_IsNow_Separating_IsNever()
            Dim k = Outline.Box(2, 1)
            Dim f As Integer
            Assert.Equal(0.0, Entry(k, New Vector(1, 1), New Vector(0.3, -1), Vector.Zero, f))
            Assert.Equal(2, f)
            Assert.Equal(0.0, Entry(k, New Vector(1, 1 + 0.5 * Slop), New Vector(0.3, -1), Vector.Zero, f))
            Assert.Equal(Infinity, Entry(k, New Vector(1, 1), New Vector(0.3, 1), Vector.Zero, f))
            ' Resting on it under gravity with no speed: pressed on now.
            Assert.Equal(0.0, Entry(k, New Vector(1, 1), Vector.Zero, Fall, f))
            ' Just bounced at 2 m/s: back after 2u/g.
            Assert.Equal(2 * 2 / G, Entry(k, New Vector(1, 1), New Vector(0, 2), Fall, f), 14)
            ' An approach slower than 10⁻¹² of the bodies' speeds is rounding, not an approach.
            Assert.Equal(Infinity, Entry(k, New Vector(1, 1), New Vector(1, -1.0E-13), Vector.Zero, f, speedScale:=1))
            Assert.Equal(0.0, Entry(k, New Vector(1, 1), New Vector(1, -1.0E-9), Vector.Zero, f, speedScale:=1))
            ' The same at a rounded corner and against a circle.
            Dim ball = Outline.Point(0.5)
            Assert.Equal(0.0, Entry(ball, New Vector(0.3, 0.4), New Vector(-1, 0), Vector.Zero, f))
            Assert.Equal(ball.VertexCount + 0, f)
            Assert.Equal(Infinity, Entry(ball, New Vector(0.3, 0.4), New Vector(1, 0), Vector.Zero, f))
        End Sub

        <Fact>
        Public Sub TwoSidedSegment_IsHitFromEitherSide()
            Dim k = Outline.Segment(New Vector(0, 0), New Vector(2, 0))
            Dim f As Integer
            Assert.Equal(1.0, Entry(k, New Vector(1, 1), New Vector(0, -1), Vector.Zero, f), 15)
            Assert.Equal(New Vector(0, 1), OutlineContact.ContactNormal(k, New Vector(1, 0), f, Slop))
            Assert.Equal(1.0, Entry(k, New Vector(1, -1), New Vector(0, 1), Vector.Zero, f), 15)
            Assert.Equal(New Vector(0, -1), OutlineContact.ContactNormal(k, New Vector(1, 0), f, Slop))
            ' From below, thrown up against gravity: reaches y = 0 when −1 + 5t − ½gt² = 0 (first root).
            Dim expected = (5 - Math.Sqrt(25 - 2 * G)) / G
            Assert.Equal(expected, Entry(k, New Vector(0.5, -1), New Vector(0, 5), Fall, f), 13)
            Assert.Equal(New Vector(0, -1), k.Normals(f))
            ' Falling onto it from above.
            Assert.Equal(Math.Sqrt(4 / G), Entry(k, New Vector(0.5, 2), Vector.Zero, Fall, f), 14)
            Assert.Equal(New Vector(0, 1), k.Normals(f))
        End Sub

        <Fact>
        Public Sub CornerOnCorner_NormalIsTheCornersBisector_AndMirrorsWithTheScene()
            ' Two unit boxes: K = [−1, 1]². A diagonal approach onto K's top-left corner, and its mirror image.
            Dim k = Outline.MinkowskiDifference(Outline.Box(1, 1), Outline.Box(1, 1))
            Dim f As Integer, fm As Integer
            Dim t = Entry(k, New Vector(-1.5, 1.5), New Vector(1, -1), Vector.Zero, f)
            Dim tm = Entry(k, New Vector(1.5, 1.5), New Vector(-1, -1), Vector.Zero, fm)
            Assert.Equal(0.5, t, 15)
            Assert.Equal(t, tm)
            Dim n = OutlineContact.ContactNormal(k, New Vector(-1, 1), f, Slop)
            Dim nm = OutlineContact.ContactNormal(k, New Vector(1, 1), fm, Slop)
            Assert.Equal(-Math.Sqrt(0.5), n.X, 15)
            Assert.Equal(Math.Sqrt(0.5), n.Y, 15)
            Assert.Equal(-n.X, nm.X)
            Assert.Equal(n.Y, nm.Y)
            ' Arriving under gravity at (1, −1) m/s on the same corner, and the mirror image.
            Dim arrive = New Vector(1, -1), t0 = 0.15
            Dim dv = arrive - t0 * Fall
            Dim d0 = New Vector(-1, 1) - t0 * dv - (0.5 * t0 * t0) * Fall
            t = Entry(k, d0, dv, Fall, f)
            tm = Entry(k, New Vector(-d0.X, d0.Y), New Vector(-dv.X, dv.Y), Fall, fm)
            Assert.Equal(t0, t, 14)
            Assert.Equal(t, tm)
            n = OutlineContact.ContactNormal(k, GeometryTestKit.PathAt(d0, dv, Fall, t), f, Slop)
            nm = OutlineContact.ContactNormal(k, GeometryTestKit.PathAt(New Vector(-d0.X, d0.Y), New Vector(-dv.X, dv.Y), Fall, tm), fm, Slop)
            Assert.Equal(-Math.Sqrt(0.5), n.X, 15)
            Assert.Equal(-n.X, nm.X)
            Assert.Equal(n.Y, nm.Y)
            ' Falling straight down with the faces flush (corner exactly over corner): the point slides down
            ' K's side without entering, as the box slides past the other one: no hit.
            Assert.Equal(Infinity, Entry(k, New Vector(-1, 3), Vector.Zero, Fall, f))
            Assert.Equal(Infinity, Entry(k, New Vector(1, 3), Vector.Zero, Fall, f))
            ' Thrown so that the top of its arc is exactly on the corner: it curves in, a hit.
            t = Entry(k, New Vector(-1 - 1 * 1, 1 - 0.5 * G), New Vector(1, G), Fall, f)
            Assert.Equal(1.0, t, 14)
            ' A diamond's top corner, hit from straight above: the normal is straight up.
            Dim diamond = Outline.Polygon({New Vector(0, -1), New Vector(1, 0), New Vector(0, 1), New Vector(-1, 0)})
            t = Entry(diamond, New Vector(0, 3), Vector.Zero, Fall, f)
            Assert.Equal(Math.Sqrt(4 / G), t, 14)
            Assert.Equal(New Vector(0, 1), OutlineContact.ContactNormal(diamond, New Vector(0, 3 - 0.5 * G * t * t), f, Slop))
        End Sub

        <Fact>
        Public Sub CornerOnCorner_RandomPolygons_MirrorImage_GivesTheMirroredNormal()
            Dim rng As New Random(31)
            For trial = 0 To 499
                Dim a = GeometryTestKit.RandomConvex(rng, Vector.Zero, 0.5)
                Dim b = GeometryTestKit.RandomConvex(rng, GeometryTestKit.RandomPoint(rng, 0.5), 0.5)
                Dim mirror = Function(p As Vector) New Vector(-p.X, p.Y)
                Dim k = Outline.MinkowskiDifference(Outline.Polygon(b), Outline.Polygon(a))
                Dim km = Outline.MinkowskiDifference(Outline.Polygon(b.Select(mirror).ToArray()), Outline.Polygon(a.Select(mirror).ToArray()))
                ' Aim at a random corner of K along its outward bisector (found from the corner's neighbours).
                Dim c = rng.Next(k.VertexCount)
                Dim v = k.Vertices(c), prev = k.Vertices((c + k.VertexCount - 1) Mod k.VertexCount), nxt = k.Vertices((c + 1) Mod k.VertexCount)
                Dim outward = (-((prev - v).Normalized(Vector.Zero) + (nxt - v).Normalized(Vector.Zero))).Normalized(Vector.Zero)
                Dim speed = 0.5 + 2 * rng.NextDouble(), t0 = 0.2 + rng.NextDouble()
                Dim d0 = v + (speed * t0) * outward
                Dim dv = -speed * outward
                Dim f As Integer, fm As Integer
                Dim t = Entry(k, d0, dv, Vector.Zero, f)
                Dim tm = Entry(km, mirror(d0), mirror(dv), Vector.Zero, fm)
                Assert.True(Math.Abs(t - t0) <= 1.0E-12, $"trial {trial}: hit at {t}, corner reached at {t0}")
                Assert.True(Math.Abs(tm - t) <= 1.0E-12, $"trial {trial}: mirror hit at {tm} vs {t}")
                Dim n = OutlineContact.ContactNormal(k, d0 + t * dv, f, Slop)
                Dim nm = OutlineContact.ContactNormal(km, mirror(d0) + tm * mirror(dv), fm, Slop)
                Assert.True((nm - mirror(n)).Length <= 1.0E-14, $"trial {trial}: normal {n}, mirror's {nm}")
                Assert.True((n - outward).Length <= 1.0E-12, $"trial {trial}: normal {n}, corner bisector {outward}")
            Next
        End Sub

        <Fact>
        Public Sub MillimetreBallAt10kMetresPerSecond_NeverTunnelsThroughASegment()
            Dim r = 0.001, speed = 10000.0
            Dim k = Outline.MinkowskiDifference(Outline.Segment(New Vector(0, 0), New Vector(1, 0)), Outline.Point(r))
            Dim f As Integer
            ' Straight down from 10 m at x0, under gravity: the face, the end caps, or a clean miss.
            For i = -30 To 1030
                Dim x0 = i / 1000.0 + 0.00003
                Dim t = Entry(k, New Vector(x0, 10), New Vector(0, -speed), Fall, f)
                Dim overEnd = If(x0 < 0, -x0, If(x0 > 1, x0 - 1, 0.0))
                If overEnd >= r Then
                    Assert.Equal(Infinity, t)
                    Continue For
                End If
                Dim contactHeight = Math.Sqrt(r * r - overEnd * overEnd)
                ' 10 − 10⁴ t − ½ g t² = contactHeight, first root, computed without cancellation.
                Dim c = 10 - contactHeight
                Dim expected = 2 * c / (speed + Math.Sqrt(speed * speed + 2 * G * c))
                Assert.True(Math.Abs(t - expected) <= 1.0E-15, $"x0 = {x0}: hit at {t}, expected {expected}")
                Dim hit = New Vector(x0, 10 - speed * t - 0.5 * G * t * t)
                Assert.True(GeometryTestKit.Gap(k, hit) >= -Slop)
            Next
            ' Sideways along the segment's own line into its end cap, from below the line and from above it.
            For Each y In {-0.0009, -0.0005, 0.0, 0.0005, 0.0009}
                Dim t = Entry(k, New Vector(-5, y), New Vector(speed, 0), Vector.Zero, f)
                Assert.Equal((5 - Math.Sqrt(r * r - y * y)) / speed, t, 15)
                Assert.Equal(k.VertexCount + 0, f)
            Next
        End Sub

        <Fact>
        Public Sub Horizon_AHitAfterItIsNone_AHitBeforeItIsUnchanged()
            Dim k = Outline.Box(2, 1)
            Dim d0 = New Vector(0.7, 2.5)
            Dim f As Integer
            Dim free = Entry(k, d0, Vector.Zero, Fall, f)
            Assert.Equal(Math.Sqrt(2 * 1.5 / G), free, 14)
            Assert.Equal(Infinity, Entry(k, d0, Vector.Zero, Fall, f, horizon:=0.5))
            Assert.Equal(-1, f)
            Assert.Equal(free, Entry(k, d0, Vector.Zero, Fall, f, horizon:=0.6))
            Assert.Equal(2, f)
            Assert.Equal(free, Entry(k, d0, Vector.Zero, Fall, f, horizon:=free))
            Assert.Equal(free, Entry(k, d0, Vector.Zero, Fall, f, horizon:=1.0E+300))
            ' Far away and moving off: nothing, with or without a horizon.
            Assert.Equal(Infinity, Entry(k, New Vector(10, 10), New Vector(1, 0), Vector.Zero, f, horizon:=5))
        End Sub

        <Fact>
        Public Sub SidewaysAcceleration_IsHandled()
            Dim f As Integer
            ' Pulled left at 2 m/s² onto the right face x = 2 from x = 3: ½·2·t² = 1.
            Assert.Equal(1.0, Entry(Outline.Box(2, 1), New Vector(3, 0.5), Vector.Zero, New Vector(-2, 0), f), 14)
            Assert.Equal(1, f)
            ' Onto the rounded corner (2, 1) of radius 0.25 at height 0.2 above it: contact at x = 2 + 0.15.
            Dim k = Outline.MinkowskiDifference(Outline.Box(2, 1), Outline.Point(0.25))
            Assert.Equal(Math.Sqrt(0.85), Entry(k, New Vector(3, 1.2), Vector.Zero, New Vector(-2, 0), f), 13)
            Assert.Equal(k.VertexCount + 2, f)
        End Sub

        <Fact>
        Public Sub StartingDeepInside_IsAnOverlapForTheResolver_NotAContact()
            ' Inside the core of a rounded box, heading for its top-right corner: the corner circle is
            ' crossed from inside, outside the corner's cone, and the faces' planes are already behind.
            Dim k = Outline.MinkowskiDifference(Outline.Box(2, 1), Outline.Point(0.1))
            Dim f As Integer
            Assert.Equal(Infinity, Entry(k, New Vector(1.9, 0.9), New Vector(1, 1), Vector.Zero, f))
            Assert.Equal(Infinity, Entry(k, New Vector(1.9, 0.9), New Vector(1, 0), Vector.Zero, f))
            Assert.Equal(Infinity, Entry(Outline.Box(2, 1), New Vector(1.9, 0.9), New Vector(1, 1), Vector.Zero, f))
        End Sub

        <Fact>
        Public Sub TouchingEdges_OnAFace_OnACorner_OnASegment()
            Dim first As Integer, second As Integer
            Dim box = Outline.Box(2, 1)
            Assert.Equal(1, OutlineContact.TouchingEdges(box, New Vector(1, 1 + 0.5 * Slop), Slop, first, second))
            Assert.Equal(2, first)
            Assert.Equal(2, OutlineContact.TouchingEdges(box, New Vector(2, 1), Slop, first, second))
            Assert.Equal(1, first) : Assert.Equal(2, second)
            Assert.Equal(0, OutlineContact.TouchingEdges(box, New Vector(1, 1.1), Slop, first, second))
            Assert.Equal(-1, first)
            Dim seg = Outline.Segment(New Vector(0, 0), New Vector(2, 0))
            Assert.Equal(2, OutlineContact.TouchingEdges(seg, New Vector(1, 0), Slop, first, second))
        End Sub
    End Class
End Namespace
