Option Strict On

''' <summary>
''' The root of a continuous function in a bracket, by Brent's method: inverse quadratic
''' interpolation or the secant while they stay inside the bracket and keep shrinking it fast
''' enough, bisection otherwise. It never leaves the bracket, converges superlinearly on smooth
''' functions, and needs at most about twice the evaluations of bisection on any function.
''' </summary>
Public Module ScalarRoot
    ''' <summary>
    ''' A root of f in [a, b], given f(a) = fa and f(b) = fb of opposite signs (or one of them zero),
    ''' to a few roundings of the root. The answer is the bracket end on the side of a (where f has
    ''' the sign of fa), so when a is "before" and f is a gap that is still open there, the answer
    ''' never lies past the crossing.
    ''' </summary>
    Public Function Brent(f As Func(Of Double, Double), a As Double, b As Double, fa As Double, fb As Double) As Double
        If f Is Nothing Then Throw New ArgumentNullException(NameOf(f))
        If fa = 0 Then Return a
        If fb = 0 Then Return b
        If (fa > 0) = (fb > 0) Then Throw New ArgumentException("f(a) and f(b) must differ in sign")
        Dim aPositive = fa > 0
        ' b is the best estimate, c the other end of the bracket, a the previous b.
        Dim c = a, fc = fa
        Dim d = b - a, e = d
        For iteration = 1 To 200
            If (fb > 0) = (fc > 0) Then
                c = a : fc = fa
                d = b - a : e = d
            End If
            If Math.Abs(fc) < Math.Abs(fb) Then
                a = b : b = c : c = a
                fa = fb : fb = fc : fc = fa
            End If
            Dim tolerance = 2 * 2.2204460492503131E-16 * Math.Abs(b) + 1.0E-300
            Dim half = 0.5 * (c - b)
            If Math.Abs(half) <= tolerance OrElse fb = 0 Then Exit For
            If Math.Abs(e) >= tolerance AndAlso Math.Abs(fa) > Math.Abs(fb) Then
                Dim s = fb / fa
                Dim p As Double, q As Double
                If a = c Then
                    p = 2 * half * s
                    q = 1 - s
                Else
                    Dim qa = fa / fc, r = fb / fc
                    p = s * (2 * half * qa * (qa - r) - (b - a) * (r - 1))
                    q = (qa - 1) * (r - 1) * (s - 1)
                End If
                If p > 0 Then q = -q Else p = -p
                If 2 * p < Math.Min(3 * half * q - Math.Abs(tolerance * q), Math.Abs(e * q)) Then
                    e = d
                    d = p / q
                Else
                    d = half
                    e = d
                End If
            Else
                d = half
                e = d
            End If
            a = b : fa = fb
            b += If(Math.Abs(d) > tolerance, d, If(half > 0, tolerance, -tolerance))
            fb = f(b)
        Next
        If fb = 0 Then Return b
        Return If((fb > 0) = aPositive, b, c)
    End Function
End Module
