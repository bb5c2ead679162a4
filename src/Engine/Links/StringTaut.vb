Option Strict On

''' <summary>
''' When a slack string snaps taut, as pure functions: the first time t ≥ 0 at which the distance
''' between its ends grows to its length L. Inside the string's reach, write the gap function
''' g(t) = L² − |r(t)|² (positive while slack) and find where it first falls to zero while falling,
''' which is what <see cref="RootFinding.EarliestEntry"/> does:
''' <list type="bullet">
''' <item>a body in free flight against a fixed anchor: r(t) = r₀ + v t + ½ a t² with a = (0, −g), so
''' g(t) is a quartic (a quadratic when g = 0);</item>
''' <item>two free bodies: gravity cancels in their difference, r(t) = r₀ + w t is a straight line and
''' g(t) a quadratic.</item>
''' </list>
''' Ends within <c>slop</c> metres of the full length count as taut already: the string pulls now (0)
''' if they are moving apart, or moving across the string with nothing pulling them inwards (the
''' first non-zero derivative of g decides, each taken as zero within rounding); if they are moving
''' together it is the next time they get that far apart. Ends further apart than L + slop are over-stretched: taut now
''' (0) if they are not moving together; if they are, the string is going slack, and it is taut the next time they
''' are that far apart again, as for ends at its length (a snap now would have nothing to stop, and the same answer
''' after it would be asked again for ever).
''' </summary>
Public Module StringTaut
    ''' <summary>
    ''' A body at <paramref name="position"/> (m) with <paramref name="velocity"/> (m/s), flying under
    ''' gravity g (m/s², towards −y), tied by a string of <paramref name="length"/> (m) to a fixed
    ''' <paramref name="anchor"/>: seconds until the string is taut, +∞ if never (only when g = 0
    ''' and the body is at rest).
    ''' </summary>
    Public Function AnchoredTautTime(anchor As Vector, length As Double, position As Vector, velocity As Vector,
                                     gravity As Double, slop As Double) As Double
        Dim r = position - anchor
        Dim c0 = length * length - r.LengthSquared
        Dim tolerance = 2 * length * slop
        If c0 < -tolerance AndAlso Vector.Dot(r, velocity) >= 0 Then Return 0
        c0 = Math.Max(c0, -tolerance)
        Dim alpha = -0.5 * gravity
        ' |r + v t + α ŷ t²|² expanded; g(t) is its negative plus L².
        Dim c4 = -(alpha * alpha)
        Dim c3 = -(2 * alpha * velocity.Y)
        Dim c2 = -(velocity.LengthSquared + 2 * alpha * r.Y)
        Dim c1 = -2 * Vector.Dot(r, velocity)
        ' Within rounding of moving across the string: not moving along it (as TimeOfImpact does).
        If c0 <= tolerance AndAlso Math.Abs(c1) <= TimeOfImpact.ApproachFraction * 2 * length * velocity.Length Then c1 = 0
        ' Moving across a string whose tension is within rounding of zero (c2 is minus the pull it would
        ' need, v² + g r_y): the parabola osculates the circle, as where a pendulum's string has just
        ' gone slack. The cubic term decides then, not the sign of a rounding error.
        If c0 <= tolerance AndAlso c1 = 0 AndAlso Math.Abs(c2) <= TimeOfImpact.ApproachFraction * (velocity.LengthSquared + gravity * Math.Abs(r.Y)) Then c2 = 0
        If c4 = 0 Then Return RootFinding.EarliestEntryQuadratic(c2, c1, Math.Max(c0, -tolerance), tolerance)
        Return RootFinding.EarliestEntry(c4, c3, c2, c1, c0, tolerance)
    End Function

    ''' <summary>
    ''' Two free bodies under the same gravity, tied by a string of <paramref name="length"/> (m):
    ''' seconds until the string is taut, +∞ if never (no relative motion).
    ''' </summary>
    Public Function PairTautTime(position1 As Vector, velocity1 As Vector, position2 As Vector, velocity2 As Vector,
                                 length As Double, slop As Double) As Double
        Dim r = position2 - position1
        Dim w = velocity2 - velocity1
        Dim c0 = length * length - r.LengthSquared
        Dim tolerance = 2 * length * slop
        If c0 < -tolerance AndAlso Vector.Dot(r, w) >= 0 Then Return 0
        Dim c1 = -2 * Vector.Dot(r, w)
        If c0 <= tolerance AndAlso Math.Abs(c1) <= TimeOfImpact.ApproachFraction * 2 * length * w.Length Then c1 = 0
        Return RootFinding.EarliestEntryQuadratic(-w.LengthSquared, c1, Math.Max(c0, -tolerance), tolerance)
    End Function
End Module
