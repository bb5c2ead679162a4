Option Strict On

''' <summary>
''' Elliptic integrals of the first kind, F(φ, k) = ∫₀^φ dϑ / √(1 − k² sin² ϑ) and K(k) = F(π/2, k),
''' as pure functions. Every function takes the complementary modulus k′ = √(1 − k²) rather than k:
''' near k = 1 (a pendulum swinging almost over the top) 1 − k² would be a difference of two nearly
''' equal numbers, whereas k′ can be computed directly from the motion (see <see cref="Pendulum"/>).
''' For small k nothing is lost either: k² below 10⁻¹⁶ changes F and K by less than a rounding.
''' </summary>
Public Module EllipticIntegral
    ''' <summary>The complementary modulus √(1 − k²), written √((1 − k)(1 + k)) so that it stays accurate near k = 1.</summary>
    Public Function Complement(modulus As Double) As Double
        Return Math.Sqrt(Math.Max(0.0, (1 - modulus) * (1 + modulus)))
    End Function

    ''' <summary>
    ''' The arithmetic–geometric mean of a, b ≥ 0: replace (a, b) by ((a + b)/2, √(ab)) until they
    ''' agree. The gap squares at every step ((a − b)/(a + b) goes to about its square over 8), so
    ''' 1 and 10⁻³⁰⁰ agree to rounding in about 14 steps and 1 and 0.5 in 4.
    ''' </summary>
    Public Function ArithmeticGeometricMean(a As Double, b As Double) As Double
        If a = 0 OrElse b = 0 Then Return 0
        For iteration = 1 To 64
            ' Once |a − b| ≤ 2e-8 a the arithmetic mean differs from the limit by (a − b)²/(16 a) < 3e-17 a.
            If Math.Abs(a - b) <= 0.00000002 * a Then Exit For
            Dim mean = 0.5 * (a + b)
            b = Math.Sqrt(a) * Math.Sqrt(b)
            a = mean
        Next
        Return 0.5 * (a + b)
    End Function

    ''' <summary>
    ''' The complete integral K(k) = π / (2 AGM(1, k′)), given the complementary modulus k′ ∈ [0, 1];
    ''' +∞ at k′ = 0 (k = 1), where K grows like ln(4/k′).
    ''' </summary>
    Public Function CompleteFirstKind(complementaryModulus As Double) As Double
        If complementaryModulus <= 0 Then Return Double.PositiveInfinity
        Return 0.5 * Math.PI / ArithmeticGeometricMean(1, complementaryModulus)
    End Function

    ''' <summary>
    ''' Carlson's symmetric integral R_F(x, y, z) = ½ ∫₀^∞ dt / √((t + x)(t + y)(t + z)) for x, y, z ≥ 0,
    ''' at most one of them zero, by the duplication theorem: each step moves x, y, z a quarter of the
    ''' way to each other, so their spread shrinks fourfold, and once it is below 8e-4 of their mean the
    ''' fifth-order series in the spread is exact to rounding (its first neglected term is ~(8e-4)⁶).
    ''' +∞ when two arguments are zero.
    ''' </summary>
    Public Function CarlsonRF(x As Double, y As Double, z As Double) As Double
        Dim zeros = If(x = 0, 1, 0) + If(y = 0, 1, 0) + If(z = 0, 1, 0)
        If zeros >= 2 Then Return Double.PositiveInfinity
        Dim mean = (x + y + z) / 3
        Dim dx = 0.0, dy = 0.0, dz = 0.0
        For iteration = 1 To 200
            mean = (x + y + z) / 3
            dx = (mean - x) / mean
            dy = (mean - y) / mean
            dz = (mean - z) / mean
            If Math.Max(Math.Abs(dx), Math.Max(Math.Abs(dy), Math.Abs(dz))) <= 0.0008 Then Exit For
            Dim sx = Math.Sqrt(x), sy = Math.Sqrt(y), sz = Math.Sqrt(z)
            Dim lambda = sx * (sy + sz) + sy * sz
            x = 0.25 * (x + lambda)
            y = 0.25 * (y + lambda)
            z = 0.25 * (z + lambda)
        Next
        Dim e2 = dx * dy - dz * dz
        Dim e3 = dx * dy * dz
        Return (1 + (e2 / 24 - 0.1 - 3.0 / 44 * e3) * e2 + e3 / 14) / Math.Sqrt(mean)
    End Function

    ''' <summary>
    ''' F(φ, k) for −π &lt; φ ≤ π given by sin φ and cos φ (which must satisfy sin² + cos² = 1):
    ''' for cos φ ≥ 0, F = sin φ · R_F(cos² φ, cos² φ + k′² sin² φ, 1), where cos² φ + k′² sin² φ is
    ''' 1 − k² sin² φ written without cancellation; beyond ±π/2 it uses F(π − φ) = 2K − F(φ).
    ''' Passing the sine and cosine instead of φ keeps full accuracy next to φ = ±π/2, where an angle
    ''' would already have lost it. The result lies in (−2K, 2K].
    ''' </summary>
    Public Function IncompleteFirstKind(sinAmplitude As Double, cosAmplitude As Double, complementaryModulus As Double) As Double
        If cosAmplitude >= 0 Then Return PrincipalPart(sinAmplitude, cosAmplitude, complementaryModulus)
        Dim twiceK = 2 * CompleteFirstKind(complementaryModulus)
        Dim mirrored = PrincipalPart(sinAmplitude, -cosAmplitude, complementaryModulus)
        Return If(sinAmplitude < 0, -twiceK - mirrored, twiceK - mirrored)
    End Function

    ''' <summary>
    ''' F(φ, k) for any real φ (rad): F(φ + nπ) = F(φ) + 2nK, so φ is brought into [−π/2, π/2] first.
    ''' </summary>
    Public Function IncompleteFirstKind(amplitude As Double, complementaryModulus As Double) As Double
        Dim turns = Math.Round(amplitude / Math.PI)
        Dim reduced = amplitude - turns * Math.PI
        Dim principal = PrincipalPart(Math.Sin(reduced), Math.Cos(reduced), complementaryModulus)
        If turns = 0 Then Return principal
        Return 2 * turns * CompleteFirstKind(complementaryModulus) + principal
    End Function

    ''' <summary>F for |φ| ≤ π/2 (cos φ ≥ 0).</summary>
    Private Function PrincipalPart(s As Double, c As Double, kc As Double) As Double
        If s = 0 Then Return 0
        Dim c2 = c * c
        Dim rf = CarlsonRF(c2, c2 + kc * kc * s * s, 1)
        If Double.IsPositiveInfinity(rf) Then Return If(s > 0, Double.PositiveInfinity, Double.NegativeInfinity)
        Return s * rf
    End Function
End Module
