Option Strict On
Imports Xunit

''' <summary>
''' The linear-drag closed forms (LinearDrag) against an independent solution of m dv/dt = m g − b v (classical
''' Runge–Kutta with small steps), the energy the drag removes against the energy balance, and the bounds that
''' conservative advancement relies on against the motion sampled densely.
''' </summary>
Public Class LinearDragTests
    Private Const G As Double = 9.81

    ''' <summary>RK4 on (x, v) with a = (0, −g) − (b/m) v, n steps to time t.</summary>
    Private Shared Sub Integrate(m As Double, b As Double, x0 As Vector, v0 As Vector, t As Double, n As Integer, ByRef x As Vector, ByRef v As Vector)
        Dim h = t / n
        x = x0 : v = v0
        Dim acc = Function(u As Vector) New Vector(0, -G) - u * (b / m)
        For k = 1 To n
            Dim k1v = acc(v), k1x = v
            Dim k2v = acc(v + k1v * (h / 2)), k2x = v + k1v * (h / 2)
            Dim k3v = acc(v + k2v * (h / 2)), k3x = v + k2v * (h / 2)
            Dim k4v = acc(v + k3v * h), k4x = v + k3v * h
            x += (k1x + 2 * k2x + 2 * k3x + k4x) * (h / 6)
            v += (k1v + 2 * k2v + 2 * k3v + k4v) * (h / 6)
        Next
    End Sub

    <Theory>
    <InlineData(0.5, 0.2, 12.0, 9.0, 1.7)>
    <InlineData(2.0, 5.0, -3.0, 20.0, 0.9)>
    <InlineData(1.0, 0.001, 4.0, 4.0, 2.5)>
    Public Sub PositionAndVelocity_MatchTheEquationOfMotion(m As Double, b As Double, vx As Double, vy As Double, t As Double)
        Dim x0 = New Vector(1, 2), v0 = New Vector(vx, vy)
        Dim tau = LinearDrag.TimeConstant(m, b)
        Dim vt = LinearDrag.TerminalVelocity(m, b, G)
        Dim x As Vector, v As Vector
        Integrate(m, b, x0, v0, t, 20000, x, v)
        Dim cx = LinearDrag.Position(x0, v0, vt, tau, t), cv = LinearDrag.Velocity(v0, vt, tau, t)
        Assert.True((cx - x).Length < 0.000000001, $"position {cx} against {x}")
        Assert.True((cv - v).Length < 0.000000001, $"velocity {cv} against {v}")
        ' Horizontally the textbook form x(t) = x₀ + v₀ₓ τ (1 − e^(−t/τ)).
        Assert.Equal(x0.X + vx * tau * (1 - Math.Exp(-t / tau)), cx.X, 12)
    End Sub

    <Fact>
    Public Sub TerminalVelocity_BalancesTheWeight_AndIsApproached()
        Dim m = 0.3, b = 1.5
        Dim vt = LinearDrag.TerminalVelocity(m, b, G)
        Assert.Equal(m * G, -b * vt.Y, 12)
        Dim late = LinearDrag.Velocity(New Vector(5, 5), vt, LinearDrag.TimeConstant(m, b), 40 * LinearDrag.TimeConstant(m, b))
        Assert.True((late - vt).Length < 0.000000000001 * 10)
    End Sub

    <Fact>
    Public Sub PositionAtSmallTimes_KeepsEveryDigit()
        ' Over 1 ns the body moves v₀ t + ½ a t²; 1 − e^(−t/τ) computed naively would lose half the digits.
        Dim m = 1.0, b = 0.5, v0 = New Vector(3, 4)
        Dim vt = LinearDrag.TerminalVelocity(m, b, G), tau = LinearDrag.TimeConstant(m, b)
        Dim t = 0.000000001
        Dim a0 = New Vector(0, -G) - v0 * (b / m)
        Dim expected = v0 * t + a0 * (0.5 * t * t)
        Dim moved = LinearDrag.Position(Vector.Zero, v0, vt, tau, t)
        Assert.True((moved - expected).Length <= 0.000000000000001 * expected.Length, $"{moved} against {expected}")
        Assert.True(Math.Abs(LinearDrag.ExpMinusOne(0.000000000001) / 0.000000000001 - 1 - 0.0000000000005) < 0.000000000000001)
        Assert.Equal(Math.Exp(0.5) - 1, LinearDrag.ExpMinusOne(0.5), 15)
    End Sub

    <Theory>
    <InlineData(0.5, 0.2, 12.0, 9.0, 1.7)>
    <InlineData(2.0, 5.0, -3.0, 20.0, 0.9)>
    Public Sub Dissipated_IsTheEnergyTheMotionLoses(m As Double, b As Double, vx As Double, vy As Double, t As Double)
        Dim x0 = New Vector(0, 10), v0 = New Vector(vx, vy)
        Dim tau = LinearDrag.TimeConstant(m, b), vt = LinearDrag.TerminalVelocity(m, b, G)
        Dim energy = Function(p As Vector, u As Vector) 0.5 * m * u.LengthSquared + m * G * p.Y
        Dim x = LinearDrag.Position(x0, v0, vt, tau, t), v = LinearDrag.Velocity(v0, vt, tau, t)
        Dim lost = energy(x0, v0) - energy(x, v)
        Dim w = LinearDrag.Dissipated(b, v0, vt, tau, t)
        Assert.True(Math.Abs(w - lost) < 0.0000000001 * energy(x0, v0), $"{w} J against {lost} J")
        ' And never decreasing along the way.
        Dim previous = 0.0
        For k = 1 To 100
            Dim now = LinearDrag.Dissipated(b, v0, vt, tau, t * k / 100)
            Assert.True(now >= previous)
            previous = now
        Next
    End Sub

    <Fact>
    Public Sub Bounds_HoldEverywhereOnTheInterval()
        Dim m = 0.8, b = 0.6
        Dim tau = LinearDrag.TimeConstant(m, b), vt = LinearDrag.TerminalVelocity(m, b, G)
        For Each v0 In {New Vector(10, 15), New Vector(-2, -30), New Vector(0, 0), New Vector(3, -13.08)}
            Dim t0 = 0.3, t1 = 2.1
            Dim speed = LinearDrag.SpeedBound(v0, vt, tau, t0, t1)
            Dim accel = LinearDrag.AccelerationBound(v0, vt, tau, t0)
            For k = 0 To 1000
                Dim t = t0 + (t1 - t0) * k / 1000
                Dim v = LinearDrag.Velocity(v0, vt, tau, t)
                Dim a = New Vector(0, -G) - v * (b / m)
                Assert.True(v.Length <= speed * (1 + 0.000000000001), $"speed {v.Length} above {speed}")
                Assert.True(a.Length <= accel * (1 + 0.000000000001), $"acceleration {a.Length} above {accel}")
            Next
        Next
    End Sub
End Class
