Option Strict On
Imports PhysicsEngine
Imports PhysicsEngine.Tests.Links
Imports Xunit
Imports Xunit.Abstractions

Namespace EventDriven
    ''' <summary>
    ''' Links in the event solver against closed forms and exact answers: pendulums on strings and rods,
    ''' a string going slack and snapping taut, Newton's cradle on strings, a mass on a vertical spring, a
    ''' spinning dumbbell, collisions with the links' impulses in the same solve, and a ball coming to rest on a box in a scene with links (which it once refused).
    ''' </summary>
    Public Class LinkedEventTests
        Private Const G As Double = 9.81
        Private Shared ReadOnly Anchor As New Vector(5, 6)
        Private ReadOnly _output As ITestOutputHelper

        Public Sub New(output As ITestOutputHelper)
            _output = output
        End Sub

        Private Shared Function EventWorld(Optional gravity As Double = G, Optional restitution As Double = 1.0) As World
            Dim w As New World(10, 10, gravity, restitution)
            w.Solver = SolverFactory.Create("event")
            Return w
        End Function

        ''' <summary>An event world with g = 0 and e = 1 holding balls <paramref name="a"/> and <paramref name="b"/> on a spring of <paramref name="stiffness"/> N/m and <paramref name="length"/> m.</summary>
        Private Shared Function SpringPairWorld(a As Circle, b As Circle, stiffness As Double, length As Double) As World
            Dim w = EventWorld(0, 1.0)
            w.Add(a)
            w.Add(b)
            w.Add(Link.CreateSpring(a, b, stiffness, length))
            Return w
        End Function

        ''' <summary>The largest |E − E₀| ÷ E₀ of kinetic plus potential energy after each of <paramref name="advances"/> advances of <paramref name="seconds"/> s.</summary>
        Private Shared Function WorstEnergyDrift(w As World, advances As Integer, seconds As Double) As Double
            Dim energy = w.KineticEnergy() + w.PotentialEnergy()
            Dim worst = 0.0
            For i = 1 To advances
                w.Advance(seconds)
                worst = Math.Max(worst, Math.Abs(w.KineticEnergy() + w.PotentialEnergy() - energy) / energy)
            Next
            Return worst
        End Function

        <Theory>
        <InlineData(LinkKind.String)>
        <InlineData(LinkKind.Rod)>
        Public Sub APendulumBobCarriedByHand_FollowsTheHand_AndLetGoAtRest_SwingsToTheMirrorPointInHalfAPeriod(kind As LinkKind)
            Dim w = EventWorld()
            Dim bob As New Circle(OnCircle(Anchor, 1, Math.PI / 3), 0.05, 0.5)
            w.Add(bob)
            w.Add(Link.CreateTie(kind, bob, Anchor, 1))
            w.Advance(0.3)
            ' Carried over a few frames to 30° on the other side, and held there.
            w.BeginDrag(bob)
            Dim hand = OnCircle(Anchor, 1, -Math.PI / 6)
            For k = 1 To 20
                w.DragTo(bob.Position + (hand - bob.Position) * (k / 20.0))
                w.Advance(1 / 60.0)
            Next
            w.DragTo(hand)
            w.Advance(1 / 60.0)
            Assert.Equal(hand.X, bob.Position.X, 9)
            Assert.Equal(hand.Y, bob.Position.Y, 9)
            w.EndDrag(Vector.Zero)
            ' Let go at rest at −30°: half a period later it is at +30°, the mirror point, by the closed form.
            Dim half = New Pendulum(Anchor, 1, G, hand, Vector.Zero).Period / 2
            w.Advance(half)
            Dim mirror = OnCircle(Anchor, 1, Math.PI / 6)
            Assert.Equal(mirror.X, bob.Position.X, 9)
            Assert.Equal(mirror.Y, bob.Position.Y, 9)
        End Sub

        <Theory>
        <InlineData(LinkKind.String)>
        <InlineData(LinkKind.Rod)>
        Public Sub PendulumFrom60Degrees_IsTheEllipticClosedForm(kind As LinkKind)
            Dim w = EventWorld()
            Dim bob As New Circle(OnCircle(Anchor, 1, Math.PI / 3), 0.05, 0.5)
            w.Add(bob)
            Dim tie = Link.CreateTie(kind, bob, Anchor, 1)
            w.Add(tie)
            Dim exact As New Pendulum(Anchor, 1, G, bob.Position, Vector.Zero)
            Dim expectedPeriod = 4 * Math.Sqrt(1 / G) * CompleteK(Math.Sin(Math.PI / 6))
            Assert.Equal(expectedPeriod, exact.Period, 0.000000000001)
            Dim worst = 0.0
            For i = 1 To CInt(Math.Round(3 * exact.Period / 0.01))
                w.Advance(0.01)
                worst = Math.Max(worst, (bob.Position - exact.PositionAt(w.Time)).Length)
                Assert.Equal(1.0, (bob.Position - Anchor).Length, 0.000000000001)
            Next
            _output.WriteLine($"{kind}: {worst} m from the closed form over three periods; tension {tie.Tension} N")
            Assert.True(worst < 0.000000001, $"{worst} m off")
            ' T = m(g cos θ + v²/L): at the turning point (60°) after 4 periods, mg/2.
            w.Advance(4 * exact.Period - w.Time)
            Assert.Equal(0.5 * 0.5 * G, tie.Tension, 0.000001)
        End Sub

        <Fact>
        Public Sub StringInAVerticalCircle_GoesSlack_FliesItsParabola_AndSnapsTaut()
            ' From the bottom with u² = 3.5 gL the tension vanishes 1.5 L above the bottom; the bob flies a
            ' parabola inside the circle until the string snaps taut (e = 1: the outward speed reverses).
            Dim w = EventWorld()
            Dim u = Math.Sqrt(3.5 * G)
            Dim bob As New Circle(Anchor + New Vector(0, -1), 0.05, 0.5, New Vector(u, 0))
            w.Add(bob)
            Dim tie = Link.CreateTie(LinkKind.String, bob, Anchor, 1)
            w.Add(tie)
            Dim exact As New Pendulum(Anchor, 1, G, bob.Position, bob.Velocity)
            Dim tSlack = exact.SlackTime()
            Dim slackPosition As Vector, slackVelocity As Vector
            exact.StateAt(tSlack, slackPosition, slackVelocity)
            Dim tTaut = tSlack + StringTaut.AnchoredTautTime(Anchor, 1, slackPosition, slackVelocity, G, 0.000000001)
            Dim energy = bob.KineticEnergy + bob.Mass * G * bob.Position.Y
            Dim worst = 0.0
            Do While w.Time < tTaut - 0.005
                w.Advance(0.005)
                Dim t = w.Time
                Dim expected As Vector
                If t <= tSlack Then
                    expected = exact.PositionAt(t)
                Else
                    Dim s = t - tSlack
                    expected = slackPosition + slackVelocity * s + New Vector(0, -0.5 * G * s * s)
                    Assert.Equal(0.0, tie.Tension)
                End If
                worst = Math.Max(worst, (bob.Position - expected).Length)
                Assert.True((bob.Position - Anchor).Length <= 1 + 0.000000001)
            Loop
            _output.WriteLine($"slack at {tSlack} s, taut at {tTaut} s; largest error {worst} m")
            Assert.True(worst < 0.000000001, $"{worst} m off")
            ' Past the snap: the string is never over-long, and with e = 1 no energy is lost.
            For i = 1 To 400
                w.Advance(0.005)
                Assert.True((bob.Position - Anchor).Length <= 1 + 0.000000001, $"t = {w.Time}: {(bob.Position - Anchor).Length} m")
                Assert.Equal(energy, bob.KineticEnergy + bob.Mass * G * bob.Position.Y, 0.000000001 * energy)
            Next
        End Sub

        <Fact>
        Public Sub NewtonsCradleOnStrings_ExactlyOneBallLeavesWithTheStrikersSpeed()
            Dim w = EventWorld()
            Dim r = 0.1, length = 1.0
            Dim balls As New List(Of Circle)
            For k = 0 To 4
                Dim top As New Vector(4 + 2 * r * k, 6)
                Dim at = If(k = 0, OnCircle(top, length, -Math.PI / 6), top + New Vector(0, -length))
                Dim c As New Circle(at, r, 0.2, id:="ball" & (k + 1).ToString(Globalization.CultureInfo.InvariantCulture))
                w.Add(c)
                w.Add(Link.CreateTie(LinkKind.String, c, top, length))
                balls.Add(c)
            Next
            Dim collisions As New List(Of CollisionRecord)
            w.CollisionListener = Sub(c) collisions.Add(c)
            ' The striker reaches the bottom after a quarter period, at the speed √(2gL(1 − cos 30°)).
            Dim striker As New Pendulum(New Vector(4, 6), length, G, balls(0).Position, Vector.Zero)
            Dim quarter = striker.Period / 4
            Dim speed = Math.Sqrt(2 * G * length * (1 - Math.Cos(Math.PI / 6)))
            w.Advance(quarter + 0.01)
            _output.WriteLine($"{collisions.Count} collisions, the first at {collisions(0).Time} s (quarter period {quarter} s)")
            Assert.Equal(4, collisions.Count)
            Assert.Equal(quarter, collisions(0).Time, 0.000000001)
            For k = 0 To 3
                Assert.Equal(collisions(0).Time, collisions(k).Time)
            Next
            ' The last ball leaves at the striker's speed; the other four are left at rest.
            Dim last As New Pendulum(New Vector(4 + 8 * r, 6), length, G, New Vector(4 + 8 * r, 6 - length), New Vector(speed, 0))
            Assert.True((balls(4).Position - last.PositionAt(0.01)).Length < 0.000000001, $"{balls(4).Position} against {last.PositionAt(0.01)}")
            For k = 0 To 3
                Assert.True(balls(k).Velocity.Length < 0.000000001, $"ball {k + 1} moves at {balls(k).Velocity.Length} m/s")
            Next
            ' It rises to the striker's height, swings back and sends the striker out again: after a full
            ' period the striker is where it started.
            w.Advance(striker.Period - w.Time)
            _output.WriteLine($"after a period: striker at {balls(0).Position}, started at {OnCircle(New Vector(4, 6), length, -Math.PI / 6)}")
            Assert.True((balls(0).Position - OnCircle(New Vector(4, 6), length, -Math.PI / 6)).Length < 0.000001)
            Assert.Equal(8, collisions.Count)
        End Sub

        <Fact>
        Public Sub MassOnAVerticalSpring_IsTheCosine()
            Dim w = EventWorld()
            Dim m = 0.5, k = 40.0, rest = 1.0
            Dim bob As New Circle(New Vector(Anchor.X, Anchor.Y - rest), 0.05, m)
            w.Add(bob)
            w.Add(Link.CreateSpring(bob, Anchor, k, rest))
            Dim sag = m * G / k
            Dim worst = 0.0
            For i = 1 To 300
                w.Advance(0.01)
                worst = Math.Max(worst, Math.Abs(bob.Position.Y - (Anchor.Y - rest - sag + sag * Math.Cos(Math.Sqrt(k / m) * w.Time))))
            Next
            _output.WriteLine($"{worst} m")
            Assert.True(worst < 0.000000001, $"{worst} m off")
        End Sub

        <Fact>
        Public Sub DumbbellWithoutGravity_SpinsAtAConstantRate()
            Dim w = EventWorld(0)
            Dim b1 As New Circle(New Vector(4.5, 5), 0.1, 1, New Vector(0.3, -2))
            Dim b2 As New Circle(New Vector(5.5, 5), 0.1, 3, New Vector(0.3, 1))
            w.Add(b1)
            w.Add(b2)
            w.Add(Link.CreateTie(LinkKind.Rod, b1, b2, 1))
            ' ω = (v₂ − v₁)·(perpendicular of the bar)/L = 3 rad/s; the centre moves at (0.3, 0.25) m/s.
            Dim centre0 = (1 * b1.Position + 3 * b2.Position) / 4
            For i = 1 To 200
                w.Advance(0.01)
                Dim t = w.Time
                Dim centre = centre0 + t * New Vector(0.3, 0.25)
                Dim bar As New Vector(Math.Cos(3 * t), Math.Sin(3 * t))
                Assert.True((b1.Position - (centre - 0.75 * bar)).Length < 0.000000001, $"t = {t}")
                Assert.True((b2.Position - (centre + 0.25 * bar)).Length < 0.000000001, $"t = {t}")
            Next
        End Sub

        <Fact>
        Public Sub PendulumHittingAWallAtAnAngle_KeepsItsEnergyAndItsLength()
            ' The wall's push is not across the rod, so the rod pulls in the same blow: with e = 1 the bob
            ' leaves with the speed it came in at, still on its circle.
            Dim w = EventWorld()
            Dim pivot As New Vector(9.3, 6)
            Dim bob As New Circle(OnCircle(pivot, 1, -Math.PI / 3), 0.1, 0.5)
            w.Add(bob)
            w.Add(Link.CreateTie(LinkKind.Rod, bob, pivot, 1))
            Dim collisions = 0
            w.CollisionListener = Sub(c) collisions += 1
            Dim energy = bob.KineticEnergy + bob.Mass * G * bob.Position.Y
            For i = 1 To 300
                w.Advance(0.01)
                Assert.Equal(1.0, (bob.Position - pivot).Length, 0.000000001)
                Assert.True(bob.Position.X <= 10 - 0.1 + 0.000000001)
                Assert.Equal(energy, bob.KineticEnergy + bob.Mass * G * bob.Position.Y, 0.000000001 * energy)
            Next
            _output.WriteLine($"{collisions} collisions with the wall")
            Assert.True(collisions >= 2)
        End Sub

        <Fact>
        Public Sub TwoPendulumsOfDifferentMass_CollideAsIn1D()
            ' Both at the bottom at the moment of impact, the strings vertical: v₁' = ((m₁ − e m₂)u)/(m₁ + m₂), v₂' = (1 + e) m₁ u/(m₁ + m₂).
            Dim e = 0.6
            Dim w = EventWorld(G, e)
            Dim r = 0.1
            Dim a As New Circle(OnCircle(New Vector(4, 6), 1, -0.5), r, 0.3)
            Dim b As New Circle(New Vector(4 + 2 * r, 5), r, 0.9)
            w.Add(a)
            w.Add(b)
            w.Add(Link.CreateTie(LinkKind.String, a, New Vector(4, 6), 1))
            w.Add(Link.CreateTie(LinkKind.String, b, New Vector(4 + 2 * r, 6), 1))
            Dim records As New List(Of CollisionRecord)
            w.CollisionListener = Sub(c) records.Add(c)
            Dim u = Math.Sqrt(2 * G * (1 - Math.Cos(0.5)))
            Dim quarter = New Pendulum(New Vector(4, 6), 1, G, a.Position, Vector.Zero).Period / 4
            w.Advance(quarter + 0.000001)
            Assert.Single(records)
            Assert.Equal(quarter, records(0).Time, 0.000000001)
            Assert.Equal((0.3 - e * 0.9) * u / 1.2, records(0).AVelocityAfter.X, 0.000000001)
            Assert.Equal((1 + e) * 0.3 * u / 1.2, records(0).BVelocityAfter.X, 0.000000001)
            Assert.Equal(0.0, records(0).BVelocityAfter.Y, 0.000000001)
        End Sub

        <Fact>
        Public Sub ABallComingToRestOnABoxOnTheFloor_InASceneWithLinks_RestsOnItsTop()
            ' Once refused; a box resting level is a level face to rest on (docs/links.md, section 6).
            Dim w = EventWorld(restitution:=0.5)
            Dim bob As New Circle(New Vector(5, 5), 0.05, 0.5, New Vector(1, 0))
            w.Add(bob)
            w.Add(Link.CreateTie(LinkKind.Rod, bob, Anchor, 1))
            Dim box = Rectangle.CreateMovable(New Vector(1, 0), 0.3, 0.2, 2, Vector.Zero, "box")
            w.Add(box)
            Dim ball As New Circle(New Vector(1.15, 0.5), 0.05, 0.1)
            w.Add(ball)
            Dim lowest = Double.PositiveInfinity
            Do While w.Time < 2
                w.Advance(0.001)
                lowest = Math.Min(lowest, ball.Position.Y)
            Loop
            Assert.True(lowest >= 0.25, $"{lowest} m: into the box")
            Assert.Equal(New Vector(1.15, 0.25), ball.Position)
            Assert.Equal(Vector.Zero, ball.Velocity)
            ' The box took the blows on the floor: it has not moved (but for the rounding of centre − offset).
            Assert.True((box.Position - New Vector(1, 0)).Length < 0.000000000000001, $"the box at {box.Position}")
            Assert.Equal(Vector.Zero, box.Velocity)
        End Sub

        <Fact>
        Public Sub RemovingTheLinks_GoesBackToTheCircleSolver()
            Dim w = EventWorld()
            Dim bob As New Circle(OnCircle(Anchor, 1, 0.4), 0.05, 0.5)
            w.Add(bob)
            Dim tie = Link.CreateTie(LinkKind.Rod, bob, Anchor, 1)
            w.Add(tie)
            w.Advance(0.1)
            w.Remove(tie)
            Dim p0 = bob.Position, v0 = bob.Velocity
            w.Advance(0.2)
            ' Free now: the parabola.
            Dim expected = p0 + v0 * 0.2 + New Vector(0, -0.5 * G * 0.04)
            Assert.True((bob.Position - expected).Length < 0.000000001)
        End Sub

        <Fact>
        Public Sub InelasticString_SnapsEverLess_AndSettlesTautInFewEvents()
            ' e = 0.5: after going slack the bob snaps taut, bounces in at half its outward speed, and so on:
            ' a geometric series with a finite total time. It must end (taut again), never over-long.
            Dim w = EventWorld(G, 0.5)
            Dim solver = DirectCast(w.Solver, EventDrivenSolver)
            Dim bob As New Circle(Anchor + New Vector(0, -1), 0.05, 0.5, New Vector(Math.Sqrt(3.5 * G), 0))
            w.Add(bob)
            Dim tie = Link.CreateTie(LinkKind.String, bob, Anchor, 1)
            w.Add(tie)
            Dim energy = bob.KineticEnergy + bob.Mass * G * bob.Position.Y
            For i = 1 To 500
                w.Advance(0.01)
                Assert.True((bob.Position - Anchor).Length <= 1 + 0.000000001)
            Next
            Dim after = bob.KineticEnergy + bob.Mass * G * bob.Position.Y
            _output.WriteLine($"energy {energy} J → {after} J; tension {tie.Tension} N")
            Assert.True(after < energy)
            ' Swinging on a taut string again, below the anchor.
            Assert.True(tie.Tension > 0)
            Assert.Equal(1.0, (bob.Position - Anchor).Length, 0.000000001)
        End Sub

        <Fact>
        Public Sub FreeBallBouncingToRest_BesideAPendulum_Ends()
            Dim w = EventWorld(G, 0.8)
            Dim bob As New Circle(OnCircle(Anchor, 1, 0.3), 0.05, 0.5)
            w.Add(bob)
            w.Add(Link.CreateTie(LinkKind.Rod, bob, Anchor, 1))
            Dim ball As New Circle(New Vector(1, 1), 0.1, 1)
            w.Add(ball)
            Dim count = 0
            w.CollisionListener = Sub(c) count += 1
            w.Advance(10)
            _output.WriteLine($"{count} collisions")
            ' Each bounce is e times as fast: from 3.4 m/s to the 3e-4 m/s below which it rests is about 44 bounces.
            Assert.InRange(count, 30, 60)
            ' Dropped from 0.9 m with e = 0.8, the bounces end after (1 + e)/(1 − e)·√(2h/g) = 3.8 s: on the floor since.
            Assert.Equal(0.1, ball.Position.Y, 0.000000001)
            Assert.Equal(0.0, ball.Velocity.Y)
        End Sub

        <Fact>
        Public Sub SpringPendulum_FollowsAFineRungeKutta_AndKeepsItsEnergy()
            ' No closed form: a bob on a spring (k = 30 N/m, rest length 0.8 m) released at rest 1 rad out,
            ' 0.9 m from the anchor. Reference: classical RK4 with steps of 10 μs.
            Dim w = EventWorld()
            Dim m = 0.5, k = 30.0, rest = 0.8
            Dim start = Anchor + 0.9 * New Vector(Math.Sin(1.0), -Math.Cos(1.0))
            Dim bob As New Circle(start, 0.05, m)
            w.Add(bob)
            w.Add(Link.CreateSpring(bob, Anchor, k, rest))
            Dim f As Action(Of Double(), Double()) =
                Sub(y, dy)
                    Dim rx = y(0) - Anchor.X, ry = y(1) - Anchor.Y
                    Dim d = Math.Sqrt(rx * rx + ry * ry)
                    Dim pull = k * (d - rest) / (m * d)
                    dy(0) = y(2)
                    dy(1) = y(3)
                    dy(2) = -pull * rx
                    dy(3) = -pull * ry - G
                End Sub
            Dim times = {0.5, 1.0, 1.5, 2.0, 2.5, 3.0}
            Dim reference = Links.LinkTestKit.Rk4At(f, {start.X, start.Y, 0, 0}, times, 0.00001)
            Dim energy = w.KineticEnergy() + w.PotentialEnergy()
            Dim worst = 0.0
            For i = 0 To times.Length - 1
                w.Advance(times(i) - w.Time)
                worst = Math.Max(worst, (bob.Position - New Vector(reference(i)(0), reference(i)(1))).Length)
                Assert.Equal(energy, w.KineticEnergy() + w.PotentialEnergy(), 0.000000001 * energy)
            Next
            _output.WriteLine($"{worst} m from RK4")
            Assert.True(worst < 0.0000001, $"{worst} m off")
        End Sub

        <Fact>
        Public Sub TwoBallsOnASpring_CentreOfMassFliesItsParabola()
            Dim w = EventWorld(G, 1.0)
            Dim a As New Circle(New Vector(3, 5), 0.1, 1, New Vector(2, 3))
            Dim b As New Circle(New Vector(3.6, 5.2), 0.1, 2, New Vector(1, 1))
            w.Add(a)
            w.Add(b)
            w.Add(Link.CreateSpring(a, b, 50, 0.5))
            Dim centre0 = w.CentreOfMass()
            Dim momentum0 = w.Momentum()
            Dim energy = w.KineticEnergy() + w.PotentialEnergy()
            For i = 1 To 50
                w.Advance(0.01)
                Dim t = w.Time
                Dim expected = centre0 + momentum0 * (t / 3) + New Vector(0, -0.5 * G * t * t)
                Assert.True((w.CentreOfMass() - expected).Length < 0.000000001, $"t = {t}")
                Assert.Equal(energy, w.KineticEnergy() + w.PotentialEnergy(), 0.000000001 * energy)
            Next
        End Sub

        <Fact>
        Public Sub TwoBallsOnAStretchedSpinningSpring_KeepTheirEnergy_To1e9_Over100Seconds()
            ' g = 0: the pair spins about its centre of mass while the spring stretches and shortens. Kinetic plus
            ' spring energy is the only energy there is, and nothing takes any away.
            Dim w = SpringPairWorld(New Circle(New Vector(4, 5), 0.1, 1, New Vector(0, 1.5)),
                                    New Circle(New Vector(6, 5), 0.1, 2, New Vector(0, -0.75)), 20, 1.2)
            Dim worst = WorstEnergyDrift(w, 100, 1.0)
            Assert.True(worst <= 0.000000001, $"the energy drifted by {worst} of itself")
            Assert.Equal(100.0, w.Time, 9)
        End Sub

        <Fact>
        Public Sub ASlowPairBarelyStretchedFarApart_KeepsItsEnergy_To1e9()
            ' g = 0: two balls 0.17 m apart on a 215 N/m spring at its length, one moving at 0.8 mm/s: they swing by some
            ' 20 µm, 10⁻⁴ of their distance apart. The stretch must be held to its own size, not to 10⁻¹² of 0.17 m
            ' (10⁻⁸ of it): integrated as the separation itself, the energy drifted by 7·10⁻⁸ of itself in 10 s.
            Dim w = SpringPairWorld(New Circle(New Vector(1.7, 5), 0.01, 0.3, New Vector(0.0008, 0.0001)),
                                    New Circle(New Vector(1.87, 5), 0.01, 0.2, Vector.Zero), 215, 0.17)
            Dim worst = WorstEnergyDrift(w, 200, 0.05)
            Assert.True(worst <= 0.000000001, $"the energy drifted by {worst} of itself")
        End Sub

        <Fact>
        Public Sub TwoBallsOnSlackStrings_FallFreely_UntilTheStringToTheirAnchorSnapsTautWhereAParabolaSaysItDoes()
            ' Ball a hangs 1 m below a point on a 1.5 m string, ball b 0.5 m beside it on a 1 m string to a; both let go at
            ' rest, e = 0.5. They fall together (their string stays as slack as it was), exactly on their parabolas, until
            ' a is 1.5 m below the point: ½ g t² = 0.5 m. There its string snaps taut, a collision with the point: a comes
            ' back up at half its speed, b falls on.
            Dim w = EventWorld(restitution:=0.5)
            Dim a As New Circle(New Vector(5, 5), 0.05, 1, Vector.Zero, "a")
            Dim b As New Circle(New Vector(5.5, 5), 0.05, 1, Vector.Zero, "b")
            w.Add(a)
            w.Add(b)
            w.Add(Link.CreateTie(LinkKind.String, a, New Vector(5, 6), 1.5))
            w.Add(Link.CreateTie(LinkKind.String, a, b, 1))
            Dim records As New List(Of CollisionRecord)
            w.CollisionListener = Sub(c) records.Add(c)
            Dim snap = Math.Sqrt(1 / G)
            w.Advance(0.9 * snap)
            Dim t = w.Time
            Assert.Equal(5 - 0.5 * G * t * t, a.Position.Y, 13)
            Assert.Equal(-G * t, b.Velocity.Y, 13)
            Assert.Empty(records)
            w.Advance(0.2 * snap)
            Dim taut = Assert.Single(records)
            Assert.Equal("string-taut", taut.KindName)
            Assert.Equal(snap, taut.Time, 12)
            Assert.Equal(0.5 * G * snap, taut.AVelocityAfter.Y, 9)
            t = w.Time
            Assert.Equal(-G * t, b.Velocity.Y, 12)
        End Sub

        <Fact>
        Public Sub ABallHeldOnTheFloorByASpring_SlidingToAndFro_KeepsItsEnergy_To1e10_Over300Seconds()
            ' g = 0: a spring to a point 2 m below the floor holds a ball on it, and pulls it back and forth along it. The
            ' contact makes the motion an integrated one, each step held to 10⁻¹¹ of the coordinates: step by step the
            ' energy drifted away, 1.1·10⁻⁹ of itself in 300 s. Nothing in it does work but the spring, and each step is
            ' now put back on the energy it started with.
            Dim w As New World(10, 10, 0, 1)
            w.Solver = SolverFactory.Create("event")
            Dim ball As New Circle(New Vector(5, 0.1), 0.1, 0.5, New Vector(3, 0))
            w.Add(ball)
            w.Add(Link.CreateSpring(ball, New Vector(5, -2), 100, 1))
            Dim worst = WorstEnergyDrift(w, 6000, 0.05)
            Assert.True(worst <= 0.0000000001, $"the energy moved by {worst} of itself")
            Assert.Equal(0.1, ball.Position.Y, 12)
        End Sub

        <Fact>
        Public Sub ALightAndAHeavyBallOnASpring_KeepTheirEnergy_To1e9_BetweenTheIntegratorsSteps()
            ' A 0.7 g ball on a spring to a 6.4 t ball: the light one oscillates some 57 times a second while the heavy
            ' one, carrying nearly all the energy, drifts at 0.2 m/s. Sampled between the integrator's steps, the heavy
            ' ball's velocity must not carry its position's rounding divided by the light ball's short steps.
            Dim light As New Circle(New Vector(5.17, 3.5), 0.0038, 0.0006941805430169185, New Vector(0.16620070135733775, -0.3483425589605806))
            Dim heavy As New Circle(New Vector(5.0, 6.587), 0.108, 6375.7145191157, New Vector(0.11892047219725678, -0.19005385617435033))
            Dim w = SpringPairWorld(light, heavy, 88.5700359321693, (heavy.Position - light.Position).Length)
            Dim worst = WorstEnergyDrift(w, 600, 0.0005)
            _output.WriteLine($"worst relative energy change {worst}")
            Assert.True(worst <= 0.000000001, $"the energy moved by {worst} of itself")
        End Sub

        <Fact>
        Public Sub VerticalSpringThrownAboveItsAnchor_IsIntegratedFromThere()
            ' The closed form holds below the anchor; above it the spring is squashed the other way.
            Dim w = EventWorld()
            Dim bob As New Circle(New Vector(Anchor.X, Anchor.Y - 0.5), 0.05, 0.5, New Vector(0, 6))
            w.Add(bob)
            w.Add(Link.CreateSpring(bob, Anchor, 20, 0.5))
            Dim energy = w.KineticEnergy() + w.PotentialEnergy()
            Dim above = False
            For i = 1 To 200
                w.Advance(0.01)
                If bob.Position.Y > Anchor.Y Then above = True
                Assert.Equal(Anchor.X, bob.Position.X, 0.000000001)
                Assert.Equal(energy, w.KineticEnergy() + w.PotentialEnergy(), 0.00000001 * energy)
            Next
            Assert.True(above)
        End Sub
    End Class
End Namespace
