Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>The pure parts of the graphs against closed forms and invariants.</summary>
Public Class GraphMathTests
    Private Shared ReadOnly RoundSteps As Double() = {1.0, 2.0, 5.0}

    <Theory>
    <InlineData(1.0, 0.5)>
    <InlineData(3.0, 2.0)>
    <InlineData(0.02, 1.0E-3)>
    Public Sub MaxwellBoltzmann_IntegratesToOne_WithMeanSpeedRootPiKTOver2m(mass As Double, kT As Double)
        ' Simpson's rule out to 12 × the most probable speed (the tail beyond is e^-72).
        Dim top = 12 * Math.Sqrt(kT / mass)
        Const Steps As Integer = 20000
        Dim h = top / Steps
        Dim area = 0.0, first = 0.0
        For i = 0 To Steps
            Dim w = If(i = 0 OrElse i = Steps, 1, If(i Mod 2 = 1, 4, 2))
            Dim v = i * h
            Dim f = MaxwellBoltzmann2D.Density(v, mass, kT)
            area += w * f
            first += w * v * f
        Next
        area *= h / 3
        first *= h / 3
        Assert.Equal(1.0, area, 9)
        Assert.Equal(Math.Sqrt(Math.PI * kT / (2 * mass)), first, 9)
        Assert.Equal(first, MaxwellBoltzmann2D.MeanSpeed(mass, kT), 9)
    End Sub

    <Fact>
    Public Sub MaxwellBoltzmann_CumulativeIsTheIntegralOfTheDensity()
        Const m = 2.0, kT = 0.7
        For Each v In {0.1, 0.5, 0.9, 2.0}
            Dim sum = 0.0
            Const Steps As Integer = 4000
            For i = 0 To Steps - 1
                Dim mid = (i + 0.5) * v / Steps
                sum += MaxwellBoltzmann2D.Density(mid, m, kT) * v / Steps
            Next
            Assert.Equal(sum, MaxwellBoltzmann2D.Cumulative(v, m, kT), 1.0E-6)
        Next
        ' The peak of v·exp(−m v²/2kT) is at v = √(kT/m).
        Dim peak = MaxwellBoltzmann2D.PeakSpeed(m, kT)
        Assert.True(MaxwellBoltzmann2D.Density(peak, m, kT) > MaxwellBoltzmann2D.Density(peak * 1.01, m, kT))
        Assert.True(MaxwellBoltzmann2D.Density(peak, m, kT) > MaxwellBoltzmann2D.Density(peak * 0.99, m, kT))
    End Sub

    <Fact>
    Public Sub MaxwellBoltzmann_ExpectedCounts_AddUpToN_AndMixtureAveragesTheMasses()
        Dim masses = {1.0, 1.0, 4.0}
        Dim edges = Enumerable.Range(0, 11).Select(Function(i) i * 0.3).ToList()
        Dim expected = MaxwellBoltzmann2D.ExpectedCounts(edges, masses, 0.5)
        Assert.Equal(3.0, expected.Sum(), 12)
        Dim v = 0.7
        Assert.Equal((2 * MaxwellBoltzmann2D.Density(v, 1, 0.5) + MaxwellBoltzmann2D.Density(v, 4, 0.5)) / 3, MaxwellBoltzmann2D.MixtureDensity(v, masses, 0.5), 14)
    End Sub

    <Fact>
    Public Sub Histogram_CountsEverySpeed_EvenBeyondTheTop()
        Dim rng As New Random(3)
        Dim speeds = Enumerable.Range(0, 1000).Select(Function(i) rng.NextDouble() * 3).ToList()
        speeds.Add(7.3) ' beyond the asked top of 4 m/s: the bins grow to hold it
        Dim h = SpeedHistogram.Count(speeds, 4.0, 20)
        Assert.Equal(1001, h.Total)
        Assert.Equal(1001, h.Counts.Sum())
        Assert.True(h.Edges(h.Edges.Count - 1) > 7.3)
        Assert.Equal(0.2, h.BinWidth, 12)
        ' Each count is the number of speeds in its bin, counted by brute force.
        For i = 0 To h.Counts.Count - 1
            Dim lo = h.Edges(i), hi = h.Edges(i + 1)
            Assert.Equal(speeds.Where(Function(s) s >= lo AndAlso s < hi).Count(), h.Counts(i))
        Next
        Assert.Equal(0, SpeedHistogram.Count(Array.Empty(Of Double)(), 1.0).Total)
    End Sub

    <Theory>
    <InlineData(0.0, 1.0, 6)>
    <InlineData(-3.7, 12.2, 8)>
    <InlineData(1000.0, 1003.0, 5)>
    <InlineData(0.0, 0.00037, 6)>
    <InlineData(5.0, 5.0, 6)>
    Public Sub AxisTicks_CoverTheRange_WithRoundSteps(low As Double, high As Double, maxTicks As Integer)
        Dim t = AxisTicks.Ticks(low, high, maxTicks)
        Assert.True(t.Count >= 2 AndAlso t.Count <= maxTicks, $"{t.Count} ticks")
        Assert.True(t(0) <= low AndAlso t(t.Count - 1) >= high)
        Dim stepSize = t(1) - t(0)
        Dim mantissa = stepSize / Math.Pow(10, Math.Floor(Math.Log10(stepSize)))
        Assert.Contains(Math.Round(mantissa, 6), RoundSteps)
        For i = 1 To t.Count - 1
            Assert.Equal(stepSize, t(i) - t(i - 1), 9)
        Next
        Assert.Equal(2.0, AxisTicks.RoundUp(1.3))
        Assert.Equal(50.0, AxisTicks.RoundUp(20.01))
    End Sub

    <Fact>
    Public Sub SeriesRecorder_StaysBounded_ThinsEvenly_AndCutsWhenTimeGoesBack()
        Dim r As New SeriesRecorder()
        Dim t = 0.0
        For i = 0 To 3 * SeriesRecorder.Capacity
            r.Offer(New SeriesSample With {.Time = t, .Kinetic = t})
            t += SeriesRecorder.FirstInterval
        Next
        Assert.True(r.Samples.Count <= SeriesRecorder.Capacity)
        Assert.True(r.Interval >= 2 * SeriesRecorder.FirstInterval)
        ' Still the whole run, from its start to (nearly) now, evenly spaced.
        Assert.Equal(0.0, r.Samples(0).Time)
        Assert.True(t - r.Samples(r.Samples.Count - 1).Time <= 2 * r.Interval)
        For i = 2 To r.Samples.Count - 1
            Assert.True(r.Samples(i).Time - r.Samples(i - 1).Time >= r.Samples(1).Time * (1 - 1.0E-9) / 2)
        Next
        ' Back to t = 1 s: what came after is gone.
        r.Offer(New SeriesSample With {.Time = 1.0})
        Assert.True(r.Samples.All(Function(s) s.Time <= 1.0))
        Assert.Equal(1.0, r.Samples(r.Samples.Count - 1).Time)
    End Sub

    <Fact>
    Public Sub GasLaw_HendersonFactor_IsOneForAPointGas_AndGrowsWithPacking()
        Assert.Equal(1.0, GasLaw.HardDiscFactor(0))
        ' Henderson (1975) at η = 0.1: (1 + 0.01/8) / 0.81.
        Assert.Equal(1.00125 / 0.81, GasLaw.HardDiscFactor(0.1), 12)
        Assert.Equal(2.0 * 0.5 / 4.0, GasLaw.IdealPressure(2, 0.5, 4.0), 15)
    End Sub
End Class
