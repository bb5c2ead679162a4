Option Strict On
Imports PhysicsEngine
Imports Xunit
Imports Xunit.Abstractions

Namespace EventDriven
    ''' <summary>
    ''' Chains of rods in the event solver (no closed form: integrated with error control): a double pendulum
    ''' and a rope of ten balls keep their rods' lengths and their energy, the double pendulum follows an
    ''' independent solution in its angles and agrees with Verlet to the order of Verlet's step over half a
    ''' second, a chain spinning into a free ball hits it when the geometry says, a rope swept through balls on
    ''' the floor never overlaps them, a chain with a spring in it keeps its energy, and redundant rods are refused.
    ''' </summary>
    Public Class ChainEventTests
        Private Const G As Double = 9.81
        Private Shared ReadOnly Anchor As New Vector(5, 6)
        Private ReadOnly _output As ITestOutputHelper

        Public Sub New(output As ITestOutputHelper)
            _output = output
        End Sub

        ''' <summary>A chain of <paramref name="count"/> balls, each <paramref name="spacing"/> m from the last, level to the right of the anchor, joined by rods.</summary>
        Private Shared Function LevelChain(w As World, count As Integer, spacing As Double, radius As Double, mass As Double) As List(Of Circle)
            Dim balls As New List(Of Circle)
            For k = 1 To count
                Dim ball As New Circle(New Vector(Anchor.X + k * spacing, Anchor.Y), radius, mass)
                w.Add(ball)
                If k = 1 Then
                    w.Add(Link.CreateTie(LinkKind.Rod, ball, Anchor, spacing))
                Else
                    w.Add(Link.CreateTie(LinkKind.Rod, ball, balls(k - 2), spacing))
                End If
                balls.Add(ball)
            Next
            Return balls
        End Function

        Private Shared Function Energy(w As World) As Double
            Dim e = 0.0
            For Each c In w.Circles
                e += 0.5 * c.Mass * c.Velocity.LengthSquared + c.Mass * w.Gravity * c.Position.Y
            Next
            Return e
        End Function

        Private Shared Function WorstLengthError(w As World) As Double
            Return w.Links.Max(Function(l) Math.Abs(l.Distance - l.Length))
        End Function

        <Fact>
        Public Sub DoublePendulumReleasedLevel_KeepsItsEnergyAndRodLengths_For10Seconds()
            Dim w As New World(10, 10, G, 1.0)
            w.Solver = SolverFactory.Create("event")
            LevelChain(w, 2, 1, 0.05, 1)
            Dim e0 = Energy(w)
            ' The energy's scale: m g L over the chain, 2 × 1 kg × g × 2 m.
            Dim scale = 2 * 1 * G * 2
            Dim worstEnergy = 0.0, worstLength = 0.0
            TestSolvers.Frames(w, 10, 0.05, Sub()
                                                  worstEnergy = Math.Max(worstEnergy, Math.Abs(Energy(w) - e0) / scale)
                                                  worstLength = Math.Max(worstLength, WorstLengthError(w))
                                              End Sub)
            _output.WriteLine($"energy {worstEnergy:E2} of m g L, rod lengths {worstLength:E2} m")
            Assert.Equal(10.0, w.Time, 12)
            Assert.True(worstEnergy <= 0.000000001, $"energy drifted by {worstEnergy:E2} of m g L")
            Assert.True(worstLength <= 0.000000001, $"a rod's length is off by {worstLength:E2} m")
            ' It did swing: the lower bob has been far from where it started.
            Assert.NotEqual(Anchor.Y, w.Circles(1).Position.Y)
        End Sub

        <Fact>
        Public Sub RopeOfTenBallsReleasedLevel_KeepsItsEnergyAndRodLengths()
            Dim w As New World(10, 10, G, 1.0)
            w.Solver = SolverFactory.Create("event")
            Dim rope = LevelChain(w, 10, 0.2, 0.05, 0.2)
            Dim e0 = Energy(w)
            Dim scale = 10 * 0.2 * G * 2
            Dim worstEnergy = 0.0, worstLength = 0.0, lowest = Anchor.Y
            TestSolvers.Frames(w, 3, 0.05, Sub()
                                               worstEnergy = Math.Max(worstEnergy, Math.Abs(Energy(w) - e0) / scale)
                                               worstLength = Math.Max(worstLength, WorstLengthError(w))
                                               lowest = Math.Min(lowest, rope(9).Position.Y)
                                           End Sub)
            _output.WriteLine($"energy {worstEnergy:E2} of m g L, rod lengths {worstLength:E2} m, lowest end {lowest} m, {w.CollisionCount} collisions")
            Assert.True(worstEnergy <= 0.000000001, $"energy drifted by {worstEnergy:E2} of m g L")
            Assert.True(worstLength <= 0.000000001, $"a rod's length is off by {worstLength:E2} m")
            Assert.True(lowest < Anchor.Y - 1.5, $"the rope's end only got down to {lowest} m")
        End Sub

        <Fact>
        Public Sub DoublePendulum_FollowsAnIndependentSolutionInAngles_To1e9Metres()
            ' The textbook equations of the double pendulum in its two angles from straight down (Lagrange),
            ' solved by classical Runge–Kutta with 10 μs steps: a different formulation and method altogether.
            Dim w As New World(10, 10, G, 1.0)
            w.Solver = SolverFactory.Create("event")
            Dim balls = LevelChain(w, 2, 1, 0.05, 1)
            Dim worst = 0.0
            Dim y = {Math.PI / 2, Math.PI / 2, 0.0, 0.0}
            Dim h = 0.00001
            For frame = 1 To 20
                For s = 1 To 10000
                    y = RungeKuttaStep(y, h)
                Next
                w.Advance(0.1)
                Dim upper = Anchor + New Vector(Math.Sin(y(0)), -Math.Cos(y(0)))
                Dim lower = upper + New Vector(Math.Sin(y(1)), -Math.Cos(y(1)))
                worst = Math.Max(worst, Math.Max((balls(0).Position - upper).Length, (balls(1).Position - lower).Length))
            Next
            _output.WriteLine($"largest distance from the angle solution over 2 s: {worst:E2} m")
            Assert.True(worst <= 0.000000001, $"{worst:E2} m from the angle solution")
        End Sub

        ''' <summary>One classical Runge–Kutta step of (θ₁, θ₂, θ₁', θ₂') for unit masses and lengths.</summary>
        Private Shared Function RungeKuttaStep(y As Double(), h As Double) As Double()
            Dim k1 = AngleRates(y)
            Dim k2 = AngleRates(Add(y, k1, h / 2))
            Dim k3 = AngleRates(Add(y, k2, h / 2))
            Dim k4 = AngleRates(Add(y, k3, h))
            Dim r(3) As Double
            For i = 0 To 3
                r(i) = y(i) + h / 6 * (k1(i) + 2 * k2(i) + 2 * k3(i) + k4(i))
            Next
            Return r
        End Function

        Private Shared Function Add(y As Double(), k As Double(), h As Double) As Double()
            Return {y(0) + h * k(0), y(1) + h * k(1), y(2) + h * k(2), y(3) + h * k(3)}
        End Function

        ''' <summary>The double pendulum's equations for m₁ = m₂ = 1 kg, L₁ = L₂ = 1 m.</summary>
        Private Shared Function AngleRates(y As Double()) As Double()
            Dim t1 = y(0), t2 = y(1), w1 = y(2), w2 = y(3)
            Dim d = t1 - t2
            Dim den = 3 - Math.Cos(2 * d)
            Dim a1 = (-3 * G * Math.Sin(t1) - G * Math.Sin(t1 - 2 * t2) - 2 * Math.Sin(d) * (w2 * w2 + w1 * w1 * Math.Cos(d))) / den
            Dim a2 = 2 * Math.Sin(d) * (2 * w1 * w1 + 2 * G * Math.Cos(t1) + w2 * w2 * Math.Cos(d)) / den
            Return {w1, w2, a1, a2}
        End Function

        ''' <summary>Both bobs' positions after 0.5 s of the level double pendulum, with the named solver.</summary>
        Private Shared Function DoublePendulumAfterHalfASecond(solver As String, Optional timeStep As Double? = Nothing) As Vector()
            Dim w As New World(10, 10, G, 1.0)
            w.Solver = SolverFactory.Create(solver, timeStep)
            Dim balls = LevelChain(w, 2, 1, 0.05, 1)
            w.Advance(0.5)
            Return {balls(0).Position, balls(1).Position}
        End Function

        <Fact>
        Public Sub DoublePendulum_AgreesWithVerlet_ToTheOrderOfItsStep()
            Dim exact = DoublePendulumAfterHalfASecond("event")
            Dim errors As New List(Of Double)
            For Each dt In {0.002, 0.001, 0.0005}
                Dim p = DoublePendulumAfterHalfASecond("verlet", dt)
                Dim e = Math.Max((p(0) - exact(0)).Length, (p(1) - exact(1)).Length)
                _output.WriteLine($"verlet dt = {dt}: {e:E3} m")
                errors.Add(e)
                ' O(dt): within a modest constant times the step.
                Assert.True(e <= 2 * dt, $"verlet at dt = {dt} is {e} m from the event solver")
            Next
            ' And it shrinks with the step, as a convergent method's does: by at least half per halving.
            Assert.True(errors(1) <= 0.6 * errors(0) AndAlso errors(2) <= 0.6 * errors(1), String.Join(", ", errors))
        End Sub

        <Fact>
        Public Sub ChainSpinningWithoutGravity_HitsAFreeBallInItsPath_AtThePredictedTime()
            ' With g = 0 a straight chain turning at ω stays straight: the lower bob runs round a circle of
            ' radius 2L at 2ωL. A ball at rest on that circle is hit when the chord between them is r₁ + r₂.
            Dim w As New World(10, 10, 0, 1.0)
            w.Solver = SolverFactory.Create("event")
            Dim centre As New Vector(5, 5)
            Dim omega = 1.5
            Dim upper As New Circle(centre + New Vector(1, 0), 0.1, 1, New Vector(0, omega))
            Dim lower As New Circle(centre + New Vector(2, 0), 0.1, 1, New Vector(0, 2 * omega))
            Dim psi = 1.2
            Dim free As New Circle(centre + 2 * New Vector(Math.Cos(psi), Math.Sin(psi)), 0.1, 1)
            w.Add(upper)
            w.Add(lower)
            w.Add(free)
            w.Add(Link.CreateTie(LinkKind.Rod, upper, centre, 1))
            w.Add(Link.CreateTie(LinkKind.Rod, lower, upper, 1))
            Dim records As New List(Of CollisionRecord)
            w.CollisionListener = Sub(c) records.Add(c)
            Dim momentBefore = AngularMomentum(w, centre)
            Dim energyBefore = Energy(w)
            Dim expected = (psi - 2 * Math.Asin(0.2 / 4)) / omega
            ' In frames, checking that the two never overlap (nothing is stepped over).
            Dim worstOverlap = 0.0
            TestSolvers.Frames(w, expected + 0.2, 0.001, Sub() worstOverlap = Math.Max(worstOverlap, 0.2 - (free.Position - lower.Position).Length))
            Assert.True(records.Count >= 1, "the free ball was not hit")
            Dim hit = records(0)
            _output.WriteLine($"hit at {hit.Time} s (expected {expected} s), free ball leaves at {free.Velocity}, worst overlap {worstOverlap:E2} m")
            Assert.Equal(expected, hit.Time, 0.000000001)
            Assert.True(worstOverlap <= 0.000000001, $"they overlapped by {worstOverlap} m")
            ' The blow is along the line of centres: the free ball leaves along it, away from the bob.
            Dim freeAfter = If(hit.A Is free, hit.AVelocityAfter, hit.BVelocityAfter)
            Assert.True(freeAfter.Length > 0.1, $"the free ball left at {freeAfter}")
            Dim lineAtHit = freeAfter.Normalized(Vector.Zero)
            Dim chord = New Vector(Math.Cos(psi), Math.Sin(psi)) * 2 - New Vector(Math.Cos(psi - 2 * Math.Asin(0.05)), Math.Sin(psi - 2 * Math.Asin(0.05))) * 2
            Assert.Equal(0.0, Vector.Cross(lineAtHit, chord.Normalized(Vector.Zero)), 9)
            ' The anchor's pull has no moment about the anchor, and e = 1: angular momentum and energy are kept.
            Assert.Equal(momentBefore, AngularMomentum(w, centre), 9)
            Assert.Equal(energyBefore, Energy(w), 9)
            Assert.Equal(1.0, (upper.Position - centre).Length, 9)
            Assert.Equal(1.0, (lower.Position - upper.Position).Length, 9)
        End Sub

        <Fact>
        Public Sub RopeSwingingIntoBallsOnTheFloor_NeverOverlapsThem_AndKeepsItsEnergyWithEOne()
            ' The rope's end sweeps down to 0.2 m above the floor, through three balls resting there: every hit
            ' is found (checked every millisecond for overlaps) and, with e = 1, no energy is lost.
            Dim w As New World(10, 10, G, 1.0)
            w.Solver = SolverFactory.Create("event")
            Dim pivot As New Vector(5, 2.2)
            Dim rope As New List(Of Circle)
            For k = 1 To 10
                Dim ball As New Circle(pivot + New Vector(0.2 * k, 0), 0.05, 0.2)
                w.Add(ball)
                w.Add(If(k = 1, Link.CreateTie(LinkKind.Rod, ball, pivot, 0.2), Link.CreateTie(LinkKind.Rod, ball, rope(k - 2), 0.2)))
                rope.Add(ball)
            Next
            For Each x In {4.4, 5.0, 5.6}
                w.Add(New Circle(New Vector(x, 0.15), 0.15, 0.5))
            Next
            Dim e0 = Energy(w)
            Dim worstOverlap = 0.0, worstLength = 0.0
            Dim rodPairs = New HashSet(Of (Circle, Circle))(w.Links.Where(Function(l) l.B IsNot Nothing).Select(Function(l) (DirectCast(l.A, Circle), DirectCast(l.B, Circle))))
            TestSolvers.Frames(w, 3, 0.001, Sub()
                                                For i = 0 To w.Circles.Count - 1
                                                    For j = i + 1 To w.Circles.Count - 1
                                                        Dim a = w.Circles(i), b = w.Circles(j)
                                                        If rodPairs.Contains((a, b)) OrElse rodPairs.Contains((b, a)) Then Continue For
                                                        worstOverlap = Math.Max(worstOverlap, a.Radius + b.Radius - (a.Position - b.Position).Length)
                                                    Next
                                                Next
                                                worstLength = Math.Max(worstLength, WorstLengthError(w))
                                            End Sub)
            Dim drift = Math.Abs(Energy(w) - e0) / (10 * 0.2 * G * 2)
            _output.WriteLine($"{w.CollisionCount} collisions, worst overlap {worstOverlap:E2} m, rods {worstLength:E2} m, energy {drift:E2} of M g L")
            Assert.True(w.CollisionCount >= 3, $"only {w.CollisionCount} collisions")
            Assert.True(worstOverlap <= 0.000000001, $"bodies overlapped by {worstOverlap} m")
            Assert.True(worstLength <= 0.000000001, $"a rod's length is off by {worstLength} m")
            Assert.True(drift <= 0.000000001, $"energy drifted by {drift:E2} of M g L")
        End Sub

        <Fact>
        Public Sub RodPendulumWithABallOnASpring_KeepsItsEnergyIncludingTheSpring()
            ' A chain with a spring in it: a bob on a rod, and a second ball hanging from the bob on a spring.
            Dim w As New World(10, 10, G, 1.0)
            w.Solver = SolverFactory.Create("event")
            Dim bob As New Circle(Anchor + New Vector(1, 0), 0.05, 1)
            Dim hanging As New Circle(Anchor + New Vector(1, -0.5), 0.05, 0.5)
            w.Add(bob)
            w.Add(hanging)
            w.Add(Link.CreateTie(LinkKind.Rod, bob, Anchor, 1))
            w.Add(Link.CreateSpring(hanging, bob, 40, 0.4))
            Dim total As Func(Of Double) = Function() Energy(w) + w.Links.Sum(Function(l) l.StoredEnergy)
            Dim e0 = total()
            Dim worst = 0.0
            TestSolvers.Frames(w, 5, 0.05, Sub() worst = Math.Max(worst, Math.Abs(total() - e0) / (1.5 * G * 1.5)))
            _output.WriteLine($"energy {worst:E2} of m g L, rod {Math.Abs(w.Links(0).Distance - 1):E2} m")
            Assert.True(worst <= 0.000000001, $"energy drifted by {worst:E2} of m g L")
            Assert.Equal(1.0, w.Links(0).Distance, 9)
        End Sub

        <Fact>
        Public Sub TwoRodsBetweenTheSameBalls_MoveAsOne_BothHeldAtTheirLength_EnergyKept()
            ' The second rod says nothing the first does not: the double pendulum swings as with one, and both keep
            ' their length (the solve holds one, and watches the other).
            Dim w As New World(10, 10, G, 1.0)
            w.Solver = SolverFactory.Create("event")
            Dim a As New Circle(New Vector(5, 5), 0.05, 1)
            Dim b As New Circle(New Vector(6, 5), 0.05, 1, New Vector(0, 1))
            w.Add(a)
            w.Add(b)
            w.Add(Link.CreateTie(LinkKind.Rod, a, Anchor, 1))
            Dim first = Link.CreateTie(LinkKind.Rod, b, a, 1)
            Dim second = Link.CreateTie(LinkKind.Rod, a, b, 1)
            w.Add(first)
            w.Add(second)
            Dim energy0 = w.KineticEnergy + w.PotentialEnergy
            For k = 1 To 20
                w.Advance(0.1)
                Assert.Equal(1.0, first.Distance, 9)
                Assert.Equal(1.0, second.Distance, 9)
            Next
            Assert.True(Math.Abs(w.KineticEnergy + w.PotentialEnergy - energy0) <= 0.000000001 * energy0, $"energy {w.KineticEnergy + w.PotentialEnergy} J, from {energy0} J")
        End Sub

        <Fact>
        Public Sub DoublePendulumCarriedByHand_AndLetGo_SwingsOnWithItsRodsHeld()
            Dim w As New World(10, 10, G, 1.0)
            w.Solver = SolverFactory.Create("event")
            Dim balls = LevelChain(w, 2, 1, 0.05, 1)
            w.Advance(0.3)
            ' The lower bob carried over a few frames to below the anchor and a little to the side, then let go at rest.
            w.BeginDrag(balls(1))
            Dim hand = Anchor + New Vector(0.5, -1.8)
            Dim start = balls(1).Position
            For k = 1 To 20
                w.DragTo(start + (hand - start) * (k / 20.0))
                w.Advance(1 / 60.0)
            Next
            w.EndDrag(Vector.Zero)
            Dim e0 = Energy(w)
            Dim worstEnergy = 0.0, worstLength = 0.0
            TestSolvers.Frames(w, 2, 0.05, Sub()
                                               worstEnergy = Math.Max(worstEnergy, Math.Abs(Energy(w) - e0) / (2 * G * 2))
                                               worstLength = Math.Max(worstLength, WorstLengthError(w))
                                           End Sub)
            _output.WriteLine($"after the hand: energy {worstEnergy:E2} of m g L, rods {worstLength:E2} m")
            Assert.True(worstLength <= 0.000000001, $"a rod's length is off by {worstLength} m")
            Assert.True(worstEnergy <= 0.000000001, $"energy drifted by {worstEnergy:E2} of m g L")
        End Sub

        Private Shared Function AngularMomentum(w As World, about As Vector) As Double
            Return w.Circles.Sum(Function(c) c.Mass * Vector.Cross(c.Position - about, c.Velocity))
        End Function
    End Class
End Namespace
