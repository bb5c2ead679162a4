Option Strict On
Imports PhysicsEngine
Imports Xunit
Imports System.Linq

''' <summary>The cases that break naive stepping: coincident centres, overlapping spawns, extreme masses, g and sizes.</summary>
Public Class HardCaseTests
    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub CoincidentCentres_SeparateWithoutNaN(solver As String)
        Dim w As New World(4, 4, 9.81, 0.5)
        w.Add(New Circle(New Vector(2, 2), 0.2, 1.0, id:="a"))
        w.Add(New Circle(New Vector(2, 2), 0.2, 1.0, id:="b"))
        w.Add(Circle.CreateFixed(New Vector(1, 1), 0.3, "peg"))
        w.Add(New Circle(New Vector(1, 1), 0.1, 1.0, id:="on-peg"))
        w.Add(New Rectangle(New Vector(2.6, 0.5), 1.0, 0.6, "block"))
        w.Add(New Circle(New Vector(3.1, 0.8), 0.1, 1.0, id:="in-block"))
        TestSolvers.Run(w, solver)
        TestSolvers.Frames(w, 2.0, 1.0 / 60, Sub() Assert.True(SceneChecks.AllFinite(w)))
        Assert.InRange(SceneChecks.MaxOverlap(w), Double.NegativeInfinity, 1.0E-3)
        Assert.True((DirectCast(w.Find("a"), Circle).Position - DirectCast(w.Find("b"), Circle).Position).Length > 0.39)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub CircleSpawnedOverlappingOthers_InZeroG_SeparatesWithoutGainingSpeed(solver As String)
        ' A 3 × 3 block of touching circles at rest, and a fourth circle dropped on its centre point.
        ' Static resolution moves positions only, so nothing may start moving.
        Dim w As New World(4, 4, 0.0, 1.0)
        For i = 0 To 2
            For j = 0 To 2
                w.Add(New Circle(New Vector(1.8 + 0.2 * i, 1.8 + 0.2 * j), 0.1, 1.0))
            Next
        Next
        TestSolvers.Run(w, solver)
        w.Advance(0.1)
        Dim spawned As New Circle(New Vector(1.9, 1.9), 0.1, 1.0, id:="spawned")
        w.Add(spawned)
        TestSolvers.Frames(w, 2.0, 1.0 / 60, Sub() Assert.True(SceneChecks.AllFinite(w)))
        Assert.InRange(SceneChecks.MaxOverlap(w), Double.NegativeInfinity, 1.0E-9)
        Assert.InRange(w.KineticEnergy(), 0.0, 1.0E-20)
        Assert.Equal(0L, w.CollisionCount)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub CircleSpawnedInsideAPile_UnderGravity_SeparatesWithoutAnExplosion(solver As String)
        Dim w As New World(1.0, 2.0, 9.81, 0.5)
        For i = 0 To 4
            w.Add(New Circle(New Vector(0.1 + 0.2 * i, 0.1), 0.1, 1.0))
        Next
        TestSolvers.Run(w, solver)
        TestSolvers.Frames(w, 0.5, 1.0 / 60)
        Dim before = w.KineticEnergy() + w.PotentialEnergy()
        Dim spawned As New Circle(New Vector(0.3, 0.12), 0.1, 1.0, id:="spawned")
        w.Add(spawned)
        before += spawned.Mass * w.Gravity * spawned.Position.Y
        Dim highest = 0.0
        TestSolvers.Frames(w, 2.0, 1.0 / 60, Sub()
                                                  Assert.True(SceneChecks.AllFinite(w))
                                                  highest = Math.Max(highest, w.KineticEnergy() + w.PotentialEnergy())
                                              End Sub)
        ' The worst the spawned ball can be given is being lifted out of the pile by its own diameter.
        Assert.InRange(highest, 0.0, before + spawned.Mass * w.Gravity * 2 * spawned.Radius)
        Assert.InRange(SceneChecks.MaxOverlap(w), Double.NegativeInfinity, 1.0E-3)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub HeavyBallRestingOnALightOne_DoesNotSinkThroughIt(solver As String)
        ' Mass ratio 1 : 10⁶ in a resting stack: the floor must hold the heavy ball up through the light one.
        Dim w As New World(2.0, 2.0, 9.81, 0.5)
        Dim light As New Circle(New Vector(1.0, 0.1), 0.1, 1.0, id:="light")
        Dim heavy As New Circle(New Vector(1.0, 0.4), 0.2, 1000000.0, id:="heavy")
        w.Add(light)
        w.Add(heavy)
        TestSolvers.Run(w, solver)
        TestSolvers.Frames(w, 2.0, 1.0 / 60, Sub()
                                                  Assert.True(SceneChecks.AllFinite(w))
                                                  Assert.InRange(SceneChecks.MaxOverlap(w), Double.NegativeInfinity, 1.0E-3)
                                              End Sub)
        Assert.InRange(light.Position.Y, 0.1 - 1.0E-6, 0.1 + 1.0E-6)
        Assert.InRange(heavy.Position.Y, 0.4 - 1.0E-3, 0.4 + 1.0E-6)
        Assert.InRange(heavy.Velocity.Length, 0.0, 1.0E-6)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub LightBallBetweenAHeavyBallAndAWall_KeepsTheBooksBalanced(solver As String)
        ' Mass ratio 1 : 10⁶, g = 0, e = 1 (the π-collisions set-up): the light ball is squeezed between the
        ' wall and the heavy ball and speeds up to about 1000 m/s. No NaN, no energy gained, order kept,
        ' and in the end the heavy ball is sent back. At the default 1 ms step the light ball would move its
        ' own diameter (1 m) per step and tunnel through the heavy one (the limit of any stepping solver,
        ' and why the event-driven one exists), so the step here is 0.1 ms: 10 cm per step at 1000 m/s.
        Dim w = TestSolvers.Run(Scenarios.PiCollisions(3), solver, 0.0001)
        Dim small = DirectCast(w.Find("small"), Circle), big = DirectCast(w.Find("big"), Circle)
        Dim e0 = w.KineticEnergy()
        TestSolvers.Frames(w, 10.0, 1.0 / 60, Sub()
                                                   Assert.True(SceneChecks.AllFinite(w))
                                                   Assert.True(small.Position.X < big.Position.X, "the light ball got past the heavy one")
                                                   Assert.InRange(w.KineticEnergy(), 0.0, e0 * (1 + 1.0E-9))
                                               End Sub)
        Assert.True(big.Velocity.X > 0, "the heavy ball should be moving away from the wall")
        Assert.True(w.CollisionCount > 100, $"only {w.CollisionCount} collisions")
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub ZeroGravity_BallMovesStraight_AndAWallTakesEOfItsSpeed(solver As String)
        Dim w As New World(4.0, 2.0, 0.0, 0.5)
        Dim ball As New Circle(New Vector(2.0, 1.0), 0.1, 1.0, New Vector(2.0, 0.0))
        w.Add(ball)
        TestSolvers.Run(w, solver)
        w.Advance(0.5)
        Assert.Equal(3.0, ball.Position.X, 9)
        Assert.Equal(1.0, ball.Position.Y, 12)
        w.Advance(0.5) ' hits the right wall (x = 3.9) at 0.95 s
        Assert.Equal(-1.0, ball.Velocity.X, 9)
        Assert.Equal(0.0, ball.Velocity.Y, 12)
        Assert.Equal(1L, w.CollisionCount)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub StrongGravity_BallBouncesToE2TimesTheDropHeight_ThenRests(solver As String)
        ' g = 100 m/s², e = 0.5, dropped from 1 m: the first rebound peaks at e² h = 0.25 m. The collision is
        ' found up to one step late, which misplaces the bounce by up to v dt (1.4 cm at 14 m/s), so
        ' allow 2 v dt on the apex.
        Const g = 100.0, e = 0.5, h = 1.0
        Dim w = TestSolvers.Run(Scenarios.BouncingBall(h, e, g), solver)
        Dim ball = w.Circles(0)
        Dim floorY = ball.Radius
        Dim bounced = False, apex = 0.0
        w.CollisionListener = Sub(r) bounced = True
        Dim dt = w.Solver.TimeStep.Value
        Do While Not bounced
            w.Advance(dt)
        Loop
        Do While ball.Velocity.Y > 0 OrElse apex = 0
            w.Advance(dt)
            apex = Math.Max(apex, ball.Position.Y - floorY)
        Loop
        Dim tolerance = 2 * Math.Sqrt(2 * g * h) * dt
        Assert.InRange(apex, e * e * h - tolerance, e * e * h + tolerance)
        TestSolvers.Frames(w, 3.0, 1.0 / 60)
        Assert.InRange(ball.Velocity.Length, 0.0, 1.0E-6)
        Assert.InRange(ball.Position.Y, floorY - 1.0E-6, floorY + 1.0E-6)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub TinyAndHugeRadiiInOneScene_StayApartAndInside(solver As String)
        ' Radii 0.001 m and 2 m together: grains poured on a big ball in a 10 m box.
        Dim w As New World(10.0, 10.0, 9.81, 0.8)
        Dim big As New Circle(New Vector(5.0, 2.0), 2.0, 100.0, id:="big")
        w.Add(big)
        Dim rng As New Random(5)
        For i = 1 To 40
            w.Add(New Circle(New Vector(3.5 + 3 * rng.NextDouble(), 4.5 + 4 * rng.NextDouble()), 0.001, 0.000001, New Vector(rng.NextDouble() - 0.5, 0)))
        Next
        TestSolvers.Run(w, solver)
        Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
        TestSolvers.Frames(w, 3.0, 1.0 / 60, Sub()
                                                  Assert.True(SceneChecks.AllFinite(w))
                                                  Assert.InRange(w.KineticEnergy() + w.PotentialEnergy(), 0.0, e0 * (1 + 1.0E-9))
                                              End Sub)
        For Each c In w.Circles
            If c Is big Then Continue For
            Assert.True((c.Position - big.Position).Length >= big.Radius + c.Radius - 1.0E-3, $"grain {c.Id} is inside the big ball")
            Assert.InRange(c.Position.X, c.Radius - 1.0E-9, w.Width - c.Radius + 1.0E-9)
            Assert.InRange(c.Position.Y, c.Radius - 1.0E-9, w.Height - c.Radius + 1.0E-9)
        Next
        Assert.InRange(big.Position.Y, 2.0 - 1.0E-3, 2.0 + 1.0E-6)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub ColumnOfBalls_RestsWithoutSinking(solver As String)
        ' Four equal balls stacked one above the other on the floor, e = 0.5.
        Dim w As New World(1.0, 2.0, 9.81, 0.5)
        For i = 0 To 3
            w.Add(New Circle(New Vector(0.5, 0.1 + 0.2 * i), 0.1, 1.0))
        Next
        TestSolvers.Run(w, solver)
        TestSolvers.Frames(w, 2.0, 1.0 / 60)
        Dim logged = w.CollisionCount
        TestSolvers.Frames(w, 1.0, 1.0 / 60, Sub() Assert.InRange(SceneChecks.MaxOverlap(w), Double.NegativeInfinity, 1.0E-6))
        For i = 0 To 3
            Dim c = w.Circles(i)
            Assert.InRange(c.Position.Y, 0.1 + 0.2 * i - 1.0E-6, 0.1 + 0.2 * i + 1.0E-6)
            Assert.InRange(c.Velocity.Length, 0.0, 1.0E-6)
        Next
        Assert.Equal(logged, w.CollisionCount)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub PyramidOfBalls_RestsQuietly(solver As String)
        ' Fifteen equal balls in a close-packed pyramid, e = 0.3: each rests on two below it. With no friction
        ' a pyramid on an open floor would spread, so the bottom row spans the box from wall to wall.
        Dim w As New World(1.0, 2.0, 9.81, 0.3)
        For row = 0 To 4
            For i = 0 To 4 - row
                w.Add(New Circle(New Vector(0.1 + 0.2 * i + 0.1 * row, 0.1 + 0.2 * Math.Sqrt(0.75) * row), 0.1, 1.0))
            Next
        Next
        Dim start = w.Circles.Select(Function(c) c.Position).ToArray()
        TestSolvers.Run(w, solver)
        ' Contacts are solved one after another, so the pyramid may creep by micrometres; a jittering or
        ' sinking one moves by millimetres (g dt² is 10 µm per step).
        TestSolvers.Frames(w, 2.0, 1.0 / 60, Sub() Assert.InRange(SceneChecks.MaxOverlap(w), Double.NegativeInfinity, 1.0E-5))
        Assert.Equal(0L, w.CollisionCount)
        For i = 0 To w.Circles.Count - 1
            Assert.True((w.Circles(i).Position - start(i)).Length < 1.0E-4, $"ball {i} moved from {start(i)} to {w.Circles(i).Position}")
            ' What is left is the speed gravity gives in part of one step before the contacts catch it.
            Assert.InRange(w.Circles(i).Velocity.Length, 0.0, 9.81 * w.Solver.TimeStep.Value)
        Next
    End Sub
End Class
