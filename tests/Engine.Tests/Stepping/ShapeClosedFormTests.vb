Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' Boxes, polygons, segments and slopes in the stepping solvers, against closed forms to O(dt): the
''' stepping solvers find a contact up to one step late, so each tolerance is a small multiple of what
''' one step can add (g·dt of speed, g·dt² of depth), and the test says which.
''' </summary>
Public Class ShapeClosedFormTests
    Private Const G As Double = 9.81

    Private Shared Function StepOf(w As World) As Double
        Return w.Solver.TimeStep.Value
    End Function

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub BoxDroppedOnTheFloor_ReboundsAtENTimesV0_AndNeverGoesBelowIt(solver As String)
        Const e = 0.8, drop = 1.0
        Dim w As New World(2.0, 3.0, G, e)
        Dim box = Rectangle.CreateMovable(New Vector(0.8, drop), 0.4, 0.2, 2.0, id:="box")
        w.Add(box)
        TestSolvers.Run(w, solver)
        Dim records As New List(Of CollisionRecord)
        w.CollisionListener = Sub(r) records.Add(r)
        Dim dt = StepOf(w)
        ' Step by step: at the end of every step the box's bottom is on or above the floor.
        For k = 1 To 2600
            w.Advance(dt)
            Assert.True(box.Position.Y >= -1.0E-12, $"the box is {-box.Position.Y} m below the floor at t = {w.Time}")
        Next
        Assert.True(records.Count >= 4, $"only {records.Count} bounces")
        Dim v0 = Math.Sqrt(2 * G * drop)
        For n = 1 To 4
            Dim r = records(n - 1)
            Assert.Equal("rectangle-wall", r.KindName)
            Assert.Equal(WallSide.Bottom, r.Wall)
            ' Each bounce may be found a step late, so its speed may be off by about g·dt; the errors add up.
            Assert.InRange(r.AVelocityAfter.Y - Math.Pow(e, n) * v0, -n * G * dt, n * G * dt)
            Assert.Equal(0.0, r.AVelocityAfter.X)
        Next
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub BoxDroppedOnASegmentFloor_BouncesAsOnTheWall(solver As String)
        ' The same drop onto a fixed segment 0.5 m up: the path-aware contact of a box with a segment.
        Const e = 0.8, drop = 1.0
        Dim w As New World(2.0, 3.0, G, e)
        w.Add(New Segment(New Vector(0, 0.5), New Vector(2, 0.5), "shelf"))
        Dim box = Rectangle.CreateMovable(New Vector(0.8, 0.5 + drop), 0.4, 0.2, 2.0, id:="box")
        w.Add(box)
        TestSolvers.Run(w, solver)
        Dim records As New List(Of CollisionRecord)
        w.CollisionListener = Sub(r) records.Add(r)
        Dim dt = StepOf(w)
        For k = 1 To 2600
            w.Advance(dt)
            Assert.True(box.Position.Y >= 0.5 - 1.0E-12, $"the box is {0.5 - box.Position.Y} m into the shelf at t = {w.Time}")
        Next
        Dim v0 = Math.Sqrt(2 * G * drop)
        For n = 1 To 4
            Assert.Equal("rectangle-segment", records(n - 1).KindName)
            Assert.Equal("shelf", records(n - 1).BName)
            Assert.InRange(records(n - 1).AVelocityAfter.Y - Math.Pow(e, n) * v0, -n * G * dt, n * G * dt)
        Next
    End Sub

    ''' <summary>A 3 m ramp at 30° (a segment), a ball and a box placed on it at rest, e = 0.5.</summary>
    Private Shared Function Ramp(solver As String, theta As Double) As (World As World, Ball As Circle, Box As Rectangle, Down As Vector, Normal As Vector)
        Dim w As New World(4.0, 3.0, G, 0.5)
        Dim top = New Vector(0.2, 2.5)
        Dim down = New Vector(Math.Cos(theta), -Math.Sin(theta))
        Dim normal = New Vector(Math.Sin(theta), Math.Cos(theta))
        w.Add(New Segment(top, top + 3 * down, "ramp"))
        Const r = 0.05
        Dim ball As New Circle(top + 0.3 * down + r * normal, r, 1.0, id:="ball")
        w.Add(ball)
        ' The box's lower-left corner on the ramp: the ramp meets the box only at that corner.
        Dim box = Rectangle.CreateMovable(top + 1.2 * down, 0.1, 0.1, 1.0, id:="box")
        w.Add(box)
        TestSolvers.Run(w, solver)
        Return (w, ball, box, down, normal)
    End Function

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub BallAndBoxPlacedAtRestOnA30DegreeSlope_SlideHalfGSinThetaTSquared(solver As String)
        Dim theta = Math.PI / 6
        Dim s = Ramp(solver, theta)
        Dim records As New List(Of CollisionRecord)
        s.World.CollisionListener = Sub(r) records.Add(r)
        Dim ball0 = s.Ball.Position, box0 = s.Box.Position
        Const t = 0.6
        TestSolvers.Frames(s.World, t, 1.0 / 60)
        Dim dt = StepOf(s.World)
        Dim a = G * Math.Sin(theta)
        Dim expected = 0.5 * a * t * t
        For Each body In {CType(s.Ball, Shape), s.Box}
            Dim moved = body.Position - If(body Is s.Ball, ball0, box0)
            ' Semi-implicit Euler is first order: s is off by ½ a dt t, so allow a dt t.
            Assert.InRange(Vector.Dot(moved, s.Down) - expected, -a * dt * t, a * dt * t)
            ' It stays on the slope: within what one step sinks it.
            Assert.InRange(Vector.Dot(moved, s.Normal), -G * dt * dt, G * dt * dt)
            Assert.InRange(Vector.Dot(body.Velocity, s.Down) - a * t, -a * dt, a * dt)
        Next
        ' Resting on the slope is not a collision.
        Assert.Empty(records)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub TwoBoxesHeadOn_MassesOneAndThree_EOneHalf_FollowTheOneDimensionalClosedForm(solver As String)
        Const m1 = 1.0, u1 = 2.0, m2 = 3.0, u2 = -1.0, e = 0.5
        Dim w As New World(10.0, 2.0, 0, e, walls:=False)
        Dim b1 = Rectangle.CreateMovable(New Vector(2, 1), 0.2, 0.2, m1, New Vector(u1, 0), "b1")
        Dim b2 = Rectangle.CreateMovable(New Vector(5, 0.9), 0.3, 0.3, m2, New Vector(u2, 0), "b2")
        w.Add(b1)
        w.Add(b2)
        TestSolvers.Run(w, solver)
        Dim records As New List(Of CollisionRecord)
        w.CollisionListener = Sub(r) records.Add(r)
        w.Advance(3.0)
        Dim v1 = (m1 * u1 + m2 * u2 + m2 * e * (u2 - u1)) / (m1 + m2)
        Dim v2 = (m1 * u1 + m2 * u2 + m1 * e * (u1 - u2)) / (m1 + m2)
        ' The faces are vertical, so the normal is exactly x and the impulse is the textbook one to rounding.
        Assert.Equal(v1, b1.Velocity.X, 9)
        Assert.Equal(v2, b2.Velocity.X, 9)
        Assert.Equal(0.0, b1.Velocity.Y)
        Assert.Equal(0.0, b2.Velocity.Y)
        Dim hit = Assert.Single(records)
        Assert.Equal("rectangle-rectangle", hit.KindName)
        Assert.Equal(CollisionKind.Other, hit.Kind)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub BoxSlidingOnTheFloorIntoAWall_StaysOnTheFloor_AndReboundsAtEV(solver As String)
        Const e = 0.8, speed = 1.5
        Dim w As New World(2.0, 1.0, G, e)
        Dim box = Rectangle.CreateMovable(New Vector(1.0, 0), 0.3, 0.2, 1.0, New Vector(speed, 0), "box")
        w.Add(box)
        TestSolvers.Run(w, solver)
        Dim records As New List(Of CollisionRecord)
        w.CollisionListener = Sub(r) records.Add(r)
        TestSolvers.Frames(w, 1.0, 1.0 / 60, Sub() Assert.Equal(0.0, box.Position.Y, 12))
        Dim hit = Assert.Single(records)
        Assert.Equal(WallSide.Right, hit.Wall)
        Assert.Equal("rectangle-wall", hit.KindName)
        Assert.Equal(-e * speed, box.Velocity.X, 9)
        Assert.Equal(0.0, box.Velocity.Y, 12)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub BoxSlidingOnASegmentIntoAFixedRectangle_StaysOnTheSegment(solver As String)
        Const e = 0.5, speed = 1.0
        Dim w As New World(3.0, 2.0, G, e)
        w.Add(New Segment(New Vector(0, 0.4), New Vector(3, 0.4), "floor"))
        w.Add(New Rectangle(New Vector(2.0, 0.4), 0.2, 1.0, "post"))
        Dim box = Rectangle.CreateMovable(New Vector(1.0, 0.4), 0.3, 0.2, 1.0, New Vector(speed, 0), "box")
        w.Add(box)
        TestSolvers.Run(w, solver)
        Dim records As New List(Of CollisionRecord)
        w.CollisionListener = Sub(r) records.Add(r)
        Dim dt = StepOf(w)
        TestSolvers.Frames(w, 1.5, 1.0 / 60, Sub() Assert.InRange(box.Position.Y - 0.4, -G * dt * dt, G * dt * dt))
        Dim hit = Assert.Single(records)
        Assert.Equal("post", hit.BName)
        Assert.Equal("rectangle-rectangle", hit.KindName)
        Assert.Equal(-e * speed, box.Velocity.X, 9)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub BallInAVOfTwo45DegreeSegments_EndsTouchingBothSides_NeverCrossingOne(solver As String)
        Dim w As New World(4.0, 3.0, G, 0.5)
        Dim apex = New Vector(2, 0.5)
        w.Add(New Segment(apex, apex + New Vector(-1.2, 1.2), "left"))
        w.Add(New Segment(apex, apex + New Vector(1.2, 1.2), "right"))
        Const r = 0.1
        Dim ball As New Circle(New Vector(2.3, 2.0), r, 1.0, id:="ball")
        w.Add(ball)
        TestSolvers.Run(w, solver)
        Dim records As New List(Of CollisionRecord)
        w.CollisionListener = Sub(c) records.Add(c)
        Dim dt = StepOf(w)
        ' The distance from each side's line, on the inside of the V: never below the radius by more than a step's sinking.
        Dim inward = {New Vector(1, 1) / Math.Sqrt(2), New Vector(-1, 1) / Math.Sqrt(2)}
        TestSolvers.Frames(w, 10.0, 1.0 / 60,
            Sub()
                For Each n In inward
                    Assert.True(Vector.Dot(ball.Position - apex, n) > 0, $"the ball crossed a side at t = {w.Time}")
                Next
            End Sub)
        ' At rest in the bottom of the V, touching both sides: its centre r·√2 above the apex.
        Assert.Equal(2.0, ball.Position.X, 5)
        Assert.InRange(ball.Position.Y - (apex.Y + r * Math.Sqrt(2)), -G * dt * dt, G * dt * dt)
        Assert.True(ball.Velocity.Length < G * dt, $"still moving at {ball.Velocity.Length} m/s")
        Assert.All(records, Sub(c) Assert.Equal("circle-segment", c.KindName))
        Assert.True(records.Count < 100, $"{records.Count} collisions")
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub StackOfBoxesAndABall_Settles_WithNoOverlap_AndThenNoCollisions(solver As String)
        ' Masses 1, 10 and 100 kg from the bottom up, a ball on top, e = 0.3, dropped with gaps.
        Dim w As New World(2.0, 3.0, G, 0.3)
        Dim bottom = Rectangle.CreateMovable(New Vector(0.8, 0.0), 0.4, 0.2, 1, id:="b1")
        Dim middle = Rectangle.CreateMovable(New Vector(0.85, 0.3), 0.3, 0.2, 10, id:="b2")
        Dim top = Rectangle.CreateMovable(New Vector(0.9, 0.6), 0.2, 0.2, 100, id:="b3")
        Dim ball As New Circle(New Vector(1.0, 1.0), 0.05, 0.1, id:="ball")
        For Each b In {CType(bottom, Shape), middle, top, ball}
            w.Add(b)
        Next
        TestSolvers.Run(w, solver)
        Dim count = 0
        w.CollisionListener = Sub(c) count += 1
        TestSolvers.Frames(w, 3.0, 1.0 / 60)
        Dim settled = count
        TestSolvers.Frames(w, 1.0, 1.0 / 60)
        Assert.Equal(settled, count)
        Dim dt = StepOf(w)
        ' Each rests on the one below: bottom faces at 0, 0.2, 0.4 and the ball's centre at 0.65 m.
        Assert.InRange(bottom.Position.Y, 0, G * dt * dt)
        Assert.InRange(middle.Position.Y - 0.2, -G * dt * dt, G * dt * dt)
        Assert.InRange(top.Position.Y - 0.4, -G * dt * dt, G * dt * dt)
        Assert.InRange(ball.Position.Y - 0.65, -G * dt * dt, G * dt * dt)
        For Each b In w.Movables
            Assert.True(b.Velocity.Length < G * dt, $"{b.Id} moves at {b.Velocity.Length} m/s")
        Next
    End Sub
End Class
