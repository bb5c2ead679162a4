Option Strict On

Namespace Generation
    ''' <summary>
    ''' SplitMix64 (Steele, Lea and Flood, 2014): a tiny generator whose output depends on its seed alone,
    ''' on every platform and runtime, so a seed names one scene for good. Every draw that shapes a scene
    ''' uses only +, −, ×, ÷, √ and exact scalings (<see cref="ExactMath"/>), which IEEE 754 rounds the same
    ''' everywhere; library functions such as Math.Log or Math.Sin may differ in the last bit between
    ''' platforms and are never used here.
    ''' </summary>
    Friend NotInheritable Class SplitMix
        Private _state As ULong

        ''' <param name="seed">any value; the same seed gives the same sequence</param>
        Friend Sub New(seed As Long)
            _state = CULng(seed And Long.MaxValue) Xor If(seed < 0, &H8000000000000000UL, 0UL)
        End Sub

        ''' <summary>The next 64 random bits.</summary>
        Friend Function NextBits() As ULong
            _state += &H9E3779B97F4A7C15UL
            Dim z = _state
            z = (z Xor (z >> 30)) * &HBF58476D1CE4E5B9UL
            z = (z Xor (z >> 27)) * &H94D049BB133111EBUL
            Return z Xor (z >> 31)
        End Function

        ''' <summary>Uniform in [0, 1), with 53 random bits.</summary>
        Friend Function NextDouble() As Double
            Return (NextBits() >> 11) * (1.0 / 9007199254740992.0)
        End Function

        ''' <summary>Uniform in [lo, hi).</summary>
        Friend Function Uniform(lo As Double, hi As Double) As Double
            Return lo + (hi - lo) * NextDouble()
        End Function

        ''' <summary>An integer from lo to hi, both included.</summary>
        Friend Function Between(lo As Integer, hi As Integer) As Integer
            If hi <= lo Then Return lo
            Return lo + CInt(NextBits() Mod CULng(hi - lo + 1))
        End Function

        ''' <summary>True with probability p.</summary>
        Friend Function Chance(p As Double) As Boolean
            Return NextDouble() < p
        End Function

        ''' <summary>
        ''' Log-uniform in [lo, hi] (0 &lt; lo ≤ hi): every factor of ten is as likely as every other, so a
        ''' range over 10¹² gives as many grams as tonnes.
        ''' </summary>
        Friend Function LogUniform(lo As Double, hi As Double) As Double
            If hi <= lo Then Return lo
            Dim v = lo * ExactMath.Exp2(NextDouble() * ExactMath.Log2(hi / lo))
            Return Math.Min(Math.Max(v, lo), hi)
        End Function

        ''' <summary>One of the items, each as likely.</summary>
        Friend Function Pick(Of T)(items As IReadOnlyList(Of T)) As T
            Return items(Between(0, items.Count - 1))
        End Function

        ''' <summary>A unit vector in a uniformly random direction (by rejection from the unit disc: no sine or cosine).</summary>
        Friend Function Direction() As Vector
            Do
                Dim x = Uniform(-1, 1)
                Dim y = Uniform(-1, 1)
                Dim s = x * x + y * y
                If s > 0.01 AndAlso s <= 1 Then
                    Dim len = Math.Sqrt(s)
                    Return New Vector(x / len, y / len)
                End If
            Loop
        End Function
    End Class
End Namespace
