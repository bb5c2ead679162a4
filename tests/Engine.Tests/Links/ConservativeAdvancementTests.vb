Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Links
    ''' <summary>Conservative advancement against brute-force sampling on random smooth motions, grazes and close pairs of roots.</summary>
    Public Class ConservativeAdvancementTests
        ''' <summary>d(t) = c₀ + c₁t + ½c₂t² + Σ aᵢ sin(ωᵢt + φᵢ), with exact rate and bounds over [0, T].</summary>
        Private NotInheritable Class Wave
            Implements IDistanceFunction

            Public C0, C1, C2 As Double
            Public Amplitudes, Frequencies, Phases As Double()

            Public Function Distance(time As Double) As Double Implements IDistanceFunction.Distance
                Dim d = C0 + (C1 + 0.5 * C2 * time) * time
                For i = 0 To Amplitudes.Length - 1
                    d += Amplitudes(i) * Math.Sin(Frequencies(i) * time + Phases(i))
                Next
                Return d
            End Function

            Public Function Rate(time As Double) As Double Implements IDistanceFunction.Rate
                Dim r = C1 + C2 * time
                For i = 0 To Amplitudes.Length - 1
                    r += Amplitudes(i) * Frequencies(i) * Math.Cos(Frequencies(i) * time + Phases(i))
                Next
                Return r
            End Function

            Public Function SpeedBound(span As Double) As Double
                Dim v = Math.Abs(C1) + Math.Abs(C2) * span
                For i = 0 To Amplitudes.Length - 1
                    v += Math.Abs(Amplitudes(i) * Frequencies(i))
                Next
                Return v
            End Function

            Public Function AccelerationBound() As Double
                Dim a = Math.Abs(C2)
                For i = 0 To Amplitudes.Length - 1
                    a += Math.Abs(Amplitudes(i)) * Frequencies(i) * Frequencies(i)
                Next
                Return a
            End Function
        End Class

        Private Shared Function RandomWave(rng As Random) As Wave
            Dim n = rng.Next(1, 4)
            Dim w As New Wave With {
                .C0 = 0.5 + rng.NextDouble(),
                .C1 = (rng.NextDouble() - 0.6) * 0.5,
                .C2 = (rng.NextDouble() - 0.5) * 0.2,
                .Amplitudes = New Double(n - 1) {},
                .Frequencies = New Double(n - 1) {},
                .Phases = New Double(n - 1) {}}
            For i = 0 To n - 1
                w.Amplitudes(i) = rng.NextDouble() * 0.6
                w.Frequencies(i) = rng.NextDouble() * 8
                w.Phases(i) = rng.NextDouble() * 2 * Math.PI
            Next
            Return w
        End Function

        ''' <summary>The first sample at or below the tolerance on a grid, refined by bisection; +∞ when none.</summary>
        Private Shared Function BruteForce(d As IDistanceFunction, span As Double, tolerance As Double, samples As Integer) As Double
            Dim previous = 0.0
            If d.Distance(0) <= tolerance Then Return 0
            For i = 1 To samples
                Dim t = span * i / samples
                If d.Distance(t) <= tolerance Then
                    Dim lo = previous, hi = t
                    For k = 1 To 60
                        Dim mid = 0.5 * (lo + hi)
                        If d.Distance(mid) <= tolerance Then hi = mid Else lo = mid
                    Next
                    Return hi
                End If
                previous = t
            Next
            Return Double.PositiveInfinity
        End Function

        <Theory>
        <InlineData(True)>
        <InlineData(False)>
        Public Sub RandomMotions_AgreeWithBruteForce_AndNeverSkipAContact(secondOrder As Boolean)
            Dim rng As New Random(If(secondOrder, 17, 18))
            Dim span = 10.0, tolerance = 0.01
            Dim found = 0
            For trial = 1 To 300
                Dim w = RandomWave(rng)
                Dim result = If(secondOrder,
                    ConservativeAdvancement.FirstContact(w, 0, span, tolerance, w.SpeedBound(span), w.AccelerationBound()),
                    ConservativeAdvancement.FirstContact(w, 0, span, tolerance, w.SpeedBound(span)))
                Dim reference = BruteForce(w, span, tolerance, 100000)
                If result.Found Then found += 1
                If Double.IsPositiveInfinity(reference) Then
                    ' Either none, or a dip narrower than the grid that brute force stepped over: then it is real.
                    If result.Found Then Assert.True(w.Distance(result.Time) <= tolerance + 0.000000001, $"trial {trial}")
                    Assert.Equal(span, result.ClearUntil)
                    Continue For
                End If
                Assert.True(result.Found, $"trial {trial}: missed the contact at {reference}")
                ' Never later than the contact brute force saw; earlier only at a real contact it missed.
                Assert.True(result.Time <= reference + 0.000000000001, $"trial {trial}: {result.Time} after {reference}")
                If result.Time < reference - 0.001 Then
                    Assert.True(w.Distance(result.Time) <= tolerance + 0.000000001, $"trial {trial}")
                Else
                    Assert.Equal(reference, result.Time, 0.000000001)
                End If
            Next
            Assert.True(found > 100, $"only {found} of 300 motions made contact: the test would say little")
        End Sub

        ''' <summary>d = κ(t − a)(t − b) + c, in factored form so that its sign is exact even where the dip is 1e-15 m deep.</summary>
        Private NotInheritable Class Dip
            Implements IDistanceFunction

            Public Kappa, A, B, Offset As Double

            Public Function Distance(time As Double) As Double Implements IDistanceFunction.Distance
                Return Kappa * (time - A) * (time - B) + Offset
            End Function

            Public Function Rate(time As Double) As Double Implements IDistanceFunction.Rate
                Return Kappa * ((time - A) + (time - B))
            End Function

            Public Function SpeedBound(span As Double) As Double
                Return Kappa * Math.Max(Math.Abs(A + B), Math.Abs(2 * span - A - B))
            End Function
        End Class

        <Theory>
        <InlineData(True)>
        <InlineData(False)>
        Public Sub Grazes_JustAboveAndJustBelowTheTolerance(secondOrder As Boolean)
            ' d = tol + ε + κ(t − 3)²: a near-miss for ε > 0, two crossings 2√(|ε|/κ) apart for ε < 0.
            ' With V alone each step near the bottom is about (d − tol)/V, so a graze of depth ε costs
            ' about Vπ/√(εκ) steps: only the shallow ones are affordable there.
            Dim tolerance = 0.001, kappa = 0.5
            Dim epsilons = If(secondOrder, {0.000000001, 0.000000000001, -0.000000000001, -0.000000001, -0.000001}, {0.000000001, -0.000000001, -0.000001})
            For Each epsilon In epsilons
                Dim w As New Dip With {.Kappa = kappa, .A = 3, .B = 3, .Offset = tolerance + epsilon}
                Dim result = If(secondOrder,
                    ConservativeAdvancement.FirstContact(w, 0, 6, tolerance, w.SpeedBound(6), 2 * kappa),
                    ConservativeAdvancement.FirstContact(w, 0, 6, tolerance, w.SpeedBound(6), maxEvaluations:=10000000))
                If epsilon > 0 Then
                    Assert.False(result.Found, $"ε = {epsilon}: {result.Time}")
                    Assert.Equal(6.0, result.ClearUntil)
                Else
                    Assert.True(result.Found, $"ε = {epsilon}")
                    Dim expected = 3 - Math.Sqrt(-epsilon / kappa)
                    ' With V alone t stops moving once (d − tol)/V &lt; ulp(t): within V ulp(t)/|d'| of the root.
                    Dim slope = 2 * kappa * Math.Sqrt(-epsilon / kappa)
                    Dim resolution = If(secondOrder, 0.000000000001, 4 * w.SpeedBound(6) * 0.00000000000000045 / slope)
                    Assert.Equal(expected, result.Time, resolution)
                    Assert.True(result.Time <= expected + 0.000000000001)
                End If
                If secondOrder Then Assert.True(result.Evaluations < 200, $"ε = {epsilon}: {result.Evaluations} evaluations")
            Next
        End Sub

        <Fact>
        Public Sub TwoRootsCloseTogether_TheFirstIsFound()
            ' d = κ(t − a)(t − b): a dip 1e-7 s wide and κ(5e-8)² = 7.5e-15 m deep, which any grid
            ' coarser than 1e-7 s steps over. The second-order search brackets it in one monotone window.
            Dim a = 2.0, kappa = 3.0
            Dim narrow As New Dip With {.Kappa = kappa, .A = a, .B = a + 0.0000001}
            Dim second = ConservativeAdvancement.FirstContact(narrow, 0, 5, 0, narrow.SpeedBound(5), 2 * kappa)
            Assert.True(second.Found)
            Assert.Equal(a, second.Time, 0.000000000000001)
            Assert.Equal(Double.PositiveInfinity, BruteForce(narrow, 5, 0, 4999))
            ' With V alone the slope at the first root, κ(b − a), sets the pace: a 1 ms wide dip.
            Dim wider As New Dip With {.Kappa = kappa, .A = a, .B = a + 0.001}
            Dim first = ConservativeAdvancement.FirstContact(wider, 0, 5, 0, wider.SpeedBound(5), maxEvaluations:=10000000)
            Assert.True(first.Found)
            Assert.Equal(a, first.Time, 0.000000000001)
        End Sub

        <Fact>
        Public Sub BudgetRunsOut_TheClearPartIsReported()
            Dim w As New Wave With {.C0 = 1, .C1 = -0.001, .C2 = 0, .Amplitudes = Array.Empty(Of Double)(), .Frequencies = Array.Empty(Of Double)(), .Phases = Array.Empty(Of Double)()}
            ' V = 100 is a poor bound for a speed of 1e-3: each step moves 1% of the way.
            Dim result = ConservativeAdvancement.FirstContact(w, 0, 10000, 0, 100, maxEvaluations:=50)
            Assert.False(result.Found)
            Assert.True(result.ClearUntil > 0 AndAlso result.ClearUntil < 1000)
            Assert.True(w.Distance(result.ClearUntil) > 0)
            ' Carrying on from there finds it: d = 1 − 0.001 t reaches 0 at 1000 s.
            Dim more = ConservativeAdvancement.FirstContact(w, result.ClearUntil, 10000, 0, 0.001)
            Assert.True(more.Found)
            Assert.Equal(1000.0, more.Time, 0.000000001)
        End Sub

        <Fact>
        Public Sub Delegates_AndAContactAtTheStart()
            Dim atStart = ConservativeAdvancement.FirstContact(Function(t) 0.5 - t, 0, 1, 0.5, 1)
            Assert.True(atStart.Found)
            Assert.Equal(0.0, atStart.Time)
            Dim linear = ConservativeAdvancement.FirstContact(Function(t) 2 - 3 * t, Function(t) -3, 0, 1, 0.5, 3, 0)
            Assert.True(linear.Found)
            Assert.Equal(0.5, linear.Time, 0.000000000000001)
            Dim clear = ConservativeAdvancement.FirstContact(Function(t) 2 + Math.Sin(t), 0, 100, 0.5, 1)
            Assert.False(clear.Found)
            Assert.Equal(100.0, clear.ClearUntil)
        End Sub
    End Class
End Namespace
