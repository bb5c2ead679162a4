Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit
Imports Xunit.Abstractions

''' <summary>
''' The gas graphs' physics over a long run: an ideal gas of N = 1000 balls, e = 1, watched for 100
''' s of simulated time. Slow-ish (a few seconds): it runs in the normal suite.
''' </summary>
<Trait("Category", "Slow")>
Public Class IdealGasTests
    Private ReadOnly _output As ITestOutputHelper

    Public Sub New(output As ITestOutputHelper)
        _output = output
    End Sub

    ''' <summary>χ² with 19 degrees of freedom that a true 2D Maxwell–Boltzmann sample exceeds with probability 0.001.</summary>
    Private Const ChiSquare19At0001 As Double = 43.82

    ''' <summary>
    ''' A dilute gas (packing fraction 0.001: discs of radius 2 mm), so that it is ideal to well under
    ''' 1 % (Henderson's hard-disc factor is 1.002, and the strip 2 mm wide along the walls that no
    ''' centre reaches is 0.2 % of the area); speeds of a few m/s so each ball collides about 70
    ''' times in 10 s. After 30 s to forget its start (speeds uniform in a square), it is watched for
    ''' 100 s: the speeds of all the balls every 5 s (about 30 collisions apart, so nearly
    ''' independent) go into 20 bins of equal Maxwell–Boltzmann probability for the gas's kT, which
    ''' e = 1 keeps exactly; and the walls' impulses give the pressure.
    ''' </summary>
    <Fact>
    Public Sub DiluteGas_SpeedsPassChiSquare_AndPressureIsNkTOverA_Within1Percent()
        Dim world = Scenarios.ElasticGas(1000, packingFraction:=0.001, radius:=0.002, seed:=11)
        For Each b In world.Movables.ToList()
            world.SetVelocity(b, b.Velocity * 8.0)
        Next
        world.Solver = SolverFactory.Create("event")
        world.Advance(30.0)
        Dim gas = GasState.Read(world)
        Dim gauge As New WallPressure(world.Time, gas.Perimeter, readingSeconds:=5.0)
        world.CollisionListener = Sub(c) gauge.Collided(c)
        Const Bins As Integer = 20
        Dim observed(Bins - 1) As Integer
        Dim samples = 0
        For k = 1 To 20
            world.Advance(5.0)
            Dim now = GasState.Read(world)
            gauge.Advance(world.Time, now.KT, now.IdealPressure)
            ' Bin i holds P between i/20 and (i + 1)/20: v = √(−2 kT ln(1 − P) / m).
            For Each v In now.Speeds
                Dim p = MaxwellBoltzmann2D.Cumulative(v, 1.0, now.KT)
                observed(Math.Min(Bins - 1, CInt(Math.Floor(p * Bins)))) += 1
                samples += 1
            Next
            ' Sanity of the histogram the app shows: every ball is in it.
            Assert.Equal(1000, SpeedHistogram.Count(now.Speeds, 4 * MaxwellBoltzmann2D.PeakSpeed(1.0, now.KT)).Total)
        Next
        Dim expected = samples / Bins
        Dim chi = observed.Sum(Function(o) (o - expected) * (o - expected) / expected)
        Dim ideal = gauge.AverageIdeal
        Dim ratio = gauge.Average / ideal
        _output.WriteLine($"kT {gas.KT:G6} J, {samples} speeds, chi2 {chi:F2} (19 dof), P {gauge.Average:G6} ± {gauge.StandardError:G2} N/m, NkT/A {ideal:G6} N/m, ratio {ratio:F5}, Henderson·area-strip estimate {GasLaw.HardDiscFactor(gas.PackingFraction) * gas.FreeArea / ((Math.Sqrt(gas.FreeArea) - 0.004) ^ 2):F5}")
        Assert.True(chi < ChiSquare19At0001, $"χ² = {chi:F1} ≥ {ChiSquare19At0001}: the speeds are not Maxwell–Boltzmann; bins {String.Join(" ", observed)}")
        Assert.InRange(ratio, 0.99, 1.01)
        ' The gauge's own error bar is much smaller than the 1 % asked.
        Assert.True(gauge.StandardError / gauge.Average < 0.004, $"standard error {gauge.StandardError / gauge.Average:P2}")
    End Sub

    ''' <summary>
    ''' The lesson's gas is not dilute (packing fraction 0.1): hard discs press harder than N k T / A,
    ''' by Henderson's factor Z = (1 + η²/8)/(1 − η)², about 1.23 here. The gauge must see that
    ''' excess, and agree with Z N k T / A within a few percent (the rest is the strip along the walls
    ''' that no centre reaches, of order r × perimeter / A ≈ 2 %).
    ''' </summary>
    <Fact>
    Public Sub LessonGas_PressesHarderThanIdeal_AsHardDiscsDo()
        Dim world = Scenes.SceneFile.LoadFile(IO.Path.Combine(ProcessRunner.RepoRoot, "scenes", "ideal-gas.json"))
        world.Solver = SolverFactory.Create("event")
        world.Advance(10.0)
        Dim gas = GasState.Read(world)
        Dim gauge As New WallPressure(world.Time, gas.Perimeter, readingSeconds:=5.0)
        world.CollisionListener = Sub(c) gauge.Collided(c)
        For k = 1 To 12
            world.Advance(5.0)
            Dim now = GasState.Read(world)
            gauge.Advance(world.Time, now.KT, now.IdealPressure)
        Next
        Dim ratio = gauge.Average / gauge.AverageIdeal
        Dim z = GasLaw.HardDiscFactor(gas.PackingFraction)
        _output.WriteLine($"eta {gas.PackingFraction:F4}, Z {z:F4}, P/(NkT/A) {ratio:F4} ± {gauge.StandardError / gauge.AverageIdeal:F4}")
        Assert.True(ratio > 1.1, $"P / (NkT/A) = {ratio:F3}: hard discs at η = {gas.PackingFraction:F3} press harder")
        Assert.InRange(ratio / z, 0.97, 1.06)
    End Sub
End Class
