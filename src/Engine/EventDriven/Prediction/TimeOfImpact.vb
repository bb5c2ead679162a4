Option Strict On

Imports System.Runtime.CompilerServices

''' <summary>
''' Times of impact as pure functions: values in, the time (s, from now) of the first contact out,
''' +∞ when there is none. Every body moves on x(t) = x + vx t, y(t) = y + vy t + ½ ay t² (ay = −g for
''' a free body, 0 for a body at rest or being dragged). Touching bodies (within <c>slop</c> metres)
''' that approach collide now (0); touching bodies that separate never do.
''' </summary>
Public Module TimeOfImpact
    ''' <summary>Discriminants below this fraction of b² count as a tangent graze, not a hit.</summary>
    Public Const GrazeFraction As Double = 1.0E-14

    ''' <summary>Normal approach speeds below this fraction of the relative speed count as zero.</summary>
    Public Const ApproachFraction As Double = 1.0E-12

    ''' <summary>
    ''' Two circles whose centres are (dx, dy) apart (A − B), with relative velocity (dvx, dvy) and
    ''' relative vertical acceleration dAy (A − B), touching at distance <paramref name="sumRadii"/>.
    ''' |Δp + Δv t + ½ Δa t²|² = R² is a quadratic when both feel the same gravity (their relative
    ''' motion is a straight line) and a quartic otherwise (a parabola against a circle).
    ''' <paramref name="speedScale"/> (m/s) is the size of the bodies' own speeds, |v_A| + |v_B|: rounding
    ''' errs in proportion to it, so an approach slower than 10⁻¹² of it is not an approach.
    ''' </summary>
    Public Function CircleCircle(dx As Double, dy As Double, dvx As Double, dvy As Double, dAy As Double,
                                 sumRadii As Double, slop As Double, Optional speedScale As Double = 0) As Double
        Return CircleCircleAccelerated(dx, dy, dvx, dvy, 0, dAy, sumRadii, slop, speedScale)
    End Function

    ''' <summary>
    ''' <see cref="CircleCircle(Double, Double, Double, Double, Double, Double, Double, Double)"/> with a relative
    ''' acceleration that may have a horizontal part too (dAx, dAy, m/s²): a body sliding down a slope.
    ''' |Δp + Δv t + ½ Δa t²|² = R² is a quartic whenever Δa ≠ 0. Its own name, not an overload: a call
    ''' with eight arguments would otherwise bind silently to CircleCircle with its optional speed scale.
    ''' </summary>
    Public Function CircleCircleAccelerated(dx As Double, dy As Double, dvx As Double, dvy As Double, dAx As Double, dAy As Double,
                                 sumRadii As Double, slop As Double, Optional speedScale As Double = 0) As Double
        Dim c0 = dx * dx + dy * dy - sumRadii * sumRadii
        Dim c1 = 2 * (dx * dvx + dy * dvy)
        Dim tol = 2 * sumRadii * slop
        ' Touching bodies approaching at less than 10⁻¹² of their speeds are not approaching: that is
        ' what rounding leaves after a perfectly inelastic (e = 0) collision, where the relative
        ' velocity should be exactly zero but is a few ulps of the bodies' own speeds.
        Dim slopeTol = ApproachFraction * 2 * sumRadii * (Math.Sqrt(dvx * dvx + dvy * dvy) + speedScale)
        If dAy = 0 AndAlso dAx = 0 Then
            ' Straight-line relative motion, inlined for the elastic gas: the hot path of the solver.
            If c0 <= tol Then Return If(c1 < -slopeTol, 0.0, Double.PositiveInfinity)
            If c1 >= 0 Then Return Double.PositiveInfinity
            Dim a = dvx * dvx + dvy * dvy
            Dim disc = c1 * c1 - 4 * a * c0
            ' A (near-)double root is a graze: the path touches the circle without entering it. The
            ' deepest overlap a graze this close could hide is ~1e-14 of the distance: nothing.
            If disc <= GrazeFraction * c1 * c1 Then Return Double.PositiveInfinity
            ' Smaller root c/q with q = −½(b − √disc) > 0: no cancellation.
            Return 2 * c0 / (-c1 + Math.Sqrt(disc))
        End If
        ' |Δp + Δv t + α t²|² with α = ½ Δa: t⁴ |α|², t³ 2 α·Δv, t² (|Δv|² + 2 α·Δp), t 2 Δp·Δv, 1 |Δp|² − R².
        Dim alphaX = 0.5 * dAx, alphaY = 0.5 * dAy
        If Math.Abs(c1) <= slopeTol AndAlso c0 <= tol Then c1 = 0
        Dim q4 = alphaX * alphaX + alphaY * alphaY, q3 = 2 * (alphaX * dvx + alphaY * dvy)
        Dim q2 = dvx * dvx + dvy * dvy + 2 * (alphaX * dx + alphaY * dy)
        Dim through = RootFinding.EarliestEntry(q4, q3, q2, c1, c0, tol)
        ' Further into each other than rounding (a blow struck late), and parting: they collide again where they come
        ' back to that depth, if they do before they part and meet at R. Waiting for R alone, two balls pressed
        ' together by their accelerations (each sliding down one side of a V) sank into each other by the depth left
        ' at every blow: 6 µm in 12 ms.
        If c0 < -tol Then Return Math.Min(through, RootFinding.EarliestEntry(q4, q3, q2, c1, 0, tol))
        Return through
    End Function

    ''' <summary>
    ''' A gap that changes as gap + rate t + ½ accel t² (a wall, a cell boundary, a rectangle face):
    ''' the first time it closes while closing.
    ''' </summary>
    <MethodImpl(MethodImplOptions.AggressiveInlining)>
    Public Function GapCloses(gap As Double, rate As Double, accel As Double, slop As Double) As Double
        ' Fast path for the common case (no gravity, clearly apart): the same answer the general
        ' routine gives for a = 0 and c > tolerance, without the call. Walls and cell exits of the gas.
        If accel = 0 AndAlso gap > slop Then Return If(rate >= 0, Double.PositiveInfinity, -gap / rate)
        Return RootFinding.EarliestEntryQuadratic(0.5 * accel, rate, gap, slop)
    End Function

    ''' <summary>
    ''' A circle of radius r (centre p, velocity v, vertical acceleration ay) against a fixed
    ''' axis-aligned rectangle [x0, x1] × [y0, y1]. The centre hits the Minkowski sum, a rectangle with
    ''' rounded corners: four faces moved out by r (a hit counts only within the face's extent) and
    ''' four corner circles of radius r (a hit counts only in the corner's own quadrant).
    ''' <paramref name="feature"/> is 0 left, 1 right, 2 bottom, 3 top face, 4 + k for corner k
    ''' (0 lower-left, 1 lower-right, 2 upper-left, 3 upper-right).
    ''' </summary>
    Public Function CircleRectangle(px As Double, py As Double, vx As Double, vy As Double, ay As Double, r As Double,
                                    x0 As Double, y0 As Double, x1 As Double, y1 As Double, slop As Double,
                                    ByRef feature As Integer) As Double
        Return CircleRectangle(px, py, vx, vy, ay, r, x0, y0, x1, y1, slop, Double.PositiveInfinity, feature)
    End Function

    ''' <summary>
    ''' <see cref="CircleRectangle(Double, Double, Double, Double, Double, Double, Double, Double, Double, Double, Double, ByRef Integer)"/>,
    ''' looking no further than <paramref name="horizon"/> s ahead: a corner the path's bounding box
    ''' cannot reach by then is not solved for (its quartic is the costly part).
    ''' </summary>
    Public Function CircleRectangle(px As Double, py As Double, vx As Double, vy As Double, ay As Double, r As Double,
                                    x0 As Double, y0 As Double, x1 As Double, y1 As Double, slop As Double, horizon As Double,
                                    ByRef feature As Integer) As Double
        Dim best = Double.PositiveInfinity
        Dim xlo = Double.NegativeInfinity, xhi = Double.PositiveInfinity, ylo = Double.NegativeInfinity, yhi = Double.PositiveInfinity
        If horizon < Double.PositiveInfinity Then PathBox.Bounds(px, py, vx, vy, ay, horizon, xlo, xhi, ylo, yhi)
        Dim reach = r + slop
        feature = -1
        Dim t As Double
        ' Faces: x is linear, y quadratic in t.
        t = GapCloses(x0 - r - px, -vx, 0, slop)
        If t < best AndAlso WithinFace(py + (vy + 0.5 * ay * t) * t, vy + ay * t, y0, y1, slop) Then best = t : feature = 0
        t = GapCloses(px - x1 - r, vx, 0, slop)
        If t < best AndAlso WithinFace(py + (vy + 0.5 * ay * t) * t, vy + ay * t, y0, y1, slop) Then best = t : feature = 1
        t = GapCloses(y0 - r - py, -vy, -ay, slop)
        If t < best AndAlso WithinFace(px + vx * t, vx, x0, x1, slop) Then best = t : feature = 2
        t = GapCloses(py - y1 - r, vy, ay, slop)
        If t < best AndAlso WithinFace(px + vx * t, vx, x0, x1, slop) Then best = t : feature = 3
        ' Corners: a parabola against a circle of radius r.
        For k = 0 To 3
            Dim cx = If((k And 1) = 0, x0, x1)
            Dim cy = If((k And 2) = 0, y0, y1)
            ' Written so that NaN still solves.
            If xhi + reach < cx OrElse xlo - reach > cx OrElse yhi + reach < cy OrElse ylo - reach > cy Then Continue For
            t = CircleCircle(px - cx, py - cy, vx, vy, ay, r, slop)
            If t < best Then
                Dim hx = px + vx * t - cx
                Dim hy = py + (vy + 0.5 * ay * t) * t - cy
                Dim rightSide = (k And 1) = 1, upperSide = (k And 2) = 2
                Dim inQuadrant = If(rightSide, hx >= -slop, hx <= slop) AndAlso If(upperSide, hy >= -slop, hy <= slop)
                If inQuadrant Then best = t : feature = 4 + k
            End If
        Next
        Return best
    End Function

    ''' <summary>
    ''' Whether a hit at coordinate h along a face [lo, hi] lands on the face. A hit at an end (to within
    ''' the touching tolerance) while moving outwards belongs to the corner: the body is leaving the face
    ''' there. A body that has just slid off a face's end is exactly there in the world's coordinates but,
    ''' by rounding, a few ulps short of it in the face's own; counted as on the face, it would be put back
    ''' on it and leave again, for ever, the clock creeping on by ulps.
    ''' </summary>
    Private Function WithinFace(h As Double, rate As Double, lo As Double, hi As Double, slop As Double) As Boolean
        If h < lo - slop OrElse h > hi + slop Then Return False
        If h >= hi - slop AndAlso rate > 0 Then Return False
        If h <= lo + slop AndAlso rate < 0 Then Return False
        Return True
    End Function
End Module
