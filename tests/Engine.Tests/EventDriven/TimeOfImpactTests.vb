Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>Time-of-impact maths against closed forms: roots, tangents, touching cases.</summary>
Public Class TimeOfImpactTests
    Private Const Slop As Double = 1.0E-12

    <Fact>
    Public Sub QuadraticRoots_AreStable_WhenOneRootIsTiny()
        ' x² − 1e8 x + 1 = 0: the naive formula loses the small root 1e-8 entirely.
        Dim x1 As Double, x2 As Double
        Assert.Equal(2, RootFinding.QuadraticRoots(1, -100000000.0, 1, x1, x2))
        Assert.Equal(1.0E-8, x1, 1.0E-20)
        Assert.Equal(100000000.0, x2, 1.0E-6)
    End Sub

    <Fact>
    Public Sub QuadraticRoots_DoubleRootCountsOnce_AndLinearFallsBack()
        Dim x1 As Double, x2 As Double
        Assert.Equal(1, RootFinding.QuadraticRoots(1, -4, 4, x1, x2))
        Assert.Equal(2.0, x1, 15)
        Assert.Equal(1, RootFinding.QuadraticRoots(0, 2, -3, x1, x2))
        Assert.Equal(1.5, x1, 15)
        Assert.Equal(0, RootFinding.QuadraticRoots(1, 0, 1, x1, x2))
    End Sub

    <Fact>
    Public Sub CubicRootsIn_FindsAllThreeRoots()
        ' (t − 1)(t − 2)(t − 3) = t³ − 6t² + 11t − 6
        Dim a As Double, b As Double, c As Double
        Assert.Equal(3, RootFinding.CubicRootsIn(1, -6, 11, -6, 0, 10, a, b, c))
        Assert.Equal(1.0, a, 12)
        Assert.Equal(2.0, b, 12)
        Assert.Equal(3.0, c, 12)
    End Sub

    <Fact>
    Public Sub CubicRootsIn_FindsADoubleRootOnce()
        ' (t − 1)²(t − 3) = t³ − 5t² + 7t − 3
        Dim a As Double, b As Double, c As Double
        Assert.Equal(2, RootFinding.CubicRootsIn(1, -5, 7, -3, 0, 10, a, b, c))
        Assert.Equal(1.0, a, 12)
        Assert.Equal(3.0, b, 12)
    End Sub

    <Fact>
    Public Sub EarliestEntry_Quartic_FindsTheFirstDownwardCrossing()
        ' (t − 1)(t − 2)(t − 3)(t − 4): positive before 1, negative on (1, 2): enters at 1.
        Dim t = RootFinding.EarliestEntry(1, -10, 35, -50, 24, 0)
        Assert.Equal(1.0, t, 12)
        ' Shifted so it starts inside (negative) on (0, 1): next entry is at 3.
        ' (t + 1)(t − 1)(t − 3)(t − 4) = t⁴ − 7t³ + 11t² + 7t − 12, f(0) < 0 with tolerance 0: a start
        ' inside counts as touching; it is increasing, so the next downward crossing (t = 3) is the entry.
        Assert.Equal(3.0, RootFinding.EarliestEntry(1, -7, 11, 7, -12, 0), 12)
    End Sub

    <Fact>
    Public Sub EarliestEntry_Quartic_TangentIsNoCollision()
        ' (t − 2)² (t² + 1): touches zero at t = 2 without going below: a graze, not an entry.
        ' = (t² − 4t + 4)(t² + 1) = t⁴ − 4t³ + 5t² − 4t + 4
        Assert.Equal(Double.PositiveInfinity, RootFinding.EarliestEntry(1, -4, 5, -4, 4, 0))
    End Sub

    <Fact>
    Public Sub CircleCircleAccelerated_TouchingByRounding_PartingAtARoundingSpeed_MeetsAgainAsABallThrownUpLands()
        ' A ball resting on a still one (its centre 0.13 mm right of the other's top), overlapping by
        ' rounding, that a contact solve left moving up at 2.7e-48 m/s (zero but for rounding) under
        ' g = 47.8 m/s²: it is thrown up at v and lands back where it started after 2 v / g. Before,
        ' the return was missed (f had to rise above 0 first) and the ball sank into the other.
        Const g As Double = 47.77712974689722, v As Double = 2.666223792282384E-48
        Const sumR As Double = 0.0025715489075532295, dx As Double = 0.00012818996373285905
        Dim dy = Math.Sqrt(sumR * sumR - dx * dx - 5.0E-20)
        Dim c0 = dx * dx + dy * dy - sumR * sumR
        Assert.InRange(c0, -2 * sumR * Slop, -1.0E-21) ' within the touching tolerance, below zero
        Dim t = TimeOfImpact.CircleCircle(dx, dy, 0, v, -g, sumR, Slop, v)
        Assert.InRange(t / (2 * v / g), 1 - 1.0E-9, 1 + 1.0E-9)
        ' The same pair at a speed that rounding does not hide lands after 2 v / g as well.
        Dim slow = TimeOfImpact.CircleCircle(dx, dy, 0, 0.001, -g, sumR, Slop, 0.001)
        Assert.InRange(slow / (2 * 0.001 / g), 1 - 1.0E-6, 1 + 1.0E-6)
    End Sub

    <Fact>
    Public Sub CircleCircleAccelerated_OverlappingBeyondRounding_PartingThenPressedBack_MeetsAgainAtThatDepth()
        ' Two balls 1 µm into each other (a blow struck late), parting at 1 mm/s along the line of centres while
        ' their accelerations press them together at 10 m/s² (each sliding down one side of a V): they come back to
        ' the same depth after 2 v / a. Waiting for them to part and meet at R (they never part), the pair was never
        ' looked at again and sank on into each other.
        Const sumR As Double = 0.13, depth As Double = 0.000001, v As Double = 0.001, a As Double = 10.0
        Dim t = TimeOfImpact.CircleCircleAccelerated(sumR - depth, 0, v, 0, -a, 0, sumR, Slop)
        Assert.InRange(t / (2 * v / a), 1 - 1.0E-9, 1 + 1.0E-9)
        ' Parting fast enough to get out: they meet again where they touch, at R, first.
        Const fast As Double = 0.1
        Dim out = TimeOfImpact.CircleCircleAccelerated(sumR - depth, 0, fast, 0, -a, 0, sumR, Slop)
        ' x(t) = R − depth + v t − ½ a t² falls back through R at the larger root of v t − ½ a t² = depth.
        Dim expected = (fast + Math.Sqrt(fast * fast - 2 * a * depth)) / a
        Assert.InRange(out / expected, 1 - 1.0E-9, 1 + 1.0E-9)
    End Sub

    <Fact>
    Public Sub CircleCircle_HeadOn_MatchesGapOverClosingSpeed()
        ' Centres 1 m apart, radii sum 0.2, closing at 2 m/s: contact after 0.8 / 2 = 0.4 s.
        Dim t = TimeOfImpact.CircleCircle(-1, 0, 2, 0, 0, 0.2, Slop)
        Assert.Equal(0.4, t, 15)
    End Sub

    <Fact>
    Public Sub CircleCircle_Oblique_MatchesClosedForm()
        ' A moves along +x with impact parameter b: contact when (x)² + b² = R² → x = −√(R² − b²).
        Dim b = 0.1, r = 0.2, x0 = -1.0, v = 3.0
        Dim expected = (-x0 - Math.Sqrt(r * r - b * b)) / v
        Assert.Equal(expected, TimeOfImpact.CircleCircle(x0, b, v, 0, 0, r, Slop), 14)
    End Sub

    <Fact>
    Public Sub CircleCircle_GrazingMiss_IsNever()
        Assert.Equal(Double.PositiveInfinity, TimeOfImpact.CircleCircle(-1, 0.2000001, 1, 0, 0, 0.2, Slop))
    End Sub

    <Fact>
    Public Sub CircleCircle_TouchingAndApproaching_IsNow()
        Assert.Equal(0.0, TimeOfImpact.CircleCircle(-0.2, 0, 1, 0, 0, 0.2, Slop))
        ' Rounding left a tiny overlap: still a contact now, not a missed collision.
        Assert.Equal(0.0, TimeOfImpact.CircleCircle(-0.2 + 1.0E-15, 0, 1, 0, 0, 0.2, Slop))
    End Sub

    <Fact>
    Public Sub CircleCircle_TouchingAndSeparating_IsNever()
        Assert.Equal(Double.PositiveInfinity, TimeOfImpact.CircleCircle(-0.2, 0, -1, 0, 0, 0.2, Slop))
        Assert.Equal(Double.PositiveInfinity, TimeOfImpact.CircleCircle(-0.2, 0, 0, 0, 0, 0.2, Slop))
    End Sub

    <Fact>
    Public Sub ParabolaOntoFixedCircle_MatchesFreeFall()
        ' A ball dropped from rest 1 m above the top of a fixed circle (sum of radii R): it falls
        ' d = ½gt² = 1 m, so t = √(2/g). Quartic path (relative acceleration −g).
        Dim g = 9.81, sumR = 0.5
        Dim t = TimeOfImpact.CircleCircle(0, sumR + 1.0, 0, 0, -g, sumR, Slop)
        Assert.Equal(Math.Sqrt(2 / g), t, 12)
    End Sub

    <Fact>
    Public Sub ParabolaOntoFixedCircle_OffCentre_MatchesGeometry()
        ' Dropped at horizontal offset b: contact when the centre is at height √(R² − b²) above.
        Dim g = 9.81, sumR = 0.5, b = 0.3, h = 2.0
        Dim drop = h - Math.Sqrt(sumR * sumR - b * b)
        Dim t = TimeOfImpact.CircleCircle(b, h, 0, 0, -g, sumR, Slop)
        Assert.Equal(Math.Sqrt(2 * drop / g), t, 12)
    End Sub

    <Fact>
    Public Sub ParabolaOverACorner_FastEnough_NeverTouchesAgain()
        ' Leaving the edge of a table with v² ≥ g r: |Δ|² = r² + t²(v² − g r) + ¼g²t⁴ ≥ r².
        Dim g = 9.81, r = 0.05
        Dim v = Math.Sqrt(g * r) * 1.01
        Assert.Equal(Double.PositiveInfinity, TimeOfImpact.CircleCircle(0, r, v, 0, -g, r, Slop))
    End Sub

    <Fact>
    Public Sub ParabolaOverACorner_TooSlow_CutsIntoTheCornerNow()
        Dim g = 9.81, r = 0.05
        Dim v = Math.Sqrt(g * r) * 0.5
        Assert.Equal(0.0, TimeOfImpact.CircleCircle(0, r, v, 0, -g, r, Slop))
    End Sub

    <Fact>
    Public Sub GapCloses_Floor_MatchesSuvat_AndReturnsAfterABounce()
        Dim g = 9.81
        ' From 1 m at rest: t = √(2h/g).
        Assert.Equal(Math.Sqrt(2 / g), TimeOfImpact.GapCloses(1.0, 0, -g, Slop), 14)
        ' Just bounced (touching) going up at u: back after 2u/g.
        Assert.Equal(2 * 3.0 / g, TimeOfImpact.GapCloses(0, 3.0, -g, Slop), 14)
        ' Touching and moving down: now.
        Assert.Equal(0.0, TimeOfImpact.GapCloses(0, -1.0, -g, Slop))
        ' Touching, no gravity, moving away: never.
        Assert.Equal(Double.PositiveInfinity, TimeOfImpact.GapCloses(0, 1.0, 0, Slop))
    End Sub

    <Fact>
    Public Sub CircleRectangle_HitsTheTopFace_AndTheCorner()
        Dim f As Integer
        ' Falling from rest onto the top face (y1 = 1) from centre height 2, r = 0.1: drop 0.9 m.
        Dim t = TimeOfImpact.CircleRectangle(0.5, 2, 0, 0, -9.81, 0.1, 0, 0, 1, 1, Slop, f)
        Assert.Equal(3, f)
        Assert.Equal(Math.Sqrt(2 * 0.9 / 9.81), t, 12)
        ' Moving left at y = 1.05 towards the upper-right corner (1, 1), no gravity:
        ' contact when (x − 1)² + 0.05² = 0.1² → x = 1 + √0.0075.
        t = TimeOfImpact.CircleRectangle(2, 1.05, -1, 0, 0, 0.1, 0, 0, 1, 1, Slop, f)
        Assert.Equal(7, f)
        Assert.Equal(1 - Math.Sqrt(0.0075), t, 12)
        ' Level with the face, beside it: the side face.
        t = TimeOfImpact.CircleRectangle(2, 0.5, -1, 0, 0, 0.1, 0, 0, 1, 1, Slop, f)
        Assert.Equal(1, f)
        Assert.Equal(0.9, t, 12)
    End Sub

    <Fact>
    Public Sub CircleRectangle_BallLeavingTheEndOfTheTopFace_IsNotCaughtByIt()
        ' On the top face (y1 = 1) an ulp short of its right end (x1 = 1), r = 1 mm, moving right at
        ' 0.85 m/s: faster than √(g r), it flies off. Touching the face, pulled in by gravity, it must
        ' not count as landing on it again: it is leaving there, and nothing else is in its way.
        Dim f As Integer
        Dim t = TimeOfImpact.CircleRectangle(1 - 1.0E-16, 1.001, 0.85, 0, -100, 0.001, 0, 0, 1, 1, Slop, f)
        Assert.Equal(Double.PositiveInfinity, t)
        ' Moving back onto the face from there, it lands on it at once.
        t = TimeOfImpact.CircleRectangle(1 - 1.0E-16, 1.001, -0.85, 0, -100, 0.001, 0, 0, 1, 1, Slop, f)
        Assert.Equal(0.0, t)
        Assert.Equal(3, f)
    End Sub

    <Fact>
    Public Sub CornerSlide_LeaveAngle_FromRestAtTheTop_IsTheTextbookAngle()
        ' Starting from (almost) rest at the top: cos θ* = 2/3.
        Assert.Equal(Math.Acos(2.0 / 3.0), CornerSlide.LeaveAngle(0, 9.81, 0.05, 0), 12)
        ' v² ≥ g r: leaves at once.
        Assert.Equal(0.0, CornerSlide.LeaveAngle(Math.Sqrt(9.81 * 0.05), 9.81, 0.05, 0))
    End Sub
    <Theory>
    <InlineData(0.0, 0.01)>
    <InlineData(0.5, 0.0)>
    <InlineData(2.0, 0.3)>
    Public Sub CornerSlideAngleAfter_InvertsDuration_FromStartToLeave(speed As Double, startAngle As Double)
        Const G = 9.81, R = 0.2
        Dim leave = CornerSlide.LeaveAngle(speed, G, R, startAngle)
        Dim total = CornerSlide.Duration(speed, G, R, startAngle, leave)
        For k = 1 To 9
            Dim t = total * k / 10
            Dim theta = CornerSlide.AngleAfter(speed, G, R, startAngle, leave, t)
            Assert.InRange(theta, startAngle, leave)
            ' The time back from that angle is the time asked for, to rounding of the quadrature.
            Assert.True(Math.Abs(CornerSlide.Duration(speed, G, R, startAngle, theta) - t) <= 1.0E-13 * total, $"t = {t}: θ = {theta}")
        Next
    End Sub

End Class
