Option Strict On
Imports Xunit

''' <summary>Quadratic drag: the width across the motion, the force's size and direction, and the tanh fall against the equation of motion.</summary>
Public Class QuadraticDragTests
    <Fact>
    Public Sub Width_IsTheExtentAcrossTheMotion()
        Assert.Equal(0.6, QuadraticDrag.Width(Outline.Point(0.3), New Vector(1, 2)), 15)
        Dim box = Outline.Box(2, 0.5)
        Assert.Equal(2.0, QuadraticDrag.Width(box, New Vector(0, -3)), 15)   ' falling: its width
        Assert.Equal(0.5, QuadraticDrag.Width(box, New Vector(4, 0)), 15)    ' sliding: its height
        Dim square = Outline.Box(1, 1)
        Assert.Equal(Math.Sqrt(2), QuadraticDrag.Width(square, New Vector(1, 1)), 14) ' corner first: the diagonal
        Assert.Equal(0.0, QuadraticDrag.Width(square, Vector.Zero))
        Dim triangle = Outline.Polygon({New Vector(0, 0), New Vector(3, 0), New Vector(0, 1)})
        Assert.Equal(3.0, QuadraticDrag.Width(triangle, New Vector(0, 5)), 15)
        Assert.Equal(1.0, QuadraticDrag.Width(triangle, New Vector(-5, 0)), 15)
    End Sub

    <Fact>
    Public Sub Force_OpposesTheMotion_WithSizeHalfRhoCdLvSquared()
        Dim v = New Vector(3, -4)
        Dim f = QuadraticDrag.Force(1.2, 0.5, 0.4, v)
        Assert.Equal(0.5 * 1.2 * 0.5 * 0.4 * 25, f.Length, 12)
        Assert.Equal(-1.0, Vector.Dot(f, v) / (f.Length * v.Length), 14)
    End Sub

    <Fact>
    Public Sub TanhFall_SolvesTheEquationOfMotion()
        Dim m = 0.2, g = 9.81, rho = 1.2, cd = 0.8, L = 0.3
        Dim vt = QuadraticDrag.TerminalSpeed(m, g, rho, cd, L)
        ' At v_t the drag balances the weight.
        Assert.Equal(m * g, QuadraticDrag.Force(rho, cd, L, New Vector(0, -vt)).Y, 12)
        ' RK4 on the fall from rest, independently.
        Dim v = 0.0, y = 0.0, h = 0.00001
        Dim acc = Function(u As Double) g - 0.5 * rho * cd * L * u * u / m
        For k = 1 To 200000 ' 2 s
            Dim k1 = acc(v), k2 = acc(v + k1 * h / 2), k3 = acc(v + k2 * h / 2), k4 = acc(v + k3 * h)
            y += h * (v + (h / 6) * (k1 + k2 + k3))
            v += (h / 6) * (k1 + 2 * k2 + 2 * k3 + k4)
        Next
        Assert.Equal(v, QuadraticDrag.FallSpeed(vt, g, 2.0), 10)
        Assert.Equal(y, QuadraticDrag.FallDistance(vt, g, 2.0), 9)
        ' Small times: ½ g t² to every digit.
        Dim early = QuadraticDrag.FallDistance(vt, g, 0.000001)
        Assert.True(Math.Abs(early / (0.5 * g * 0.000001 * 0.000001) - 1) < 0.0000000001, $"{early} m") ' ½ g t² (1 − (g t/v_t)²/6 …): the correction is 1e-12
    End Sub
End Class
