Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' Boxes, polygons and segments with the event solver, against closed forms: exact times of impact
''' (a parabola against a face is a quadratic), impulses along the contact normal, momentum kept.
''' </summary>
Public Class ShapeCollisionTests
    Private Const G As Double = 9.81

    <Fact>
    Public Sub TwoBoxesHeadOn_Masses1And3_e05_FollowThe1DClosedForm()
        ' g = 0, no walls: box 1 (1 kg) at 2 m/s towards box 2 (3 kg) at −1 m/s.
        Dim w As New World(10, 4, 0.0, 0.5, walls:=False)
        Dim a = Rectangle.CreateMovable(New Vector(1, 1), 0.5, 0.5, 1.0, New Vector(2, 0), "a")
        Dim b = Rectangle.CreateMovable(New Vector(4, 1.2), 0.6, 0.3, 3.0, New Vector(-1, 0), "b")
        w.Add(a)
        w.Add(b)
        UseEventSolver(w)
        Dim records As New List(Of CollisionRecord)
        w.CollisionListener = Sub(r) records.Add(r)
        w.Advance(2.0)
        Assert.Single(records)
        ' They meet when the gap 4 − 1.5 = 2.5 m closes at 3 m/s.
        Assert.Equal(2.5 / 3, records(0).Time, 12)
        Assert.Equal("rectangle-rectangle", records(0).KindName)
        ' 1D with restitution: v1' = (m1 u1 + m2 u2 − m2 e (u1 − u2)) / (m1 + m2), v2' likewise.
        Dim u1 = 2.0, u2 = -1.0, m1 = 1.0, m2 = 3.0, e = 0.5
        Dim v1 = (m1 * u1 + m2 * u2 - m2 * e * (u1 - u2)) / (m1 + m2)
        Dim v2 = (m1 * u1 + m2 * u2 + m1 * e * (u1 - u2)) / (m1 + m2)
        Assert.True(Math.Abs(a.Velocity.X - v1) <= 1.0E-12, $"box a at {a.Velocity.X}, not {v1}")
        Assert.True(Math.Abs(b.Velocity.X - v2) <= 1.0E-12, $"box b at {b.Velocity.X}, not {v2}")
        Assert.Equal(0.0, a.Velocity.Y)
        Assert.Equal(0.0, b.Velocity.Y)
    End Sub

    <Fact>
    Public Sub BoxDroppedOnTheFloor_ReboundsAtEToTheN_AndRestsAtTheSeriesTime_NeverBelowTheFloor()
        Dim h0 = 1.0, e = 0.7
        Dim w As New World(3, 3, G, e)
        Dim box = Rectangle.CreateMovable(New Vector(1, h0), 0.4, 0.3, 2.0, id:="box")
        w.Add(box)
        Dim solver = UseEventSolver(w)
        Dim ups As New List(Of Double)
        w.CollisionListener = Sub(r) ups.Add(r.AVelocityAfter.Y)
        Dim lowest = Double.PositiveInfinity
        For k = 1 To 5000
            w.Advance(0.002)
            lowest = Math.Min(lowest, box.Position.Y)
        Next
        Dim v0 = Math.Sqrt(2 * G * h0)
        Assert.True(ups.Count > 20, $"only {ups.Count} bounces")
        For n = 1 To 10
            Assert.True(Math.Abs(ups(n - 1) - e ^ n * v0) <= 1.0E-9 * v0, $"rebound {n}: {ups(n - 1)} vs {e ^ n * v0}")
        Next
        Dim t0 = Math.Sqrt(2 * h0 / G)
        Dim rest = solver.RestTime(box)
        Assert.True(rest.HasValue, "the box never came to rest")
        Assert.True(Math.Abs(rest.Value - t0 * (1 + e) / (1 - e)) < 0.001, $"rest at {rest.Value}")
        Assert.True(lowest >= 0, $"the box went {-lowest} m below the floor")
        Assert.Equal(0.0, box.Position.Y)
        Assert.Equal(0.0, box.Velocity.Y)
    End Sub

    <Fact>
    Public Sub BoxSlidingOnTheFloor_IntoAWall_StaysOnTheFloorExactly()
        Dim w As New World(4, 2, G, 0.8)
        Dim box = Rectangle.CreateMovable(New Vector(1, 0), 0.5, 0.5, 1.0, New Vector(3, 0), "box")
        w.Add(box)
        UseEventSolver(w)
        Dim hits As New List(Of CollisionRecord)
        w.CollisionListener = Sub(r) hits.Add(r)
        For k = 1 To 300
            w.Advance(0.01)
            Assert.Equal(0.0, box.Position.Y)
            Assert.Equal(0.0, box.Velocity.Y)
        Next
        Dim wallHits = hits.Where(Function(r) r.B Is Nothing AndAlso r.Wall <> WallSide.Bottom).ToList()
        Assert.True(wallHits.Count >= 2, $"{wallHits.Count} wall hits")
        ' First the right wall at t = (4 − 0.5 − 1)/3, leaving at −e·3 m/s.
        Assert.Equal(WallSide.Right, wallHits(0).Wall)
        Assert.Equal(2.5 / 3, wallHits(0).Time, 12)
        Assert.Equal(-0.8 * 3, wallHits(0).AVelocityAfter.X, 12)
        Assert.Equal("rectangle-wall", wallHits(0).KindName)
    End Sub

    <Fact>
    Public Sub BallHittingASegmentsEndOffCentre_ReflectsAboutTheLineFromTheEnd()
        ' g = 0: a ball moving along +x whose path passes 0.05 m above the segment's left end.
        Dim w As New World(6, 4, 0.0, 1.0)
        w.Add(New Segment(New Vector(3, 2), New Vector(4, 2), "seg"))
        Dim r = 0.1
        Dim ball As New Circle(New Vector(1, 2 + 0.05), r, 1.0, New Vector(2, 0), "ball")
        w.Add(ball)
        UseEventSolver(w)
        Dim records As New List(Of CollisionRecord)
        w.CollisionListener = Sub(rec) records.Add(rec)
        w.Advance(1.2)
        Assert.Single(records)
        Dim hit = records(0)
        Assert.Equal("circle-segment", hit.KindName)
        ' Contact when the centre is r from the end (3, 2): x = 3 − √(r² − 0.05²).
        Dim dx = Math.Sqrt(r * r - 0.05 * 0.05)
        Assert.Equal((3 - dx - 1) / 2, hit.Time, 12)
        ' Reflection about the line from the end to the centre.
        Dim n = New Vector(-dx, 0.05) / r
        Dim v = New Vector(2, 0)
        Dim expected = v - n * (2 * Vector.Dot(v, n))
        Assert.True((hit.AVelocityAfter - expected).Length <= 1.0E-12, $"after {hit.AVelocityAfter}, expected {expected}")
    End Sub

    <Theory>
    <InlineData(1)>
    <InlineData(-1)>
    Public Sub OneMillimetreBallAt1e4MetresPerSecond_BouncesOffASegment_FromEitherSide(side As Integer)
        Dim w As New World(10, 10, 0.0, 1.0)
        w.Add(New Segment(New Vector(5, 2), New Vector(5, 8), "wall"))
        Dim ball As New Circle(New Vector(5 - side * 3, 5), 0.001, 0.001, New Vector(side * 10000.0, 0), "b")
        w.Add(ball)
        UseEventSolver(w)
        Dim first As CollisionRecord? = Nothing
        w.CollisionListener = Sub(r) If first Is Nothing Then first = r
        w.Advance(0.0004)
        Assert.True(first.HasValue, "it never touched the segment")
        Assert.Equal("circle-segment", first.Value.KindName)
        Assert.Equal(-side * 10000.0, first.Value.AVelocityAfter.X, 9)
        ' It is still on its own side.
        Assert.True(side * (5 - ball.Position.X) > 0, $"it crossed the segment: x = {ball.Position.X}")
    End Sub

    <Fact>
    Public Sub BallDroppedOnASlope_e1_FirstThreeImpacts_FollowTheParabolaAndTheReflection()
        ' A 30° segment through (0, 0), a ball dropped from rest above it.
        Dim theta = Math.PI / 6
        Dim w As New World(20, 12, G, 1.0)
        Dim a = New Vector(0.5, 7), dir = New Vector(Math.Cos(theta), -Math.Sin(theta))
        w.Add(New Segment(a, a + dir * 14, "slope"))
        Dim r = 0.1
        Dim start = New Vector(3, 6.2)
        Dim ball As New Circle(start, r, 1.0, id:="ball")
        w.Add(ball)
        UseEventSolver(w)
        Dim records As New List(Of CollisionRecord)
        w.CollisionListener = Sub(rec) records.Add(rec)
        w.Advance(4.0)
        Assert.True(records.Count >= 3, $"{records.Count} impacts")
        ' The face the centre meets: the segment's line moved out by r along its upward normal.
        Dim n = New Vector(Math.Sin(theta), Math.Cos(theta))
        Dim p = start, v = Vector.Zero, t = 0.0
        For k = 0 To 2
            ' gap(τ) = n·(p + v τ − ½ g τ² ŷ − a) − r, a quadratic; its entering root.
            Dim c0 = Vector.Dot(n, p - a) - r, c1 = Vector.Dot(n, v), c2 = -0.5 * G * n.Y
            Dim tau = (-c1 - Math.Sqrt(c1 * c1 - 4 * c2 * c0)) / (2 * c2)
            If tau <= 0 Then tau = (-c1 + Math.Sqrt(c1 * c1 - 4 * c2 * c0)) / (2 * c2)
            p = p + v * tau + New Vector(0, -0.5 * G * tau * tau)
            v = v + New Vector(0, -G * tau)
            t += tau
            Assert.True(Math.Abs(records(k).Time - t) <= 1.0E-9, $"impact {k + 1} at {records(k).Time}, expected {t}")
            v = v - n * (2 * Vector.Dot(v, n))
            Assert.True((records(k).AVelocityAfter - v).Length <= 1.0E-9 * v.Length, $"impact {k + 1}: rebound {records(k).AVelocityAfter}, expected {v}")
        Next
    End Sub

    <Fact>
    Public Sub PolygonsBoxesAndCircles_InABox_KeepMomentumInEveryCollision_AndNeverOverlap()
        ' g = 0: triangles, boxes and circles thrown about a walled box.
        Dim w As New World(4, 4, 0.0, 0.6)
        Dim rng As New Random(5)
        For k = 0 To 8
            Dim c = New Vector(0.2 + 1.3 * (k Mod 3), 0.2 + 1.3 * (k \ 3))
            Dim vel = New Vector(rng.NextDouble() * 6 - 3, rng.NextDouble() * 6 - 3)
            Select Case k Mod 3
                Case 0 : w.Add(New Polygon({c, c + New Vector(0.6, 0), c + New Vector(0.2, 0.5)}, 1 + k, vel))
                Case 1 : w.Add(Rectangle.CreateMovable(c, 0.5, 0.4, 2 + k, vel))
                Case Else : w.Add(New Circle(c + New Vector(0.3, 0.3), 0.25, 1.5 + k, vel))
            End Select
        Next
        UseEventSolver(w)
        Dim between = 0
        w.CollisionListener = Sub(r)
                                  If r.B Is Nothing OrElse r.B.IsFixed Then Return
                                  between += 1
                                  Dim before = r.AVelocityBefore * r.A.Mass + r.BVelocityBefore * r.B.Mass
                                  Dim after = r.AVelocityAfter * r.A.Mass + r.BVelocityAfter * r.B.Mass
                                  If (after - before).Length > 1.0E-12 * (r.AVelocityBefore.Length * r.A.Mass + r.BVelocityBefore.Length * r.B.Mass) Then
                                      Assert.Fail($"{r.KindName} at {r.Time}: momentum {before} before, {after} after")
                                  End If
                              End Sub
        For k = 1 To 200
            w.Advance(0.05)
            Assert.True(DeepestShapeOverlap(w) <= 1.0E-9, $"overlap {DeepestShapeOverlap(w)} at {w.Time}")
        Next
        Assert.True(between > 30, $"only {between} collisions between bodies")
    End Sub

    <Fact>
    Public Sub CornerOnCorner_ASymmetricSceneStaysSymmetric()
        ' Two boxes fall corner first onto the two top corners of a fixed box, mirror images of each
        ' other about x = 5: the run stays a mirror image.
        Dim w As New World(10, 6, G, 0.5)
        w.Add(New Rectangle(New Vector(4, 0), 2, 1, "base"))
        Dim left = Rectangle.CreateMovable(New Vector(3.5, 2), 0.5, 0.5, 1.0, id:="left")
        Dim right = Rectangle.CreateMovable(New Vector(6, 2), 0.5, 0.5, 1.0, id:="right")
        w.Add(left)
        w.Add(right)
        UseEventSolver(w)
        Dim hits = 0
        w.CollisionListener = Sub(r) hits += 1
        For k = 1 To 100
            w.Advance(0.01)
            Assert.True(Math.Abs((left.Position.X + 0.5) - (10 - right.Position.X)) <= 1.0E-12, $"x {left.Position.X} vs {right.Position.X} at {w.Time}")
            Assert.True(Math.Abs(left.Position.Y - right.Position.Y) <= 1.0E-12)
            Assert.True(Math.Abs(left.Velocity.X + right.Velocity.X) <= 1.0E-12)
        Next
        Assert.True(hits >= 2, "they never hit the corners")
    End Sub

    ''' <summary>The deepest overlap between any two bodies that collide (and any body and a wall), m.</summary>
    Friend Shared Function DeepestShapeOverlap(w As World) As Double
        Dim worst = 0.0
        Dim bodies = w.Bodies
        For i = 0 To bodies.Count - 1
            For j = i + 1 To bodies.Count - 1
                Dim a = bodies(i), b = bodies(j)
                If a.IsFixed AndAlso b.IsFixed Then Continue For
                Dim k = Outline.MinkowskiDifference(b.Outline, a.Outline)
                worst = Math.Max(worst, OutlineContact.Penetration(k, a.Position - b.Position).Depth)
            Next
            If w.Walls AndAlso Not bodies(i).IsFixed Then
                worst = Math.Max(worst, -bodies(i).BoundsMin.X)
                worst = Math.Max(worst, -bodies(i).BoundsMin.Y)
                worst = Math.Max(worst, bodies(i).BoundsMax.X - w.Width)
                worst = Math.Max(worst, bodies(i).BoundsMax.Y - w.Height)
            End If
        Next
        Return worst
    End Function
End Class
