Option Strict On

''' <summary>
''' The speed distribution of an ideal gas in two dimensions. With two velocity components each
''' normal with variance kT/m, the speed has the density f(v) = (m v / kT) exp(−m v² / 2kT)
''' (a Rayleigh distribution), mean speed √(πkT / 2m), and P(speed ≤ v) = 1 − exp(−m v² / 2kT).
''' A mixture of masses at one temperature has the mass-weighted average of these curves.
''' </summary>
Public NotInheritable Class MaxwellBoltzmann2D
    Private Sub New()
    End Sub

    ''' <summary>f(v), per m/s, for speed <paramref name="v"/> (m/s), mass <paramref name="mass"/> (kg) and kT (J).</summary>
    Public Shared Function Density(v As Double, mass As Double, kT As Double) As Double
        If v < 0 OrElse Not (kT > 0) OrElse Not (mass > 0) Then Return 0
        Dim a = mass / kT
        Return a * v * Math.Exp(-0.5 * a * v * v)
    End Function

    ''' <summary>P(speed ≤ v) for one mass (kg) at kT (J).</summary>
    Public Shared Function Cumulative(v As Double, mass As Double, kT As Double) As Double
        If v <= 0 OrElse Not (kT > 0) OrElse Not (mass > 0) Then Return 0
        Return -ExpM1(-0.5 * mass * v * v / kT)
    End Function

    ''' <summary>The mean speed √(πkT / 2m), m/s.</summary>
    Public Shared Function MeanSpeed(mass As Double, kT As Double) As Double
        Return Math.Sqrt(Math.PI * kT / (2 * mass))
    End Function

    ''' <summary>The most probable speed √(kT / m), m/s.</summary>
    Public Shared Function PeakSpeed(mass As Double, kT As Double) As Double
        Return Math.Sqrt(kT / mass)
    End Function

    ''' <summary>The density of a gas whose bodies have these masses (kg), all at kT (J): the average of each body's curve.</summary>
    Public Shared Function MixtureDensity(v As Double, masses As IReadOnlyList(Of Double), kT As Double) As Double
        If masses Is Nothing OrElse masses.Count = 0 Then Return 0
        Dim sum = 0.0
        For Each m In masses
            sum += Density(v, m, kT)
        Next
        Return sum / masses.Count
    End Function

    ''' <summary>P(speed ≤ v) for the mixture of <paramref name="masses"/> (kg) at kT (J).</summary>
    Public Shared Function MixtureCumulative(v As Double, masses As IReadOnlyList(Of Double), kT As Double) As Double
        If masses Is Nothing OrElse masses.Count = 0 Then Return 0
        Dim sum = 0.0
        For Each m In masses
            sum += Cumulative(v, m, kT)
        Next
        Return sum / masses.Count
    End Function

    ''' <summary>How many of <paramref name="masses"/>.Count bodies the curve puts in each bin of <paramref name="edges"/> (m/s); the last bin runs on to ∞.</summary>
    Public Shared Function ExpectedCounts(edges As IReadOnlyList(Of Double), masses As IReadOnlyList(Of Double), kT As Double) As Double()
        If edges Is Nothing Then Throw New ArgumentNullException(NameOf(edges))
        If masses Is Nothing Then Throw New ArgumentNullException(NameOf(masses))
        Dim bins = edges.Count - 1
        Dim result(Math.Max(0, bins) - 1) As Double
        For i = 0 To bins - 1
            Dim upper = If(i = bins - 1, 1.0, MixtureCumulative(edges(i + 1), masses, kT))
            result(i) = masses.Count * (upper - MixtureCumulative(edges(i), masses, kT))
        Next
        Return result
    End Function

    ''' <summary>eˣ − 1, accurate for small x (netstandard2.0 has no Math.Expm1).</summary>
    Private Shared Function ExpM1(x As Double) As Double
        If Math.Abs(x) < 1.0E-5 Then Return x + 0.5 * x * x + x * x * x / 6
        Return Math.Exp(x) - 1
    End Function
End Class
