Option Strict On
Imports PhysicsEngine

Namespace Links
    ''' <summary>
    ''' Independent references for the link maths: quadrature, a classical fixed-step Runge–Kutta
    ''' integrator, and the pendulum's equation in its angle. Nothing here uses the code under test.
    ''' </summary>
    Friend Module LinkTestKit
        ' 5-point Gauss–Legendre on [−1, 1].
        Private ReadOnly Nodes As Double() = {-0.906179845938664, -0.5384693101056831, 0.0, 0.5384693101056831, 0.906179845938664}
        Private ReadOnly Weights As Double() = {0.23692688505618908, 0.47862867049936647, 0.5688888888888889, 0.47862867049936647, 0.23692688505618908}

        ''' <summary>∫ f over [a, b] by composite 5-point Gauss–Legendre on <paramref name="panels"/> panels.</summary>
        Public Function Integrate(f As Func(Of Double, Double), a As Double, b As Double, panels As Integer) As Double
            Dim h = (b - a) / panels
            Dim sum = 0.0
            For p = 0 To panels - 1
                Dim mid = a + (p + 0.5) * h
                For k = 0 To 4
                    sum += Weights(k) * f(mid + 0.5 * h * Nodes(k))
                Next
            Next
            Return 0.5 * h * sum
        End Function

        ''' <summary>F(φ, k) by quadrature of 1/√(1 − k² sin² ϑ).</summary>
        Public Function EllipticFByQuadrature(phi As Double, k As Double) As Double
            Return Integrate(Function(t) 1 / Math.Sqrt(1 - k * k * Math.Sin(t) * Math.Sin(t)), 0, phi, 4000)
        End Function

        ''' <summary>One classical RK4 step of y' = f(y) (autonomous), in place.</summary>
        Public Sub Rk4Step(f As Action(Of Double(), Double()), y As Double(), h As Double)
            Dim n = y.Length
            Dim k1(n - 1) As Double, k2(n - 1) As Double, k3(n - 1) As Double, k4(n - 1) As Double, tmp(n - 1) As Double
            f(y, k1)
            For i = 0 To n - 1 : tmp(i) = y(i) + 0.5 * h * k1(i) : Next
            f(tmp, k2)
            For i = 0 To n - 1 : tmp(i) = y(i) + 0.5 * h * k2(i) : Next
            f(tmp, k3)
            For i = 0 To n - 1 : tmp(i) = y(i) + h * k3(i) : Next
            f(tmp, k4)
            For i = 0 To n - 1
                y(i) += h / 6 * (k1(i) + 2 * k2(i) + 2 * k3(i) + k4(i))
            Next
        End Sub

        ''' <summary>y' = f(y) from 0 to each of the (ascending) times, with steps no longer than <paramref name="maxStep"/>; the states at those times.</summary>
        Public Function Rk4At(f As Action(Of Double(), Double()), y0 As Double(), times As Double(), maxStep As Double) As Double()()
            Dim y = DirectCast(y0.Clone(), Double())
            Dim result(times.Length - 1)() As Double
            Dim t = 0.0
            For i = 0 To times.Length - 1
                Dim span = times(i) - t
                Dim steps = Math.Max(1, CInt(Math.Ceiling(span / maxStep)))
                Dim h = span / steps
                For s = 1 To steps
                    Rk4Step(f, y, h)
                Next
                t = times(i)
                result(i) = DirectCast(y.Clone(), Double())
            Next
            Return result
        End Function

        ''' <summary>θ'' = −(g/L) sin θ as a first-order system (θ, θ').</summary>
        Public Function PendulumEquation(gravity As Double, length As Double) As Action(Of Double(), Double())
            Return Sub(y, dy)
                       dy(0) = y(1)
                       dy(1) = -gravity / length * Math.Sin(y(0))
                   End Sub
        End Function

        ''' <summary>The point at angle θ from the downward vertical on a circle of radius L about the anchor.</summary>
        Public Function OnCircle(anchor As Vector, length As Double, theta As Double) As Vector
            Return New Vector(anchor.X + length * Math.Sin(theta), anchor.Y - length * Math.Cos(theta))
        End Function

        ''' <summary>Velocity of a point moving at θ' on that circle.</summary>
        Public Function AlongCircle(length As Double, theta As Double, rate As Double) As Vector
            Return New Vector(length * rate * Math.Cos(theta), length * rate * Math.Sin(theta))
        End Function

        ''' <summary>The complete elliptic integral K(k) by the arithmetic–geometric mean: π / (2 AGM(1, √(1 − k²))).</summary>
        Public Function CompleteK(k As Double) As Double
            Dim a = 1.0, b = Math.Sqrt(1 - k * k)
            For i = 1 To 30
                Dim mean = (a + b) / 2
                b = Math.Sqrt(a * b)
                a = mean
            Next
            Return Math.PI / (2 * a)
        End Function

        ''' <summary>|a − b|, m.</summary>
        Public Function Distance(a As Vector, b As Vector) As Double
            Return (a - b).Length
        End Function
    End Module
End Namespace
