Option Strict On

''' <summary>
''' Quadratic drag, the air resistance of a body moving fast through a fluid: F = −½ ρ C_d L |v| v, ρ the
''' fluid's (areal) density, C_d the drag coefficient and L the body's width across its motion (in this 2D
''' world the frontal "area" is a length). Falling, a body speeds up until the drag balances its weight, at
''' the terminal speed v_t = √(2 m g/(ρ C_d L)); from rest, v(t) = v_t tanh(g t/v_t). docs/forces.md, "Quadratic drag".
''' </summary>
Public Module QuadraticDrag
    ''' <summary>The drag force, N: −½ ρ C_d L |v| v.</summary>
    Public Function Force(density As Double, dragCoefficient As Double, width As Double, velocity As Vector) As Vector
        Return velocity * (-0.5 * density * dragCoefficient * width * velocity.Length)
    End Function

    ''' <summary>
    ''' L, m: the outline's extent perpendicular to <paramref name="velocity"/>, the width the fluid meets (a
    ''' circle's diameter whatever the direction; a box's width when it falls, its height when it slides
    ''' sideways, in between when it moves obliquely). 0 when the velocity is zero (there is no drag then).
    ''' </summary>
    Public Function Width(outline As Outline, velocity As Vector) As Double
        If outline Is Nothing Then Throw New ArgumentNullException(NameOf(outline))
        Dim speed = velocity.Length
        If speed = 0 Then Return 0
        Dim across = New Vector(-velocity.Y / speed, velocity.X / speed)
        Dim lo = Double.PositiveInfinity, hi = Double.NegativeInfinity
        For Each c In outline.Vertices
            Dim d = Vector.Dot(c, across)
            lo = Math.Min(lo, d)
            hi = Math.Max(hi, d)
        Next
        Return hi - lo + 2 * outline.Radius
    End Function

    ''' <summary>v_t = √(2 m g/(ρ C_d L)), m/s: the falling speed at which drag balances the weight.</summary>
    Public Function TerminalSpeed(mass As Double, gravity As Double, density As Double, dragCoefficient As Double, width As Double) As Double
        Return Math.Sqrt(2 * mass * gravity / (density * dragCoefficient * width))
    End Function

    ''' <summary>
    ''' The speed (m/s) t seconds after a vertical fall from rest: m dv/dt = m g − k v² with k = ½ ρ C_d L
    ''' separates to dv/(v_t² − v²) = (g/v_t²) dt, whose integral is artanh(v/v_t)/v_t, so v = v_t tanh(g t/v_t).
    ''' </summary>
    Public Function FallSpeed(terminalSpeed As Double, gravity As Double, t As Double) As Double
        Return terminalSpeed * Math.Tanh(gravity * t / terminalSpeed)
    End Function

    ''' <summary>The distance (m) fallen from rest by time t: the integral of v_t tanh(g t/v_t), (v_t²/g) ln cosh(g t/v_t).</summary>
    Public Function FallDistance(terminalSpeed As Double, gravity As Double, t As Double) As Double
        Dim x = Math.Abs(gravity * t / terminalSpeed)
        Dim logCosh As Double
        If x < 1 Then
            ' cosh x − 1 = 2 sinh²(x/2), and ln(1 + y) without cancellation: small falls keep every digit.
            Dim sh = Math.Sinh(0.5 * x)
            Dim y = 2 * sh * sh
            Dim u = 1 + y
            logCosh = If(u = 1, y, Math.Log(u) * y / (u - 1))
        Else
            ' ln cosh x = x + ln(1 + e^(−2x)) − ln 2, which does not overflow for large x.
            logCosh = x + Math.Log(1 + Math.Exp(-2 * x)) - Math.Log(2)
        End If
        Return terminalSpeed * terminalSpeed / gravity * logCosh
    End Function
End Module
