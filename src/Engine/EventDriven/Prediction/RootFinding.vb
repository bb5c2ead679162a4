Option Strict On

''' <summary>
''' Real roots of polynomials of degree ≤ 4 as pure functions, without a fixed-step search: the
''' roots of the derivative split the time axis into intervals on which the polynomial is monotone,
''' so each interval holds at most one root and a bracketed Newton/bisection finds it safely.
''' Coefficients are given highest power first: f(t) = c4 t⁴ + c3 t³ + c2 t² + c1 t + c0.
''' </summary>
Public Module RootFinding
    ''' <summary>
    ''' Real roots of a t² + b t + c = 0 in ascending order; returns how many (0, 1 or 2; a double
    ''' root counts once). a = 0 falls back to the linear equation. Uses q = −½(b + sign(b)√disc) and
    ''' the roots q/a and c/q, so neither root suffers catastrophic cancellation.
    ''' </summary>
    Public Function QuadraticRoots(a As Double, b As Double, c As Double, ByRef x1 As Double, ByRef x2 As Double) As Integer
        x1 = Double.NaN
        x2 = Double.NaN
        If a = 0 Then
            If b = 0 Then Return 0
            x1 = -c / b
            Return 1
        End If
        Dim disc = b * b - 4 * a * c
        If disc < 0 Then Return 0
        If disc = 0 Then
            x1 = -b / (2 * a)
            Return 1
        End If
        Dim s = Math.Sqrt(disc)
        Dim q = -0.5 * (b + If(b >= 0, s, -s))
        Dim r1 = q / a
        Dim r2 = c / q
        If r1 <= r2 Then
            x1 = r1
            x2 = r2
        Else
            x1 = r2
            x2 = r1
        End If
        Return 2
    End Function

    ''' <summary>f(t) by Horner's rule.</summary>
    Public Function Evaluate(c4 As Double, c3 As Double, c2 As Double, c1 As Double, c0 As Double, t As Double) As Double
        Return (((c4 * t + c3) * t + c2) * t + c1) * t + c0
    End Function

    ''' <summary>
    ''' The root of f in [lo, hi], given that f(lo) and f(hi) have opposite signs (or one is zero).
    ''' Newton steps are taken while they stay inside the shrinking bracket, bisection otherwise. The
    ''' bracket end on the side where f has the sign of f(lo) is returned, so for a distance function
    ''' that is still positive at lo the answer never lies past the contact.
    ''' </summary>
    Public Function BracketedRoot(c4 As Double, c3 As Double, c2 As Double, c1 As Double, c0 As Double,
                                  lo As Double, hi As Double) As Double
        Dim flo = Evaluate(c4, c3, c2, c1, c0, lo)
        If flo = 0 Then Return lo
        Dim fhi = Evaluate(c4, c3, c2, c1, c0, hi)
        If fhi = 0 Then Return hi
        Dim loPositive = flo > 0
        Dim x = 0.5 * (lo + hi)
        For iteration = 1 To 200
            Dim fx = Evaluate(c4, c3, c2, c1, c0, x)
            If fx = 0 Then Return x
            If (fx > 0) = loPositive Then lo = x Else hi = x
            If hi - lo <= 4.0E-16 * Math.Max(Math.Abs(lo), Math.Abs(hi)) OrElse hi - lo < 1.0E-300 Then Exit For
            Dim d = ((4 * c4 * x + 3 * c3) * x + 2 * c2) * x + c1
            Dim nx = If(d <> 0, x - fx / d, Double.NaN)
            ' Newton only while it lands strictly inside the bracket; bisection otherwise.
            If nx > lo AndAlso nx < hi Then x = nx Else x = 0.5 * (lo + hi)
            If x = lo OrElse x = hi Then Exit For
        Next
        Return lo
    End Function

    ''' <summary>
    ''' Real roots of a3 t³ + a2 t² + a1 t + a0 strictly inside (lo, hi), ascending; returns how many.
    ''' The roots of the derivative (a quadratic) cut (lo, hi) into monotone pieces; a root is found in
    ''' each piece whose ends differ in sign, and a double root (a touching extremum) is returned once.
    ''' </summary>
    Public Function CubicRootsIn(a3 As Double, a2 As Double, a1 As Double, a0 As Double, lo As Double, hi As Double,
                                 ByRef x1 As Double, ByRef x2 As Double, ByRef x3 As Double) As Integer
        x1 = Double.NaN
        x2 = Double.NaN
        x3 = Double.NaN
        Dim p1 As Double, p2 As Double
        Dim n = QuadraticRoots(3 * a3, 2 * a2, a1, p1, p2)
        ' Breakpoints lo < b1 < b2 < hi.
        Dim b1 = hi, b2 = hi
        If n >= 1 AndAlso p1 > lo AndAlso p1 < hi Then b1 = p1
        If n = 2 AndAlso p2 > lo AndAlso p2 < hi Then
            If b1 = hi Then b1 = p2 Else b2 = p2
        End If
        Dim count = 0
        Dim u = lo
        Dim fu = Evaluate(0, a3, a2, a1, a0, lo)
        For piece = 0 To 2
            Dim v = If(piece = 0, b1, If(piece = 1, b2, hi))
            If v <= u Then Continue For
            Dim fv = Evaluate(0, a3, a2, a1, a0, v)
            Dim root = Double.NaN
            If fv = 0 AndAlso v < hi Then
                root = v
            ElseIf (fu < 0 AndAlso fv > 0) OrElse (fu > 0 AndAlso fv < 0) Then
                root = BracketedRoot(0, a3, a2, a1, a0, u, v)
            End If
            If Not Double.IsNaN(root) Then
                If count = 0 Then
                    x1 = root
                ElseIf count = 1 Then
                    If root <> x1 Then x2 = root Else count -= 1
                ElseIf root <> x2 Then
                    x3 = root
                Else
                    count -= 1
                End If
                count += 1
            End If
            u = v
            fu = fv
        Next
        Return count
    End Function

    ''' <summary>
    ''' The earliest t ≥ 0 at which f (a gap or a squared-distance excess: positive means apart)
    ''' crosses from positive to ≤ 0 while decreasing; +∞ when it never does. When f(0) ≤ tolerance
    ''' the bodies already touch: they collide now (t = 0) if f is decreasing at 0 (the first
    ''' non-zero derivative is negative); touching bodies that separate collide only when f comes back
    ''' down to where it started (or to 0, if it started above), as in <see cref="EarliestEntryQuadratic"/>.
    ''' </summary>
    Public Function EarliestEntry(c4 As Double, c3 As Double, c2 As Double, c1 As Double, c0 As Double,
                                  tolerance As Double) As Double
        If c4 = 0 AndAlso c3 = 0 Then Return EarliestEntryQuadratic(c2, c1, c0, tolerance)
        ' Initial direction: the sign of the first non-zero derivative at t = 0.
        Dim direction = If(c1 <> 0, c1, If(c2 <> 0, c2, If(c3 <> 0, c3, c4)))
        Dim touching = c0 <= tolerance
        If touching AndAlso direction < 0 Then Return 0
        ' Touching and separating, f starting within the tolerance below 0 (rounding): measured from
        ' its start, so a pair that parts at a rounding error's speed while its acceleration presses it
        ' together (a ball left at rest on another) is found coming back at once. From f(0) < 0 it
        ' would have to rise above 0 first, and a rise far below rounding never shows in the sum: the
        ' pair would be missed, and sink into each other. (A start deeper inside keeps its meaning: the
        ' next time f falls through 0.)
        If touching AndAlso c0 < 0 AndAlso c0 >= -tolerance Then c0 = 0
        ' Cauchy's bound: every real root of f and of f' lies below it.
        Dim lead = If(c4 <> 0, c4, c3)
        Dim bound = 1 + Math.Max(Math.Max(Math.Abs(c3 / lead), Math.Abs(c2 / lead)), Math.Max(Math.Abs(c1 / lead), Math.Abs(c0 / lead)))
        Dim boundD = 1 + Math.Max(Math.Max(Math.Abs(3 * c3 / (4 * lead)), Math.Abs(2 * c2 / (4 * lead))), Math.Abs(c1 / (4 * lead)))
        If c4 = 0 Then boundD = 1 + Math.Max(Math.Abs(2 * c2 / (3 * c3)), Math.Abs(c1 / (3 * c3)))
        bound = Math.Max(bound, boundD)
        Dim k1 As Double, k2 As Double, k3 As Double
        Dim nk = CubicRootsIn(4 * c4, 3 * c3, 2 * c2, c1, 0, bound, k1, k2, k3)
        Dim u = 0.0
        Dim fu = c0
        For piece = 0 To nk
            Dim v = If(piece = nk, bound, If(piece = 0, k1, If(piece = 1, k2, k3)))
            Dim fv = Evaluate(c4, c3, c2, c1, c0, v)
            ' fv = 0 at a critical point is a tangent graze (a double root), not an entry.
            Dim entersHere = fv < 0 AndAlso fu > 0
            If piece = 0 AndAlso touching Then entersHere = False
            If entersHere Then Return BracketedRoot(c4, c3, c2, c1, c0, u, v)
            u = v
            fu = fv
        Next
        ' Beyond the bound f keeps the sign of its leading term; a negative one still enters.
        If lead < 0 AndAlso fu > 0 Then Return bound
        Return Double.PositiveInfinity
    End Function

    ''' <summary>
    ''' <see cref="EarliestEntry"/> for f(t) = a t² + b t + c in closed form: the entering root is the
    ''' smaller root when the parabola opens upwards and the larger one when it opens downwards. Unlike
    ''' the quartic, a start well below −tolerance is not a contact but a start beyond the line (the
    ''' gap of a face plane, which extends past the face): only a later downward crossing counts.
    ''' </summary>
    Public Function EarliestEntryQuadratic(a As Double, b As Double, c As Double, tolerance As Double) As Double
        If c < -tolerance Then
            ' Well past the line (a wall plane beyond a face's extent, a cell boundary just crossed):
            ' only a parabola opening downwards comes back, entering at its larger root.
            If a >= 0 Then Return Double.PositiveInfinity
            Dim y1 As Double, y2 As Double
            If QuadraticRoots(a, b, c, y1, y2) < 2 OrElse y2 <= 0 Then Return Double.PositiveInfinity
            Return y2
        End If
        If c <= tolerance Then
            If b < 0 OrElse (b = 0 AndAlso a < 0) Then Return 0
            ' Touching and separating: only a parabola opening downwards comes back.
            If a >= 0 Then Return Double.PositiveInfinity
            Dim r1 As Double, r2 As Double
            Dim n = QuadraticRoots(a, b, Math.Max(c, 0), r1, r2)
            If n = 0 Then Return Double.PositiveInfinity
            Return Math.Max(If(n = 2, r2, r1), 0)
        End If
        If a = 0 Then
            If b >= 0 Then Return Double.PositiveInfinity
            Return -c / b
        End If
        Dim x1 As Double, x2 As Double
        Dim count = QuadraticRoots(a, b, c, x1, x2)
        If a > 0 Then
            ' Positive outside the roots: enters at the smaller one, if it lies ahead.
            If count < 2 OrElse x1 < 0 Then Return Double.PositiveInfinity
            Return x1
        End If
        ' Opening downwards with c > 0: the roots straddle 0 and it enters at the larger one.
        Return If(count = 2, x2, x1)
    End Function
End Module
