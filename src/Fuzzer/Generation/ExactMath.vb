Option Strict On

Namespace Generation
    ''' <summary>
    ''' 2^x and log₂ y built from square roots, products and exact scalings only: IEEE 754 rounds those
    ''' correctly, so the results (and the scenes drawn with them) carry the same bits on every platform.
    ''' About 30 correct bits, far more than a random draw needs.
    ''' </summary>
    Friend Module ExactMath
        Private Const Bits As Integer = 30

        ''' <summary>2^x for a finite x, from the binary digits of its fraction: 2^(Σ bᵢ 2⁻ⁱ) = Π (2^(2⁻ⁱ))^bᵢ.</summary>
        Friend Function Exp2(x As Double) As Double
            Dim whole = Math.Floor(x)
            Dim fraction = x - whole
            Dim result = 1.0
            Dim root = 2.0
            For i = 1 To Bits
                root = Math.Sqrt(root)
                fraction *= 2
                If fraction >= 1 Then
                    result *= root
                    fraction -= 1
                End If
            Next
            Return Math.ScaleB(result, CInt(whole))
        End Function

        ''' <summary>log₂ y for a finite y &gt; 0: the exponent, then the fraction's digits by repeated squaring of the mantissa.</summary>
        Friend Function Log2(y As Double) As Double
            If Not (y > 0) OrElse Double.IsInfinity(y) Then Throw New ArgumentOutOfRangeException(NameOf(y), "must be a finite number greater than 0")
            Dim exponent = Math.ILogB(y)
            Dim mantissa = Math.ScaleB(y, -exponent) ' in [1, 2)
            Dim result = CDbl(exponent)
            Dim digit = 1.0
            For i = 1 To Bits
                mantissa *= mantissa
                digit /= 2
                If mantissa >= 2 Then
                    mantissa /= 2
                    result += digit
                End If
            Next
            Return result
        End Function
    End Module
End Namespace
