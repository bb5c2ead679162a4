Option Strict On
Imports System.Globalization

''' <summary>An elastic gas in a box: kinetic energy must not drift (e = 1, g = 0).</summary>
Friend NotInheritable Class GasEnergyScene
    Implements IBenchScene

    Private ReadOnly _count As Integer
    Private ReadOnly _seconds As Double

    ''' <param name="count">number of circles</param>
    ''' <param name="seconds">simulated seconds per run</param>
    Public Sub New(count As Integer, seconds As Double)
        _count = count
        _seconds = seconds
    End Sub

    ''' <summary>Packing fraction of every gas in the benchmark (circle area ÷ box area).</summary>
    Public Const PackingFraction As Double = 0.1

    Public ReadOnly Property Name As String = "gas-energy" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Elastic gas: energy drift" Implements IBenchScene.Title

    Public ReadOnly Property Description As String Implements IBenchScene.Description
        Get
            Return "Scenarios.ElasticGas(N = " & _count.ToString(CultureInfo.InvariantCulture) & ", packing fraction 0.1, r = 0.01 m, seed 1): " &
                   "e = 1, g = 0, walls on. Closed form: kinetic energy is conserved exactly. Error = |KE(T) − KE(0)| / KE(0) after " &
                   _seconds.ToString("0.##", CultureInfo.InvariantCulture) & " s. Collisions/s here is per wall-clock second."
        End Get
    End Property

    Public ReadOnly Property ErrorMetric As String = "relative energy drift" Implements IBenchScene.ErrorMetric

    Public ReadOnly Property SimulatedSeconds As Double Implements IBenchScene.SimulatedSeconds
        Get
            Return _seconds
        End Get
    End Property

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.ElasticGas(_count, PackingFraction)
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        Dim before = world.KineticEnergy()
        If Not Sampling.Advance(world, _seconds, sampleStep, budget) Then Return SceneMeasurement.Stopped(world, budget)
        Dim after = world.KineticEnergy()
        Dim escaped = world.Circles.Where(Function(c) Not c.Position.IsFinite OrElse c.Position.X < 0 OrElse c.Position.Y < 0 OrElse
                                                       c.Position.X > world.Width OrElse c.Position.Y > world.Height).Count()
        ' Energy alone does not tell the solvers apart (an elastic impulse conserves it exactly), so the
        ' note also gives what stepping leaves behind: circles sunk into each other.
        Dim note = "deepest overlap " & NumberText.Sci(Overlap.Deepest(world)) & " m"
        If escaped > 0 Then note &= "; " & escaped.ToString(CultureInfo.InvariantCulture) & " circle(s) outside the box"
        Return New SceneMeasurement(Math.Abs(after - before) / before, note)
    End Function
End Class
