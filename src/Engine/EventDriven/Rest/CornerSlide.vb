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
    ''' <summary>Panels of the rough quadrature that brings <see cref="AngleAfter"/> near its root before the full one finishes it.</summary>
    Private Const RoughPanels As Integer = 4
    ''' <summary>
    ''' When the integrand bends (<see cref="BendOf"/>) within this many panel widths of the start,
    ''' those first panels are replaced by panels shrinking geometrically towards the start.
    ''' </summary>
    Private Const GradedWidths As Integer = 5
    ''' <summary>Each graded panel is this much narrower than the one after it (full quadrature; 1.25 keeps 10⁻¹³).</summary>
    Private Const GradedRatio As Double = 1.25
    ''' <summary>The same for the rough quadrature, which needs only 10⁻⁵.</summary>
    Private Const RoughGradedRatio As Double = 2.0
    ''' <summary>The graded panels go down to the bend's scale divided by this; one last panel reaches the start.</summary>
    Private Const GradedDepth As Double = 32
    ''' <summary>At most this many rough Newton steps (they stop sooner, see <see cref="RoughEnough"/>).</summary>
    Private Const MaxRoughSteps As Integer = 20
    ''' <summary>How close (a fraction of the time) the rough phase gets before the full quadrature takes over.</summary>
    Private Const RoughEnough As Double = 0.00001
    ''' <summary>The fraction of the time a last Newton step may leave undone.</summary>
    Private Const Undone As Double = 1.0E-17
    ''' <summary>2⁻⁵², the spacing of doubles at 1 (Double.Epsilon is the smallest denormal, not this).</summary>
    Private Const MachineEpsilon As Double = 2.2204460492503131E-16

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
        Return SpeedAfterTurning(speed, gravity, radius, startAngle, angle - startAngle)
    End Function

    ''' <summary>
    ''' Speed (m/s) after turning through φ = θ − θ0 (rad). Taking φ itself, not θ, keeps its digits when
    ''' φ is far smaller than θ0: θ0 + φ would round φ to the ulp of θ0.
    ''' </summary>
    Private Function SpeedAfterTurning(speed As Double, gravity As Double, radius As Double, startAngle As Double, turn As Double) As Double
        ' cos θ0 − cos θ = 2 sin(θ0 + φ/2) sin(φ/2): no cancellation for θ near θ0.
        Dim drop = 2 * Math.Sin(startAngle + 0.5 * turn) * Math.Sin(0.5 * turn)
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
        Return TimeToTurn(speed, gravity, radius, startAngle, angle - startAngle, Panels, GradedRatio)
    End Function

    ''' <summary>
    ''' Time (s) to turn through φ = <paramref name="turn"/> (rad, &gt; 0) from θ0, by Gauss–Legendre on
    ''' <paramref name="panelCount"/> panels in s = √φ. The nodes' speeds are taken at s² itself, never
    ''' at θ0 + s², whose rounding would cost the nodes near the start most of their digits. When the
    ''' integrand bends near the start (a slow start, or one near the top: <see cref="BendOf"/>), the
    ''' first <see cref="GradedWidths"/> panels are replaced by panels shrinking by
    ''' <paramref name="ratio"/> towards it: evenly spaced panels would miss the bend (a ball starting
    ''' at 10⁻⁵ m/s on the top of a corner took a time 1 % wrong).
    ''' </summary>
    Private Function TimeToTurn(speed As Double, gravity As Double, radius As Double, startAngle As Double, turn As Double,
                                panelCount As Integer, ratio As Double) As Double
        Dim h = Math.Sqrt(turn) / panelCount
        Dim sum = 0.0
        Dim first = 0
        Dim bend = BendOf(speed, gravity, radius, startAngle)
        If bend < GradedWidths * h Then
            first = Math.Min(GradedWidths, panelCount)
            Dim upper = first * h
            Do While upper > bend / GradedDepth
                Dim lower = upper / ratio
                sum += Panel(speed, gravity, radius, startAngle, lower, upper)
                upper = lower
            Loop
            sum += Panel(speed, gravity, radius, startAngle, 0, upper)
        End If
        For p = first To panelCount - 1
            Dim mid = (p + 0.5) * h
            For k = 0 To Nodes.Length - 1
                Dim s = mid + 0.5 * h * Nodes(k)
                Dim v = SpeedAfterTurning(speed, gravity, radius, startAngle, s * s)
                If v > 0 Then sum += Weights(k) * 0.5 * h * 2 * s * radius / v
            Next
        Next
        Return sum
    End Function

    ''' <summary>The integrand 2sR / v(s²) over one panel, s from <paramref name="lower"/> to <paramref name="upper"/>, by 5-point Gauss–Legendre.</summary>
    Private Function Panel(speed As Double, gravity As Double, radius As Double, startAngle As Double, lower As Double, upper As Double) As Double
        Dim mid = 0.5 * (lower + upper), half = 0.5 * (upper - lower)
        Dim sum = 0.0
        For k = 0 To Nodes.Length - 1
            Dim s = mid + half * Nodes(k)
            Dim v = SpeedAfterTurning(speed, gravity, radius, startAngle, s * s)
            If v > 0 Then sum += Weights(k) * half * 2 * s * radius / v
        Next
        Return sum
    End Function

    ''' <summary>
    ''' The value of s (√rad) near which the integrand 2sR / v(s²) bends, or +∞ when it does not. For
    ''' small s, v² = v0² + 2gR sin θ0 · s² + gR cos θ0 · s⁴ + …, and the integrand changes shape where
    ''' one term takes over from another: v0² from the s² term at v0 / √(2gR sin θ0), v0² from the s⁴
    ''' term at √(v0 / √(gR cos θ0)), the s² term from the s⁴ term at √(2 tan θ0). The smallest of these
    ''' is where the panels must be fine.
    ''' </summary>
    Private Function BendOf(speed As Double, gravity As Double, radius As Double, startAngle As Double) As Double
        Dim square = 2 * gravity * radius * Math.Sin(startAngle) ' m²/s² per rad: the s² term
        Dim quartic = gravity * radius * Math.Cos(startAngle) ' the s⁴ term
        Dim bend = Double.PositiveInfinity
        If square > 0 AndAlso quartic > 0 Then bend = Math.Sqrt(square / quartic)
        If speed > 0 AndAlso square > 0 Then bend = Math.Min(bend, speed / Math.Sqrt(square))
        If speed > 0 AndAlso quartic > 0 Then bend = Math.Min(bend, Math.Sqrt(speed / Math.Sqrt(quartic)))
        Return bend
    End Function

    ''' <summary>
    ''' The angle reached after sliding for <paramref name="time"/> seconds: the root of
    ''' Duration(θ) = time, by Newton's method (dDuration/dθ = R / v(θ)). It starts from the Taylor
    ''' series of the motion and runs first on a rough quadrature (<see cref="RoughPanels"/> panels), which
    ''' brings it within <see cref="RoughEnough"/> of the time for an eighth of the work each step; then on
    ''' <see cref="Duration"/> itself, kept inside a bracket that bisection shrinks whenever a Newton step
    ''' would leave it or the speed there is zero. A step ends it when what it leaves undone, ½|D''|δ²
    ''' (D'' = −R²g sin θ / v³), is below <see cref="Undone"/> of the time: one or two full quadratures.
    ''' </summary>
    Public Function AngleAfter(speed As Double, gravity As Double, radius As Double, startAngle As Double,
                               leaveAngle As Double, time As Double) As Double
        If Not (time > 0) OrElse Not (leaveAngle > startAngle) Then Return startAngle
        If speed = 0 AndAlso startAngle = 0 Then Return startAngle ' at rest on top: it never moves
        ' θ'' = (g/R) sin θ and θ''' = (g/R) cos θ · θ', from θ' = v0/R at the start.
        Dim omega = speed / radius, alpha = gravity / radius
        Dim theta = startAngle + time * (omega + time * (0.5 * alpha * Math.Sin(startAngle) + time * alpha * Math.Cos(startAngle) * omega / 6))
        If Not (theta > startAngle AndAlso theta < leaveAngle) Then theta = 0.5 * (startAngle + leaveAngle)
        For iteration = 1 To MaxRoughSteps
            Dim f = TimeToTurn(speed, gravity, radius, startAngle, theta - startAngle, RoughPanels, RoughGradedRatio) - time
            Dim nextTheta = NewtonStep(speed, gravity, radius, startAngle, theta, f)
            If Not (nextTheta > startAngle AndAlso nextTheta < leaveAngle) Then nextTheta = 0.5 * (theta + If(f > 0, startAngle, leaveAngle))
            theta = nextTheta
            If Math.Abs(f) <= RoughEnough * time Then Exit For
        Next
        ' The bracket, and how far from the time each end is (s; +∞ at the far end until it is looked at).
        Dim lo = startAngle, hi = leaveAngle
        Dim missLo = time, missHi = Double.PositiveInfinity
        For iteration = 1 To 100
            Dim f = Duration(speed, gravity, radius, startAngle, theta) - time
            If f < 0 Then
                lo = theta
                missLo = -f
            ElseIf f > 0 Then
                hi = theta
                missHi = f
            Else
                Return theta
            End If
            Dim nextTheta = NewtonStep(speed, gravity, radius, startAngle, theta, f)
            Dim stepSize = nextTheta - theta
            If Not (nextTheta > lo AndAlso nextTheta < hi) Then
                Dim middle = 0.5 * (lo + hi)
                ' The bracket is two neighbouring doubles (the root lies between them): the nearer in time.
                If Not (middle > lo AndAlso middle < hi) Then Return If(missLo <= missHi, lo, hi)
                ' A step below rounding lands on the bracket's end: θ is the root to rounding.
                If Math.Abs(stepSize) <= 2 * MachineEpsilon * Math.Abs(theta) Then Return theta
                ' Outside the bracket (or no slope): bisect instead.
                nextTheta = middle
            Else
                ' What the step leaves: the quadratic term, and the cubic one bounded by the |δ| added to sin θ.
                Dim v = SpeedAt(speed, gravity, radius, startAngle, theta)
                If 0.5 * gravity * (Math.Abs(Math.Sin(theta)) + Math.Abs(stepSize)) * (radius * stepSize) * (radius * stepSize) <=
                   Undone * time * v * v * v Then Return nextTheta
            End If
            theta = nextTheta
        Next
        Return theta
    End Function

    ''' <summary>Newton's step for Duration(θ) − time = f: θ − f v(θ) / R; NaN where the ball is at rest (no slope).</summary>
    Private Function NewtonStep(speed As Double, gravity As Double, radius As Double, startAngle As Double, theta As Double, f As Double) As Double
        Dim v = SpeedAt(speed, gravity, radius, startAngle, theta)
        Return If(v > 0, theta - f * v / radius, Double.NaN)
    End Function
End Module
