Option Strict On

''' <summary>
''' One body on a rod or taut string to a fixed point: the pendulum in Jacobi elliptic functions
''' (<see cref="Pendulum"/>). A string goes slack where its tension falls to zero (<see cref="Pendulum.SlackTime"/>).
''' </summary>
Friend NotInheritable Class PendulumMotion
    Inherits LinkedMotion

    Private ReadOnly _link As Link
    Private ReadOnly _pendulum As Pendulum
    Private ReadOnly _slack As Double
    Private ReadOnly _speedBound As Double
    Private ReadOnly _gravity As Double

    Friend Sub New(body As Shape, link As Link, startTime As Double, gravity As Double)
        MyBase.New({body}, startTime)
        _link = link
        _gravity = gravity
        Dim anchor = link.EndB
        _pendulum = New Pendulum(anchor, link.Length, gravity, body.CentreOfMass, body.Velocity)
        If link.Kind = LinkKind.String Then
            Dim slackAfter = _pendulum.SlackTime()
            ' Released at full length with no pull yet (from the horizontal, at rest), the tension grows
            ' from zero; a swing that never rises above the anchor only touches zero at its turning points.
            If slackAfter = 0 AndAlso _pendulum.Regime = PendulumRegime.Libration AndAlso _pendulum.MaxAngle <= Math.PI / 2 * (1 + 0.000000001) Then slackAfter = Double.PositiveInfinity
            _slack = startTime + slackAfter
        Else
            _slack = Double.PositiveInfinity
        End If
        ' Energy: v² = v₀² + 2g(y₀ − y), largest at the lowest point, y = anchor − L.
        Dim v0 = _pendulum.VelocityAt(0)
        Dim drop = _pendulum.PositionAt(0).Y - (anchor.Y - link.Length)
        _speedBound = Math.Sqrt(v0.LengthSquared + 2 * gravity * Math.Max(drop, 0)) * (1 + 0.000000001)
    End Sub

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        _pendulum.StateAt(time - StartTime, position, velocity)
    End Sub

    Friend Overrides Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return _speedBound
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        ' Along the path at most g; towards the anchor v²/L.
        Return _gravity + _speedBound * _speedBound / _link.Length
    End Function

    Friend Overrides ReadOnly Property TransitionTime As Double
        Get
            Return _slack
        End Get
    End Property

    ''' <summary>The string's tension has fallen to zero: it goes slack.</summary>
    Friend Overrides Function Transition(world As World) As Boolean
        _released = _link
        Return True
    End Function

    Private _released As Link

    ''' <summary>After the transition: the string, gone slack.</summary>
    Friend Overrides ReadOnly Property Released As Object
        Get
            Return _released
        End Get
    End Property

    Friend Overrides ReadOnly Property HeldLinks As Link()
        Get
            Return {_link}
        End Get
    End Property

    Friend Overrides Sub UpdateTensions(time As Double)
        _link.SetTension(Bodies(0).Mass * _pendulum.TensionPerMassAt(time - StartTime))
    End Sub
End Class
