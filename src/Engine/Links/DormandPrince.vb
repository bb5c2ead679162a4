Option Strict On

''' <summary>
''' One step of the Dormand–Prince 5(4) pair for y' = f(y): six new evaluations of f give a fifth-order
''' result and an embedded fourth-order one; their difference estimates the step's error. The seventh
''' evaluation, f at the result, is the next step's first ("first same as last").
''' </summary>
Friend Module DormandPrince
    ''' <summary>
    ''' A step of <paramref name="h"/> (s) from <paramref name="y"/>, where f(y) = <paramref name="k1"/>. Returns the
    ''' largest error estimate ÷ (absolute + relative × |y| + h × rounding) over the components: the step is good
    ''' when it is ≤ 1. <paramref name="result"/> is the fifth-order state and <paramref name="slope"/> f there.
    ''' <paramref name="rounding"/>, when given, is how far each component of f at y may be off by rounding alone
    ''' (a stiff spring at its length: k (d − L) is the difference of two large, nearly equal numbers). The error
    ''' estimate is a weighted sum of h × f, so h times that rounding is noise that no shorter step removes:
    ''' without this floor the step shrinks towards zero while the state stands still. <paramref name="removeHeld"/>,
    ''' when given, takes from the error estimates (laid out as the state) the part that constraints fix at the
    ''' result, and says whether it could: the error is then measured in what they leave free.
    ''' </summary>
    Friend Function TryStep(f As Func(Of Double(), Double()), y As Double(), k1 As Double(), h As Double,
                            relativeTolerance As Double, absoluteTolerance As Double,
                            ByRef result As Double(), ByRef slope As Double(),
                            Optional rounding As Double() = Nothing,
                            Optional removeHeld As Func(Of Double(), Double(), Boolean) = Nothing) As Double
        Dim k2 = f(Combine(y, h, k1, 1 / 5.0))
        Dim k3 = f(Combine(y, h, k1, 3 / 40.0, k2, 9 / 40.0))
        Dim k4 = f(Combine(y, h, k1, 44 / 45.0, k2, -56 / 15.0, k3, 32 / 9.0))
        Dim k5 = f(Combine(y, h, k1, 19372 / 6561.0, k2, -25360 / 2187.0, k3, 64448 / 6561.0, k4, -212 / 729.0))
        Dim k6 = f(Combine(y, h, k1, 9017 / 3168.0, k2, -355 / 33.0, k3, 46732 / 5247.0, k4, 49 / 176.0, k5, -5103 / 18656.0))
        result = Combine(y, h, k1, 35 / 384.0, k3, 500 / 1113.0, k4, 125 / 192.0, k5, -2187 / 6784.0, k6, 11 / 84.0)
        slope = f(result)
        Dim worst = 0.0
        Dim errors As Double() = Nothing
        If removeHeld IsNot Nothing Then
            errors = New Double(y.Length - 1) {}
            For i = 0 To y.Length - 1
                errors(i) = StepError(h, k1, k3, k4, k5, k6, slope, i)
            Next
            If Not removeHeld(result, errors) Then errors = Nothing
        End If
        For i = 0 To y.Length - 1
            ' The fifth-order result minus the embedded fourth-order one.
            Dim e = If(errors IsNot Nothing, errors(i), StepError(h, k1, k3, k4, k5, k6, slope, i))
            Dim scale = absoluteTolerance + relativeTolerance * Math.Max(Math.Abs(y(i)), Math.Abs(result(i)))
            If rounding IsNot Nothing Then scale += h * rounding(i)
            worst = Math.Max(worst, Math.Abs(e) / scale)
        Next
        Return worst
    End Function

    ''' <summary>Component <paramref name="i"/> of the fifth-order result minus the embedded fourth-order one.</summary>
    Private Function StepError(h As Double, k1 As Double(), k3 As Double(), k4 As Double(), k5 As Double(), k6 As Double(), slope As Double(), i As Integer) As Double
        Return h * (71 / 57600.0 * k1(i) - 71 / 16695.0 * k3(i) + 71 / 1920.0 * k4(i) - 17253 / 339200.0 * k5(i) + 22 / 525.0 * k6(i) - 1 / 40.0 * slope(i))
    End Function

    ''' <summary>How much to multiply the step by after an error ratio of <paramref name="worst"/>: the fifth root rule with a safety factor, between 0.2 and 5.</summary>
    Friend Function StepFactor(worst As Double) As Double
        Return If(worst = 0, 5, Math.Min(5, Math.Max(0.2, 0.9 * Math.Pow(worst, -0.2))))
    End Function

    ''' <summary>y + h Σ wᵢ kᵢ.</summary>
    Private Function Combine(y As Double(), h As Double, k1 As Double(), w1 As Double,
                             Optional k2 As Double() = Nothing, Optional w2 As Double = 0,
                             Optional k3 As Double() = Nothing, Optional w3 As Double = 0,
                             Optional k4 As Double() = Nothing, Optional w4 As Double = 0,
                             Optional k5 As Double() = Nothing, Optional w5 As Double = 0,
                             Optional k6 As Double() = Nothing, Optional w6 As Double = 0) As Double()
        Dim r(y.Length - 1) As Double
        For i = 0 To y.Length - 1
            Dim s = w1 * k1(i)
            If k2 IsNot Nothing Then s += w2 * k2(i)
            If k3 IsNot Nothing Then s += w3 * k3(i)
            If k4 IsNot Nothing Then s += w4 * k4(i)
            If k5 IsNot Nothing Then s += w5 * k5(i)
            If k6 IsNot Nothing Then s += w6 * k6(i)
            r(i) = y(i) + h * s
        Next
        Return r
    End Function
End Module
