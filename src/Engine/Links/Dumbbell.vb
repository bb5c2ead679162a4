Option Strict On

''' <summary>
''' Two point masses joined by a rod (or a taut string) of length L and nothing else, under gravity,
''' in closed form. Gravity pulls both equally, so the centre of mass flies on its parabola while
''' the rod turns about it at a constant rate ω: the only forces along the rod are equal and
''' opposite, so they change neither the total momentum nor the angular momentum about the centre of
''' mass, μ L² ω. The rod's tension supplies the centripetal force of each mass about the centre of
''' mass: T = μ ω² L, with μ = m₁m₂/(m₁ + m₂) the reduced mass; it never falls below zero, so a
''' string on its own never goes slack.
''' The rate ω comes from the part of the relative velocity across the rod. Its part along the rod
''' must already be removed (the impulse that makes a rod or string taut does that): it is ignored.
''' </summary>
Public NotInheritable Class Dumbbell
    Private ReadOnly _mass1 As Double
    Private ReadOnly _mass2 As Double
    Private ReadOnly _length As Double
    Private ReadOnly _gravity As Double
    Private ReadOnly _centre As Vector
    Private ReadOnly _centreVelocity As Vector
    Private ReadOnly _direction As Vector
    Private ReadOnly _omega As Double

    ''' <summary>The motion that starts from the two masses' positions (m) and velocities (m/s).</summary>
    ''' <param name="length">L &gt; 0, m: the relative position is taken along the line of the two positions at this length</param>
    ''' <param name="gravity">g ≥ 0, m/s², pulling towards −y</param>
    Public Sub New(mass1 As Double, position1 As Vector, velocity1 As Vector,
                   mass2 As Double, position2 As Vector, velocity2 As Vector,
                   length As Double, gravity As Double)
        If Not (mass1 > 0 AndAlso mass1 < Double.PositiveInfinity) Then Throw New ArgumentOutOfRangeException(NameOf(mass1), "must be positive and finite")
        If Not (mass2 > 0 AndAlso mass2 < Double.PositiveInfinity) Then Throw New ArgumentOutOfRangeException(NameOf(mass2), "must be positive and finite")
        If Not (length > 0 AndAlso length < Double.PositiveInfinity) Then Throw New ArgumentOutOfRangeException(NameOf(length), "must be positive and finite")
        If Not (gravity >= 0 AndAlso gravity < Double.PositiveInfinity) Then Throw New ArgumentOutOfRangeException(NameOf(gravity), "must be non-negative and finite")
        Dim relative = position2 - position1
        If relative.LengthSquared = 0 Then Throw New ArgumentException("the two positions must differ", NameOf(position2))
        _mass1 = mass1
        _mass2 = mass2
        _length = length
        _gravity = gravity
        Dim total = mass1 + mass2
        _centre = (mass1 / total) * position1 + (mass2 / total) * position2
        _centreVelocity = (mass1 / total) * velocity1 + (mass2 / total) * velocity2
        _direction = relative.Normalized(Vector.Zero)
        _omega = Vector.Cross(_direction, velocity2 - velocity1) / length
    End Sub

    ''' <summary>ω, rad/s, anticlockwise positive: the rate at which the line from mass 1 to mass 2 turns.</summary>
    Public ReadOnly Property AngularVelocity As Double
        Get
            Return _omega
        End Get
    End Property

    ''' <summary>μ = m₁m₂/(m₁ + m₂), kg.</summary>
    Public ReadOnly Property ReducedMass As Double
        Get
            Return _mass1 * _mass2 / (_mass1 + _mass2)
        End Get
    End Property

    ''' <summary>The rod's tension, N: μ ω² L, constant.</summary>
    Public ReadOnly Property Tension As Double
        Get
            Return ReducedMass * _omega * _omega * _length
        End Get
    End Property

    ''' <summary>Centre of mass at time t (s after the start), m: on its parabola.</summary>
    Public Function CentreOfMassAt(time As Double) As Vector
        Return New Vector(_centre.X + _centreVelocity.X * time,
                          _centre.Y + (_centreVelocity.Y - 0.5 * _gravity * time) * time)
    End Function

    ''' <summary>Both masses' positions (m) and velocities (m/s) at time t (s after the start).</summary>
    Public Sub StateAt(time As Double, ByRef position1 As Vector, ByRef velocity1 As Vector,
                       ByRef position2 As Vector, ByRef velocity2 As Vector)
        Dim angle = _omega * time
        Dim c = Math.Cos(angle), s = Math.Sin(angle)
        Dim across = _direction.Perpendicular()
        ' r(t) = L(d cos ωt + d⊥ sin ωt), the vector from mass 1 to mass 2, and its rate ω L(−d sin ωt + d⊥ cos ωt).
        Dim r = _length * (c * _direction + s * across)
        Dim rRate = (_omega * _length) * (c * across - s * _direction)
        Dim total = _mass1 + _mass2
        Dim centre = CentreOfMassAt(time)
        Dim centreVelocity = New Vector(_centreVelocity.X, _centreVelocity.Y - _gravity * time)
        position1 = centre - (_mass2 / total) * r
        position2 = centre + (_mass1 / total) * r
        velocity1 = centreVelocity - (_mass2 / total) * rRate
        velocity2 = centreVelocity + (_mass1 / total) * rRate
    End Sub
End Class
