Option Strict On

''' <summary>
''' A frictionless ball sliding over a corner (or over the top of a fixed circle) without leaving it:
''' its centre moves on a circle of radius R about the corner. With θ measured from the upward
''' vertical, energy gives v² = v0² + 2gR(cos θ0 − cos θ), and the normal force vanishes when gravity's
''' radial part can no longer supply the centripetal force, g cos θ = v²/R, that is at
''' cos θ* = (v0² + 2gR cos θ0) / (3gR). The time to get there is ∫ R dθ / v(θ), done by quadrature.
''' </summary>
Public Module CornerSlide
    ' 5-point Gauss–Legendre nodes and weights on [−1, 1].
    Private ReadOnly Nodes As Double() = {-0.906179845938664, -0.5384693101056831, 0.0, 0.5384693101056831, 0.906179845938664}
    Private ReadOnly Weights As Double() = {0.23692688505618908, 0.47862867049936647, 0.5688888888888889, 0.47862867049936647, 0.23692688505618908}
    Private Const Panels As Integer = 32

    ''' <summary>The angle θ* (rad, from the upward vertical) at which the ball leaves the surface.</summary>
    ''' <param name="speed">tangential speed at θ0, m/s</param>
    ''' <param name="gravity">g, m/s²</param>
    ''' <param name="radius">R, m: the radius of the circle the centre moves on</param>
    ''' <param name="startAngle">θ0, rad</param>
    Public Function LeaveAngle(speed As Double, gravity As Double, radius As Double, startAngle As Double) As Double
        Dim cosLeave = (speed * speed + 2 * gravity * radius * Math.Cos(startAngle)) / (3 * gravity * radius)
        If cosLeave >= Math.Cos(startAngle) Then Return startAngle
        Return Math.Acos(Math.Max(-1.0, cosLeave))
    End Function

    ''' <summary>Speed (m/s) at angle θ after starting at θ0 with speed v0, by energy conservation.</summary>
    Public Function SpeedAt(speed As Double, gravity As Double, radius As Double, startAngle As Double, angle As Double) As Double
        ' cos θ0 − cos θ = 2 sin((θ + θ0)/2) sin((θ − θ0)/2): no cancellation for θ near θ0.
        Dim drop = 2 * Math.Sin(0.5 * (angle + startAngle)) * Math.Sin(0.5 * (angle - startAngle))
        Return Math.Sqrt(Math.Max(0.0, speed * speed + 2 * gravity * radius * drop))
    End Function

    ''' <summary>
    ''' Time (s) to slide from θ0 to θ. With θ = θ0 + s² the integrand 2sR / v stays finite even when
    ''' the ball starts from rest (v ∝ s near the start), so plain Gauss–Legendre panels converge.
    ''' Starting from rest exactly at the top (v0 = 0, θ0 = 0) the ball never moves: +∞.
    ''' </summary>
    Public Function Duration(speed As Double, gravity As Double, radius As Double, startAngle As Double, angle As Double) As Double
        If angle <= startAngle Then Return 0
        If speed = 0 AndAlso startAngle = 0 Then Return Double.PositiveInfinity
        Dim sEnd = Math.Sqrt(angle - startAngle)
        Dim h = sEnd / Panels
        Dim sum = 0.0
        For p = 0 To Panels - 1
            Dim mid = (p + 0.5) * h
            For k = 0 To Nodes.Length - 1
                Dim s = mid + 0.5 * h * Nodes(k)
                Dim v = SpeedAt(speed, gravity, radius, startAngle, startAngle + s * s)
                If v > 0 Then sum += Weights(k) * 0.5 * h * 2 * s * radius / v
            Next
        Next
        Return sum
    End Function

    ''' <summary>
    ''' The angle reached after sliding for <paramref name="time"/> seconds: the root of
    ''' Duration(θ) = time, by Newton's method (dDuration/dθ = R / v(θ)) kept inside a bracket that
    ''' bisection shrinks whenever a Newton step would leave it or the speed there is zero.
    ''' </summary>
    Public Function AngleAfter(speed As Double, gravity As Double, radius As Double, startAngle As Double,
                               leaveAngle As Double, time As Double) As Double
        Dim lo = startAngle, hi = leaveAngle
        Dim theta = 0.5 * (lo + hi)
        For iteration = 1 To 100
            Dim f = Duration(speed, gravity, radius, startAngle, theta) - time
            If f < 0 Then lo = theta Else hi = theta
            If f = 0 OrElse hi - lo <= 4 * Double.Epsilon Then Return theta
            Dim v = SpeedAt(speed, gravity, radius, startAngle, theta)
            Dim nextTheta = If(v > 0, theta - f * v / radius, Double.NaN)
            ' Outside the bracket (or no slope): bisect instead.
            If Not (nextTheta > lo AndAlso nextTheta < hi) Then nextTheta = 0.5 * (lo + hi)
            If nextTheta = theta Then Return theta
            If Math.Abs(nextTheta - theta) <= 1.0E-15 * Math.Max(1.0, Math.Abs(theta)) Then Return nextTheta
            theta = nextTheta
        Next
        Return theta
    End Function
End Module
