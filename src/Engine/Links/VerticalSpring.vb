Option Strict On

''' <summary>
''' A body on a spring of rest length ℓ &gt; 0 to a fixed anchor, moving on the vertical line through
''' the anchor, under gravity, in closed form. With s = y − y_anchor (negative below), the spring's
''' length is |s| and its pull on the body is −k(|s| − ℓ) sign(s), so on one side of the anchor
''' the force is linear in s: m s'' = −k(s − s_eq) − c s' with s_eq = ±ℓ − mg/k (+ above, − below).
''' That is the damped oscillator of <see cref="DampedOscillator"/> about s_eq, valid while the
''' body stays on its side; <see cref="TimeToAnchor"/> says when it would reach the anchor, after
''' which the caller must integrate instead. Along the line, the spring's damping is on the whole
''' velocity, so this is exact for a damped spring too.
''' Only the vertical parts are used: the body is taken to be straight above or below the anchor
''' with a vertical velocity.
''' </summary>
Public NotInheritable Class VerticalSpring
    Private ReadOnly _oscillator As DampedOscillator
    Private ReadOnly _anchor As Vector
    Private ReadOnly _equilibrium As Double
    Private ReadOnly _offset As Double
    Private ReadOnly _velocity As Double
    Private ReadOnly _side As Integer

    ''' <summary>The motion from the body's height and vertical speed.</summary>
    ''' <param name="anchor">fixed end of the spring, m</param>
    ''' <param name="mass">kg</param>
    ''' <param name="stiffness">k, N/m</param>
    ''' <param name="restLength">ℓ &gt; 0, m</param>
    ''' <param name="damping">c ≥ 0, N·s/m</param>
    ''' <param name="gravity">g ≥ 0, m/s², towards −y</param>
    ''' <param name="position">start, m (its x is ignored: the anchor's is used)</param>
    ''' <param name="velocity">start velocity, m/s (its x is ignored)</param>
    Public Sub New(anchor As Vector, mass As Double, stiffness As Double, restLength As Double, damping As Double,
                   gravity As Double, position As Vector, velocity As Vector)
        If Not (restLength > 0 AndAlso restLength < Double.PositiveInfinity) Then Throw New ArgumentOutOfRangeException(NameOf(restLength), "must be positive and finite")
        If Not (gravity >= 0 AndAlso gravity < Double.PositiveInfinity) Then Throw New ArgumentOutOfRangeException(NameOf(gravity), "must be non-negative and finite")
        _oscillator = New DampedOscillator(mass, stiffness, damping)
        _anchor = anchor
        Dim s0 = position.Y - anchor.Y
        _side = Math.Sign(s0)
        Dim sag = mass * gravity / stiffness
        _equilibrium = If(_side >= 0, restLength, -restLength) - sag
        _offset = s0 - _equilibrium
        _velocity = velocity.Y
    End Sub

    ''' <summary>The height about which it oscillates, m (the anchor's height ± ℓ − mg/k).</summary>
    Public ReadOnly Property EquilibriumHeight As Double
        Get
            Return _anchor.Y + _equilibrium
        End Get
    End Property

    ''' <summary>The underlying scalar oscillator (ω, γ, regime).</summary>
    Public ReadOnly Property Oscillator As DampedOscillator
        Get
            Return _oscillator
        End Get
    End Property

    ''' <summary>Position (m) and velocity (m/s) at time t ≥ 0 (s after the start); valid before <see cref="TimeToAnchor"/>.</summary>
    Public Sub StateAt(time As Double, ByRef position As Vector, ByRef velocity As Vector)
        Dim p As Double, q As Double, dp As Double, dq As Double
        _oscillator.Propagate(time, p, q, dp, dq)
        position = New Vector(_anchor.X, _anchor.Y + _equilibrium + p * _offset + q * _velocity)
        velocity = New Vector(0, dp * _offset + dq * _velocity)
    End Sub

    ''' <summary>Position at time t, m.</summary>
    Public Function PositionAt(time As Double) As Vector
        Dim p As Vector, v As Vector
        StateAt(time, p, v)
        Return p
    End Function

    ''' <summary>Velocity at time t, m/s.</summary>
    Public Function VelocityAt(time As Double) As Vector
        Dim p As Vector, v As Vector
        StateAt(time, p, v)
        Return v
    End Function

    ''' <summary>True when the body ever reaches the anchor (then this closed form stops being the motion there).</summary>
    Public Function ReachesAnchor() As Boolean
        Return TimeToAnchor() < Double.PositiveInfinity
    End Function

    ''' <summary>
    ''' The first time (s, ≥ 0) at which the body reaches the anchor's height, or +∞. The motion is
    ''' cut into pieces on which e = s − s_eq is monotone, at the zeros of e'(t): tan(ω_d t) =
    ''' ω_d v₀ / (ω² e₀ + γ v₀) when underdamped (only the first two matter: each later swing is
    ''' smaller than the one before on the same side), tanh(βt)/β = v₀ / (ω² e₀ + γ v₀) (at most one)
    ''' otherwise. The first piece whose ends straddle the anchor holds the crossing, found by
    ''' <see cref="ScalarRoot.Brent"/>.
    ''' </summary>
    Public Function TimeToAnchor() As Double
        If _side = 0 Then Return 0
        Dim target = -_equilibrium
        Dim gapAt As Func(Of Double, Double) = Function(t) _oscillator.Displacement(t, _offset, _velocity) - target
        Dim omega = _oscillator.NaturalFrequency, gamma = _oscillator.DecayRate
        Dim drive = omega * omega * _offset + gamma * _velocity
        ' Ends of the monotone pieces.
        Dim ends As New List(Of Double)(3) From {0.0}
        If _oscillator.Regime = DampingRegime.Underdamped Then
            Dim wd = _oscillator.DampedFrequency
            Dim phase = Math.Atan2(wd * _velocity, drive)
            If phase <= 0 Then phase += Math.PI
            ends.Add(phase / wd)
            ends.Add((phase + Math.PI) / wd)
        Else
            Dim beta = Math.Sqrt(Math.Abs(gamma * gamma - omega * omega))
            Dim ratio = If(drive <> 0, _velocity / drive, Double.PositiveInfinity)
            If ratio > 0 Then
                If _oscillator.Regime = DampingRegime.Critical OrElse beta = 0 Then
                    ends.Add(ratio)
                ElseIf beta * ratio < 1 Then
                    ends.Add(0.5 * Math.Log((1 + beta * ratio) / (1 - beta * ratio)) / beta)
                End If
            End If
        End If
        Dim lo = 0.0
        Dim gapLo = gapAt(0)
        If gapLo = 0 Then Return 0
        For i = 1 To ends.Count - 1
            Dim hi = ends(i)
            Dim gapHi = gapAt(hi)
            If gapHi = 0 OrElse (gapHi > 0) <> (gapLo > 0) Then Return ScalarRoot.Brent(gapAt, lo, hi, gapLo, gapHi)
            lo = hi
            gapLo = gapHi
        Next
        If _oscillator.Regime = DampingRegime.Underdamped Then Return Double.PositiveInfinity
        ' The last piece runs monotonically towards e = 0 (gap → −target) for ever: it crosses only if
        ' it starts on the target's far side, gap of the target's sign.
        If Not ((target > 0 AndAlso gapLo > 0) OrElse (target < 0 AndAlso gapLo < 0)) Then Return Double.PositiveInfinity
        Dim span = 1 / Math.Max(Math.Abs(_oscillator.DecayRate), omega)
        Dim far = lo + span
        Dim gapFar = gapAt(far)
        For doubling = 1 To 200
            If gapFar = 0 OrElse (gapFar > 0) <> (gapLo > 0) Then Return ScalarRoot.Brent(gapAt, lo, far, gapLo, gapFar)
            span *= 2
            far = lo + span
            gapFar = gapAt(far)
        Next
        Return Double.PositiveInfinity
    End Function
End Class
