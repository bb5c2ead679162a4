Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Links
    ''' <summary>Damped springs in closed form against a fine RK4 of their ODE, their limits and the vertical spring's anchor time.</summary>
    Public Class OscillatorTests
        Private Const G As Double = 9.81

        <Theory>
        <InlineData(0.0)>
        <InlineData(0.000000000001)>
        <InlineData(0.3)>
        <InlineData(3.999999)>
        <InlineData(4.0)>
        <InlineData(4.000001)>
        <InlineData(5.0)>
        <InlineData(60.0)>
        Public Sub ZeroLengthSpring_MatchesRk4OfItsEquation(damping As Double)
            ' m = 0.5 kg, k = 8 N/m: ω = 4 rad/s; critical damping c = 2mω = 4 N·s/m.
            Dim mass = 0.5, k = 8.0
            Dim anchor As New Vector(0.3, 1.0)
            Dim p0 As New Vector(1.1, -0.2), v0 As New Vector(-0.7, 2.5)
            Dim spring As New ZeroLengthSpring(anchor, mass, k, damping, G, p0, v0)
            Assert.True(spring.IsExact = (damping = 0))
            Dim equation As Action(Of Double(), Double()) =
                Sub(y, dy)
                    dy(0) = y(2) : dy(1) = y(3)
                    dy(2) = (-k * (y(0) - anchor.X) - damping * y(2)) / mass
                    dy(3) = (-k * (y(1) - anchor.Y) - damping * y(3)) / mass - G
                End Sub
            Dim times = {0.1, 0.5, 1.3, 2.0, 3.7, 5.0}
            Dim states = LinkTestKit.Rk4At(equation, {p0.X, p0.Y, v0.X, v0.Y}, times, 0.00005)
            For i = 0 To times.Length - 1
                Dim position As Vector, velocity As Vector
                spring.StateAt(times(i), position, velocity)
                Assert.True(LinkTestKit.Distance(New Vector(states(i)(0), states(i)(1)), position) < 0.000000001, $"t = {times(i)}: {position}")
                Assert.True(LinkTestKit.Distance(New Vector(states(i)(2), states(i)(3)), velocity) < 0.000000001, $"t = {times(i)}: {velocity}")
            Next
        End Sub

        <Fact>
        Public Sub Regimes_AreContinuousThroughCriticalDamping()
            Dim critical As New DampedOscillator(2, 18, 12)
            Assert.Equal(DampingRegime.Critical, critical.Regime)
            For Each factor In {1 - 0.000000001, 1 + 0.000000001, 1 - 0.000001, 1 + 0.000001}
                Dim near As New DampedOscillator(2, 18, 12 * factor)
                For Each t In {0.01, 0.3, 1.0, 10.0, 100.0}
                    Dim expected = critical.Displacement(t, 1.5, -2)
                    ' dE/dc is bounded, so a relative change δ in c moves e by O(δ) of its scale (1.5 m, 2 m/s).
                    Assert.Equal(expected, near.Displacement(t, 1.5, -2), 3 * Math.Abs(1 - factor) * 10)
                    Assert.Equal(critical.Velocity(t, 1.5, -2), near.Velocity(t, 1.5, -2), 3 * Math.Abs(1 - factor) * 30)
                Next
            Next
        End Sub

        <Fact>
        Public Sub HeavyDamping_AtLargeTimes_FollowsTheSlowMode()
            ' γ = 500, ω = 1: the slow rate is −ω²/(γ + β) ≈ −1e-3. At t = 5000 s e = A₁ e^(r₁t) with
            ' A₁ = (v₀ − r₂ e₀)/(2β); the fast mode e^(r₂t) underflows to 0, and nothing overflows.
            Dim osc As New DampedOscillator(1, 1, 1000)
            Dim gamma = 500.0, beta = Math.Sqrt(gamma * gamma - 1)
            Dim r1 = -1 / (gamma + beta), r2 = -(gamma + beta)
            Dim e0 = 0.3, v0 = 4.0
            For Each t In {1.0, 100.0, 5000.0, 1000000.0}
                Dim slow = (v0 - r2 * e0) / (2 * beta) * Math.Exp(r1 * t)
                Dim e = osc.Displacement(t, e0, v0)
                Assert.False(Double.IsNaN(e))
                Assert.True(Math.Abs(e - slow) <= 0.000000000001 * Math.Abs(slow) + 1.0E-300, $"t = {t}: {e} vs {slow}")
                Assert.True(Math.Abs(osc.Velocity(t, e0, v0) - r1 * slow) <= 0.000000000001 * Math.Abs(r1 * slow) + 1.0E-300)
            Next
        End Sub

        <Fact>
        Public Sub TinyDamping_DecaysAsItsEnvelope_OverLongTimes()
            ' c = 2e-9 N·s/m on m = 1 kg: γ = 1e-9; after 1e6 s the envelope is e^(−1e-3).
            Dim osc As New DampedOscillator(1, 4, 0.000000002)
            Dim t = 1000000.0
            Dim wd = Math.Sqrt(4 - 1.0E-18)
            Dim expected = Math.Exp(-0.000000001 * t) * (Math.Cos(wd * t) + 0.000000001 / wd * Math.Sin(wd * t))
            Assert.Equal(expected, osc.Displacement(t, 1, 0), 0.0000000001)
        End Sub

        <Fact>
        Public Sub VerticalSpring_ReleasedUnstretched_OscillatesByMgOverK()
            ' Released at rest with the spring at its rest length below the anchor:
            ' y(t) = y_eq + (mg/k) cos(√(k/m) t), y_eq = anchor − ℓ − mg/k.
            Dim mass = 0.2, k = 5.0, rest = 0.4
            Dim anchor As New Vector(2, 3)
            Dim spring As New VerticalSpring(anchor, mass, k, rest, 0, G, New Vector(2, 3 - rest), Vector.Zero)
            Dim sag = mass * G / k
            Dim yEq = anchor.Y - rest - sag
            Assert.Equal(yEq, spring.EquilibriumHeight, 0.000000000001)
            Dim omega = Math.Sqrt(k / mass)
            For t = 0.0 To 10.0 Step 0.01
                Assert.Equal(yEq + sag * Math.Cos(omega * t), spring.PositionAt(t).Y, 0.000000001)
                Assert.Equal(-sag * omega * Math.Sin(omega * t), spring.VelocityAt(t).Y, 0.000000001)
            Next
            Assert.False(spring.ReachesAnchor())
        End Sub

        <Theory>
        <InlineData(0.0, 1.0)>
        <InlineData(0.0, 3.5)>
        <InlineData(0.4, 3.5)>
        <InlineData(0.4, 1.0)>
        <InlineData(6.0, 3.0)>
        <InlineData(6.0, -3.0)>
        <InlineData(1.0, -9.0)>
        <InlineData(0.0, -5.0)>
        Public Sub VerticalSpring_TimeToAnchor_IsTheFirstArrival(damping As Double, speed As Double)
            ' Above the anchor on a stiff spring (ℓ = 0.5 m, sag 0.0981 m): it reaches the anchor only if
            ' pushed down hard enough (or pulled, above, past the equilibrium on the far side).
            Dim mass = 0.1, k = 10.0, rest = 0.5
            Dim anchor As New Vector(0, 0)
            Dim start As New Vector(0, 0.45)
            Dim spring As New VerticalSpring(anchor, mass, k, rest, damping, G, start, New Vector(0, speed))
            Dim t = spring.TimeToAnchor()
            ' Reference: the first sign change of y on a fine grid of the closed form, 20 s.
            Dim firstSample = Double.PositiveInfinity
            For i = 1 To 200000
                If spring.PositionAt(i * 0.0001).Y <= 0 Then firstSample = i * 0.0001 : Exit For
            Next
            If damping = 0 Then
                ' Undamped: it reaches the anchor exactly when its amplitude √(e₀² + (v₀/ω)²) exceeds s_eq.
                Dim sEq = rest - mass * G / k
                Dim amplitude = Math.Sqrt((start.Y - sEq) ^ 2 + speed * speed * mass / k)
                Assert.Equal(amplitude > sEq, t < Double.PositiveInfinity)
            End If
            If Double.IsPositiveInfinity(firstSample) Then
                Assert.Equal(Double.PositiveInfinity, t)
            Else
                Assert.True(t > firstSample - 0.0001 AndAlso t <= firstSample, $"{t} vs sampled {firstSample}")
                Assert.Equal(0.0, spring.PositionAt(t).Y, 0.000000000001)
            End If
        End Sub

        <Fact>
        Public Sub VerticalSpring_AboveASoftSpring_SinksThroughTheAnchor()
            ' ℓ = 0.1 m < mg/k = 0.981 m: there is no equilibrium above the anchor; even overdamped it gets there.
            Dim spring As New VerticalSpring(New Vector(0, 0), 1, 10, 0.1, 100, G, New Vector(0, 0.05), Vector.Zero)
            Assert.Equal(DampingRegime.Overdamped, spring.Oscillator.Regime)
            Dim t = spring.TimeToAnchor()
            Assert.True(t > 0 AndAlso t < Double.PositiveInfinity)
            Assert.Equal(0.0, spring.PositionAt(t).Y, 0.000000000001)
            Assert.True(spring.PositionAt(0.999 * t).Y > 0)
        End Sub
    End Class
End Namespace
