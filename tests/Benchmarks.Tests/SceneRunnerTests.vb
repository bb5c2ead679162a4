Option Strict On
Imports PhysicsEngine
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>
''' The measuring harness on real scenes with the semi-implicit Euler solver. Errors are checked for
''' the behaviour a first-order method must show; costs are only checked to exist (never timed).
''' </summary>
Public Class SceneRunnerTests
    <Fact>
    Public Sub Run_ReportsASolverTheFactoryDoesNotKnowAsNotAvailable_InsteadOfThrowing()
        Dim r = SceneRunner.Run(New ProjectileScene(), "no-such-solver", Nothing, 1, 10)
        Assert.False(r.Available)
        Assert.Contains("not available", r.Note)
        Assert.True(Double.IsNaN(r.Error))
    End Sub

    <Fact>
    Public Sub Run_Projectile_ErrorShrinksWithTheStep_AndCostIsMeasured()
        Dim coarse = SceneRunner.Run(New ProjectileScene(), "euler", 1 / 60.0, 1, 30)
        Dim fine = SceneRunner.Run(New ProjectileScene(), "euler", 1 / 1000.0, 1, 30)
        Assert.True(coarse.Available)
        Assert.Equal("position error at landing (m)", coarse.ErrorMetric)
        Assert.True(coarse.Error > 0, "semi-implicit Euler is first order: it cannot land exactly")
        Assert.True(fine.Error < coarse.Error / 5, $"error at 1/1000 ({fine.Error}) should be well below error at 1/60 ({coarse.Error})")
        Assert.False(Double.IsNaN(coarse.MsPerSimulatedSecond))
        Assert.Equal(1, coarse.Runs)
        Assert.Equal(1 / 60.0, coarse.TimeStep)
    End Sub

    <Fact>
    Public Sub Run_ARealTimeScene_NotesTheMedianRunsFactorOverRealTime_AndOtherScenesDoNot()
        Dim plain = SceneRunner.Run(New ProjectileScene(), "euler", 1 / 250.0, 3, 30)
        Dim timed = SceneRunner.Run(New RealTimeProjectile(), "euler", 1 / 250.0, 3, 30)
        Assert.DoesNotContain("real time", plain.Note, StringComparison.Ordinal)
        Dim expected = (1000 / timed.MsPerSimulatedSecond).ToString("0.#", Globalization.CultureInfo.InvariantCulture) & "× real time"
        Assert.EndsWith(expected, timed.Note, StringComparison.Ordinal)
    End Sub

    ''' <summary>The projectile, reported with its speed over real time.</summary>
    Private NotInheritable Class RealTimeProjectile
        Implements IBenchScene, IRealTimeScene
        Private ReadOnly _scene As New ProjectileScene()
        Public ReadOnly Property Name As String Implements IBenchScene.Name
            Get
                Return _scene.Name
            End Get
        End Property
        Public ReadOnly Property Title As String Implements IBenchScene.Title
            Get
                Return _scene.Title
            End Get
        End Property
        Public ReadOnly Property Description As String Implements IBenchScene.Description
            Get
                Return _scene.Description
            End Get
        End Property
        Public ReadOnly Property ErrorMetric As String Implements IBenchScene.ErrorMetric
            Get
                Return _scene.ErrorMetric
            End Get
        End Property
        Public ReadOnly Property SimulatedSeconds As Double Implements IBenchScene.SimulatedSeconds
            Get
                Return _scene.SimulatedSeconds
            End Get
        End Property
        Public Function Build() As World Implements IBenchScene.Build
            Return _scene.Build()
        End Function
        Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
            Return _scene.Measure(world, sampleStep, budget)
        End Function
    End Class

    <Fact>
    Public Sub BouncingApex_WithASmallStep_FindsFiveApexesCloseToTheClosedForm()
        Dim scene As New BouncingApexScene()
        Dim world = scene.Build()
        world.Solver = SolverFactory.Create("euler", 1 / 2000.0)
        Dim m = scene.Measure(world, 1 / 2000.0, New RunBudget(60))
        Assert.Equal("", m.Note) ' all five apexes were found
        Assert.InRange(m.Error, 1.0E-6, 0.01)
    End Sub

    <Fact>
    Public Sub BouncingRest_NotesTheBouncesAndTheLastOne()
        Dim scene As New BouncingRestScene()
        Dim world = scene.Build()
        world.Solver = SolverFactory.Create("euler", 1 / 1000.0)
        Dim m = scene.Measure(world, 1 / 1000.0, New RunBudget(60))
        Assert.Matches("^\d+ bounces, last at \d+\.\d{3} s$", m.Note)
        Assert.InRange(m.Error, 0.0, BouncingRestScene.RestTime)
    End Sub

    <Fact>
    Public Sub Measure_StopsWhenTheBudgetIsSpent_AndSaysHowFarItGot()
        Dim scene As New PileScene()
        Dim world = scene.Build()
        world.Solver = SolverFactory.Create("euler", 1 / 1000.0)
        Dim m = scene.Measure(world, 1 / 1000.0, New RunBudget(0))
        Assert.False(m.Completed)
        Assert.True(Double.IsNaN(m.Error))
        Assert.Matches("^stopped at 0\.01 s simulated: over the 0 s wall-clock budget$", m.Note)
        Assert.True(world.Time < scene.SimulatedSeconds)
    End Sub

    <Fact>
    Public Sub Projectile_MeasuresWhereTheSolverLanded_InTwoRuns()
        Dim scene As New ProjectileScene()
        Dim world = scene.Build()
        world.Solver = SolverFactory.Create("euler", 1 / 1000.0)
        Dim m = scene.Measure(world, 1 / 1000.0, New RunBudget(60))
        Assert.True(m.Completed)
        Assert.Matches("^landed at 1\.44\d\d s \(closed form 1\.4416 s\)$", m.Note)
        ' Landing is found at the end of a step: within one step (1 ms at ~7 m/s) plus Euler's own O(dt) drift.
        Assert.InRange(m.Error, 0.0, 0.05)
    End Sub

    <Fact>
    Public Sub DeepestOverlap_FindsCircleAndWallOverlaps()
        Dim w As New World(2, 2, 0, 1, walls:=False)
        w.Add(New Circle(New Vector(0.5, 1), 0.2, 1))
        w.Add(New Circle(New Vector(0.8, 1), 0.2, 1)) ' centres 0.3 apart: overlap 0.1
        Assert.Equal(0.1, Overlap.Deepest(w), 12)
        Dim outside As New Circle(New Vector(1.9, 1), 0.25, 1) ' 0.15 past the right side
        w.Add(outside)
        Assert.Equal(0.1, Overlap.Deepest(w), 12) ' no walls, no wall overlap
        Dim walled As New World(2, 2, 0, 1)
        Dim c As New Circle(New Vector(1, 1), 0.25, 1)
        walled.Add(c)
        c.Position = New Vector(1.9, 1) ' as a solver might leave it, past the wall
        Assert.Equal(0.15, Overlap.Deepest(walled), 12)
    End Sub
End Class
