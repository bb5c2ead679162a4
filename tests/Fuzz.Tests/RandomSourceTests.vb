Option Strict On
Imports PhysicsEngine.Fuzzing.Generation
Imports Xunit

''' <summary>The seeded random source and the platform-independent 2^x and log₂ the generator draws with.</summary>
Public Class RandomSourceTests
    <Fact>
    Public Sub SplitMix_GivesTheReferenceSequence()
        ' SplitMix64 (Steele, Lea and Flood 2014) from state 0 and 1234567, as the reference C code gives it.
        Dim zero As New SplitMix(0)
        Assert.Equal(&HE220A8397B1DCDAFUL, zero.NextBits())
        Assert.Equal(&H6E789E6AA1B965F4UL, zero.NextBits())
        Assert.Equal(&H6C45D188009454FUL, zero.NextBits())
        Dim other As New SplitMix(1234567)
        Assert.Equal(&H599ED017FB08FC85UL, other.NextBits())
        Assert.Equal(&H2C73F08458540FA5UL, other.NextBits())
    End Sub

    <Fact>
    Public Sub Exp2AndLog2_AgreeWithTheLibrary()
        For Each x In {-20.0, -3.7, -1.0, -0.5, 0.0, 0.1234, 0.5, 1.0, 2.999, 10.25, 39.9}
            Dim expected = Math.Pow(2, x)
            Assert.True(Math.Abs(ExactMath.Exp2(x) - expected) <= 0.00000001 * expected, $"2^{x}: {ExactMath.Exp2(x)} against {expected}")
        Next
        For Each y In {0.000001, 0.001, 0.3, 1.0, 1.5, 2.0, 7.0, 1000.0, 1.0E+12}
            Assert.True(Math.Abs(ExactMath.Log2(y) - Math.Log2(y)) <= 0.00000001 * Math.Max(1, Math.Abs(Math.Log2(y))), $"log2 {y}: {ExactMath.Log2(y)} against {Math.Log2(y)}")
        Next
    End Sub

    <Fact>
    Public Sub LogUniform_PutsAsManyDrawsInEveryDecade()
        Dim rng As New SplitMix(42)
        Dim counts(11) As Integer
        Const draws = 120000
        For i = 1 To draws
            Dim v = rng.LogUniform(0.000001, 1000000.0)
            Assert.InRange(v, 0.000001, 1000000.0)
            counts(Math.Min(11, CInt(Math.Floor(Math.Log10(v) + 6)))) += 1
        Next
        ' 10 000 expected per decade; the binomial spread is about 96, so 5 % is over five sigma.
        For Each c In counts
            Assert.InRange(c, 9500, 10500)
        Next
    End Sub

    <Fact>
    Public Sub Direction_IsAUnitVector_PointingEveryWay()
        Dim rng As New SplitMix(7)
        Dim quadrants(3) As Integer
        For i = 1 To 4000
            Dim d = rng.Direction()
            Assert.InRange(d.Length, 1 - 0.000000000000001, 1 + 0.000000000000001)
            quadrants(If(d.X >= 0, 0, 1) + If(d.Y >= 0, 0, 2)) += 1
        Next
        For Each q In quadrants
            Assert.InRange(q, 850, 1150)
        Next
    End Sub
End Class
