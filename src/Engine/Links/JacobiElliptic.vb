Option Strict On

''' <summary>
''' The Jacobi elliptic functions sn, cn, dn and the amplitude am for one modulus k, given by its
''' complement k′ = √(1 − k²) (exact near k = 1, see <see cref="EllipticIntegral"/>). The descending
''' Landen transformation, the AGM ladder a₀ = 1, b₀ = k′, aₙ₊₁ = (aₙ + bₙ)/2, bₙ₊₁ = √(aₙ bₙ), turns
''' sn(u, k) into sin(AGM · u) at the top of the ladder; walking back down it (Bulirsch's form of the
''' recurrence, which carries cot and dn rather than angles, so no arcsine loses accuracy) gives
''' sn, cn and dn to a few roundings. The ladder depends only on k′, so it is built once here and
''' every evaluation afterwards allocates nothing.
''' </summary>
Public NotInheritable Class JacobiElliptic
    ''' <summary>Enough rungs for any k′ ≥ 10⁻³⁰⁸: the AGM of 1 and k′ converges in about log₂ ln(4/k′) + 3 steps.</summary>
    Private Const MaxRungs As Integer = 24

    Private ReadOnly _kc As Double
    Private ReadOnly _rungs As Integer
    Private ReadOnly _a(MaxRungs - 1) As Double
    Private ReadOnly _b(MaxRungs - 1) As Double
    Private ReadOnly _agm As Double
    Private ReadOnly _quarterPeriod As Double

    ''' <summary>The functions for the modulus whose complement is <paramref name="complementaryModulus"/> (k′ ∈ [0, 1]).</summary>
    Public Sub New(complementaryModulus As Double)
        If Not (complementaryModulus >= 0 AndAlso complementaryModulus <= 1) Then
            Throw New ArgumentOutOfRangeException(NameOf(complementaryModulus), "must lie in [0, 1]")
        End If
        _kc = complementaryModulus
        If _kc = 0 Then
            _quarterPeriod = Double.PositiveInfinity
            Return
        End If
        Dim a = 1.0, b = _kc
        Dim rungs = 0
        Dim mean = 0.5 * (a + b)
        Do
            _a(rungs) = a
            _b(rungs) = b
            rungs += 1
            mean = 0.5 * (a + b)
            ' Bulirsch's stopping rule: one more rung after this gap adds less than a rounding.
            If Math.Abs(a - b) <= 0.00000002 * a OrElse rungs = MaxRungs Then Exit Do
            b = Math.Sqrt(a) * Math.Sqrt(b)
            a = mean
        Loop
        _rungs = rungs
        _agm = mean
        _quarterPeriod = 0.5 * Math.PI / mean
    End Sub

    ''' <summary>k′ = √(1 − k²).</summary>
    Public ReadOnly Property ComplementaryModulus As Double
        Get
            Return _kc
        End Get
    End Property

    ''' <summary>K(k), the quarter period of sn and cn (+∞ for k = 1).</summary>
    Public ReadOnly Property QuarterPeriod As Double
        Get
            Return _quarterPeriod
        End Get
    End Property

    ''' <summary>
    ''' sn(u), cn(u) and dn(u). u is first brought into [−2K, 2K] (sn and cn have period 4K, dn 2K),
    ''' so a large u costs its own rounding (about 10⁻¹⁶ |u|) and nothing more. At k = 1 they are
    ''' tanh u, sech u, sech u.
    ''' </summary>
    Public Sub Evaluate(u As Double, ByRef sn As Double, ByRef cn As Double, ByRef dn As Double)
        If _kc = 0 Then
            sn = Math.Tanh(u)
            cn = 1 / Math.Cosh(u)
            dn = cn
            Return
        End If
        Dim period = 4 * _quarterPeriod
        If Math.Abs(u) > 2 * _quarterPeriod Then u -= period * Math.Round(u / period)
        ' Below 1e-150 the cotangent below would overflow when squared; sn = u − O(u³) there.
        If Math.Abs(u) < 1.0E-150 Then
            sn = u
            cn = 1
            dn = 1
            Return
        End If
        Dim top = u * _agm
        Dim s = Math.Sin(top)
        Dim c = Math.Cos(top)
        dn = 1
        If s = 0 Then
            sn = 0
            cn = c
            Return
        End If
        ' Down the ladder with r = cot at each level (Bulirsch 1965; the form of Numerical Recipes' sncndn).
        Dim ratio = c / s
        Dim carry = _agm * ratio
        For level = _rungs - 1 To 0 Step -1
            Dim an = _a(level)
            ratio *= carry
            carry *= dn
            dn = (_b(level) + ratio) / (an + ratio)
            ratio = carry / an
        Next
        Dim magnitude = 1 / Math.Sqrt(carry * carry + 1)
        sn = If(s >= 0, magnitude, -magnitude)
        cn = carry * sn
    End Sub

    ''' <summary>sn(u, k).</summary>
    Public Function Sn(u As Double) As Double
        Dim s As Double, c As Double, d As Double
        Evaluate(u, s, c, d)
        Return s
    End Function

    ''' <summary>cn(u, k).</summary>
    Public Function Cn(u As Double) As Double
        Dim s As Double, c As Double, d As Double
        Evaluate(u, s, c, d)
        Return c
    End Function

    ''' <summary>dn(u, k).</summary>
    Public Function Dn(u As Double) As Double
        Dim s As Double, c As Double, d As Double
        Evaluate(u, s, c, d)
        Return d
    End Function

    ''' <summary>
    ''' The amplitude am(u) = φ with F(φ, k) = u, unwrapped (it grows by π every 2K): u is reduced
    ''' into [−K, K], where cn ≥ 0 so atan2(sn, cn) is the right branch, and nπ added back.
    ''' </summary>
    Public Function Amplitude(u As Double) As Double
        If _kc = 0 Then Return Math.Atan2(Math.Tanh(u), 1 / Math.Cosh(u))
        Dim halfPeriod = 2 * _quarterPeriod
        Dim turns = Math.Round(u / halfPeriod)
        Dim s As Double, c As Double, d As Double
        Evaluate(u - turns * halfPeriod, s, c, d)
        Return turns * Math.PI + Math.Atan2(s, c)
    End Function
End Class
