Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Links
    ''' <summary>The closed-form pendulum against energy, symmetry, the small-angle series and a fine RK4 of θ'' = −(g/L) sin θ.</summary>
    Public Class PendulumTests
        Private Const G As Double = 9.81
        Private Shared ReadOnly Anchor As New Vector(1.5, 2.0)

        Private Shared Function Released(length As Double, theta As Double, rate As Double) As Pendulum
            Return New Pendulum(Anchor, length, G, LinkTestKit.OnCircle(Anchor, length, theta), LinkTestKit.AlongCircle(length, theta, rate))
        End Function

        <Fact>
        Public Sub ReleasedFrom60Degrees_IsAtTheOtherTurningPointEveryHalfPeriod()
            Dim length = 1.2
            Dim theta0 = Math.PI / 3
            Dim p = Released(length, theta0, 0)
            Assert.Equal(PendulumRegime.Libration, p.Regime)
            Dim half = p.Period / 2
            For n = 1 To 10
                Dim expected = LinkTestKit.OnCircle(Anchor, length, If(n Mod 2 = 1, -theta0, theta0))
                Dim position As Vector, velocity As Vector
                p.StateAt(n * half, position, velocity)
                Assert.True(LinkTestKit.Distance(expected, position) < 0.000000001, $"n = {n}: {position} vs {expected}")
                Assert.True(velocity.Length < 0.00000001, $"n = {n}: speed {velocity.Length}")
            Next
        End Sub

        <Fact>
        Public Sub Period_MatchesTheSmallAngleSeriesAndTheQuadrature()
            Dim length = 0.8
            For Each amplitude In {0.001, 0.05, 0.2}
                ' T = 2π√(L/g)(1 + θ²/16 + 11θ⁴/3072 + 173θ⁶/737280 + …).
                Dim a2 = amplitude * amplitude
                Dim series = 2 * Math.PI * Math.Sqrt(length / G) * (1 + a2 / 16 + 11 * a2 * a2 / 3072 + 173 * a2 * a2 * a2 / 737280)
                Assert.Equal(series, Released(length, amplitude, 0).Period, 1.0E-9)
            Next
            ' Large swings: T = 4√(L/g) ∫₀^(π/2) dφ / √(1 − k² sin² φ), k = sin(θmax/2), by quadrature.
            For Each amplitude In {1.0, 2.5, 3.1}
                Dim k = Math.Sin(amplitude / 2)
                Dim expected = 4 * Math.Sqrt(length / G) * LinkTestKit.EllipticFByQuadrature(Math.PI / 2, k)
                Assert.Equal(expected, Released(length, amplitude, 0).Period, 1.0E-9)
            Next
        End Sub

        <Fact>
        Public Sub Energy_IsConservedOver1000Periods()
            Dim length = 1.0
            Dim p = Released(length, 2.0, 0.7)
            Dim e0 = EnergyPerMass(p, 0)
            Dim t = 0.0
            Dim last = 1000 * p.Period
            Dim rng As New Random(3)
            Do While t < last
                Dim e = EnergyPerMass(p, t)
                Assert.True(Math.Abs(e - e0) < 0.000000001 * (G * length), $"t = {t}: {e} vs {e0}")
                ' The point stays on the circle.
                Assert.Equal(length, LinkTestKit.Distance(p.PositionAt(t), Anchor), 1.0E-12)
                t += rng.NextDouble() * p.Period
            Loop
        End Sub

        Private Shared Function EnergyPerMass(p As Pendulum, t As Double) As Double
            Dim position As Vector, velocity As Vector
            p.StateAt(t, position, velocity)
            Return 0.5 * velocity.LengthSquared + G * position.Y
        End Function

        <Theory>
        <InlineData(0.3, 0.0)>
        <InlineData(-1.0, 2.0)>
        <InlineData(2.9, -0.5)>
        <InlineData(0.0, 7.5)>
        <InlineData(3.0, 4.0)>
        <InlineData(-2.0, -9.0)>
        Public Sub Motion_MatchesAFineRk4OfTheAngleEquation(theta0 As Double, rate0 As Double)
            ' L = 0.5 m: ω₀² = 19.6 s⁻²; θ'₀ = 7.5 or 9 rad/s goes over the top (rotation).
            Dim length = 0.5
            Dim p = Released(length, theta0, rate0)
            Dim rng As New Random(11)
            Dim times = Enumerable.Range(0, 12).Select(Function(i) rng.NextDouble() * 4).OrderBy(Function(x) x).ToArray()
            Dim states = LinkTestKit.Rk4At(LinkTestKit.PendulumEquation(G, length), {theta0, rate0}, times, 0.0002)
            For i = 0 To times.Length - 1
                Dim expected = LinkTestKit.OnCircle(Anchor, length, states(i)(0))
                Dim position As Vector, velocity As Vector
                p.StateAt(times(i), position, velocity)
                Assert.True(LinkTestKit.Distance(expected, position) < 0.000000001, $"t = {times(i)}: {position} vs {expected}")
                Dim expectedVelocity = LinkTestKit.AlongCircle(length, states(i)(0), states(i)(1))
                Assert.True(LinkTestKit.Distance(expectedVelocity, velocity) < 0.00000001, $"t = {times(i)}: {velocity} vs {expectedVelocity}")
                Assert.Equal(states(i)(1), p.AngularVelocityAt(times(i)), 1.0E-8)
            Next
        End Sub

        <Fact>
        Public Sub Rotation_GoesOverTheTopOncePerPeriod()
            Dim length = 0.5
            ' u = Lθ' = 5 m/s at the bottom, u² = 25 > 4gL = 19.62: it goes over the top.
            Dim p = Released(length, 0, 10)
            Assert.Equal(PendulumRegime.Rotation, p.Regime)
            ' After one period it is back at the bottom with the same speed, the angle 2π further on.
            Assert.True(LinkTestKit.Distance(p.PositionAt(p.Period), p.PositionAt(0)) < 0.000000000001)
            Assert.Equal(2 * Math.PI, p.AngleAt(p.Period), 1.0E-10)
            Assert.Equal(20 * Math.PI, p.AngleAt(10 * p.Period), 1.0E-9)
            ' Half way round in time it is at the top, by symmetry.
            Assert.True(LinkTestKit.Distance(p.PositionAt(p.Period / 2), New Vector(Anchor.X, Anchor.Y + length)) < 0.000000000001)
            ' The speed at the top follows from energy: v² = u² − 4gL.
            Assert.Equal(Math.Sqrt(25 - 4 * G * length), p.VelocityAt(p.Period / 2).Length, 1.0E-12)
        End Sub

        <Fact>
        Public Sub NearSeparatrix_StaysFiniteAndMatchesRk4()
            ' At the bottom with u² = 4gL(1 − 1e-12): k′² = 1e-12, it climbs to within ~2e-6 rad of the top.
            Dim length = 1.0
            For Each sign In {1.0, -1.0}
                Dim rate0 = sign * 2 * Math.Sqrt(G / length) * Math.Sqrt(1 - 0.000000000001)
                Dim p = Released(length, 0, rate0)
                Assert.Equal(PendulumRegime.Libration, p.Regime)
                Assert.True(p.Period > 0 AndAlso p.Period < 100, $"period {p.Period}")
                Dim times = {0.5, 1.0, 1.5, 2.0, 2.5}
                Dim states = LinkTestKit.Rk4At(LinkTestKit.PendulumEquation(G, length), {0.0, rate0}, times, 0.0001)
                For i = 0 To times.Length - 1
                    Dim expected = LinkTestKit.OnCircle(Anchor, length, states(i)(0))
                    Assert.True(LinkTestKit.Distance(expected, p.PositionAt(times(i))) < 0.00000001, $"t = {times(i)}")
                Next
                ' Energy holds all the way through several slow passes near the top.
                Dim e0 = EnergyPerMass(p, 0)
                For t = 0.0 To 3 * p.Period Step p.Period / 97
                    Assert.True(Math.Abs(EnergyPerMass(p, t) - e0) < 0.000000001 * G * length)
                Next
            Next
            ' Just over: a rotation, also finite.
            Dim over = Released(length, 0, 2 * Math.Sqrt(G / length) * Math.Sqrt(1 + 0.000000000001))
            Assert.Equal(PendulumRegime.Rotation, over.Regime)
            Assert.True(over.Period > 0 AndAlso over.Period < 100)
            Assert.Equal(2 * Math.PI, over.AngleAt(over.Period), 1.0E-8)
        End Sub

        <Fact>
        Public Sub Separatrix_CreepsToTheTop()
            ' From the side (θ = π/2) with exactly the speed that reaches the top: v² = 2gL.
            Dim length = 1.0
            Dim p = New Pendulum(Anchor, length, G, New Vector(Anchor.X + length, Anchor.Y), New Vector(0, Math.Sqrt(2 * G * length)))
            Assert.True(p.Regime = PendulumRegime.Separatrix OrElse p.Regime = PendulumRegime.Libration OrElse p.Regime = PendulumRegime.Rotation)
            ' Angle rises monotonically towards π, staying finite.
            Dim previous = p.AngleAt(0)
            For t = 0.1 To 5.0 Step 0.1
                Dim a = p.AngleAt(t)
                Assert.False(Double.IsNaN(a))
                Assert.True(a >= previous - 0.000000000001)
                previous = a
            Next
            Assert.True(Math.PI - previous < 0.0001)
        End Sub

        <Fact>
        Public Sub RestAndNoGravity()
            Dim bottom = Released(1, 0, 0)
            Assert.Equal(PendulumRegime.Rest, bottom.Regime)
            Assert.Equal(New Vector(Anchor.X, Anchor.Y - 1), bottom.PositionAt(123.0))
            Assert.Equal(Double.PositiveInfinity, bottom.SlackTime())
            Dim top = New Pendulum(Anchor, 1, G, New Vector(Anchor.X, Anchor.Y + 1), Vector.Zero)
            Assert.Equal(PendulumRegime.Rest, top.Regime)
            Assert.Equal(0.0, top.SlackTime())
            ' g = 0: uniform circular motion, θ = θ₀ + θ'₀ t.
            Dim spin = New Pendulum(Anchor, 2, 0, LinkTestKit.OnCircle(Anchor, 2, 0.4), LinkTestKit.AlongCircle(2, 0.4, -1.3))
            Assert.Equal(PendulumRegime.Uniform, spin.Regime)
            Assert.Equal(2 * Math.PI / 1.3, spin.Period, 1.0E-12)
            For Each t In {0.0, 0.7, 5.0, 100.0}
                Assert.True(LinkTestKit.Distance(LinkTestKit.OnCircle(Anchor, 2, 0.4 - 1.3 * t), spin.PositionAt(t)) < 0.000000000001)
            Next
            Assert.Equal(2 * 1.3 * 1.3, spin.TensionPerMassAt(3), 1.0E-12)
            Assert.Equal(Double.PositiveInfinity, spin.SlackTime())
        End Sub

        <Theory>
        <InlineData(2.5)>
        <InlineData(3.0)>
        <InlineData(4.2)>
        <InlineData(4.9)>
        Public Sub SlackTime_IsAtHeightUSquaredPlusGLOver3G(uSquaredOverGL As Double)
            ' A bob given speed u at the bottom, 2gL < u² < 5gL: the string goes slack at the height
            ' (u² + gL)/(3g) above the bottom (u² < 4gL swings, u² > 4gL would go round).
            Dim length = 0.7
            Dim u = Math.Sqrt(uSquaredOverGL * G * length)
            For Each sign In {1.0, -1.0}
                Dim p = Released(length, 0, sign * u / length)
                Dim t = p.SlackTime()
                Assert.True(t > 0 AndAlso t < p.Period, $"slack at {t}")
                Dim height = p.PositionAt(t).Y - (Anchor.Y - length)
                Assert.Equal((u * u + G * length) / (3 * G), height, 1.0E-9)
                Assert.Equal(0.0, p.TensionPerMassAt(t), 1.0E-8)
                ' Taut all the way up to it.
                For k = 0 To 99
                    Assert.True(p.TensionPerMassAt(t * k / 100) > 0)
                Next
            Next
        End Sub

        <Fact>
        Public Sub SlackTime_NeverForSmallSwingsOrFastLoops_AndNowWhenAlreadySlack()
            Assert.Equal(Double.PositiveInfinity, Released(1, 1.2, 0).SlackTime())
            ' u² = 5.5 gL at the bottom: taut even at the top.
            Assert.Equal(Double.PositiveInfinity, Released(1, 0, Math.Sqrt(5.5 * G)).SlackTime())
            ' Above the horizontal and too slow to stay taut: slack at once.
            Assert.Equal(0.0, Released(1, 2.5, 0.1).SlackTime())
            ' A swing just beyond 90° goes slack before its turning point.
            Dim p = Released(1, 1.7, 0)
            Assert.True(p.TensionPerMassAt(0) < 0)
            Assert.Equal(0.0, p.SlackTime())
        End Sub

        ''' <summary>
        ''' A bob above the horizontal swinging down at just the speed that makes the tension zero there (L θ'² = −g cos θ),
        ''' as where a ball leaves the round top it slid on and the string to its centre takes over: the tension rises
        ''' from zero, so the string is not slack now; it goes slack where the tension next falls to zero, at the same
        ''' height on the other side. Also with the tension a rounding error below zero.
        ''' </summary>
        <Theory>
        <InlineData(2.0, 0.0)>
        <InlineData(2.0, -0.000000000001)>
        <InlineData(1.7, 0.000000000001)>
        <InlineData(2.6, -0.0000000001)>
        Public Sub SlackTime_FromZeroTensionRising_IsWhereItFallsToZeroOnTheOtherSide(theta As Double, pullError As Double)
            Dim length = 0.8
            Dim rate = -Math.Sqrt(-G * Math.Cos(theta) / length * (1 + pullError))
            Dim p = Released(length, theta, rate)
            Dim t = p.SlackTime()
            Assert.True(t > 0 AndAlso t < p.Period, $"slack at {t}")
            Dim start = p.PositionAt(0) - Anchor, there = p.PositionAt(t) - Anchor
            Assert.Equal(-start.X, there.X, 1.0E-9)
            Assert.Equal(start.Y, there.Y, 1.0E-9)
            For k = 1 To 99
                Assert.True(p.TensionPerMassAt(t * k / 100) > 0)
            Next
        End Sub

        ''' <summary>The same start with the bob swinging up (the tension falling from zero): slack at once.</summary>
        <Fact>
        Public Sub SlackTime_FromZeroTensionFalling_IsNow()
            Dim length = 0.8, theta = 2.0
            Dim rate = Math.Sqrt(-G * Math.Cos(theta) / length)
            Assert.True(Released(length, theta, rate).SlackTime() < 0.000000000001)
            ' Well below zero (not rounding) and rising: slack at once too.
            Assert.Equal(0.0, Released(length, theta, -rate * 0.99).SlackTime())
        End Sub

        <Fact>
        Public Sub TimeToAngle_ReachesTheAngleFirstThen()
            Dim rng As New Random(21)
            For trial = 1 To 40
                Dim theta0 = (rng.NextDouble() - 0.5) * 2 * 3
                Dim rate0 = (rng.NextDouble() - 0.5) * 20
                Dim p = Released(0.6, theta0, rate0)
                Dim target = (rng.NextDouble() - 0.5) * 2 * Math.PI
                Dim t = p.TimeToAngle(target)
                If Double.IsPositiveInfinity(t) Then
                    Assert.Equal(PendulumRegime.Libration, p.Regime)
                    Assert.True(Math.Abs(target) > p.MaxAngle - 0.000000000001)
                    Continue For
                End If
                Dim reached = p.AngleAt(t)
                Assert.Equal(0.0, Math.IEEERemainder(reached - target, 2 * Math.PI), 1.0E-9)
                ' Not reached before: sampled finely, θ − target (mod 2π) never changes sign near zero.
                Dim previous = Math.IEEERemainder(p.AngleAt(0) - target, 2 * Math.PI)
                For k = 1 To 400
                    Dim d = Math.IEEERemainder(p.AngleAt(t * k / 401) - target, 2 * Math.PI)
                    Dim crossed = Math.Sign(d) <> Math.Sign(previous) AndAlso Math.Abs(d) < 1 AndAlso Math.Abs(previous) < 1
                    Assert.False(crossed AndAlso Math.Abs(previous) > 0.000000001, $"trial {trial}: reached {target} before {t}")
                    previous = d
                Next
            Next
        End Sub
    End Class
End Namespace
