Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' Resting and sliding on any support, with the event solver: down a frictionless slope exactly
''' (s = ½ g sin θ t²), round the end of a ramp and over a fixed circle (leaving where the normal
''' force vanishes), into the bottom of a V, and boxes stacked on boxes — each in finitely many events.
''' </summary>
Public Class SupportTests
    Private Const G As Double = 9.81

    ''' <summary>A segment from (x0, y0) going down to the right at angle θ (rad), length L (m).</summary>
    Private Shared Function Ramp(x0 As Double, y0 As Double, theta As Double, length As Double, Optional id As String = "ramp") As Segment
        Return New Segment(New Vector(x0, y0), New Vector(x0 + length * Math.Cos(theta), y0 - length * Math.Sin(theta)), id)
    End Function

    <Theory>
    <InlineData(30.0)>
    <InlineData(10.0)>
    <InlineData(60.0)>
    <InlineData(1.0)>
    <InlineData(0.25)>
    Public Sub BallAtRestOnASlope_SlidesDownIt_AsHalfGSinThetaTSquared(degrees As Double)
        Dim theta = degrees * Math.PI / 180
        Dim w As New World(20, 12, G, 0.5)
        Dim ramp = SupportTests.Ramp(0.5, 11, theta, 12)
        w.Add(ramp)
        Dim r = 0.1
        ' Touching the ramp at 2 m along it, at rest.
        Dim along = New Vector(Math.Cos(theta), -Math.Sin(theta))
        Dim n = New Vector(Math.Sin(theta), Math.Cos(theta))
        Dim start = ramp.StartPoint + along * 2 + n * r
        Dim ball As New Circle(start, r, 1.0, id:="ball")
        w.Add(ball)
        Dim solver = UseEventSolver(w)
        For k = 1 To 10
            w.Advance(0.1)
            Dim t = w.Time
            Dim s = 0.5 * G * Math.Sin(theta) * t * t
            Dim expected = start + along * s
            Assert.True((ball.Position - expected).Length <= 1.0E-9, $"{degrees}°, t = {t}: at {ball.Position}, expected {expected}")
            Dim v = along * (G * Math.Sin(theta) * t)
            Assert.True((ball.Velocity - v).Length <= 1.0E-9, $"{degrees}°, t = {t}: velocity {ball.Velocity}, expected {v}")
        Next
        Assert.True(solver.EventCount < 100, $"{solver.EventCount} events for a plain slide")
    End Sub

    <Fact>
    Public Sub BoxAtRestOnASlope_SlidesOnItsCorner_AsHalfGSinThetaTSquared()
        Dim theta = 25 * Math.PI / 180
        Dim w As New World(20, 12, G, 0.3)
        Dim ramp = SupportTests.Ramp(0.5, 11, theta, 12)
        w.Add(ramp)
        ' An upright box resting on its lower-left corner, 3 m along the ramp.
        Dim along = New Vector(Math.Cos(theta), -Math.Sin(theta))
        Dim corner = ramp.StartPoint + along * 3
        Dim box = Rectangle.CreateMovable(corner, 0.4, 0.3, 2.0, id:="box")
        w.Add(box)
        UseEventSolver(w)
        For k = 1 To 10
            w.Advance(0.1)
            Dim t = w.Time
            Dim expected = corner + along * (0.5 * G * Math.Sin(theta) * t * t)
            Assert.True((box.Position - expected).Length <= 1.0E-9, $"t = {t}: at {box.Position}, expected {expected}")
        Next
    End Sub

    <Fact>
    Public Sub BallInAVOfTwo45DegreeSides_e05_EndsTouchingBoth_InFewEvents_NeverCrossingASide()
        Dim w As New World(10, 10, G, 0.5)
        ' The V's bottom at (5, 2); each side 3 m long at 45°.
        Dim bottom = New Vector(5, 2)
        Dim leftSide As New Segment(bottom + New Vector(-3, 3), bottom, "left")
        Dim rightSide As New Segment(bottom, bottom + New Vector(3, 3), "right")
        w.Add(leftSide)
        w.Add(rightSide)
        Dim r = 0.2
        Dim ball As New Circle(New Vector(4.3, 4.5), r, 1.0, New Vector(1.5, 0), "ball")
        w.Add(ball)
        Dim solver = UseEventSolver(w)
        For k = 1 To 1000
            w.Advance(0.01)
            ' Never across a side: the centre stays above both lines by about r.
            Dim d = ball.Position - bottom
            Assert.True((d.Y - d.X) / Math.Sqrt(2) >= r - 1.0E-9 AndAlso (d.Y + d.X) / Math.Sqrt(2) >= r - 1.0E-9, $"crossed a side at t = {w.Time}: {ball.Position}")
        Next
        ' At rest where it touches both sides: straight above the bottom, r √2 up.
        Dim rest = bottom + New Vector(0, r * Math.Sqrt(2))
        Assert.True((ball.Position - rest).Length <= 1.0E-6, $"ended at {ball.Position}, not {rest}")
        Assert.Equal(Vector.Zero, ball.Velocity)
        Assert.True(solver.EventCount < 100000, $"{solver.EventCount} events")
    End Sub

    <Fact>
    Public Sub BallNudgedOffTheTopOfAFixedCircle_LeavesAtCosThetaTwoThirds_KeepingItsEnergy()
        Dim w As New World(10, 10, G, 0.5)
        Dim radiusBig = 1.0, r = 0.1
        Dim centre = New Vector(5, 3)
        w.Add(Circle.CreateFixed(centre, radiusBig, "dome"))
        ' On top, a little to the right, at rest: it rolls off to the right.
        Dim rr = radiusBig + r
        Dim phi0 = 0.01
        Dim ball As New Circle(centre + New Vector(Math.Sin(phi0), Math.Cos(phi0)) * rr, r, 1.0, id:="ball")
        w.Add(ball)
        UseEventSolver(w)
        Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
        Dim leftAt As Vector? = Nothing
        For k = 1 To 4000
            w.Advance(0.0005)
            Dim energy = w.KineticEnergy() + w.PotentialEnergy()
            ' It leaves the dome ten slops (about 1e-10 m) clear of it, which lifts it by up to
            ' that height: m g 1e-10 m is about 1e-11 of this energy.
            Assert.True(energy <= e0 * (1 + 1.0E-10), $"energy grew from {e0} to {energy} at t = {w.Time}")
            Dim d = ball.Position - centre
            If leftAt Is Nothing AndAlso d.Length > rr + 1.0E-10 Then leftAt = d
            If leftAt IsNot Nothing AndAlso ball.Velocity.Y < -4 Then Exit For
        Next
        Assert.True(leftAt.HasValue, "it never left the dome")
        ' From rest at φ0 it leaves where cos φ = (2/3) cos φ0 (energy, and the normal force reaching zero).
        Dim expectedCos = 2.0 / 3 * Math.Cos(phi0)
        Dim actualCos = leftAt.Value.Y / leftAt.Value.Length
        Assert.True(Math.Abs(actualCos - expectedCos) < 2.0E-3, $"left at cos φ = {actualCos}, expected {expectedCos}")
    End Sub

    <Fact>
    Public Sub BallRoundingAFixedCircle_IsNotStoppedByABallFarAwayMovingTowardsIt()
        ' The slide is followed exactly until a neighbour could reach the disc it sweeps; a ball 4 m
        ' away, heading that way but falling to the floor long before, never can.
        Dim w As New World(10, 10, G, 0.5)
        Dim radiusBig = 1.0, r = 0.1
        Dim centre = New Vector(5, 3)
        w.Add(Circle.CreateFixed(centre, radiusBig, "dome"))
        Dim rr = radiusBig + r
        Dim phi0 = 0.01
        Dim ball As New Circle(centre + New Vector(Math.Sin(phi0), Math.Cos(phi0)) * rr, r, 1.0, id:="ball")
        w.Add(ball)
        w.Add(New Circle(New Vector(0.5, 1.0), 0.1, 1.0, New Vector(1, 0), id:="far"))
        Dim solver = UseEventSolver(w)
        Dim leftAt As Vector? = Nothing
        Dim eventsAtLeave As Long
        For k = 1 To 4000
            w.Advance(0.0005)
            Dim d = ball.Position - centre
            If leftAt Is Nothing AndAlso d.Length > rr + 1.0E-10 Then leftAt = d : eventsAtLeave = solver.EventCount
            If leftAt IsNot Nothing AndAlso ball.Velocity.Y < -4 Then Exit For
        Next
        Assert.True(leftAt.HasValue, "it never left the dome")
        Dim expectedCos = 2.0 / 3 * Math.Cos(phi0)
        Dim actualCos = leftAt.Value.Y / leftAt.Value.Length
        Assert.True(Math.Abs(actualCos - expectedCos) < 2.0E-3, $"left at cos φ = {actualCos}, expected {expectedCos}")
        ' Followed exactly, the whole slide is a handful of events; hopping round it takes thousands.
        Assert.True(eventsAtLeave < 200, $"{eventsAtLeave} events before it left the dome")
    End Sub

    <Fact>
    Public Sub BallSlidingDownARampThatEndsOnTheFloor_BouncesOnTheFloor_AndGoesOnAlongIt()
        ' The ramp meets the floor at (3, 0): the ball's lowest point reaches the floor before its
        ' contact point reaches the ramp's end, so the floor, not the ramp's end, must stop its fall.
        Dim theta = 30 * Math.PI / 180
        Dim w As New World(6, 4, G, 0.5)
        Dim ramp As New Segment(New Vector(3 - 3 * Math.Cos(theta), 3 * Math.Sin(theta)), New Vector(3, 0), "ramp")
        w.Add(ramp)
        Dim r = 0.1
        Dim along = New Vector(Math.Cos(theta), -Math.Sin(theta))
        Dim n = New Vector(Math.Sin(theta), Math.Cos(theta))
        Dim ball As New Circle(ramp.StartPoint + along * 0.5 + n * r, r, 1.0, id:="ball")
        w.Add(ball)
        UseEventSolver(w)
        Dim floorHits = 0
        w.CollisionListener = Sub(c) If c.Wall = WallSide.Bottom Then floorHits += 1
        Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
        Dim farthest = 0.0
        For k = 1 To 150
            w.Advance(0.01)
            Assert.True(ball.Position.Y >= r - 1.0E-9, $"below the floor at t = {w.Time}: y = {ball.Position.Y}")
            Assert.True(DistanceToSegment(ball.Position, ramp.StartPoint, ramp.EndPoint) >= r - 1.0E-9, $"inside the ramp at t = {w.Time}")
            Assert.True(w.KineticEnergy() + w.PotentialEnergy() <= e0 * (1 + 1.0E-12), $"energy grew at t = {w.Time}")
            farthest = Math.Max(farthest, ball.Position.X)
        Next
        ' Frictionless: the floor takes only the vertical part of its velocity; it goes on along the floor.
        Assert.True(floorHits > 0, "it never met the floor")
        Assert.True(farthest > 5, $"it stopped at x = {farthest} instead of going on along the floor")
    End Sub

    <Fact>
    Public Sub BallSlidingDownARamp_GoesRoundItsLowerEnd_AndFliesOff()
        Dim theta = 20 * Math.PI / 180
        Dim w As New World(20, 12, G, 0.5)
        Dim ramp = SupportTests.Ramp(1, 6, theta, 4)
        w.Add(ramp)
        Dim r = 0.1
        Dim along = New Vector(Math.Cos(theta), -Math.Sin(theta))
        Dim n = New Vector(Math.Sin(theta), Math.Cos(theta))
        Dim ball As New Circle(ramp.StartPoint + along * 0.5 + n * r, r, 1.0, id:="ball")
        w.Add(ball)
        UseEventSolver(w)
        Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
        Dim beyond = False
        For k = 1 To 600
            w.Advance(0.005)
            Assert.True(w.KineticEnergy() + w.PotentialEnergy() <= e0 * (1 + 1.0E-12), $"energy grew at t = {w.Time}")
            ' Never inside the ramp: its centre stays r or more from the segment.
            Dim toSegment = DistanceToSegment(ball.Position, ramp.StartPoint, ramp.EndPoint)
            Assert.True(toSegment >= r - 1.0E-9, $"inside the ramp at t = {w.Time}: {toSegment}")
            If ball.Position.X > ramp.EndPoint.X + r Then beyond = True
        Next
        Assert.True(beyond, "it never left the ramp's end")
    End Sub

    <Fact>
    Public Sub StackOfBoxes_SettlesWithoutOverlap_AndThenCostsNoEvents()
        Dim w As New World(4, 6, G, 0.3)
        For k = 0 To 4
            w.Add(Rectangle.CreateMovable(New Vector(1.5 + 0.02 * k, 0.1 + 0.7 * k), 0.8, 0.5, 1.0 + k))
        Next
        Dim solver = UseEventSolver(w)
        For k = 1 To 50
            w.Advance(0.1)
            Assert.True(ShapeCollisionTests.DeepestShapeOverlap(w) <= 1.0E-9, $"overlap {ShapeCollisionTests.DeepestShapeOverlap(w)} at {w.Time}")
        Next
        Dim events = solver.EventCount
        w.Advance(10.0)
        Assert.Equal(events, solver.EventCount)
        ' Each box on the one below it.
        Dim boxes = w.Movables.Cast(Of Rectangle)().OrderBy(Function(b) b.Position.Y).ToList()
        Assert.Equal(0.0, boxes(0).Position.Y)
        For k = 1 To boxes.Count - 1
            Assert.True(Math.Abs(boxes(k).Position.Y - (boxes(k - 1).Position.Y + 0.5)) <= 1.0E-6, $"box {k} at y = {boxes(k).Position.Y}")
        Next
    End Sub

    Private Shared Function DistanceToSegment(p As Vector, a As Vector, b As Vector) As Double
        Dim ab = b - a
        Dim s = Math.Max(0, Math.Min(1, Vector.Dot(p - a, ab) / Vector.Dot(ab, ab)))
        Return (p - (a + ab * s)).Length
    End Function
    <Fact>
    Public Sub BallDroppedBetweenAWallAndAPeg_ComesToRestTouchingBoth_InFewEvents()
        ' The gap (13 mm) is narrower than the ball (14 mm): it wedges there, held by the wall and the peg.
        Dim w As New World(0.2, 0.3, G, 0.5)
        Const rp = 0.005, r = 0.007
        Dim peg = New Vector(0.018, 0.1)
        w.Add(Circle.CreateFixed(peg, rp, "peg"))
        Dim ball As New Circle(New Vector(0.0075, 0.2), r, 0.005, id:="ball")
        w.Add(ball)
        Dim solver = UseEventSolver(w)
        w.Advance(1.0)
        Assert.True(solver.EventCount < 100000, $"{solver.EventCount} events")
        Assert.Equal(Vector.Zero, ball.Velocity)
        Assert.True(Math.Abs(ball.Position.X - r) <= 1.0E-6, $"x = {ball.Position.X}, not touching the wall")
        Assert.True(Math.Abs((ball.Position - peg).Length - (r + rp)) <= 1.0E-6, $"{(ball.Position - peg).Length - (r + rp)} m from the peg")
    End Sub

End Class
