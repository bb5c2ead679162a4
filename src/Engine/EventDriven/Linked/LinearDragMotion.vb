Option Strict On

''' <summary>
''' One free body under gravity and linear drag −b v alone (no quadratic drag, no liquid anywhere), in closed
''' form (<see cref="LinearDrag"/>): an exponential approach to the terminal velocity v_t = (0, −m g/b) with time
''' constant τ = m/b. Its velocity runs along a straight line from v₀ towards v_t, so the speed over any interval is
''' largest at one of its ends and the acceleration, (v_t − v) /τ, shrinks: exact bounds for conservative
''' advancement. The energy the drag removes has a closed form too (<see cref="Dissipated"/>).
''' </summary>
Friend NotInheritable Class LinearDragMotion
    Inherits LinkedMotion
    Implements IDissipatingMotion

    Private ReadOnly _p0 As Vector
    Private ReadOnly _v0 As Vector
    Private ReadOnly _terminal As Vector
    Private ReadOnly _tau As Double
    Private ReadOnly _drag As Double

    ''' <summary>The body's motion from its state now; its <see cref="Shape.LinearDrag"/> must be &gt; 0.</summary>
    Friend Sub New(body As Shape, startTime As Double, gravity As Double)
        MyBase.New({body}, startTime)
        _p0 = body.CentreOfMass
        _v0 = body.Velocity
        _drag = body.LinearDrag
        _tau = LinearDrag.TimeConstant(body.Mass, _drag)
        _terminal = LinearDrag.TerminalVelocity(body.Mass, _drag, gravity)
    End Sub

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        Dim t = time - StartTime
        position = LinearDrag.Position(_p0, _v0, _terminal, _tau, t)
        velocity = LinearDrag.Velocity(_v0, _terminal, _tau, t)
    End Sub

    Friend Overrides Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return LinearDrag.SpeedBound(_v0, _terminal, _tau, Math.Max(t0 - StartTime, 0), Math.Max(t1 - StartTime, 0)) * (1 + 0.000000000001)
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return LinearDrag.AccelerationBound(_v0, _terminal, _tau, Math.Max(t0 - StartTime, 0)) * (1 + 0.000000000001)
    End Function

    ''' <summary>The energy the drag has removed since the start, J (<see cref="LinearDrag.Dissipated"/>).</summary>
    Friend Function Dissipated(time As Double) As Double Implements IDissipatingMotion.Dissipated
        Return LinearDrag.Dissipated(_drag, _v0, _terminal, _tau, time - StartTime)
    End Function
End Class
