Option Strict On

''' <summary>
''' Two bodies joined by a rod (or a taut string) and nothing else: the centre of mass flies its parabola and
''' the bar turns at a constant rate (<see cref="Dumbbell"/>). A taut string between two free bodies stays
''' taut: its tension, μω²L, is never negative.
''' </summary>
Friend NotInheritable Class DumbbellMotion
    Inherits LinkedMotion

    Private ReadOnly _link As Link
    Private ReadOnly _dumbbell As Dumbbell
    Private ReadOnly _gravity As Double
    Private ReadOnly _centreVelocity As Vector
    Private ReadOnly _arm As Double()

    Friend Sub New(a As Shape, b As Shape, link As Link, startTime As Double, gravity As Double)
        MyBase.New({a, b}, startTime)
        _link = link
        _gravity = gravity
        _dumbbell = New Dumbbell(a.Mass, a.CentreOfMass, a.Velocity, b.Mass, b.CentreOfMass, b.Velocity, link.Length, gravity)
        Dim total = a.Mass + b.Mass
        _centreVelocity = (a.Mass / total) * a.Velocity + (b.Mass / total) * b.Velocity
        ' Each end turns about the centre of mass on a circle of radius L m_other / (m₁ + m₂).
        _arm = {link.Length * b.Mass / total, link.Length * a.Mass / total}
    End Sub

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        Dim p1 As Vector, v1 As Vector, p2 As Vector, v2 As Vector
        _dumbbell.StateAt(time - StartTime, p1, v1, p2, v2)
        position = If(k = 0, p1, p2)
        velocity = If(k = 0, v1, v2)
    End Sub

    Friend Overrides Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double
        ' The centre's speed is convex in time (largest at an end), plus the turning speed ω × arm.
        Dim c0 = New Vector(_centreVelocity.X, _centreVelocity.Y - _gravity * (t0 - StartTime))
        Dim c1 = New Vector(_centreVelocity.X, _centreVelocity.Y - _gravity * (t1 - StartTime))
        Return (Math.Max(c0.Length, c1.Length) + Math.Abs(_dumbbell.AngularVelocity) * _arm(k)) * (1 + 0.000000001)
    End Function

    ''' <summary>The centre of mass falls with the frame (when the gravities agree); in it each end only turns about the centre.</summary>
    Friend Overrides Function FallingBounds(k As Integer, t0 As Double, t1 As Double, gravity As Double,
                                            ByRef frame As Vector, ByRef speed As Double, ByRef acceleration As Double) As Boolean
        If gravity <> _gravity Then Return False
        frame = New Vector(_centreVelocity.X, _centreVelocity.Y - _gravity * (t0 - StartTime))
        Dim omega = Math.Abs(_dumbbell.AngularVelocity)
        ' The ends' velocities are worked out apart from the centre's: a rounding of the frame's speed is allowed for.
        speed = omega * _arm(k) * (1 + 0.000000001) + 0.000000000001 * frame.Length
        acceleration = omega * omega * _arm(k) * (1 + 0.000000001)
        Return True
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        Dim omega = _dumbbell.AngularVelocity
        Return (_gravity + omega * omega * _arm(k)) * (1 + 0.000000001)
    End Function

    Friend Overrides ReadOnly Property HeldLinks As Link()
        Get
            Return {_link}
        End Get
    End Property

    Friend Overrides Sub UpdateTensions(time As Double)
        _link.SetTension(_dumbbell.Tension)
    End Sub
End Class
