Option Strict On

''' <summary>
''' Two free bodies joined by springs to each other and to nothing else. Gravity pulls both alike and the springs'
''' pulls are equal and opposite, so the centre of mass flies its parabola in closed form, and only the separation
''' r = p_B − p_A moves under the springs: μ r'' = −Σ (k(|r| − L) + c ṙ·r̂) r̂, with μ = m_A m_B / (m_A + m_B). That
''' separation is integrated (<see cref="QuinticTrajectory"/>), and each body is the centre of mass plus its share
''' of it: p_A = P − (m_B/M) r, p_B = P + (m_A/M) r.
''' Integrating the separation rather than each body's own coordinates matters when the masses differ widely: the
''' heavy body then carries nearly all the energy, and the rounding of its position (metres) divided by a step of
''' the light body's fast oscillation would show in its velocity, and so in the energy, ½Mv², at 10⁻⁹ of the total.
''' Here the heavy body's velocity is the exact centre velocity plus only m_light/M of the separation's rate.
''' <para>
''' What is integrated is not r itself but its change since the start, δ = r − r₀, and each spring's stretch is worked
''' out from it without subtracting lengths: |r₀ + δ| − |r₀| = (2 r₀·δ + |δ|²) ÷ (|r₀ + δ| + |r₀|), plus the constant
''' |r₀| − L. A slow pair 0.17 m apart stretched by 19 µm then has its stretch to the last digit, not to 10⁻¹² of
''' 0.17 m (which is 10⁻⁸ of the stretch, and showed in its energy); and the error control asks its positions to
''' 3·10⁻¹³ of the pair's own swing (the stretch its internal energy would make, or the distance its relative speed
''' covers in a second, whichever is smaller, and never below a thousandth), not of a metre.
''' </para>
''' </summary>
Friend NotInheritable Class SpringPairMotion
    Inherits LinkedMotion

    Private Const RelativeTolerance As Double = 0.000000000003
    Private Const AbsoluteTolerance As Double = 0.0000000000003

    Private ReadOnly _links As Link()
    Private ReadOnly _gravity As Double
    ' The reduced mass μ, kg.
    Private ReadOnly _reduced As Double
    ' Each body's share of the separation: p_k = P + _share(k) r (−m_B/M for A, m_A/M for B).
    Private ReadOnly _share As Double()
    ' The centre of mass and its velocity at the start, m and m/s.
    Private ReadOnly _centre As Vector
    Private ReadOnly _centreVelocity As Vector
    ' The separation at the start r₀ (m), its length |r₀|, and each spring's |r₀| − L (m).
    Private ReadOnly _start As Vector
    Private ReadOnly _startLength As Double
    Private ReadOnly _startStretch As Double()
    ' The separation's change since the start δ = r − r₀ and its rate (m, m/s), integrated.
    Private ReadOnly _path As QuinticTrajectory
    ' The stretch looked at so far: the contact searches stop at its end, so that a stiff spring's pair, made anew at
    ' each collision, is integrated only as far as the next one needs.
    Private ReadOnly _lookahead As Lookahead

    ''' <summary>Whether the group is two bodies joined only by springs between them (none to a fixed point).</summary>
    Friend Shared Function Fits(group As LinkedGroup) As Boolean
        Return group.Bodies.Count = 2 AndAlso group.Links.Count > 0 AndAlso
            group.Links.All(Function(l) l.Kind = LinkKind.Spring AndAlso Not l.IsAnchored)
    End Function

    ''' <summary>The two bodies <paramref name="a"/> and <paramref name="b"/> on <paramref name="links"/> (all between them) from their states now.</summary>
    Friend Sub New(a As Shape, b As Shape, links As List(Of Link), startTime As Double, gravity As Double)
        MyBase.New({a, b}, startTime)
        _links = links.ToArray()
        _gravity = gravity
        Dim total = a.Mass + b.Mass
        _reduced = a.Mass * b.Mass / total
        _share = {-b.Mass / total, a.Mass / total}
        _centre = (a.Mass / total) * a.CentreOfMass + (b.Mass / total) * b.CentreOfMass
        _centreVelocity = (a.Mass / total) * a.Velocity + (b.Mass / total) * b.Velocity
        Dim r = b.CentreOfMass - a.CentreOfMass, w = b.Velocity - a.Velocity
        _start = r
        _startLength = r.Length
        _startStretch = _links.Select(Function(l) _startLength - l.Length).ToArray()
        ' The fastest spring's angular frequency (rad/s), for the first step; the pair's energy in its own frame (J).
        Dim fastest = 0.0, stiffness = 0.0
        Dim energy = 0.5 * _reduced * w.LengthSquared
        For i = 0 To _links.Length - 1
            Dim l = _links(i)
            fastest = Math.Max(fastest, Math.Sqrt(l.Stiffness / _reduced))
            stiffness += l.Stiffness
            energy += 0.5 * l.Stiffness * _startStretch(i) * _startStretch(i)
        Next
        Dim firstStepSeconds = Lookahead.FirstStepSeconds(fastest)
        _lookahead = New Lookahead(startTime, firstStepSeconds)
        _path = New QuinticTrajectory("the spring integrator", AddressOf Derivative, {0, 0, w.X, w.Y}, startTime, firstStepSeconds, RelativeTolerance,
                                      AbsoluteTolerance * SwingScale(energy, stiffness), rounding:=AddressOf Rounding)
    End Sub

    ''' <summary>
    ''' The pair's own swing, as a number of metres (or metres per second) at most 1: the stretch its internal energy
    ''' <paramref name="energy"/> (J) would make on the springs (<paramref name="stiffness"/>, N/m in all), or the
    ''' relative speed it would have (distance in a second), whichever is smaller; never below 10⁻³ (a pair all but at
    ''' rest, asked for its rounding, was stepped over a million times a second).
    ''' </summary>
    Private Function SwingScale(energy As Double, stiffness As Double) As Double
        Dim stretch = If(stiffness > 0, Math.Sqrt(2 * energy / stiffness), 1.0)
        Dim speed = Math.Sqrt(2 * energy / _reduced)
        Return Math.Max(0.001, Math.Min(1.0, Math.Min(stretch, speed)))
    End Function

    ''' <summary>|r| − |r₀| for r = r₀ + δ (m), with no lengths subtracted: (2 r₀·δ + |δ|²) ÷ (|r| + |r₀|).</summary>
    Private Function StretchSinceStart(delta As Vector, dist As Double) As Double
        Dim sum = dist + _startLength
        If sum = 0 Then Return 0
        Return (2 * Vector.Dot(_start, delta) + delta.LengthSquared) / sum
    End Function

    ''' <summary>
    ''' The end of the stretch looked at so far: nothing happens there but looking further. Without it the searches
    ''' of both bodies looked a whole horizon ahead after every collision, and the separation was integrated that far
    ''' each time: a 4 kN/m spring between two 10 mg balls, one struck every microsecond by a ball it pinned, took
    ''' 28 000 steps (30 ms of CPU) per collision.
    ''' </summary>
    Friend Overrides ReadOnly Property TransitionTime As Double
        Get
            Return _lookahead.EndTimeSeconds
        End Get
    End Property

    ''' <summary>Looks twice as far from the start (<see cref="Lookahead.LookFurther"/>) and goes on as it was.</summary>
    Friend Overrides Function LookFurther(time As Double) As Boolean
        _lookahead.LookFurther(time)
        Return True
    End Function

    ''' <summary>d/dt of (δ, ṙ): ṙ, and the springs' push along r ÷ μ (m/s²).</summary>
    Private Function Derivative(y As Double()) As Double()
        Dim delta As New Vector(y(0), y(1)), w As New Vector(y(2), y(3))
        Dim r = _start + delta
        Dim d(3) As Double
        d(0) = y(2)
        d(1) = y(3)
        Dim dist = r.Length
        If dist = 0 Then Return d
        Dim grown = StretchSinceStart(delta, dist)
        Dim along = 0.0
        For i = 0 To _links.Length - 1
            Dim l = _links(i)
            ' k(d − L) + c ḋ: positive pulls the ends together.
            along += l.Stiffness * (grown + _startStretch(i)) + l.Damping * Vector.Dot(w, r) / dist
        Next
        Dim acceleration = r * (-along / (dist * _reduced))
        d(2) = acceleration.X
        d(3) = acceleration.Y
        Return d
    End Function

    ''' <summary>
    ''' How far d/dt of (δ, ṙ) may be off by rounding alone, the floor of the error control: a few units in the last place
    ''' of Σ (k (|r₀| + L + |δ| + |grown|) + c |ṙ|) ÷ μ, the sizes of the lengths the push comes from. The stretch is
    ''' worked out without subtracting lengths, but a stiff pair at rest is still not stepped to chase what is below
    ''' that: with a floor of the stretch's own size, a 3 mg body on a 95 kN/m spring to a 41 kg ball took over a
    ''' million steps a second.
    ''' </summary>
    Private Function Rounding(y As Double()) As Double()
        Dim size = 0.0
        Dim delta As New Vector(y(0), y(1))
        Dim grown = Math.Abs(StretchSinceStart(delta, (_start + delta).Length)), rate = Math.Sqrt(y(2) * y(2) + y(3) * y(3))
        For i = 0 To _links.Length - 1
            size += _links(i).Stiffness * (grown + _startLength + _links(i).Length + delta.Length) + _links(i).Damping * rate
        Next
        size *= SpringTerm.Ulps / _reduced
        Return {0, 0, size, size}
    End Function

    Friend Overrides ReadOnly Property StepsTaken As Integer
        Get
            Return _path.StepCount
        End Get
    End Property

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        Dim delta As Vector, w As Vector
        _path.StateAt(time, 0, delta, w)
        Dim r = _start + delta
        Dim tau = time - StartTime
        Dim centre = New Vector(_centre.X + _centreVelocity.X * tau, _centre.Y + (_centreVelocity.Y - 0.5 * _gravity * tau) * tau)
        Dim centreVelocity = New Vector(_centreVelocity.X, _centreVelocity.Y - _gravity * tau)
        position = centre + _share(k) * r
        velocity = centreVelocity + _share(k) * w
    End Sub

    Friend Overrides Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double
        ' The centre's speed is convex in time (largest at an end), plus the body's share of the separation's rate.
        Dim c0 = New Vector(_centreVelocity.X, _centreVelocity.Y - _gravity * (t0 - StartTime))
        Dim c1 = New Vector(_centreVelocity.X, _centreVelocity.Y - _gravity * (t1 - StartTime))
        Return (Math.Max(c0.Length, c1.Length) + Math.Abs(_share(k)) * _path.Bound(0, t0, t1, 1)) * (1 + 0.000000001)
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return (_gravity + Math.Abs(_share(k)) * _path.Bound(0, t0, t1, 2)) * (1 + 0.000000001)
    End Function
End Class
