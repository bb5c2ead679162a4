Option Strict On
Imports PhysicsEngine
Imports PhysicsEngine.Tests.Links
Imports Xunit
Imports Xunit.Abstractions

Namespace Stepping
    ''' <summary>
    ''' Links in the stepping solvers against closed forms: the pendulum from 60° (period and path), a mass on
    ''' a vertical spring, a spinning dumbbell, and a string that goes slack in a vertical circle. The error
    ''' must be first order or better: small at 1 ms and at least halved at 0.5 ms.
    ''' </summary>
    Public Class LinkSteppingTests
        Private Const G As Double = 9.81
        Private ReadOnly _output As ITestOutputHelper

        Public Sub New(output As ITestOutputHelper)
            _output = output
        End Sub

        Private Shared ReadOnly Anchor As New Vector(5, 6)

        ''' <summary>A bob of 0.5 kg, radius 0.05 m, on a rod or string of length L released at rest from θ₀.</summary>
        Private Shared Function PendulumWorld(kind As LinkKind, length As Double, theta0 As Double, solver As String, dt As Double) As World
            Dim w As New World(10, 10, G, 1.0)
            Dim bob As New Circle(Anchor + New Vector(length * Math.Sin(theta0), -length * Math.Cos(theta0)), 0.05, 0.5)
            w.Add(bob)
            w.Add(Link.CreateTie(kind, bob, Anchor, length))
            w.Solver = SolverFactory.Create(solver, dt)
            Return w
        End Function

        ''' <summary>The largest distance (m) between the bob and the closed form over <paramref name="span"/> s, read every 10 ms.</summary>
        Private Shared Function PendulumPathError(kind As LinkKind, solver As String, dt As Double, span As Double) As Double
            Dim length = 1.0, theta0 = Math.PI / 3
            Dim w = PendulumWorld(kind, length, theta0, solver, dt)
            Dim bob = w.Circles(0)
            Dim exact As New Pendulum(Anchor, length, G, bob.Position, Vector.Zero)
            Dim worst = 0.0
            For i = 1 To CInt(Math.Round(span / 0.01))
                w.Advance(0.01)
                worst = Math.Max(worst, (bob.Position - exact.PositionAt(w.Time)).Length)
                ' A rod or taut string keeps the bob on the circle to rounding.
                Assert.Equal(length, (bob.Position - Anchor).Length, 0.000000001)
            Next
            Return worst
        End Function

        <Theory>
        <InlineData("euler", LinkKind.Rod)>
        <InlineData("verlet", LinkKind.Rod)>
        <InlineData("euler", LinkKind.String)>
        <InlineData("verlet", LinkKind.String)>
        Public Sub PendulumFrom60Degrees_FollowsTheEllipticClosedForm(solver As String, kind As LinkKind)
            Dim span = 3 * New Pendulum(Anchor, 1, G, Anchor + New Vector(Math.Sin(Math.PI / 3), -Math.Cos(Math.PI / 3)), Vector.Zero).Period
            Dim coarse = PendulumPathError(kind, solver, 0.001, span)
            Dim fine = PendulumPathError(kind, solver, 0.0005, span)
            _output.WriteLine($"{solver} {kind}: {coarse} m at 1 ms, {fine} m at 0.5 ms")
            Assert.True(coarse < 0.05, $"{coarse} m off after three periods at 1 ms")
            Assert.True(fine < 0.6 * coarse, $"{fine} m at 0.5 ms against {coarse} m at 1 ms: not first order")
        End Sub

        <Theory>
        <InlineData("euler")>
        <InlineData("verlet")>
        Public Sub PendulumFrom60Degrees_PeriodIsTheCompleteEllipticIntegral(solver As String)
            ' T = 4√(L/g) K(sin(θ₀/2)); measured between the bob's returns to x at its highest, through the
            ' times its horizontal velocity changes sign (interpolated linearly between steps).
            Dim length = 1.0, theta0 = Math.PI / 3
            Dim expected = 4 * Math.Sqrt(length / G) * CompleteK(Math.Sin(theta0 / 2))
            Dim errors = New Double(1) {}
            For pass = 0 To 1
                Dim dt = If(pass = 0, 0.001, 0.0005)
                Dim w = PendulumWorld(LinkKind.Rod, length, theta0, solver, dt)
                Dim bob = w.Circles(0)
                Dim turns As New List(Of Double)
                Dim previous = 0.0
                Do While turns.Count < 5
                    Dim t0 = w.Time
                    w.Advance(dt)
                    Dim vx = bob.Velocity.X
                    If previous <> 0 AndAlso Math.Sign(vx) <> Math.Sign(previous) Then turns.Add(t0 + dt * previous / (previous - vx))
                    previous = vx
                Loop
                ' Turning points every half period: the first is at T/2, the fifth at 5T/2.
                Dim measured = (turns(4) - turns(0)) / 2
                errors(pass) = Math.Abs(measured - expected)
                _output.WriteLine($"{solver} dt {dt}: T = {measured} s against {expected} s")
            Next
            Assert.True(errors(0) < 0.005 * expected, $"period off by {errors(0)} s")
            Assert.True(errors(1) < 0.6 * errors(0) OrElse errors(1) < 0.000001, $"{errors(1)} s at 0.5 ms against {errors(0)} s at 1 ms")
        End Sub

        ''' <summary>Largest |y − y(t)| (m) over 3 s for a mass released at rest with the spring at its natural length.</summary>
        Private Shared Function SpringError(solver As String, dt As Double) As Double
            Dim m = 0.5, k = 40.0, rest = 1.0
            Dim w As New World(10, 10, G, 1.0)
            Dim bob As New Circle(New Vector(Anchor.X, Anchor.Y - rest), 0.05, m)
            w.Add(bob)
            w.Add(Link.CreateSpring(bob, Anchor, k, rest))
            w.Solver = SolverFactory.Create(solver, dt)
            ' y(t) = y_eq + (mg/k) cos(√(k/m) t), y_eq = anchor − ℓ − mg/k.
            Dim sag = m * G / k
            Dim yEq = Anchor.Y - rest - sag
            Dim omega = Math.Sqrt(k / m)
            Dim worst = 0.0
            For i = 1 To 300
                w.Advance(0.01)
                worst = Math.Max(worst, Math.Abs(bob.Position.Y - (yEq + sag * Math.Cos(omega * w.Time))))
                Assert.Equal(Anchor.X, bob.Position.X, 0.000000000001)
            Next
            Return worst
        End Function

        <Theory>
        <InlineData("euler")>
        <InlineData("verlet")>
        Public Sub MassOnAVerticalSpring_OscillatesAboutItsEquilibrium(solver As String)
            Dim coarse = SpringError(solver, 0.001)
            Dim fine = SpringError(solver, 0.0005)
            _output.WriteLine($"{solver}: {coarse} m at 1 ms, {fine} m at 0.5 ms (amplitude {0.5 * G / 40} m)")
            Assert.True(coarse < 0.01, $"{coarse} m off")
            Assert.True(fine < 0.6 * coarse, $"{fine} m at 0.5 ms against {coarse} m at 1 ms")
        End Sub

        <Theory>
        <InlineData("euler")>
        <InlineData("verlet")>
        Public Sub DampedSpring_FollowsTheDampedClosedForm(solver As String)
            Dim m = 0.5, k = 40.0, rest = 1.0, c = 0.8
            Dim errors = New Double(1) {}
            For pass = 0 To 1
                Dim dt = If(pass = 0, 0.001, 0.0005)
                Dim w As New World(10, 10, G, 1.0)
                Dim start As New Vector(Anchor.X, Anchor.Y - rest - 0.3)
                Dim bob As New Circle(start, 0.05, m, New Vector(0, 0.5))
                w.Add(bob)
                w.Add(Link.CreateSpring(bob, Anchor, k, rest, c))
                w.Solver = SolverFactory.Create(solver, dt)
                Dim exact As New VerticalSpring(Anchor, m, k, rest, c, G, start, New Vector(0, 0.5))
                For i = 1 To 300
                    w.Advance(0.01)
                    errors(pass) = Math.Max(errors(pass), Math.Abs(bob.Position.Y - exact.PositionAt(w.Time).Y))
                Next
            Next
            _output.WriteLine($"{solver}: {errors(0)} m at 1 ms, {errors(1)} m at 0.5 ms")
            Assert.True(errors(0) < 0.01, $"{errors(0)} m off")
            Assert.True(errors(1) < 0.6 * errors(0), $"{errors(1)} m at 0.5 ms against {errors(0)} m at 1 ms")
        End Sub

        <Theory>
        <InlineData("euler")>
        <InlineData("verlet")>
        Public Sub DumbbellSpinningWithoutGravity_KeepsItsLengthAndSpin(solver As String)
            Dim errors = New Double(1) {}
            For pass = 0 To 1
                Dim dt = If(pass = 0, 0.001, 0.0005)
                Dim w As New World(10, 10, 0, 1.0)
                Dim b1 As New Circle(New Vector(4.5, 5), 0.1, 1, New Vector(0.3, -2))
                Dim b2 As New Circle(New Vector(5.5, 5), 0.1, 3, New Vector(0.3, 1))
                w.Add(b1)
                w.Add(b2)
                w.Add(Link.CreateTie(LinkKind.Rod, b1, b2, 1))
                w.Solver = SolverFactory.Create(solver, dt)
                Dim exact As New Dumbbell(1, b1.Position, b1.Velocity, 3, b2.Position, b2.Velocity, 1, 0)
                Dim momentum = w.Momentum()
                Dim energy = w.KineticEnergy()
                For i = 1 To 200
                    w.Advance(0.01)
                    Dim p1 As Vector, v1 As Vector, p2 As Vector, v2 As Vector
                    exact.StateAt(w.Time, p1, v1, p2, v2)
                    errors(pass) = Math.Max(errors(pass), Math.Max((b1.Position - p1).Length, (b2.Position - p2).Length))
                    Assert.Equal(1.0, (b2.Position - b1.Position).Length, 0.000000001)
                    ' The rod's pulls are equal and opposite: momentum is kept to rounding.
                    Assert.True((w.Momentum() - momentum).Length < 0.000000001, $"momentum {w.Momentum()} against {momentum}")
                Next
                _output.WriteLine($"{solver} dt {dt}: energy {w.KineticEnergy()} J against {energy} J")
                Assert.Equal(energy, w.KineticEnergy(), 0.01 * energy)
            Next
            _output.WriteLine($"{solver}: {errors(0)} m at 1 ms, {errors(1)} m at 0.5 ms")
            Assert.True(errors(0) < 0.05, $"{errors(0)} m off")
            Assert.True(errors(1) < 0.6 * errors(0), $"{errors(1)} m at 0.5 ms against {errors(0)} m at 1 ms")
        End Sub

        <Theory>
        <InlineData("euler")>
        <InlineData("verlet")>
        Public Sub StringInAVerticalCircle_GoesSlackWhereTheTensionVanishes_AndFliesItsParabola(solver As String)
            ' From the bottom with u² = 3.5 gL the tension vanishes at cos θ = −(u² − 2gL)/(3gL) = −1/2,
            ' 1.5 L above the bottom; the bob then flies a parabola inside the circle until the string snaps taut.
            Dim length = 1.0
            Dim u = Math.Sqrt(3.5 * G * length)
            Dim errors = New Double(1) {}
            Dim slackErrors = New Double(1) {}
            For pass = 0 To 1
                Dim dt = If(pass = 0, 0.001, 0.0005)
                Dim w As New World(10, 10, G, 1.0)
                Dim bob As New Circle(Anchor + New Vector(0, -length), 0.05, 0.5, New Vector(u, 0))
                w.Add(bob)
                Dim tie = Link.CreateTie(LinkKind.String, bob, Anchor, length)
                w.Add(tie)
                w.Solver = SolverFactory.Create(solver, dt)
                Dim exact As New Pendulum(Anchor, length, G, bob.Position, bob.Velocity)
                Dim tSlack = exact.SlackTime()
                Dim slackPosition As Vector, slackVelocity As Vector
                exact.StateAt(tSlack, slackPosition, slackVelocity)
                Assert.Equal(Anchor.Y + 0.5 * length, slackPosition.Y, 0.000000001)
                Dim tTaut = tSlack + StringTaut.AnchoredTautTime(Anchor, length, slackPosition, slackVelocity, G, 0.000000001)
                ' The first time the bob is clearly inside the circle.
                Dim seenSlack = Double.NaN
                Do While w.Time < tTaut - 0.02
                    w.Advance(dt)
                    Dim inside = (bob.Position - Anchor).Length < length * (1 - 0.00001)
                    If inside AndAlso Double.IsNaN(seenSlack) Then seenSlack = w.Time
                    If w.Time > tSlack + 0.02 Then
                        ' On the parabola from where the closed form went slack.
                        Dim s = w.Time - tSlack
                        Dim flight = slackPosition + slackVelocity * s + New Vector(0, -0.5 * G * s * s)
                        errors(pass) = Math.Max(errors(pass), (bob.Position - flight).Length)
                        Assert.True(inside, $"t = {w.Time}: the string should be slack")
                        Assert.Equal(0.0, tie.Tension)
                    End If
                Loop
                slackErrors(pass) = Math.Abs(seenSlack - tSlack)
                _output.WriteLine($"{solver} dt {dt}: slack at {seenSlack} s (closed form {tSlack} s), taut at {tTaut} s, flight off by {errors(pass)} m")
            Next
            Assert.True(errors(0) < 0.05, $"{errors(0)} m off the parabola")
            Assert.True(errors(1) < 0.6 * errors(0), $"{errors(1)} m at 0.5 ms against {errors(0)} m at 1 ms")
            Assert.True(slackErrors(0) < 0.02, $"slack {slackErrors(0)} s late or early")
        End Sub

        <Theory>
        <InlineData(LinkKind.Rod)>
        <InlineData(LinkKind.Spring)>
        Public Sub Verlet_KeepsEnergyBoundedOverManyPeriods(kind As LinkKind)
            ' Symplectic: the energy wobbles with the step but does not drift. Compare the spread over the
            ' first five seconds with the spread over the last five of sixty.
            Dim w As New World(10, 10, G, 1.0)
            Dim bob As New Circle(Anchor + New Vector(Math.Sin(1.0), -Math.Cos(1.0)), 0.05, 0.5)
            w.Add(bob)
            If kind = LinkKind.Rod Then
                w.Add(Link.CreateTie(LinkKind.Rod, bob, Anchor, 1))
            Else
                ' A swinging, stretching spring: energy sloshes between the swing and the bounce.
                w.Add(Link.CreateSpring(bob, Anchor, 30, 0.8))
            End If
            w.Solver = SolverFactory.Create("verlet", 0.001)
            Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
            Dim early = 0.0, late = 0.0
            For i = 1 To 6000
                w.Advance(0.01)
                Dim drift = Math.Abs(w.KineticEnergy() + w.PotentialEnergy() - e0)
                If w.Time <= 5 Then early = Math.Max(early, drift)
                If w.Time > 55 Then late = Math.Max(late, drift)
            Next
            Dim scale = 0.5 * G
            _output.WriteLine($"{kind}: energy off by {early} J in the first 5 s, {late} J in the last 5 s (of mgL = {scale} J)")
            Assert.True(late < 0.001 * scale, $"{late} J off after a minute")
            Assert.True(late < 3 * early + 0.000001 * scale, $"{late} J against {early} J: drifting")
        End Sub

        <Theory>
        <InlineData("euler")>
        <InlineData("verlet")>
        Public Sub NewtonsCradleOnStrings_TheLastBallTakesTheStrikersSwing(solver As String)
            ' Five 0.2 kg balls on 1 m strings, touching; the first released from 30°. After the blow the
            ' last ball rises to the striker's height, L(1 − cos 30°), and the others stay near the bottom.
            Dim w As New World(10, 10, G, 1.0)
            Dim r = 0.1
            Dim balls As New List(Of Circle)
            For k = 0 To 4
                Dim top As New Vector(4 + 2 * r * k, 6)
                Dim at = If(k = 0, top + New Vector(-Math.Sin(Math.PI / 6), -Math.Cos(Math.PI / 6)), top + New Vector(0, -1))
                Dim c As New Circle(at, r, 0.2)
                w.Add(c)
                w.Add(Link.CreateTie(LinkKind.String, c, top, 1))
                balls.Add(c)
            Next
            w.Solver = SolverFactory.Create(solver, 0.0005)
            Dim highest = 0.0, othersHighest = 0.0
            ' The blow comes after a quarter period (0.51 s); the last ball is highest a quarter period later.
            For i = 1 To 120
                w.Advance(0.01)
                If w.Time > 0.6 Then
                    highest = Math.Max(highest, balls(4).Position.Y)
                    For k = 0 To 3
                        othersHighest = Math.Max(othersHighest, balls(k).Position.Y)
                    Next
                End If
            Next
            Dim rise = highest - 5, expected = 1 - Math.Cos(Math.PI / 6)
            _output.WriteLine($"{solver}: the last ball rose {rise} m (striker's drop {expected} m); the others at most {othersHighest - 5} m")
            Assert.Equal(expected, rise, 0.01 * expected)
            Assert.True(othersHighest - 5 < 0.01 * expected, $"the others rose {othersHighest - 5} m")
        End Sub

        ''' <summary>
        ''' A 50 mg ball on a compressed spring to a fixed point, damped at c = 0.55 N·s/m (tests/cases), g = 100,
        ''' e = 0.34: c h/m = 11 at the 1 ms step. Taken as a force at the step's start, the damping reversed the
        ''' stretch rate and made it ten times larger every step: 10⁵ m/s by t = 0.01 s, infinity and NaN (an
        ''' ArithmeticException in a wall contact) by t = 0.3 s. Taken at the step's new velocities it only slows the
        ''' stretching: the ball swings down about the fixed point as if on a rod, bounces along the floor and comes
        ''' to rest in the bottom right corner, where the spring, still 0.16 m short of its length, holds it. It never
        ''' gains energy, and the books (energy plus what was taken) never show more than it started with.
        ''' </summary>
        <Theory>
        <InlineData("euler")>
        <InlineData("verlet")>
        Public Sub LightBallOnAStronglyDampedSpring_SwingsDown_AndComesToRestInTheCorner_NeverGainingEnergy(solver As String)
            Dim w = Scenes.SceneFile.LoadFile(TestRepo.CaseFile("stepping-light-ball-on-damped-spring.json"))
            w.Solver = SolverFactory.Create(solver)
            Dim ball = w.Circles(0)
            Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
            Dim dissipated = 0.0
            Dim highest = 0.0
            Dim settled = Vector.Zero
            For i = 1 To 40
                w.Advance(0.05)
                Assert.True(Finite(ball.Position) AndAlso Finite(ball.Velocity), $"t = {w.Time}: {ball.Position}, {ball.Velocity}")
                Assert.True(w.Dissipated >= dissipated, $"t = {w.Time}: dissipated fell from {dissipated} J to {w.Dissipated} J")
                dissipated = w.Dissipated
                Dim energy = w.KineticEnergy() + w.PotentialEnergy()
                highest = Math.Max(highest, energy / e0)
                Assert.True(energy <= e0, $"t = {w.Time}: {energy} J against {e0} J at the start")
                Assert.True(energy + w.Dissipated <= e0, $"t = {w.Time}: {energy} J + {w.Dissipated} J taken against {e0} J at the start")
                If i = 30 Then settled = ball.Position
            Next
            _output.WriteLine($"{solver}: energy at most {highest} of the start's; {dissipated} J taken of {e0} J; at {ball.Position}")
            Assert.Equal(settled, ball.Position)
            Assert.Equal(w.Width - ball.Radius, ball.Position.X, 0.000000001)
            Assert.Equal(ball.Radius, ball.Position.Y, 0.000000001)
        End Sub

        Private Shared Function Finite(v As Vector) As Boolean
            Return Not (Double.IsNaN(v.X) OrElse Double.IsInfinity(v.X) OrElse Double.IsNaN(v.Y) OrElse Double.IsInfinity(v.Y))
        End Function
    End Class
End Namespace
