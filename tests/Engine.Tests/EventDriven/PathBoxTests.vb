Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' The box around a stretch of a path, which decides which neighbouring cells a ball searches: too
''' small and a partner is missed, too big and the search does needless work.
''' </summary>
Public Class PathBoxTests
    <Fact>
    Public Sub BallThrownUp_BoxReachesTheApex_OnlyIfTheStretchDoes()
        ' From y = 1 m at 4 m/s up under g = 10 m/s²: apex 0.8 m higher, 0.4 s later.
        Dim xlo, xhi, ylo, yhi As Double
        PathBox.Bounds(0, 1, 0, 4, -10, 0.9, xlo, xhi, ylo, yhi)
        Assert.Equal(1.8, yhi, 12)
        Assert.Equal(1.0 + 4 * 0.9 - 5 * 0.81, ylo, 12) ' where it is at the end, below the start
        PathBox.Bounds(0, 1, 0, 4, -10, 0.2, xlo, xhi, ylo, yhi)
        Assert.Equal(1.0 + 4 * 0.2 - 5 * 0.04, yhi, 12) ' still rising at the end
        Assert.Equal(1.0, ylo, 12)
    End Sub

    <Fact>
    Public Sub StraightLine_BoxIsItsEnds()
        Dim xlo, xhi, ylo, yhi As Double
        PathBox.Bounds(2, 3, -1, 0.5, 0, 4, xlo, xhi, ylo, yhi)
        Assert.Equal(-2.0, xlo, 12)
        Assert.Equal(2.0, xhi, 12)
        Assert.Equal(3.0, ylo, 12)
        Assert.Equal(5.0, yhi, 12)
    End Sub

    <Fact>
    Public Sub RandomStretches_BoxHoldsEveryPoint_AndNoMore()
        Dim rng As New Random(7)
        For k = 0 To 999
            Dim px = rng.NextDouble() * 2 - 1, py = rng.NextDouble() * 2 - 1
            Dim vx = rng.NextDouble() * 6 - 3, vy = rng.NextDouble() * 6 - 3
            Dim ay = If(k Mod 4 = 0, 0.0, rng.NextDouble() * 40 - 20)
            Dim span = rng.NextDouble()
            Dim xlo, xhi, ylo, yhi As Double
            PathBox.Bounds(px, py, vx, vy, ay, span, xlo, xhi, ylo, yhi)
            Dim sxlo = Double.PositiveInfinity, sxhi = Double.NegativeInfinity
            Dim sylo = Double.PositiveInfinity, syhi = Double.NegativeInfinity
            Const Samples = 4000
            For s = 0 To Samples
                Dim t = span * s / Samples
                Dim x = px + vx * t, y = py + vy * t + 0.5 * ay * t * t
                Assert.True(x >= xlo - 1.0E-12 AndAlso x <= xhi + 1.0E-12, $"stretch {k}: x = {x} at t = {t} outside {xlo} … {xhi}")
                Assert.True(y >= ylo - 1.0E-12 AndAlso y <= yhi + 1.0E-12, $"stretch {k}: y = {y} at t = {t} outside {ylo} … {yhi}")
                sxlo = Math.Min(sxlo, x) : sxhi = Math.Max(sxhi, x)
                sylo = Math.Min(sylo, y) : syhi = Math.Max(syhi, y)
            Next
            ' Tight: the sampled extremes come within the sampling error of the box.
            Assert.True(xlo > sxlo - 1.0E-9 AndAlso xhi < sxhi + 1.0E-9, $"stretch {k}: x box too wide")
            Assert.True(ylo > sylo - 1.0E-6 AndAlso yhi < syhi + 1.0E-6, $"stretch {k}: y box too tall")
        Next
    End Sub
End Class
