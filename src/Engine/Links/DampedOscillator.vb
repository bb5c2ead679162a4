Option Strict On

''' <summary>
''' The displacement e from equilibrium of a mass m on a spring of stiffness k with a dashpot c:
''' m e'' + c e' + k e = 0, that is e'' + 2γ e' + ω² e = 0 with ω = √(k/m) and γ = c/(2m). The answer
''' is linear in the start values: e(t) = P(t) e₀ + Q(t) v₀ and e'(t) = P'(t) e₀ + Q'(t) v₀, where P and
''' Q solve the equation from (1, 0) and (0, 1). They work componentwise for a vector e too. Each
''' regime has its own stable form (E = e^(−γt)):
''' <list type="bullet">
''' <item>under (γ &lt; ω, ω_d = √((ω − γ)(ω + γ))): Q = E sin(ω_d t)/ω_d, P = E cos(ω_d t) + γQ;</item>
''' <item>critical (γ = ω): Q = E t, P = E(1 + γt);</item>
''' <item>over (γ &gt; ω, β = √((γ − ω)(γ + ω))): with the slow and fast rates r₁ = −ω²/(γ + β) (no
''' cancellation) and r₂ = −(γ + β), Q = (e^(r₁t) − e^(r₂t))/(2β). Near critical damping that
''' difference cancels, so it is written e^(r₁t) t (1 − e^(−2βt))/(2βt) with an accurate e^x − 1.</item>
''' </list>
''' Always P' = −ω² Q; Q' = P − 2γQ, written per regime so it does not cancel either.
''' Nothing overflows for t ≥ 0: only decaying exponentials appear.
''' </summary>
Public NotInheritable Class DampedOscillator
    Private ReadOnly _omega As Double
    Private ReadOnly _gamma As Double
    Private ReadOnly _regime As DampingRegime
    ' ω_d (under) or β (over).
    Private ReadOnly _beta As Double
    Private ReadOnly _slow As Double
    Private ReadOnly _fast As Double

    ''' <summary>A mass (kg) on a spring (N/m) with damping (N·s/m, ≥ 0).</summary>
    Public Sub New(mass As Double, stiffness As Double, damping As Double)
        If Not (mass > 0 AndAlso mass < Double.PositiveInfinity) Then Throw New ArgumentOutOfRangeException(NameOf(mass), "must be positive and finite")
        If Not (stiffness > 0 AndAlso stiffness < Double.PositiveInfinity) Then Throw New ArgumentOutOfRangeException(NameOf(stiffness), "must be positive and finite")
        If Not (damping >= 0 AndAlso damping < Double.PositiveInfinity) Then Throw New ArgumentOutOfRangeException(NameOf(damping), "must be non-negative and finite")
        _omega = Math.Sqrt(stiffness / mass)
        _gamma = damping / (2 * mass)
        If _gamma < _omega Then
            _regime = DampingRegime.Underdamped
            _beta = Math.Sqrt((_omega - _gamma) * (_omega + _gamma))
        ElseIf _gamma = _omega Then
            _regime = DampingRegime.Critical
        Else
            _regime = DampingRegime.Overdamped
            _beta = Math.Sqrt((_gamma - _omega) * (_gamma + _omega))
            _slow = -_omega * _omega / (_gamma + _beta)
            _fast = -(_gamma + _beta)
        End If
    End Sub

    ''' <summary>ω = √(k/m), rad/s.</summary>
    Public ReadOnly Property NaturalFrequency As Double
        Get
            Return _omega
        End Get
    End Property

    ''' <summary>γ = c/(2m), 1/s: the envelope decays as e^(−γt).</summary>
    Public ReadOnly Property DecayRate As Double
        Get
            Return _gamma
        End Get
    End Property

    ''' <summary>Which regime.</summary>
    Public ReadOnly Property Regime As DampingRegime
        Get
            Return _regime
        End Get
    End Property

    ''' <summary>ω_d = √(ω² − γ²) when underdamped (rad/s), else 0.</summary>
    Public ReadOnly Property DampedFrequency As Double
        Get
            Return If(_regime = DampingRegime.Underdamped, _beta, 0.0)
        End Get
    End Property

    ''' <summary>
    ''' The fundamental solutions at time t ≥ 0 (s): e(t) = p e₀ + q v₀ and e'(t) = dp e₀ + dq v₀.
    ''' </summary>
    Public Sub Propagate(time As Double, ByRef p As Double, ByRef q As Double, ByRef dp As Double, ByRef dq As Double)
        Select Case _regime
            Case DampingRegime.Underdamped
                Dim envelope = Math.Exp(-_gamma * time)
                Dim angle = _beta * time
                Dim c = envelope * Math.Cos(angle)
                q = envelope * Math.Sin(angle) / _beta
                p = c + _gamma * q
                dq = c - _gamma * q
            Case DampingRegime.Critical
                Dim envelope = Math.Exp(-_gamma * time)
                q = envelope * time
                p = envelope + _gamma * q
                dq = envelope - _gamma * q
            Case Else
                Dim eSlow = Math.Exp(_slow * time)
                Dim eFast = Math.Exp(_fast * time)
                If _beta >= 0.5 * _gamma Then
                    ' Far from critical: the two modes separately.
                    Dim twoBeta = 2 * _beta
                    q = (eSlow - eFast) / twoBeta
                    p = (_slow * eFast - _fast * eSlow) / twoBeta
                    dq = (_slow * eSlow - _fast * eFast) / twoBeta
                Else
                    ' Near critical: E cosh βt and E sinh(βt)/β without the cancelling difference.
                    Dim coshPart = 0.5 * (eSlow + eFast)
                    q = eSlow * time * OneMinusExpOver(2 * _beta * time)
                    p = coshPart + _gamma * q
                    dq = coshPart - _gamma * q
                End If
        End Select
        dp = -_omega * _omega * q
    End Sub

    ''' <summary>e(t) from e₀ and v₀ (any units, consistent).</summary>
    Public Function Displacement(time As Double, displacement0 As Double, velocity0 As Double) As Double
        Dim p As Double, q As Double, dp As Double, dq As Double
        Propagate(time, p, q, dp, dq)
        Return p * displacement0 + q * velocity0
    End Function

    ''' <summary>e'(t) from e₀ and v₀.</summary>
    Public Function Velocity(time As Double, displacement0 As Double, velocity0 As Double) As Double
        Dim p As Double, q As Double, dp As Double, dq As Double
        Propagate(time, p, q, dp, dq)
        Return dp * displacement0 + dq * velocity0
    End Function

    ''' <summary>(1 − e^(−z))/z, 1 at z = 0, accurate for small z.</summary>
    Private Shared Function OneMinusExpOver(z As Double) As Double
        If z = 0 Then Return 1
        Return -ExpMinusOne(-z) / z
    End Function

    ''' <summary>
    ''' e^x − 1 to a few roundings even for tiny x (Kahan's trick: with u = e^x rounded, (u − 1) x / ln u
    ''' cancels the rounding of u). .NET has no Math.Expm1 on every target.
    ''' </summary>
    Friend Shared Function ExpMinusOne(x As Double) As Double
        Dim u = Math.Exp(x)
        If u = 1 Then Return x
        Dim um1 = u - 1
        If um1 = -1 Then Return -1
        Return um1 * x / Math.Log(u)
    End Function
End Class
