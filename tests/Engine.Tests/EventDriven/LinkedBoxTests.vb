Option Strict On
Imports PhysicsEngine
Imports PhysicsEngine.Tests.Links
Imports Xunit
Imports Xunit.Abstractions

Namespace EventDriven
    ''' <summary>
    ''' Boxes and polygons in a scene with links, in the event solver, against closed forms: the ballistic
    ''' pendulum (momentum in the blow, then the swing up to v'²/(2g)), a pendulum bob stopping dead on a box at
    ''' rest, a box on a vertical spring, a box bouncing to rest on the floor beside a pendulum, a polygon
    ''' pendulum's period, two boxes head on; the Verlet solver agreeing at O(dt); and what is still refused (resting
    ''' elsewhere is in <see cref="LinkedRestTests"/>).
    ''' </summary>
    Public Class LinkedBoxTests
        Private ReadOnly _output As ITestOutputHelper

        Public Sub New(output As ITestOutputHelper)
            _output = output
        End Sub

        ''' <summary>A movable box of the given size (m) and mass (kg) with its centre at <paramref name="centre"/>.</summary>
        Private Shared Function BoxAt(centre As Vector, width As Double, height As Double, mass As Double, Optional id As String = Nothing) As Rectangle
            Return Rectangle.CreateMovable(New Vector(centre.X - width / 2, centre.Y - height / 2), width, height, mass, Vector.Zero, id)
        End Function

        ' ---- The ballistic pendulum ----

        Private Shared Function BallisticPendulum(solver As String, kind As LinkKind, e As Double, ByRef box As Rectangle, ByRef ball As Circle, Optional dt As Double = 0.001) As World
            Dim w = NewWorld(solver, e, dt)
            Dim anchor As New Vector(5, 6)
            box = BoxAt(New Vector(5, 5), 0.2, 0.2, 2.0, "box")
            w.Add(box)
            w.Add(Link.CreateTie(kind, box, anchor, 1))
            ' Fired level at 10 m/s from 1 cm beside the box's face, at the height of its centre.
            ball = New Circle(New Vector(4.84, 5), 0.05, 0.5, New Vector(10, 0), "ball")
            w.Add(ball)
            Return w
        End Function

        <Theory>
        <InlineData(LinkKind.Rod)>
        <InlineData(LinkKind.String)>
        Public Sub BallisticPendulum_MomentumIsKeptInTheBlow_AndTheBoxSwingsUpToVSquaredOver2g(kind As LinkKind)
            Const E As Double = 0.5
            Dim box As Rectangle = Nothing, ball As Circle = Nothing
            Dim w = BallisticPendulum("event", kind, E, box, ball)
            Dim records As New List(Of CollisionRecord)
            w.CollisionListener = Sub(r) records.Add(r)
            w.Advance(0.01)
            Assert.Single(records)
            Dim hit = records(0)
            Assert.True(hit.A Is box AndAlso hit.B Is ball OrElse hit.A Is ball AndAlso hit.B Is box)
            Dim boxBefore = If(hit.A Is box, hit.AVelocityBefore, hit.BVelocityBefore), boxAfter = If(hit.A Is box, hit.AVelocityAfter, hit.BVelocityAfter)
            Dim ballBefore = If(hit.A Is ball, hit.AVelocityBefore, hit.BVelocityBefore), ballAfter = If(hit.A Is ball, hit.AVelocityAfter, hit.BVelocityAfter)
            ' Momentum in the blow, both components (the string is vertical, the blow level: it takes no share).
            Dim before = 0.5 * ballBefore + 2.0 * boxBefore, after = 0.5 * ballAfter + 2.0 * boxAfter
            Assert.True((after - before).Length < 0.000000000001 * before.Length, $"momentum {before} before, {after} after")
            ' Newton's experimental law, level: the ball arrives at 10 m/s (nothing pushes it sideways in flight).
            Assert.Equal(10.0, ballBefore.X, 12)
            Dim u = 0.5 * (1 + E) * 10 / 2.5
            Assert.Equal(u, boxAfter.X, 12)
            Assert.Equal(0.0, boxAfter.Y, 12)
            Assert.Equal((0.5 - E * 2.0) * 10 / 2.5, ballAfter.X, 12)
            ' Then the box is a pendulum from the bottom at u: the closed form, and at a quarter period it has risen u²/(2g).
            Dim swing As New Pendulum(New Vector(5, 6), 1, G, New Vector(5, 5), New Vector(u, 0))
            Dim worst = 0.0
            Dim quarter = hit.Time + swing.Period / 4
            Do While w.Time + 0.01 < quarter
                w.Advance(0.01)
                worst = Math.Max(worst, (box.CentreOfMass - swing.PositionAt(w.Time - hit.Time)).Length)
            Loop
            w.Advance(quarter - w.Time)
            worst = Math.Max(worst, (box.CentreOfMass - swing.PositionAt(w.Time - hit.Time)).Length)
            _output.WriteLine($"{kind}: {worst} m from the pendulum; height {box.CentreOfMass.Y - 5} m against {u * u / (2 * G)} m")
            Assert.True(worst < 0.000000001, $"{worst} m off the pendulum")
            Assert.Equal(u * u / (2 * G), box.CentreOfMass.Y - 5, 9)
            Assert.Equal(1.0, (box.CentreOfMass - New Vector(5, 6)).Length, 12)
            Assert.Single(records.Where(Function(r) r.A Is box OrElse r.B Is box))
        End Sub

        <Fact>
        Public Sub BallisticPendulum_Verlet_AgreesAtOrderDt()
            ' Verlet finds the blow a step late or early, so its box speed (and swing) is out by O(dt).
            Dim heights As New List(Of Double)
            For Each dt In {0.001, 0.0005}
                Dim box As Rectangle = Nothing, ball As Circle = Nothing
                Dim w = BallisticPendulum("verlet", LinkKind.Rod, 0.5, box, ball, dt)
                Dim highest = 0.0
                ' Past the turning point (about 0.55 s after the blow at 57°).
                For k = 1 To 800
                    w.Advance(0.001)
                    highest = Math.Max(highest, box.CentreOfMass.Y - 5)
                Next
                heights.Add(highest)
                _output.WriteLine($"dt = {dt}: highest {highest} m")
            Next
            Dim exact = 3.0 * 3.0 / (2 * G)
            Assert.True(Math.Abs(heights(0) - exact) < 0.02 * exact, $"{heights(0)} against {exact}")
            Assert.True(Math.Abs(heights(1) - exact) < 0.02 * exact, $"{heights(1)} against {exact}")
        End Sub

        ' ---- A pendulum bob strikes a box at rest on the floor ----

        Private Shared Function BobAndBox(solver As String, ByRef bob As Circle, ByRef box As Rectangle, Optional dt As Double = 0.001) As World
            Dim w = NewWorld(solver, 1.0, dt)
            Dim anchor As New Vector(5, 1.1)
            bob = AddPendulum(w, LinkKind.Rod, anchor, 1, -Math.PI / 3, 1.0)
            ' On the floor, its face where the bob's front is at the bottom of the swing.
            box = Rectangle.CreateMovable(New Vector(5.05, 0), 0.2, 0.2, 1.0, Vector.Zero, "box")
            w.Add(box)
            Return w
        End Function

        <Fact>
        Public Sub PendulumBobStrikesABoxAtRestOnTheFloor_EqualMassesElastic_TheBobStops_AndTheBoxSlidesOffAtItsSpeed()
            Dim bob As Circle = Nothing, box As Rectangle = Nothing
            Dim w = BobAndBox("event", bob, box)
            Dim records As New List(Of CollisionRecord)
            w.CollisionListener = Sub(r) records.Add(r)
            Dim swing As New Pendulum(New Vector(5, 1.1), 1, G, bob.Position, Vector.Zero)
            ' It reaches the bottom after a quarter period, at √(2gL(1 − cos 60°)) = √(gL).
            w.Advance(swing.Period / 4 + 0.001)
            Assert.Single(records)
            Dim hit = records(0)
            _output.WriteLine($"hit at {hit.Time} s (quarter period {swing.Period / 4} s); bob {bob.Velocity}, box {box.Velocity}")
            Assert.Equal(swing.Period / 4, hit.Time, 9)
            Dim v = Math.Sqrt(G * 1)
            Assert.Equal(v, hit.AVelocityBefore.X, 9)
            Assert.True(bob.Velocity.Length < 0.000000001, $"the bob still moves at {bob.Velocity}")
            Assert.Equal(hit.AVelocityBefore.X, box.Velocity.X, 12)
            Assert.Equal(0.0, box.Velocity.Y)
            ' The box slides off on the floor at that speed, exactly on it; the bob hangs still at the bottom.
            Dim t0 = hit.Time, x0 = 5.05
            For k = 1 To 50
                w.Advance(0.01)
                Assert.Equal(x0 + v * (w.Time - t0), box.Position.X, 9)
                Assert.Equal(0.0, box.Position.Y)
                Assert.True((bob.Position - New Vector(5, 0.1)).Length < 0.000000001, $"the bob is at {bob.Position}")
            Next
            Assert.Single(records)
        End Sub

        <Fact>
        Public Sub PendulumBobStrikesABox_Verlet_AgreesAtOrderDt()
            Dim speeds As New List(Of Double)
            For Each dt In {0.001, 0.0005}
                Dim bob As Circle = Nothing, box As Rectangle = Nothing
                Dim w = BobAndBox("verlet", bob, box, dt)
                w.Advance(0.8)
                speeds.Add(box.Velocity.X)
                _output.WriteLine($"dt = {dt}: box {box.Velocity}, bob {bob.Velocity}")
                Assert.True(bob.Velocity.Length < 0.05 * Math.Sqrt(G), $"the bob still moves at {bob.Velocity}")
            Next
            Assert.True(Math.Abs(speeds(0) - Math.Sqrt(G)) < 0.02 * Math.Sqrt(G))
            Assert.True(Math.Abs(speeds(1) - Math.Sqrt(G)) < 0.02 * Math.Sqrt(G))
        End Sub

        ' ---- A box on a vertical spring ----

        Private Shared Function SpringBox(solver As String, ByRef box As Rectangle, ByRef anchor As Vector, Optional dt As Double = 0.001) As World
            Dim w = NewWorld(solver, 1.0, dt)
            box = BoxAt(New Vector(5, 5), 0.2, 0.2, 0.5, "box")
            w.Add(box)
            ' Straight above its centre (as the scene's numbers give it), 1 m up: the spring's natural length.
            anchor = New Vector(box.CentreOfMass.X, box.CentreOfMass.Y + 1)
            w.Add(Link.CreateSpring(box, anchor, 40, 1))
            Return w
        End Function

        <Fact>
        Public Sub BoxOnAVerticalSpring_IsSimpleHarmonicMotion()
            Dim box As Rectangle = Nothing, anchor As Vector
            Dim w = SpringBox("event", box, anchor)
            Dim y0 = box.CentreOfMass.Y
            Dim stretch = 0.5 * G / 40, omega = Math.Sqrt(40 / 0.5)
            Dim worst = 0.0
            For k = 1 To 300
                w.Advance(0.01)
                Dim exact = y0 - stretch + stretch * Math.Cos(omega * w.Time)
                worst = Math.Max(worst, Math.Abs(box.CentreOfMass.Y - exact))
                Assert.Equal(anchor.X, box.CentreOfMass.X, 12)
            Next
            _output.WriteLine($"{worst} m from y_eq + (mg/k) cos ωt over 3 s")
            Assert.True(worst < 0.000000001, $"{worst} m off")
        End Sub

        <Fact>
        Public Sub BoxOnAVerticalSpring_Verlet_ConvergesToTheEventSolverAtSecondOrder()
            AssertVerletConvergesAtSecondOrder(
                Function(solver, dt)
                    Dim box As Rectangle = Nothing, anchor As Vector
                    Dim w = SpringBox(solver, box, anchor, dt)
                    w.Advance(2)
                    Return box.CentreOfMass
                End Function)
        End Sub

        ' ---- A box bouncing to rest on the floor beside a pendulum ----

        <Fact>
        Public Sub BoxDroppedOnTheFloorBesideAPendulum_ReboundsAtEToTheN_ComesToRest_NeverBelowTheFloor()
            Const E As Double = 0.5, H0 As Double = 1.0
            Dim w = NewWorld("event", E)
            Dim bob = AddPendulum(w, LinkKind.String, New Vector(8, 8), 1, Math.PI / 6, 0.5)
            Dim box = Rectangle.CreateMovable(New Vector(2, H0), 0.3, 0.2, 2, Vector.Zero, "box")
            w.Add(box)
            Dim bounces As New List(Of CollisionRecord)
            w.CollisionListener = Sub(r) If r.A Is box Then bounces.Add(r)
            Dim lowest = Double.PositiveInfinity
            Dim t0 = Math.Sqrt(2 * H0 / G), v0 = Math.Sqrt(2 * G * H0)
            Dim restTime = t0 * (1 + E) / (1 - E)
            Do While w.Time < restTime + 0.5
                w.Advance(0.001)
                lowest = Math.Min(lowest, box.Position.Y)
            Loop
            _output.WriteLine($"{bounces.Count} bounces, lowest {lowest} m; at rest at {box.Position} with {box.Velocity}")
            Assert.True(bounces.Count >= 10)
            For n = 1 To 10
                Dim r = bounces(n - 1)
                Assert.Equal(WallSide.Bottom, r.Wall)
                Assert.Equal(Math.Pow(E, n) * v0, r.AVelocityAfter.Y, 9)
                Assert.Equal(0.0, r.AVelocityAfter.X)
            Next
            ' The series' sum: every bounce is over by t₀(1 + e)/(1 − e), and the box lies on the floor.
            Assert.True(bounces.Last().Time < restTime + 0.000001, $"still bouncing at {bounces.Last().Time} s, rest due at {restTime} s")
            Assert.True(lowest >= 0, $"{lowest} m: below the floor")
            Assert.Equal(0.0, box.Position.Y)
            Assert.Equal(Vector.Zero, box.Velocity)
            Dim count = bounces.Count
            w.Advance(1)
            Assert.Equal(count, bounces.Count)
            Assert.Equal(0.0, box.Position.Y)
            ' The pendulum swung on undisturbed, on its string.
            Assert.Equal(1.0, (bob.Position - New Vector(8, 8)).Length, 12)
        End Sub

        ' ---- A polygon pendulum ----

        Private Shared Function PolygonPendulum(solver As String, ByRef triangle As Polygon, Optional dt As Double = 0.001) As World
            Dim w = NewWorld(solver, 1.0, dt)
            Dim c = OnCircle(New Vector(5, 6), 1, Math.PI / 3)
            ' A triangle whose centroid is c: its corners' average.
            triangle = New Polygon({c + New Vector(-0.12, -0.08), c + New Vector(0.12, -0.08), c + New Vector(0, 0.16)}, 1.5, Vector.Zero, "triangle")
            w.Add(triangle)
            w.Add(Link.CreateTie(LinkKind.Rod, triangle, New Vector(5, 6), 1))
            Return w
        End Function

        <Fact>
        Public Sub PolygonOnARod_SwingsWithThePendulumPeriod()
            Dim triangle As Polygon = Nothing
            Dim w = PolygonPendulum("event", triangle)
            Dim start = triangle.CentreOfMass
            Dim period = 4 * Math.Sqrt(1 / G) * CompleteK(Math.Sin(Math.PI / 6))
            Dim exact As New Pendulum(New Vector(5, 6), 1, G, start, Vector.Zero)
            Dim worst = 0.0
            For k = 1 To 200
                w.Advance(period / 100)
                worst = Math.Max(worst, (triangle.CentreOfMass - exact.PositionAt(w.Time)).Length)
            Next
            _output.WriteLine($"{worst} m from the pendulum over two periods; back at {triangle.CentreOfMass} against {start}")
            Assert.True(worst < 0.000000001, $"{worst} m off")
            Assert.True((triangle.CentreOfMass - start).Length < 0.000000001, "not back where it started after two periods")
        End Sub

        <Fact>
        Public Sub PolygonOnARod_Verlet_ConvergesToTheEventSolverAtSecondOrder()
            AssertVerletConvergesAtSecondOrder(
                Function(solver, dt)
                    Dim triangle As Polygon = Nothing
                    Dim w = PolygonPendulum(solver, triangle, dt)
                    w.Advance(1.5)
                    Return triangle.CentreOfMass
                End Function)
        End Sub

        ''' <summary>
        ''' Verlet against the event solver, from where <paramref name="endCentre"/> (solver, dt in s) says the tested
        ''' body's centre ends (m): within 0.1 mm at dt = 1 ms, and more than 3 times closer at 0.5 ms (second order).
        ''' </summary>
        Private Sub AssertVerletConvergesAtSecondOrder(endCentre As Func(Of String, Double, Vector))
            Dim exact = endCentre("event", 0.001)
            Dim errors As New List(Of Double)
            For Each dt In {0.001, 0.0005}
                errors.Add((endCentre("verlet", dt) - exact).Length)
            Next
            _output.WriteLine($"Verlet off by {errors(0)} m at 1 ms, {errors(1)} m at 0.5 ms")
            Assert.True(errors(0) < 0.0001, $"{errors(0)} m")
            Assert.True(errors(1) < errors(0) / 3, "not second order")
        End Sub

        ' ---- Two boxes head on, on the floor ----

        <Fact>
        Public Sub TwoBoxesHeadOnOnTheFloor_BesideAPendulum_FollowThe1DCollision()
            Const E As Double = 0.5
            Dim w = NewWorld("event", E)
            AddPendulum(w, LinkKind.Rod, New Vector(8, 8), 1, 0.3, 0.5)
            Dim a = Rectangle.CreateMovable(New Vector(1, 0), 0.2, 0.2, 1, New Vector(2, 0), "a")
            Dim b = Rectangle.CreateMovable(New Vector(3, 0), 0.3, 0.4, 3, New Vector(-1, 0), "b")
            w.Add(a)
            w.Add(b)
            Dim records As New List(Of CollisionRecord)
            w.CollisionListener = Sub(r) If r.B Is a OrElse r.B Is b Then records.Add(r)
            w.Advance(1)
            Assert.Single(records)
            ' The 1.8 m gap closes at 3 m/s.
            Assert.Equal(1.8 / 3, records(0).Time, 12)
            Dim first = records(0).A, second = records(0).B
            Dim va = If(first Is a, records(0).AVelocityAfter, records(0).BVelocityAfter)
            Dim vb = If(first Is a, records(0).BVelocityAfter, records(0).AVelocityAfter)
            ' u₁' = (m₁u₁ + m₂u₂ − m₂e(u₁ − u₂))/(m₁ + m₂), and the other by Newton's law.
            Assert.Equal((1 * 2 + 3 * -1 - 3 * E * 3) / 4, va.X, 12)
            Assert.Equal((1 * 2 + 3 * -1 + 1 * E * 3) / 4, vb.X, 12)
            Assert.Equal(0.0, va.Y)
            Assert.Equal(0.0, vb.Y)
            Assert.Equal(0.0, a.Position.Y)
            Assert.Equal(0.0, b.Position.Y)
        End Sub

        <Fact>
        Public Sub TwoBoxesMeetingCornerOnCorner_ArePushedApartAlongTheBisector()
            ' Without gravity (a ball on a spring elsewhere makes it a scene with links): box a runs at (1, 0.3)
            ' m/s so that its upper-right corner meets box b's lower-left corner, after 0.7 s. Corner on corner
            ' takes the bisector of the pair shape's corner, n = (1, 1)/√2, whatever the direction it came from
            ' (not the direction rounding leaves between two corners a hair apart): equal masses, e = 1, so the
            ' impulse is (1 + e)(u·n)/(2/m) = 1.3/√2 N·s along n.
            Dim w As New World(10, 10, 0, 1.0)
            w.Solver = SolverFactory.Create("event")
            Dim ball As New Circle(New Vector(8, 8), 0.05, 0.5, New Vector(0.3, 0), "ball")
            w.Add(ball)
            w.Add(Link.CreateSpring(ball, New Vector(8, 8), 10, 0))
            Dim a = Rectangle.CreateMovable(New Vector(1, 1), 0.25, 0.25, 1, New Vector(1, 0.3), "a")
            Dim b = Rectangle.CreateMovable(New Vector(1.25 + 0.7, 1.25 + 0.7 * 0.3), 0.25, 0.25, 1, Vector.Zero, "b")
            w.Add(a)
            w.Add(b)
            Dim records As New List(Of CollisionRecord)
            w.CollisionListener = Sub(r) If r.B Is b OrElse r.A Is b Then records.Add(r)
            w.Advance(1.5)
            Assert.Single(records)
            Assert.Equal(0.7, records(0).Time, 12)
            Assert.Equal(0.35, a.Velocity.X, 12)
            Assert.Equal(-0.35, a.Velocity.Y, 12)
            Assert.Equal(0.65, b.Velocity.X, 12)
            Assert.Equal(0.65, b.Velocity.Y, 12)
        End Sub

        <Fact>
        Public Sub ABoxFallingFlushPastAnother_DoesNotCatchOnItsCorner_AndBouncesToRestBesideIt()
            ' Box b falls with its left face exactly on box a's right face (a rests on the floor): passing a's
            ' corner and sliding down its face is no collision (docs/shapes.md: a corner counts only for a point
            ' going into it). b bounces on the floor beside a, at eⁿ of its landing speed, and comes to rest.
            Const E As Double = 0.5
            Dim w = NewWorld("event", E)
            AddPendulum(w, LinkKind.Rod, New Vector(8, 8), 1, 0.3, 0.5)
            Dim a = Rectangle.CreateMovable(New Vector(1, 0), 0.25, 0.5, 1, Vector.Zero, "a")
            Dim b = Rectangle.CreateMovable(New Vector(1.25, 1), 0.25, 0.25, 1, Vector.Zero, "b")
            w.Add(a)
            w.Add(b)
            Dim records As New List(Of CollisionRecord)
            w.CollisionListener = Sub(r) If r.A Is a OrElse r.A Is b Then records.Add(r)
            w.Advance(2)
            _output.WriteLine($"{records.Count} collisions; b at {b.Position} with {b.Velocity}")
            Assert.All(records, Sub(r) Assert.True(r.B Is Nothing AndAlso r.A Is b, $"{r.A.Id} hit {r.BName}"))
            Dim v0 = Math.Sqrt(2 * G * 1)
            For n = 1 To 5
                Assert.Equal(Math.Pow(E, n) * v0, records(n - 1).AVelocityAfter.Y, 9)
            Next
            Assert.Equal(New Vector(1.25, 0), b.Position)
            Assert.Equal(New Vector(1, 0), a.Position)
            Assert.Equal(Vector.Zero, a.Velocity)
        End Sub

        ' ---- What used to be refused ----

        <Fact>
        Public Sub ABoxOnARodComingToRestOnAFixedTable_BouncesLessEachTime_ThenRestsWhereItsCircleMeetsTheTable()
            ' A box on a rod swings down onto a table and bounces on it, each time less, at the same point of its
            ' circle. At rest there the table takes its whole weight and the rod none (a frictionless table cannot
            ' hold a sideways pull): centre 0.125 m above the table, on the rod's circle, still.
            Dim w = NewWorld("event", 0.5)
            w.Add(New Rectangle(New Vector(1, 0), 4, 1, "table"))
            Dim box = Rectangle.CreateMovable(New Vector(3.675, 1.375), 0.25, 0.25, 1, Vector.Zero, "box")
            w.Add(box)
            Dim rod = Link.CreateTie(LinkKind.Rod, box, New Vector(3, 1.5), 0.8)
            w.Add(rod)
            Dim records As New List(Of CollisionRecord)
            w.CollisionListener = Sub(r) records.Add(r)
            Dim lowest = Double.PositiveInfinity
            For k = 1 To 100
                w.Advance(0.1)
                lowest = Math.Min(lowest, box.Position.Y)
                Assert.Equal(0.8, rod.Distance, 9)
            Next
            Assert.True(records.Count >= 3, $"{records.Count} bounces")
            Assert.True(lowest >= 1 - 0.000000001, $"sank to {lowest} m")
            Assert.Equal(1.0, box.Position.Y, 9)
            Assert.Equal(3 + Math.Sqrt(0.8 * 0.8 - 0.375 * 0.375), box.CentreOfMass.X, 9)
            Assert.Equal(Vector.Zero, box.Velocity)
            Assert.Equal(0.0, rod.Tension, 9)
        End Sub

        <Fact>
        Public Sub ABoxOnASpringPullingAlongATable_SlidesAsTheSpringSays_ThenFallsOffItsEnd()
            ' The spring lies level with the box's centre, so it pulls along the table while gravity holds the box
            ' on it: simple harmonic motion about the spring's rest, x = 1.15 − 0.5 cos ωt with ω = √(k/m), on the
            ' table top, until the box's left edge passes the table's right end (centre at 1.4 m, cos ωt = −1/2).
            Dim w = NewWorld("event", 1.0)
            w.Add(New Rectangle(New Vector(0.25, 0), 1, 0.5, "table"))
            Dim box = Rectangle.CreateMovable(New Vector(0.5, 0.5), 0.3, 0.2, 2, Vector.Zero, "box")
            w.Add(box)
            w.Add(Link.CreateSpring(box, New Vector(1.65, 0.6), 10, 0.5))
            Dim omega = Math.Sqrt(10 / 2.0)
            Dim leaves = (2 * Math.PI / 3) / omega
            Do While w.Time < leaves - 0.05
                w.Advance(0.05)
                Assert.Equal(1.15 - 0.5 * Math.Cos(omega * w.Time), box.CentreOfMass.X, 9)
                Assert.Equal(0.5, box.Position.Y)
            Loop
            w.Advance(0.2)
            Assert.True(box.Position.Y < 0.5 - 0.01, $"still at {box.Position.Y} m")
        End Sub
    End Class
End Namespace
