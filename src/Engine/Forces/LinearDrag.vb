Option Strict On

''' <summary>
''' A body under gravity and linear (Stokes) drag F = −b v has m dv/dt = m g − b v, a first-order linear
''' equation with the exact solution an exponential approach to the terminal velocity:
''' <code>
'''   v(t) = v_t + (v₀ − v_t) e^(−t/τ),    x(t) = x₀ + v_t t + (v₀ − v_t) τ (1 − e^(−t/τ)),
'''   τ = m/b,  v_t = τ g = (0, −m g/b).
''' </code>
''' Horizontally (g's part 0) this is x(t) = x₀ + v₀ₓ τ (1 − e^(−t/τ)). Pure functions, with the bounds that
''' conservative advancement needs and the energy the drag removes. docs/forces.md, "Linear drag".
''' </summary>
Public Module LinearDrag
    ''' <summary>τ = m/b, s: the time in which the gap to the terminal velocity falls by a factor e.</summary>
    Public Function TimeConstant(mass As Double, drag As Double) As Double
        Return mass / drag
    End Function

    ''' <summary>v_t = τ g, m/s: where m g = b v, the weight balanced by the drag. (0, −m g/b) under gravity g (m/s²) towards −y.</summary>
    Public Function TerminalVelocity(mass As Double, drag As Double, gravity As Double) As Vector
        Return New Vector(0, -mass * gravity / drag)
    End Function

    ''' <summary>v(t), m/s, from v₀ at t = 0.</summary>
    Public Function Velocity(v0 As Vector, terminal As Vector, tau As Double, t As Double) As Vector
        Dim decay = Math.Exp(-t / tau)
        Return terminal + (v0 - terminal) * decay
    End Function

    ''' <summary>x(t), m, from x₀ and v₀ at t = 0. 1 − e^(−t/τ) is computed without cancellation for small t.</summary>
    Public Function Position(x0 As Vector, v0 As Vector, terminal As Vector, tau As Double, t As Double) As Vector
        Dim grown = -ExpMinusOne(-t / tau) ' 1 − e^(−t/τ)
        Return x0 + terminal * t + (v0 - terminal) * (tau * grown)
    End Function

    ''' <summary>
    ''' The energy the drag has removed by time t, J: ∫ b |v|² dt, with |v|² = |v_t|² + 2 v_t·w e^(−t/τ) + |w|² e^(−2t/τ),
    ''' w = v₀ − v_t, so b [ |v_t|² t + 2 v_t·w τ (1 − e^(−t/τ)) + |w|² (τ/2)(1 − e^(−2t/τ)) ]. Never negative.
    ''' </summary>
    Public Function Dissipated(drag As Double, v0 As Vector, terminal As Vector, tau As Double, t As Double) As Double
        Dim w = v0 - terminal
        Dim once = -ExpMinusOne(-t / tau), twice = -ExpMinusOne(-2 * t / tau)
        Dim work = drag * (terminal.LengthSquared * t + 2 * Vector.Dot(terminal, w) * tau * once + w.LengthSquared * 0.5 * tau * twice)
        Return Math.Max(work, 0)
    End Function

    ''' <summary>
    ''' The largest speed over [t0, t1] (s, from the start), m/s. v(t) = v_t + w s with s = e^(−t/τ) moving
    ''' monotonically, so v runs along a straight segment and |v|, convex along it, is largest at an end.
    ''' </summary>
    Public Function SpeedBound(v0 As Vector, terminal As Vector, tau As Double, t0 As Double, t1 As Double) As Double
        Return Math.Max(Velocity(v0, terminal, tau, t0).Length, Velocity(v0, terminal, tau, t1).Length)
    End Function

    ''' <summary>The largest acceleration over [t0, t1] (s, from the start), m/s²: |v₀ − v_t| e^(−t/τ)/τ, which only shrinks, so its value at t0.</summary>
    Public Function AccelerationBound(v0 As Vector, terminal As Vector, tau As Double, t0 As Double) As Double
        Return (v0 - terminal).Length * Math.Exp(-t0 / tau) / tau
    End Function

    ''' <summary>
    ''' e^x − 1 to full relative precision, also for x near 0 where Math.Exp(x) − 1 loses every digit
    ''' (netstandard2.0 has no expm1): u = e^x, then (u − 1) x / ln u, whose rounding errors cancel (Kahan).
    ''' </summary>
    Friend Function ExpMinusOne(x As Double) As Double
        Dim u = Math.Exp(x)
        If u = 1.0 Then Return x
        Dim um1 = u - 1.0
        If um1 = -1.0 Then Return -1.0
        Return um1 * x / Math.Log(u)
    End Function
End Module
