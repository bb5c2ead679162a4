Option Strict On

''' <summary>
''' A point on a taut link of length L to a fixed anchor, under gravity g, in closed form. θ is the
''' angle from the downward vertical, anticlockwise positive, so the point is at
''' anchor + L (sin θ, −cos θ). Energy gives θ'² = θ'₀² + 2ω₀²(cos θ − cos θ₀) with ω₀ = √(g/L), that is
''' θ'² = 4ω₀²(k² − sin²(θ/2)) with k² = sin²(θ₀/2) + (θ'₀/2ω₀)².
''' <list type="bullet">
''' <item>k &lt; 1, libration: sin(θ/2) = k sn(ω₀t + u₀, k), cos(θ/2) = dn, θ' = 2kω₀ cn; period 4K(k)/ω₀.</item>
''' <item>k &gt; 1, rotation: θ/2 = σ am(kω₀t + v₀, 1/k) (σ the direction), θ' = 2σkω₀ dn; one loop takes 2K(1/k)/(kω₀).</item>
''' <item>k = 1, separatrix: sin(θ/2) = tanh(ω₀t + u₀); it creeps up to the top for ever.</item>
''' <item>g = 0: uniform circular motion (the rotation formula with modulus 0).</item>
''' </list>
''' The complementary modulus, which decides everything near the top, is computed as a product
''' (cos(θ₀/2) − |θ'₀|/2ω₀)(cos(θ₀/2) + |θ'₀|/2ω₀), never as 1 − k², so a swing that nearly goes over
''' the top is as accurate as its starting data allow: a relative error ε in the energy moves the
''' period by about ε/(2k′²) of itself, which is the conditioning of the motion, not of the formula.
''' Only the tangential part of the start velocity is used; the start position is projected onto
''' the circle along the radius.
''' </summary>
Public NotInheritable Class Pendulum
    Private ReadOnly _anchor As Vector
    Private ReadOnly _length As Double
    Private ReadOnly _gravity As Double
    Private ReadOnly _regime As PendulumRegime
    Private ReadOnly _startAngle As Double
    Private ReadOnly _startRate As Double
    Private ReadOnly _startSinHalf As Double
    Private ReadOnly _startCosHalf As Double
    ' u = _rate t + _u0 is the argument of the elliptic functions; _modulus is k (libration) or 1/k (rotation).
    Private ReadOnly _modulus As Double
    Private ReadOnly _rate As Double
    Private ReadOnly _u0 As Double
    Private ReadOnly _direction As Double
    Private ReadOnly _jacobi As JacobiElliptic

    ''' <summary>
    ''' The motion that starts at <paramref name="position"/> (put on the circle along its radius)
    ''' with the tangential part of <paramref name="velocity"/>.
    ''' </summary>
    ''' <param name="anchor">the fixed end of the link, m</param>
    ''' <param name="length">L &gt; 0, m</param>
    ''' <param name="gravity">g ≥ 0, m/s², pulling towards −y</param>
    ''' <param name="position">start position, m; must differ from the anchor</param>
    ''' <param name="velocity">start velocity, m/s</param>
    Public Sub New(anchor As Vector, length As Double, gravity As Double, position As Vector, velocity As Vector)
        If Not (length > 0 AndAlso length < Double.PositiveInfinity) Then Throw New ArgumentOutOfRangeException(NameOf(length), "must be positive and finite")
        If Not (gravity >= 0 AndAlso gravity < Double.PositiveInfinity) Then Throw New ArgumentOutOfRangeException(NameOf(gravity), "must be non-negative and finite")
        Dim radial = position - anchor
        If radial.LengthSquared = 0 OrElse Not radial.IsFinite Then Throw New ArgumentException("must differ from the anchor", NameOf(position))
        If Not velocity.IsFinite Then Throw New ArgumentException("must be finite", NameOf(velocity))
        _anchor = anchor
        _length = length
        _gravity = gravity
        _startAngle = Math.Atan2(radial.X, -radial.Y)
        ' The tangent (cos θ, sin θ) is the radial unit vector turned a quarter turn anticlockwise.
        Dim tangent = radial.Normalized(Vector.Zero).Perpendicular()
        _startRate = Vector.Dot(velocity, tangent) / length
        ' sin(θ₀/2) and cos(θ₀/2) from the radial unit vector (sin θ, −cos θ) by the half-angle formulas,
        ' each where it does not cancel, so that a point exactly at the top has cos(θ₀/2) = 0 exactly.
        Dim unit = radial.Normalized(Vector.Zero)
        If unit.Y <= 0 Then
            _startCosHalf = Math.Sqrt(0.5 * (1 - unit.Y))
            _startSinHalf = unit.X / (2 * _startCosHalf)
        Else
            _startSinHalf = If(unit.X < 0, -1, 1) * Math.Sqrt(0.5 * (1 + unit.Y))
            _startCosHalf = unit.X / (2 * _startSinHalf)
        End If
        _direction = If(_startRate < 0, -1.0, 1.0)
        Dim omega0 = Math.Sqrt(gravity / length)
        Dim halfRate = 0.5 * Math.Abs(_startRate)

        If gravity = 0 OrElse omega0 = 0 Then
            If _startRate = 0 Then
                _regime = PendulumRegime.Rest
                Return
            End If
            ' Rotation with modulus 0: am(u, 0) = u, θ = θ₀ + θ'₀ t.
            _regime = PendulumRegime.Uniform
            _modulus = 0
            _rate = halfRate
            _jacobi = New JacobiElliptic(1)
            _u0 = EllipticIntegral.IncompleteFirstKind(_direction * _startSinHalf, _startCosHalf, 1)
            Return
        End If

        Dim w = halfRate / omega0
        ' k′² = cos²(θ₀/2) − w², as a product with no cancellation; its sign decides the regime.
        Dim gap = _startCosHalf - w
        If gap > 0 OrElse (gap = 0 AndAlso _startRate <> 0) Then
            Dim k = Vector.Hypot(_startSinHalf, w)
            If k = 0 Then
                _regime = PendulumRegime.Rest
                Return
            End If
            Dim kc = If(gap > 0, Math.Min(1.0, Math.Sqrt(gap * (_startCosHalf + w))), 0.0)
            _regime = If(kc > 0, PendulumRegime.Libration, PendulumRegime.Separatrix)
            _modulus = k
            _rate = omega0
            _jacobi = New JacobiElliptic(kc)
            ' am(u₀) = φ₀ with sn = sin(θ₀/2)/k and cn = θ'₀/(2kω₀).
            _u0 = EllipticIntegral.IncompleteFirstKind(_startSinHalf / k, _direction * w / k, kc)
        ElseIf gap = 0 Then
            ' At the very top with no speed: balanced there for ever.
            _regime = PendulumRegime.Rest
        Else
            Dim bigOmega = Vector.Hypot(omega0 * _startSinHalf, halfRate)
            Dim kc = Math.Min(1.0, Math.Sqrt((halfRate - omega0 * _startCosHalf) * (halfRate + omega0 * _startCosHalf)) / bigOmega)
            _regime = PendulumRegime.Rotation
            _modulus = omega0 / bigOmega
            _rate = bigOmega
            _jacobi = New JacobiElliptic(kc)
            _u0 = EllipticIntegral.IncompleteFirstKind(_direction * _startSinHalf, _startCosHalf, kc)
        End If
    End Sub

    ''' <summary>The fixed end, m.</summary>
    Public ReadOnly Property Anchor As Vector
        Get
            Return _anchor
        End Get
    End Property

    ''' <summary>L, m.</summary>
    Public ReadOnly Property Length As Double
        Get
            Return _length
        End Get
    End Property

    ''' <summary>g, m/s².</summary>
    Public ReadOnly Property Gravity As Double
        Get
            Return _gravity
        End Get
    End Property

    ''' <summary>Which of the motions this is.</summary>
    Public ReadOnly Property Regime As PendulumRegime
        Get
            Return _regime
        End Get
    End Property

    ''' <summary>θ₀ ∈ (−π, π], rad from the downward vertical, anticlockwise positive.</summary>
    Public ReadOnly Property StartAngle As Double
        Get
            Return _startAngle
        End Get
    End Property

    ''' <summary>θ'₀, rad/s (the start velocity's tangential part over L).</summary>
    Public ReadOnly Property StartAngularVelocity As Double
        Get
            Return _startRate
        End Get
    End Property

    ''' <summary>
    ''' The elliptic modulus: k = sin(θmax/2) for a libration or the separatrix (1), 1/k for a
    ''' rotation, 0 for uniform motion and rest.
    ''' </summary>
    Public ReadOnly Property Modulus As Double
        Get
            Return _modulus
        End Get
    End Property

    ''' <summary>The largest |θ| reached, rad: 2 arcsin k for a libration, π when it reaches or passes the top, |θ₀| at rest.</summary>
    Public ReadOnly Property MaxAngle As Double
        Get
            Select Case _regime
                Case PendulumRegime.Libration
                    Return 2 * Math.Atan2(_modulus, _jacobi.ComplementaryModulus)
                Case PendulumRegime.Rest
                    Return Math.Abs(_startAngle)
                Case Else
                    Return Math.PI
            End Select
        End Get
    End Property

    ''' <summary>
    ''' Seconds for one full swing (libration, 4K(k)/ω₀) or one full turn (rotation, 2K(1/k)/(kω₀);
    ''' 2π/|θ'| when g = 0); +∞ at rest and on the separatrix.
    ''' </summary>
    Public ReadOnly Property Period As Double
        Get
            Select Case _regime
                Case PendulumRegime.Libration
                    Return 4 * _jacobi.QuarterPeriod / _rate
                Case PendulumRegime.Rotation, PendulumRegime.Uniform
                    Return 2 * _jacobi.QuarterPeriod / _rate
                Case Else
                    Return Double.PositiveInfinity
            End Select
        End Get
    End Property

    ''' <summary>sin(θ/2), cos(θ/2) and θ' (rad/s) at time t (s after the start).</summary>
    Public Sub HalfAngleAt(time As Double, ByRef sinHalf As Double, ByRef cosHalf As Double, ByRef angularVelocity As Double)
        Dim sn As Double, cn As Double, dn As Double
        Select Case _regime
            Case PendulumRegime.Rest
                sinHalf = _startSinHalf
                cosHalf = _startCosHalf
                angularVelocity = 0
            Case PendulumRegime.Libration, PendulumRegime.Separatrix
                _jacobi.Evaluate(_rate * time + _u0, sn, cn, dn)
                sinHalf = _modulus * sn
                cosHalf = dn
                angularVelocity = 2 * _modulus * _rate * cn
            Case Else
                _jacobi.Evaluate(_rate * time + _u0, sn, cn, dn)
                sinHalf = _direction * sn
                cosHalf = cn
                angularVelocity = 2 * _direction * _rate * dn
        End Select
    End Sub

    ''' <summary>Position (m) and velocity (m/s) at time t (s after the start).</summary>
    Public Sub StateAt(time As Double, ByRef position As Vector, ByRef velocity As Vector)
        Dim sh As Double, ch As Double, rate As Double
        HalfAngleAt(time, sh, ch, rate)
        Dim sinTheta = 2 * sh * ch
        Dim cosTheta = (ch - sh) * (ch + sh)
        position = New Vector(_anchor.X + _length * sinTheta, _anchor.Y - _length * cosTheta)
        velocity = New Vector(_length * rate * cosTheta, _length * rate * sinTheta)
    End Sub

    ''' <summary>Position at time t (s after the start), m.</summary>
    Public Function PositionAt(time As Double) As Vector
        Dim p As Vector, v As Vector
        StateAt(time, p, v)
        Return p
    End Function

    ''' <summary>Velocity at time t (s after the start), m/s.</summary>
    Public Function VelocityAt(time As Double) As Vector
        Dim p As Vector, v As Vector
        StateAt(time, p, v)
        Return v
    End Function

    ''' <summary>
    ''' θ at time t, rad. A libration stays in (−π, π); a rotation's angle keeps growing (or falling)
    ''' by 2π per turn, starting from θ₀.
    ''' </summary>
    Public Function AngleAt(time As Double) As Double
        Select Case _regime
            Case PendulumRegime.Rest
                Return _startAngle
            Case PendulumRegime.Libration, PendulumRegime.Separatrix
                Dim sh As Double, ch As Double, rate As Double
                HalfAngleAt(time, sh, ch, rate)
                Return 2 * Math.Atan2(sh, ch)
            Case Else
                Return 2 * _direction * _jacobi.Amplitude(_rate * time + _u0)
        End Select
    End Function

    ''' <summary>θ' at time t, rad/s.</summary>
    Public Function AngularVelocityAt(time As Double) As Double
        Dim sh As Double, ch As Double, rate As Double
        HalfAngleAt(time, sh, ch, rate)
        Return rate
    End Function

    ''' <summary>
    ''' The link's tension per unit mass at time t, N/kg: Newton's second law along the radius,
    ''' T − mg cos θ = m L θ'², so T/m = L θ'² + g cos θ. Negative means a string would be slack.
    ''' </summary>
    Public Function TensionPerMassAt(time As Double) As Double
        Dim sh As Double, ch As Double, rate As Double
        HalfAngleAt(time, sh, ch, rate)
        Return _length * rate * rate + _gravity * (ch - sh) * (ch + sh)
    End Function

    ''' <summary>
    ''' The first time (s, ≥ 0) at which the tension falls to zero, where a string goes slack: 0 when
    ''' it is not positive at the start (unless it is zero within rounding and rising), +∞ when it never falls to zero. With energy,
    ''' T/m = L θ'₀² − 2g cos θ₀ + 3g cos θ, so it vanishes where cos θ = c* = (2g cos θ₀ − L θ'₀²)/(3g)
    ''' (for a start at the bottom with speed u, at the height (u² + gL)/(3g) above it). That angle is
    ''' reached only if c* lies above the lowest cos θ of the motion (cos θmax, or −1 for a rotation);
    ''' a tension that only touches zero at the top is not a slack string.
    ''' </summary>
    Public Function SlackTime() As Double
        Dim cos0 = (_startCosHalf - _startSinHalf) * (_startCosHalf + _startSinHalf)
        Dim spin = _length * _startRate * _startRate ' L θ'₀², N/kg
        Dim pull = spin + _gravity * cos0
        ' d(T/m)/dt = −3g sin θ θ': the tension falls where sin θ θ' > 0 and rises where it is < 0.
        Dim sinRate = 2 * _startSinHalf * _startCosHalf * _startRate
        ' A start at zero tension, within rounding, with the tension rising (a ball leaving the top of a round support
        ' it slid on, where the string to the support's centre takes over) is not slack: the pull grows from there.
        Dim fromZero = sinRate < 0 AndAlso pull <= 0 AndAlso pull >= -PullRounding * (spin + Math.Abs(_gravity))
        If pull <= 0 AndAlso Not fromZero Then Return 0
        If _gravity = 0 OrElse _regime = PendulumRegime.Rest OrElse _regime = PendulumRegime.Uniform Then Return Double.PositiveInfinity
        Dim cosSlack = (2 * _gravity * cos0 - spin) / (3 * _gravity)
        If cosSlack <= -1 Then Return Double.PositiveInfinity
        Dim sinHalf = Math.Sqrt(0.5 * (1 - cosSlack))
        Dim u1 As Double
        If _regime = PendulumRegime.Rotation Then
            u1 = EllipticIntegral.IncompleteFirstKind(sinHalf, Math.Sqrt(0.5 * (1 + cosSlack)), _jacobi.ComplementaryModulus)
        Else
            ' sn(u) = ±sin(θ/2)/k, reachable only below the turning point.
            If sinHalf >= _modulus Then Return Double.PositiveInfinity
            Dim x = sinHalf / _modulus
            Dim cosPhi = Math.Sqrt((_modulus - sinHalf) * (_modulus + sinHalf)) / _modulus
            u1 = EllipticIntegral.IncompleteFirstKind(x, cosPhi, _jacobi.ComplementaryModulus)
        End If
        ' cos θ = c* at u = ±u₁ + 2Kn. A start within rounding of that angle counts as now if the
        ' tension is falling there (the point rising: sin θ₀ θ'₀ > 0), else as left behind.
        Dim falling = sinRate > 0
        Dim halfPeriod = 2 * _jacobi.QuarterPeriod
        Dim margin = If(falling, -1, 1) * RoundingMargin(halfPeriod)
        Dim first = FirstAfter(u1, halfPeriod, _u0 + margin), second = FirstAfter(-u1, halfPeriod, _u0 + margin)
        Dim u = Math.Min(first, second)
        ' From zero tension, rising: the crossing nearest the start may be the one it rises through, within rounding of
        ' the start; the string goes slack at the next, where the tension falls (the crossings alternate).
        If fromZero AndAlso Not FallsAt(u) Then u = Math.Max(first, second)
        Return Math.Max(0, (u - _u0) / _rate)
    End Function

    ''' <summary>The share of the tension's scale, L θ'² + g (N/kg), within which a tension counts as zero: rounding.</summary>
    Private Const PullRounding As Double = 0.000000001

    ''' <summary>Whether the tension falls at elliptic argument <paramref name="u"/> (sin θ θ' > 0 there).</summary>
    Private Function FallsAt(u As Double) As Boolean
        If Double.IsInfinity(u) Then Return True
        Dim sh As Double, ch As Double, rate As Double
        HalfAngleAt((u - _u0) / _rate, sh, ch, rate)
        Return sh * ch * rate > 0
    End Function

    ''' <summary>
    ''' The first time (s, strictly after the start) at which θ = <paramref name="angle"/> (rad, taken
    ''' modulo 2π), or +∞ if the motion never gets there (beyond a libration's amplitude, or at rest).
    ''' A start within rounding of the angle counts as having left it.
    ''' </summary>
    Public Function TimeToAngle(angle As Double) As Double
        If Double.IsNaN(angle) OrElse Double.IsInfinity(angle) Then Throw New ArgumentOutOfRangeException(NameOf(angle), "must be finite")
        If _regime = PendulumRegime.Rest Then Return Double.PositiveInfinity
        Dim reduced = angle - 2 * Math.PI * Math.Round(angle / (2 * Math.PI))
        Dim sinHalf = Math.Sin(0.5 * reduced), cosHalf = Math.Cos(0.5 * reduced)
        Dim kc = _jacobi.ComplementaryModulus
        Dim quarter = _jacobi.QuarterPeriod
        Dim u As Double
        If _regime = PendulumRegime.Libration OrElse _regime = PendulumRegime.Separatrix Then
            If Math.Abs(sinHalf) > _modulus Then Return Double.PositiveInfinity
            Dim ah = Math.Abs(sinHalf)
            Dim cosPhi = Math.Sqrt(Math.Max(0, (_modulus - ah) * (_modulus + ah))) / _modulus
            Dim u1 = EllipticIntegral.IncompleteFirstKind(sinHalf / _modulus, cosPhi, kc)
            Dim margin = RoundingMargin(4 * quarter)
            ' sn(u) = sin(θ/2)/k at u₁ and 2K − u₁, every 4K (the separatrix reaches each angle once).
            u = FirstAfter(u1, 4 * quarter, _u0 + margin)
            If quarter < Double.PositiveInfinity Then u = Math.Min(u, FirstAfter(2 * quarter - u1, 4 * quarter, _u0 + margin))
        Else
            ' am(u) = σθ/2 modulo π, every 2K.
            Dim target = _direction * 0.5 * reduced
            target -= Math.PI * Math.Round(target / Math.PI)
            Dim u1 = EllipticIntegral.IncompleteFirstKind(Math.Sin(target), Math.Cos(target), kc)
            u = FirstAfter(u1, 2 * quarter, _u0 + RoundingMargin(2 * quarter))
        End If
        Return (u - _u0) / _rate
    End Function

    ''' <summary>The first of u₁ + n P (n whole) strictly after <paramref name="after"/>; P = +∞ means u₁ alone.</summary>
    Private Shared Function FirstAfter(u1 As Double, period As Double, after As Double) As Double
        If Double.IsInfinity(period) Then Return If(u1 > after, u1, Double.PositiveInfinity)
        Dim n = Math.Floor((after - u1) / period) + 1
        Dim u = u1 + n * period
        If u <= after Then u += period
        Return u
    End Function

    ''' <summary>A few roundings of the elliptic argument around the start.</summary>
    Private Function RoundingMargin(period As Double) As Double
        Dim size = Math.Abs(_u0) + If(Double.IsInfinity(period), 1.0, period)
        Return 1.0E-14 * size
    End Function
End Class
