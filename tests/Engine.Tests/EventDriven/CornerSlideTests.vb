Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' The time to slide round a corner (<see cref="CornerSlide.Duration"/>) against closed forms, and its
''' inverse (<see cref="CornerSlide.AngleAfter"/>) against a closed form and against plain bisection.
''' </summary>
Public Class CornerSlideTests
    Private Const G As Double = 9.81 ' m/s²

    <Theory>
    <InlineData(0.05, 0.000000001)>
    <InlineData(0.3, 0.00000001)>
    <InlineData(1.0, 0.00000001)>
    Public Sub Duration_JustAfterAStartFromRest_IsTheSeries(startAngle As Double, turn As Double)
        ' From rest, cos θ0 − cos θ = φ sin θ0 (1 + φ cot θ0 / 2 + O(φ²)) with φ = θ − θ0, so
        ' ∫ R dθ / v = √(2Rφ / (g sin θ0)) (1 − φ cot θ0 / 12 + O(φ²)): exact to 10⁻¹⁶ for φ this small.
        ' A quadrature that rounded its nodes to θ0 + s² would lose half the digits of φ.
        Const R = 0.2 ' m
        Dim angle = startAngle + turn
        Dim phi = angle - startAngle ' exactly what the rounded angle means
        Dim series = Math.Sqrt(2 * R * phi / (G * Math.Sin(startAngle))) * (1 - phi / Math.Tan(startAngle) / 12)
        Dim time = CornerSlide.Duration(0, G, R, startAngle, angle)
        Assert.True(Math.Abs(time / series - 1) <= 1.0E-13, $"{time} s against {series} s")
    End Sub

    <Theory>
    <InlineData(0.05, 0.8, 1.0E-13)>
    <InlineData(0.3, 0.6, 1.0E-13)>
    <InlineData(0.7, 0.84, 1.0E-13)>
    <InlineData(0.001, 0.8, 1.0E-12)>
    <InlineData(0.0001, 0.8, 1.0E-12)>
    <InlineData(0.000001, 0.8, 1.0E-12)>
    Public Sub Duration_OnTheSeparatrix_IsTheClosedForm(startAngle As Double, angle As Double, tolerance As Double)
        ' With the energy of rest at the top, v0² = 2gR(1 − cos θ0), the speed is v = 2√(gR) sin(θ/2) and
        ' ∫ R dθ / v = √(R/g) ln(tan(θ/4) / tan(θ0/4)). The starts nearest the top (θ0 ≤ 10⁻³) bend the
        ' integrand within the first panel of 32 (the speed grows from v0 first as s, then as s²): evenly
        ' spaced panels were 3·10⁻⁸ out at θ0 = 10⁻³ and 4 % at 10⁻⁶.
        Const R = 0.05 ' m
        Dim speed = 2 * Math.Sqrt(G * R) * Math.Sin(startAngle / 2)
        Dim exact = Math.Sqrt(R / G) * Math.Log(Math.Tan(angle / 4) / Math.Tan(startAngle / 4))
        Dim time = CornerSlide.Duration(speed, G, R, startAngle, angle)
        Assert.True(Math.Abs(time / exact - 1) <= tolerance, $"{time} s against {exact} s")
    End Sub

    <Theory>
    <InlineData(0.05, 0.00001, 0.8)>
    <InlineData(0.02, 0.001, 0.5)>
    <InlineData(0.1, 0.01, 0.7)>
    <InlineData(0.2, 0.3, 0.6)>
    Public Sub Duration_StartingSlowlyOverTheTop_IsTheEllipticIntegral(radius As Double, speed As Double, angle As Double)
        ' From the top (θ0 = 0) at speed v0, v² = v0² + 4gR sin²(θ/2), so with u = θ/2 the time is
        ' (2R/v0) ∫ du / √(1 + k² sin² u), k² = 4gR/v0²: the incomplete elliptic integral
        ' F(u | −k²) = sin u · R_F(cos² u, 1 + k² sin² u, 1), with Carlson's R_F to the last digits.
        ' A ball leaving a flat top at 10⁻⁵ m/s took a time 1 % wrong on evenly spaced panels.
        Dim k2 = 4 * G * radius / (speed * speed)
        Dim u = angle / 2
        Dim exact = 2 * radius / speed * Math.Sin(u) * CarlsonRF(Math.Cos(u) * Math.Cos(u), 1 + k2 * Math.Sin(u) * Math.Sin(u), 1)
        Dim time = CornerSlide.Duration(speed, G, radius, 0, angle)
        Assert.True(Math.Abs(time / exact - 1) <= 1.0E-12, $"{time} s against {exact} s")
    End Sub

    ''' <summary>
    ''' Carlson's symmetric elliptic integral R_F(x, y, z) = ½ ∫₀^∞ dt / √((t+x)(t+y)(t+z)), by the
    ''' duplication theorem until the three arguments agree to 10⁻⁴, then the fifth-order series
    ''' (error below 10⁻¹⁸ there).
    ''' </summary>
    Private Shared Function CarlsonRF(x As Double, y As Double, z As Double) As Double
        Dim a = (x + y + z) / 3
        Do While Math.Max(Math.Abs(x - a), Math.Max(Math.Abs(y - a), Math.Abs(z - a))) >= 0.0001 * a
            Dim lambda = Math.Sqrt(x * y) + Math.Sqrt(y * z) + Math.Sqrt(z * x)
            x = (x + lambda) / 4
            y = (y + lambda) / 4
            z = (z + lambda) / 4
            a = (x + y + z) / 3
        Loop
        Dim dx = 1 - x / a, dy = 1 - y / a, dz = -dx - dy
        Dim e2 = dx * dy - dz * dz, e3 = dx * dy * dz
        Return (1 - e2 / 10 + e3 / 14 + e2 * e2 / 24 - 3 * e2 * e3 / 44) / Math.Sqrt(a)
    End Function

    <Fact>
    Public Sub AngleAfter_OnTheSeparatrix_IsTheClosedForm()
        ' Inverting the closed form above: θ(t) = 4 atan(tan(θ0/4) e^(t √(g/R))). It leaves at cos θ* = 2/3.
        ' Starts near the top (θ0 = 10⁻⁴) spend most of the time where the integrand bends, near the start.
        Const R = 0.0225 ' m
        For Each startAngle In {0.0001, 0.1, 0.3, 0.6}
            Dim speed = 2 * Math.Sqrt(G * R) * Math.Sin(startAngle / 2)
            Dim leave = CornerSlide.LeaveAngle(speed, G, R, startAngle)
            Assert.Equal(Math.Acos(2.0 / 3.0), leave, 12)
            Dim total = Math.Sqrt(R / G) * Math.Log(Math.Tan(leave / 4) / Math.Tan(startAngle / 4))
            For k = 0 To 20
                Dim t = total * k / 20
                Dim exact = 4 * Math.Atan(Math.Tan(startAngle / 4) * Math.Exp(t * Math.Sqrt(G / R)))
                Dim theta = CornerSlide.AngleAfter(speed, G, R, startAngle, leave, t)
                Assert.True(Math.Abs(theta - exact) <= 1.0E-12 * (leave - startAngle), $"θ0 = {startAngle}, t = {t}: {theta} against {exact}")
            Next
        Next
    End Sub

    <Fact>
    Public Sub AngleAfter_AgreesWithBisection_ForRandomSlides()
        ' Random corners, starts (a quarter of them from rest, some climbing over the top) and times
        ' (some a hair after the start or before the end). Bisection on Duration to the last bit is the
        ' brute-force answer; the time back from the angle found must be the time asked for.
        Dim random = New Random(20261125)
        Dim trials = 0
        While trials < 1000
            Dim radius = 0.005 + 0.5 * random.NextDouble() ' m
            Dim startAngle = -0.3 + 1.1 * random.NextDouble() ' rad
            Dim speed = If(random.Next(4) = 0, 0.0, Math.Sqrt(G * radius) * random.NextDouble()) ' m/s
            Dim leave = CornerSlide.LeaveAngle(speed, G, radius, startAngle)
            If Not (leave > startAngle) Then Continue While ' flies off at once
            If speed < Math.Sqrt(2 * G * radius * (1 - Math.Cos(startAngle))) AndAlso startAngle < 0 Then Continue While ' turns back before the top
            ' Half of them end early, on the next face.
            Dim finish = If(random.Next(2) = 0, leave, startAngle + (leave - startAngle) * (0.05 + 0.95 * random.NextDouble()))
            Dim total = CornerSlide.Duration(speed, G, radius, startAngle, finish)
            Dim fraction As Double
            Select Case random.Next(5)
                Case 0 : fraction = 1.0E-9 * random.NextDouble()
                Case 1 : fraction = 1 - 1.0E-9 * random.NextDouble()
                Case Else : fraction = random.NextDouble()
            End Select
            Dim t = total * fraction
            Dim theta = CornerSlide.AngleAfter(speed, G, radius, startAngle, finish, t)
            Dim brute = Bisect(speed, radius, startAngle, finish, t)
            Dim context = $"v0 = {speed}, R = {radius}, θ0 = {startAngle}, end {finish}, t = {t} of {total}: {theta} against {brute}"
            Assert.InRange(theta, startAngle, finish)
            ' As near in time as bisection gets, to 10⁻¹³ of the whole slide. (Bisection's own miss is not
            ' zero when no double lies near the root: a hair after a start from rest, θ − θ0 can be 10⁻²².)
            Dim miss = Math.Abs(CornerSlide.Duration(speed, G, radius, startAngle, theta) - t)
            Dim bruteMiss = Math.Abs(CornerSlide.Duration(speed, G, radius, startAngle, brute) - t)
            Assert.True(miss <= bruteMiss + 1.0E-13 * total, context)
            Assert.True(Math.Abs(theta - brute) <= 1.0E-12 * (finish - startAngle), context)
            trials += 1
        End While
    End Sub

    <Fact>
    Public Sub AngleAfter_AtTheStart_IsTheStartExactly()
        Assert.Equal(0.3, CornerSlide.AngleAfter(0, G, 0.1, 0.3, 0.8, 0))
        Assert.Equal(0.3, CornerSlide.AngleAfter(0.5, G, 0.1, 0.3, 0.8, 0))
        ' At rest exactly on top it never moves.
        Assert.Equal(0.0, CornerSlide.AngleAfter(0, G, 0.1, 0, 0.8, 1.0))
    End Sub

    ''' <summary>The root of Duration(θ) = t on [θ0, end] by bisection, until the bracket is two adjacent doubles.</summary>
    Private Shared Function Bisect(speed As Double, radius As Double, startAngle As Double, finish As Double, t As Double) As Double
        Dim lo = startAngle, hi = finish
        Do
            Dim mid = 0.5 * (lo + hi)
            If Not (mid > lo AndAlso mid < hi) Then Exit Do
            If CornerSlide.Duration(speed, G, radius, startAngle, mid) < t Then lo = mid Else hi = mid
        Loop
        Dim errLo = Math.Abs(CornerSlide.Duration(speed, G, radius, startAngle, lo) - t)
        Dim errHi = Math.Abs(CornerSlide.Duration(speed, G, radius, startAngle, hi) - t)
        Return If(errLo <= errHi, lo, hi)
    End Function
End Class
