Option Strict On

''' <summary>
''' One body on a spring to a fixed point, in closed form: a spring of rest length 0 moves it on an ellipse
''' (or a shrinking spiral) about where it hangs (<see cref="ZeroLengthSpring"/>); a spring of positive
''' length moves a body on the vertical line through the anchor up and down about its equilibrium
''' (<see cref="VerticalSpring"/>) until it would reach the anchor's height (then <see cref="IntegratedMotion"/> goes on). Energy, ½mv² + ½k x² + mgy,
''' never grows (damping only takes it away), which bounds the speed and the stretch.
''' </summary>
Friend NotInheritable Class SpringMotion
    Inherits LinkedMotion

    Private ReadOnly _link As Link
    Private ReadOnly _zero As ZeroLengthSpring
    Private ReadOnly _vertical As VerticalSpring
    Private ReadOnly _speedBound As Double
    Private ReadOnly _accelerationBound As Double
    Private ReadOnly _end As Double = Double.PositiveInfinity

    ''' <summary>Whether <see cref="SpringMotion"/> has a closed form for this body on this spring now.</summary>
    Friend Shared Function Fits(body As Shape, link As Link, gravity As Double) As Boolean
        If link.Length = 0 Then Return New ZeroLengthSpring(link.EndB, body.Mass, link.Stiffness, link.Damping, gravity, body.CentreOfMass, body.Velocity).IsExact
        ' Clear of the anchor's height: at it (where this form hands over) the integrator goes on.
        Return body.CentreOfMass.X = link.EndB.X AndAlso body.Velocity.X = 0 AndAlso Math.Abs(body.CentreOfMass.Y - link.EndB.Y) > 0.000001 * link.Length
    End Function

    Friend Sub New(body As Shape, link As Link, startTime As Double, gravity As Double)
        MyBase.New({body}, startTime)
        _link = link
        Dim m = body.Mass, k = link.Stiffness, c = link.Damping
        Dim anchor = link.EndB
        Dim r = body.CentreOfMass - anchor
        Dim v = body.Velocity
        Dim weight = m * gravity
        If link.Length = 0 Then
            _zero = New ZeroLengthSpring(anchor, m, k, c, gravity, body.CentreOfMass, v)
            ' E = ½mv² + ½k|r|² + mg r_y; the potential is least, −(mg)²/(2k), where it hangs.
            Dim energy = 0.5 * m * v.LengthSquared + 0.5 * k * r.LengthSquared + weight * r.Y
            Dim spare = Math.Max(energy + weight * weight / (2 * k), 0)
            _speedBound = Math.Sqrt(2 * spare / m)
            Dim reach = (weight + Math.Sqrt(weight * weight + 2 * k * Math.Max(energy, -weight * weight / (2 * k)))) / k
            _accelerationBound = gravity + (k * reach + c * _speedBound) / m
        Else
            _vertical = New VerticalSpring(anchor, m, k, link.Length, c, gravity, body.CentreOfMass, v)
            ' On one side of the anchor m s'' = −k(s − s_eq) − c s': the energy above the least, at s_eq, bounds
            ' the speed (½mv²) and the distance from s_eq (½k e²).
            Dim s = r.Y
            Dim sEq = _vertical.EquilibriumHeight - anchor.Y
            Dim spare = 0.5 * m * v.Y * v.Y + 0.5 * k * (s - sEq) * (s - sEq)
            _speedBound = Math.Sqrt(2 * spare / m)
            Dim amplitude = Math.Sqrt(2 * spare / k)
            _accelerationBound = (k * amplitude + c * _speedBound) / m
            _end = startTime + _vertical.TimeToAnchor()
        End If
        _speedBound *= 1 + 0.000000001
        _accelerationBound *= 1 + 0.000000001
    End Sub

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        If _zero IsNot Nothing Then
            _zero.StateAt(time - StartTime, position, velocity)
        Else
            _vertical.StateAt(time - StartTime, position, velocity)
        End If
    End Sub

    Friend Overrides Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return _speedBound
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return _accelerationBound
    End Function

    Friend Overrides ReadOnly Property TransitionTime As Double
        Get
            Return _end
        End Get
    End Property

    ''' <summary>The body reaches the anchor's height, where the closed form ends: the integrator takes over from there.</summary>
    Friend Overrides Function Transition(world As World) As Boolean
        Return False
    End Function
End Class
