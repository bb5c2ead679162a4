Option Strict On
Imports PhysicsEngine
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>
''' The benchmark's ramp, box, pendulum and spring scenes: their closed forms checked independently,
''' and the event solver measured against them (exact to rounding) beside a first-order stepping run.
''' </summary>
Public Class ShapeAndLinkScenesTests
    Private Shared ReadOnly QuickRun As String() = {"--quick"}

    <Fact>
    Public Sub PendulumPeriod_TendsToTwoPiRootLOverG_ForSmallSwings()
        Assert.Equal(2 * Math.PI * Math.Sqrt(1.5 / 9.81), ClosedForms.PendulumPeriod(1.5, 0.0001, 9.81), 8)
    End Sub

    <Fact>
    Public Sub PendulumPeriod_MatchesTheIntegralForT_ByQuadrature()
        ' T = 4 √(L/g) ∫₀^{π/2} dφ / √(1 − k² sin² φ), k = sin(θ0/2): Simpson's rule on 2000 strips.
        Dim k = Math.Sin(Math.PI / 6)
        Dim n = 2000, h = Math.PI / 2 / n, sum = 0.0
        For i = 0 To n
            Dim f = 1 / Math.Sqrt(1 - k * k * Math.Sin(i * h) ^ 2)
            sum += If(i = 0 OrElse i = n, f, If(i Mod 2 = 1, 4 * f, 2 * f))
        Next
        Dim expected = 4 * Math.Sqrt(1.5 / 9.81) * sum * h / 3
        Assert.Equal(expected, ClosedForms.PendulumPeriod(1.5, Math.PI / 3, 9.81), 10)
    End Sub

    <Fact>
    Public Sub SpringHeight_StartsAtY0_ReachesTwiceTheStretchAtHalfAPeriod_AndSatisfiesHookesLaw()
        Dim k = 20.0, m = 0.5, g = 9.81, y0 = 2.5
        Dim w = Math.Sqrt(k / m)
        Assert.Equal(y0, ClosedForms.SpringHeight(y0, k, m, g, 0), 12)
        Assert.Equal(y0 - 2 * m * g / k, ClosedForms.SpringHeight(y0, k, m, g, Math.PI / w), 12)
        ' m y'' = −k (y − y0) − m g, by central differences at a few times.
        Dim dt = 0.0001
        For Each t In {0.3, 1.1, 2.7}
            Dim y = ClosedForms.SpringHeight(y0, k, m, g, t)
            Dim acc = (ClosedForms.SpringHeight(y0, k, m, g, t + dt) - 2 * y + ClosedForms.SpringHeight(y0, k, m, g, t - dt)) / (dt * dt)
            Assert.Equal(-k * (y - y0) - m * g, m * acc, 5)
        Next
    End Sub

    <Theory>
    <InlineData("ramp-slide", 1.0E-9)>
    <InlineData("box-drop", 1.0E-9)>
    <InlineData("pendulum", 1.0E-9)>
    <InlineData("spring", 1.0E-9)>
    <InlineData("drag-projectile", 1.0E-9)>
    <InlineData("tanh-fall", 1.0E-9)>
    <InlineData("floating-box", 1.0E-9)>
    Public Sub EventSolver_MeetsTheClosedForm_WhereAFirstOrderStepperDoesNot(name As String, tolerance As Double)
        Dim options = BenchmarkOptions.Parse(QuickRun)
        Dim exact = SceneRunner.Run(SceneCatalog.Create(name, options), "event", Nothing, 1, 60)
        Dim stepped = SceneRunner.Run(SceneCatalog.Create(name, options), "euler", 1 / 30.0, 1, 60)
        Assert.True(exact.Available AndAlso stepped.Available)
        Assert.InRange(exact.Error, 0.0, tolerance)
        Assert.True(stepped.Error > 100 * tolerance, $"{name}: Euler at 1/30 s gave {stepped.Error}, which a first-order method cannot reach")
    End Sub
End Class
