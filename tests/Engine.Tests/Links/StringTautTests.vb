Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Links
    ''' <summary>Slack strings snapping taut: against brute force, the exact chord, and a slack-flight-taut round trip.</summary>
    Public Class StringTautTests
        Private Const G As Double = 9.81
        Private Const Slop As Double = 0.000000000001

        ''' <summary>The first time |r(t)| ≥ L on a fine grid, refined by bisection.</summary>
        Private Shared Function BruteForce(separation As Func(Of Double, Double), length As Double, span As Double, samples As Integer) As Double
            Dim previous = 0.0
            For i = 1 To samples
                Dim t = span * i / samples
                If separation(t) >= length Then
                    Dim lo = previous, hi = t
                    For k = 1 To 80
                        Dim mid = 0.5 * (lo + hi)
                        If separation(mid) >= length Then hi = mid Else lo = mid
                    Next
                    Return hi
                End If
                previous = t
            Next
            Return Double.PositiveInfinity
        End Function

        Private Shared Function Flight(p As Vector, v As Vector, t As Double) As Vector
            Return New Vector(p.X + v.X * t, p.Y + (v.Y - 0.5 * G * t) * t)
        End Function

        <Fact>
        Public Sub AnchoredBody_MatchesBruteForce()
            Dim rng As New Random(4)
            Dim anchor As New Vector(1, 5)
            For trial = 1 To 300
                Dim length = 0.3 + rng.NextDouble() * 2
                Dim radius = length * Math.Sqrt(rng.NextDouble()) * 0.999
                Dim angle = rng.NextDouble() * 2 * Math.PI
                Dim p = anchor + radius * New Vector(Math.Cos(angle), Math.Sin(angle))
                Dim v As New Vector((rng.NextDouble() - 0.5) * 10, (rng.NextDouble() - 0.5) * 10)
                Dim t = StringTaut.AnchoredTautTime(anchor, length, p, v, G, Slop)
                Dim reference = BruteForce(Function(s) (Flight(p, v, s) - anchor).Length, length, 5, 50000)
                Assert.Equal(reference, t, 0.000000001)
                Assert.Equal(length, (Flight(p, v, t) - anchor).Length, 0.000000000001 * length)
            Next
        End Sub

        <Fact>
        Public Sub AnchoredBody_StartingAtFullLength()
            Dim anchor As New Vector(0, 0)
            Dim p As New Vector(0.6, -0.8)
            ' Moving outwards: taut now.
            Assert.Equal(0.0, StringTaut.AnchoredTautTime(anchor, 1, p, New Vector(0.6, -0.8), G, Slop))
            ' Below the anchor, moving across the string: gravity and the motion pull it taut now.
            Assert.Equal(0.0, StringTaut.AnchoredTautTime(anchor, 1, p, New Vector(0.8, 0.6), G, Slop))
            ' Above the anchor, moving slowly across: gravity pulls it inwards, so it flies and comes back.
            Dim above As New Vector(0.6, 0.8)
            Dim slow = New Vector(-0.8, 0.6) * 0.5
            Dim t = StringTaut.AnchoredTautTime(anchor, 1, above, slow, G, Slop)
            Assert.True(t > 0 AndAlso t < Double.PositiveInfinity)
            Assert.Equal(1.0, Flight(above, slow, t).Length, 0.000000000001)
            ' Moving inwards: the next time it is that far out, with and without gravity.
            Dim inward As New Vector(-1.2, 2)
            Dim reference = BruteForce(Function(s) If(s < 0.000001, 0, Flight(p, inward, s).Length), 1, 5, 50000)
            Assert.Equal(reference, StringTaut.AnchoredTautTime(anchor, 1, p, inward, G, Slop), 0.000000001)
            ' g = 0: the chord, at t = −2 r·v / |v|².
            Dim chord = -2 * Vector.Dot(p, inward) / inward.LengthSquared
            Assert.Equal(chord, StringTaut.AnchoredTautTime(anchor, 1, p, inward, 0, Slop), 0.000000000000001)
            ' A point a rounding outside, moving inwards, is the same case.
            Dim rounded = p * (1 + 0.0000000000000002)
            Assert.Equal(chord, StringTaut.AnchoredTautTime(anchor, 1, rounded, inward, 0, Slop), 0.000000000001)
            ' Over-stretched and moving outwards: taut now. Moving inwards, the string is going slack: it is taut the next
            ' time the body is that far out (g = 0: the chord of that circle), not now, where a snap would stop nothing.
            Assert.Equal(0.0, StringTaut.AnchoredTautTime(anchor, 1, p * 1.1, p, G, Slop))
            Dim far = p * 1.1
            Assert.Equal(-2 * Vector.Dot(far, inward) / inward.LengthSquared, StringTaut.AnchoredTautTime(anchor, 1, far, inward, 0, Slop), 0.000000000001)
            Dim falling = StringTaut.AnchoredTautTime(anchor, 1, far, inward, G, Slop)
            Assert.True(falling > 0 AndAlso falling < Double.PositiveInfinity, $"taut after {falling} s")
            ' Over-stretched at rest: taut now. Inside it at rest without gravity: never.
            Assert.Equal(0.0, StringTaut.AnchoredTautTime(anchor, 1, p * 1.1, Vector.Zero, 0, Slop))
            Assert.Equal(Double.PositiveInfinity, StringTaut.AnchoredTautTime(anchor, 1, p * 0.5, Vector.Zero, 0, Slop))
        End Sub

        <Fact>
        Public Sub Pair_MatchesBruteForceAndTheChord()
            Dim rng As New Random(9)
            For trial = 1 To 300
                Dim length = 0.2 + rng.NextDouble()
                Dim p1 As New Vector(rng.NextDouble(), rng.NextDouble())
                Dim angle = rng.NextDouble() * 2 * Math.PI
                Dim p2 = p1 + length * rng.NextDouble() * New Vector(Math.Cos(angle), Math.Sin(angle))
                Dim v1 As New Vector(rng.NextDouble() * 4 - 2, rng.NextDouble() * 4 - 2)
                Dim v2 As New Vector(rng.NextDouble() * 4 - 2, rng.NextDouble() * 4 - 2)
                Dim t = StringTaut.PairTautTime(p1, v1, p2, v2, length, Slop)
                ' Both fall alike; the separation is that of the straight-line relative motion.
                Dim reference = BruteForce(Function(s) ((p2 + s * v2) - (p1 + s * v1)).Length, length, 20, 200000)
                Assert.Equal(reference, t, 0.00000001)
            Next
            ' At full length moving together: the chord; apart: now.
            Dim a As New Vector(0, 0), b As New Vector(1, 0)
            Assert.Equal(2 * 1 / 3.0, StringTaut.PairTautTime(a, New Vector(1, 1), b, New Vector(-2, 1), 1, Slop), 0.000000000000001)
            Assert.Equal(0.0, StringTaut.PairTautTime(a, Vector.Zero, b, New Vector(0.1, 0), 1, Slop))
            Assert.Equal(0.0, StringTaut.PairTautTime(a, Vector.Zero, b, New Vector(0, 3), 1, Slop))
            Assert.Equal(Double.PositiveInfinity, StringTaut.PairTautTime(a, New Vector(1, 1), New Vector(0.5, 0), New Vector(1, 1), 1, Slop))
            ' Over-stretched: taut now while the ends move apart or keep their distance; coming together, the next time they
            ' are that far apart again (the chord), or a pair a few nanometres over a 300 m string that a blow sent back
            ' together was found taut now, snapped to no effect, and found taut again, for ever.
            Dim over As New Vector(1.1, 0)
            Assert.Equal(0.0, StringTaut.PairTautTime(a, Vector.Zero, over, New Vector(0.1, 0), 1, Slop))
            Assert.Equal(0.0, StringTaut.PairTautTime(a, Vector.Zero, over, Vector.Zero, 1, Slop))
            Assert.Equal(2 * 1.1 * 1 / (1 + 0.25), StringTaut.PairTautTime(a, Vector.Zero, over, New Vector(-1, 0.5), 1, Slop), 0.000000000001)
            Dim stretched As New Vector(300.000000005, 0)
            Assert.True(StringTaut.PairTautTime(a, Vector.Zero, stretched, New Vector(-0.001, 0.0001), 300, 0.000000001) > 1)
        End Sub

        <Fact>
        Public Sub Pendulum_SlackFlightTaut_RoundTrip()
            ' A bob given u² = 3.5 gL at the bottom goes slack part way up, flies on a parabola inside
            ' the circle and snaps taut again at distance L.
            Dim anchor As New Vector(0, 0)
            Dim length = 1.0
            Dim u = Math.Sqrt(3.5 * G * length)
            Dim p As New Pendulum(anchor, length, G, New Vector(0, -length), New Vector(u, 0))
            Dim tSlack = p.SlackTime()
            Dim position As Vector, velocity As Vector
            p.StateAt(tSlack, position, velocity)
            Dim tTaut = StringTaut.AnchoredTautTime(anchor, length, position, velocity, G, 0.000000001)
            Assert.True(tTaut > 0.01, $"taut again after {tTaut}")
            Dim reference = BruteForce(Function(s) If(s < 0.001, 0, Flight(position, velocity, s).Length), length, 3, 300000)
            Assert.Equal(reference, tTaut, 0.000000001)
            Dim landing = Flight(position, velocity, tTaut)
            Assert.Equal(length, landing.Length, 0.000000001)
            ' Time runs backwards on a parabola with the velocity reversed: from the landing point the
            ' string is taut again when the bob is back where it went slack. There the parabola osculates
            ' the circle (zero tension: the same curvature), |r|² − L² has a triple root, and rounding
            ' moves that root by about (1e-16)^(1/3) s; the distance at it is still L.
            Dim landingVelocity As New Vector(velocity.X, velocity.Y - G * tTaut)
            Dim back = StringTaut.AnchoredTautTime(anchor, length, landing, -landingVelocity, G, 0.000000001)
            Assert.Equal(tTaut, back, 0.0001)
            Assert.Equal(length, Flight(landing, -landingVelocity, back).Length, 0.000000001)
        End Sub

        <Fact>
        Public Sub FlightBetweenTwoPointsOfTheCircle_RunsBackTheSameWay()
            ' From the circle, inwards (not along it), the body lands on the circle after t; from there
            ' with the velocity reversed it flies the same parabola back and lands where it started.
            Dim rng As New Random(12)
            Dim anchor As New Vector(0.2, -0.1)
            For trial = 1 To 200
                Dim length = 0.5 + rng.NextDouble()
                Dim angle = rng.NextDouble() * 2 * Math.PI
                Dim radial As New Vector(Math.Cos(angle), Math.Sin(angle))
                Dim start = anchor + length * radial
                Dim inward = -radial * (0.5 + rng.NextDouble() * 4) + radial.Perpendicular() * ((rng.NextDouble() - 0.5) * 6)
                Dim t = StringTaut.AnchoredTautTime(anchor, length, start, inward, G, Slop)
                Assert.True(t > 0 AndAlso t < Double.PositiveInfinity)
                Dim landing = Flight(start, inward, t)
                Assert.Equal(length, (landing - anchor).Length, 0.000000000001)
                Dim back As New Vector(-inward.X, -(inward.Y - G * t))
                Dim tBack = StringTaut.AnchoredTautTime(anchor, length, landing, back, G, Slop)
                Assert.Equal(t, tBack, 0.000000001)
                Assert.True(LinkTestKit.Distance(start, Flight(landing, back, tBack)) < 0.000000001)
            Next
        End Sub
    End Class
End Namespace
