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
    ' The separation r and its rate (m, m/s), integrated.
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
        ' The fastest spring's angular frequency (rad/s), for the first step.
        Dim fastest = 0.0
        For Each l In _links
            fastest = Math.Max(fastest, Math.Sqrt(l.Stiffness / _reduced))
        Next
        Dim firstStepSeconds = Lookahead.FirstStepSeconds(fastest)
        _lookahead = New Lookahead(startTime, firstStepSeconds)
        _path = New QuinticTrajectory("the spring integrator", AddressOf Derivative, {r.X, r.Y, w.X, w.Y}, startTime, firstStepSeconds, RelativeTolerance, AbsoluteTolerance,
                                      rounding:=AddressOf Rounding)
    End Sub

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

    ''' <summary>d/dt of (r, ṙ): ṙ, and the springs' push along r ÷ μ (m/s²).</summary>
    Private Function Derivative(y As Double()) As Double()
        Dim r As New Vector(y(0), y(1)), w As New Vector(y(2), y(3))
        Dim d(3) As Double
        d(0) = y(2)
        d(1) = y(3)
        Dim dist = r.Length
        If dist = 0 Then Return d
        Dim along = 0.0
        For Each l In _links
            ' k(d − L) + c ḋ: positive pulls the ends together.
            along += l.Stiffness * (dist - l.Length) + l.Damping * Vector.Dot(w, r) / dist
        Next
        Dim acceleration = r * (-along / (dist * _reduced))
        d(2) = acceleration.X
        d(3) = acceleration.Y
        Return d
    End Function

    ''' <summary>
    ''' How far d/dt of (r, ṙ) may be off by rounding alone: a few units in the last place of Σ (k (|r| + L) + c |ṙ|)
    ''' ÷ μ, the sizes of the numbers whose difference the push is (at a stiff spring's length it is all rounding).
    ''' </summary>
    Private Function Rounding(y As Double()) As Double()
        Dim size = 0.0
        Dim dist = Math.Sqrt(y(0) * y(0) + y(1) * y(1)), rate = Math.Sqrt(y(2) * y(2) + y(3) * y(3))
        For Each l In _links
            size += l.Stiffness * (dist + l.Length) + l.Damping * rate
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
        Dim r As Vector, w As Vector
        _path.StateAt(time, 0, r, w)
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
