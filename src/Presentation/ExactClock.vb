Option Strict On

''' <summary>
''' Durations that land a clock on an exact time. A world's clock after an advance of d seconds from
''' t is the rounded sum t + d; t + (target − t) is not always exactly the target, and a rewound run
''' must stop at the very time (to the last bit) the first run stopped at.
''' </summary>
Public Module ExactClock
    ''' <summary>
    ''' The duration d (s, ≥ 0) whose rounded sum with <paramref name="from"/> is exactly
    ''' <paramref name="target"/> (s, ≥ from). One always exists: the exact difference lies within the
    ''' interval of reals that round to the target, and doubles near it are no farther apart than that.
    ''' </summary>
    Public Function DurationTo(from As Double, target As Double) As Double
        If Not (target >= from) Then Throw New ArgumentOutOfRangeException(NameOf(target), "the target must not be before the start")
        Dim d = target - from
        ' A few ulps at most either way; the bound only guards against a clock that is not finite.
        For k = 1 To 64
            Dim sum = from + d
            If sum = target Then Return d
            d = If(sum < target, NextUp(d), NextDown(d))
        Next
        Return target - from
    End Function

    ''' <summary>The next double above a finite d ≥ 0.</summary>
    Private Function NextUp(d As Double) As Double
        If d = 0 Then Return Double.Epsilon
        Return BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(d) + 1)
    End Function

    ''' <summary>The next double below a finite d &gt; 0 (0 stays 0).</summary>
    Private Function NextDown(d As Double) As Double
        If d <= 0 Then Return 0
        Return BitConverter.Int64BitsToDouble(BitConverter.DoubleToInt64Bits(d) - 1)
    End Function
End Module
