Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' Fixed bodies of every shape win in the stepping solvers: no body's centre ends a step inside one,
''' nothing is pushed through a segment (which has no thickness), and even a 1 mm ball at 10⁴ m/s, which
''' moves 10 m in one step, bounces back off a segment, because a body whose path crossed into a fixed
''' body leaves by the side it came in by. Momentum is conserved in every contact of two movable bodies.
''' </summary>
Public Class ShapeFixedBodiesWinTests
    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub TinyBallAt10To4MetresPerSecond_BouncesBackOffASegment(solver As String)
        Dim w As New World(4.0, 3.0, 0, 1.0)
        w.Add(New Segment(New Vector(2, 0.5), New Vector(2, 2.5), "plate"))
        Dim ball As New Circle(New Vector(1.5, 1.5), 0.001, 0.01, New Vector(10000.0, 0), "fast")
        w.Add(ball)
        TestSolvers.Run(w, solver)
        Dim records As New List(Of CollisionRecord)
        w.CollisionListener = Sub(r) records.Add(r)
        Dim dt = w.Solver.TimeStep.Value
        For k = 1 To 50
            w.Advance(dt)
            Assert.True(ball.Position.X < 2, $"the ball is beyond the plate at x = {ball.Position.X}, t = {w.Time}")
        Next
        Dim first = records(0)
        Assert.Equal("plate", first.BName)
        Assert.Equal("circle-segment", first.KindName)
        Assert.Equal(-10000.0, first.AVelocityAfter.X, 6)
        Assert.Equal(10000.0, ball.Velocity.Length, 6)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub FastBoxAndPolygon_BounceBackOffASegment(solver As String)
        ' 100 m/s: 10 cm a step, far more than the 2 cm bodies.
        Dim w As New World(4.0, 3.0, 0, 1.0)
        w.Add(New Segment(New Vector(2, 0.5), New Vector(2, 2.5), "plate"))
        Dim box = Rectangle.CreateMovable(New Vector(1.5, 1.0), 0.02, 0.02, 1.0, New Vector(100, 0), "box")
        Dim tri As New Polygon({New Vector(1.5, 2.0), New Vector(1.52, 2.0), New Vector(1.51, 2.02)}, 1.0, New Vector(100, 0), "tri")
        w.Add(box)
        w.Add(tri)
        TestSolvers.Run(w, solver)
        For k = 1 To 200
            w.Advance(w.Solver.TimeStep.Value)
            Assert.True(box.BoundsMax.X <= 2 + 1.0E-12, $"the box reached x = {box.BoundsMax.X} at t = {w.Time}")
            Assert.True(tri.BoundsMax.X <= 2 + 1.0E-12, $"the triangle reached x = {tri.BoundsMax.X} at t = {w.Time}")
        Next
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub HeavyBoxDrivingALightBall_OntoASegment_NeverPushesItThrough(solver As String)
        ' A 10⁶ kg box at 30 m/s drives a 1 g ball down onto a shelf of no thickness.
        Dim w As New World(4.0, 4.0, 9.81, 1.0)
        w.Add(New Segment(New Vector(0.5, 1.0), New Vector(3.5, 1.0), "shelf"))
        Dim light As New Circle(New Vector(2.0, 1.05), 0.05, 0.001, id:="light")
        Dim heavy = Rectangle.CreateMovable(New Vector(1.7, 1.2), 0.6, 0.4, 1000000.0, New Vector(0, -30), "heavy")
        w.Add(light)
        w.Add(heavy)
        TestSolvers.Run(w, solver)
        For k = 1 To 300
            w.Advance(0.001)
            For Each b In {CType(light, Shape), heavy}
                Dim c = b.CentreOfMass
                If c.X > 0.5 AndAlso c.X < 3.5 Then Assert.True(c.Y > 1.0, $"{b.Id} went through the shelf: y = {c.Y} at t = {w.Time}")
            Next
        Next
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub RandomScenesWithEveryKind_NoCentreEverEndsAStepInsideAFixedBody_OrCrossesASegment(solver As String)
        For seed = 1 To 6
            Dim w = MixedScenes.Build(seed, 25, 9.81, 0.5)
            TestSolvers.Run(w, solver)
            Dim dt = w.Solver.TimeStep.Value
            Dim segments = w.Segments.ToList()
            ' Which side of each segment each body's centre is on, while it is over the segment.
            Dim sides As New Dictionary(Of (Shape, Segment), Integer)
            For k = 1 To 1500
                w.Advance(dt)
                For Each b In w.Movables
                    Assert.True(b.Position.IsFinite AndAlso b.Velocity.IsFinite, $"seed {seed}: {b.Id} is not finite")
                    Assert.True(b.BoundsMin.X >= -1.0E-9 AndAlso b.BoundsMin.Y >= -1.0E-9 AndAlso b.BoundsMax.X <= w.Width + 1.0E-9 AndAlso b.BoundsMax.Y <= w.Height + 1.0E-9,
                                $"seed {seed}: {b.Id} is outside the container at t = {w.Time}")
                    Dim holder = MixedScenes.FixedHoldingCentre(w, b)
                    Assert.True(holder Is Nothing, $"seed {seed}: {b.Id} ({b.KindName}) has its centre inside {holder?.Id} at t = {w.Time}")
                    Dim c = b.CentreOfMass
                    For Each s In segments
                        Dim along = s.EndPoint - s.StartPoint
                        Dim u = Vector.Dot(c - s.StartPoint, along) / along.LengthSquared
                        Dim key = (CType(b, Shape), s)
                        If u <= 0 OrElse u >= 1 Then
                            sides.Remove(key)
                            Continue For
                        End If
                        Dim side = Math.Sign(Vector.Cross(along, c - s.StartPoint))
                        Dim before As Integer
                        If sides.TryGetValue(key, before) AndAlso side <> 0 Then
                            Assert.True(before = side, $"seed {seed}: {b.Id} ({b.KindName}) crossed {s.Id} at t = {w.Time}")
                        End If
                        If side <> 0 Then sides(key) = side
                    Next
                Next
            Next
        Next
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub EveryContactOfTwoMovableBodies_ConservesMomentum(solver As String)
        For Each gravity In {0.0, 9.81}
            For seed = 11 To 13
                Dim w = MixedScenes.Build(seed, 30, gravity, 0.7)
                TestSolvers.Run(w, solver)
                Dim pairs = 0
                Dim kinds As New HashSet(Of String)
                w.CollisionListener =
                    Sub(r)
                        If r.B Is Nothing OrElse r.B.IsFixed Then Return
                        pairs += 1
                        kinds.Add(r.KindName)
                        Dim before = r.A.Mass * r.AVelocityBefore + r.B.Mass * r.BVelocityBefore
                        Dim after = r.A.Mass * r.AVelocityAfter + r.B.Mass * r.BVelocityAfter
                        Dim scale = r.A.Mass * r.AVelocityBefore.Length + r.B.Mass * r.BVelocityBefore.Length
                        Assert.True((after - before).Length <= 1.0E-12 * scale, $"{r.KindName} at t = {r.Time}: momentum changed by {(after - before).Length} of {scale}")
                        ' Newton's law along the normal: the pair separates (e > 0) or moves together.
                        Dim n = (r.AVelocityAfter - r.AVelocityBefore).Normalized(Vector.Zero)
                        Assert.True(Vector.Dot(r.AVelocityAfter - r.BVelocityAfter, n) >= -1.0E-9 * scale / Math.Min(r.A.Mass, r.B.Mass))
                    End Sub
                TestSolvers.Frames(w, 2.0, 1.0 / 60)
                Assert.True(pairs > 10, $"seed {seed}, g = {gravity}: only {pairs} contacts between movable bodies")
                Assert.True(kinds.Count >= 3, $"seed {seed}, g = {gravity}: only {String.Join(", ", kinds)}")
            Next
        Next
    End Sub
End Class
