Option Strict On
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>The command line: modes, lists, and a one-line message for bad input.</summary>
Public Class BenchmarkOptionsTests
    <Fact>
    Public Sub Defaults_AreTheFullRun_WithEveryDtFrom30To4000PerSecond()
        Dim o = BenchmarkOptions.Parse(Array.Empty(Of String)())
        Assert.False(o.Quick)
        Assert.Equal("docs", o.OutDir)
        Assert.Equal(8, o.TimeSteps.Count)
        Assert.Equal(1 / 30.0, o.TimeSteps(0))
        Assert.Equal(1 / 4000.0, o.TimeSteps(7))
        Assert.Equal(Values(100, 1000, 10000, 100000), o.GasSizes)
        Assert.Equal(Values("event", "euler", "verlet"), o.Solvers)
        Assert.Equal(3, o.GasRounds)
    End Sub

    <Fact>
    Public Sub Quick_IsSmaller()
        Dim o = BenchmarkOptions.Parse(Values("--quick"))
        Assert.True(o.TimeSteps.Count < 8)
        Assert.True(o.GasSizes.Max() <= 1000)
        Assert.True(o.Repeats < BenchmarkOptions.Parse(Array.Empty(Of String)()).Repeats)
        Assert.Equal(1, o.GasRounds)
    End Sub

    <Fact>
    Public Sub GasRounds_AreRead()
        Assert.Equal(5, BenchmarkOptions.Parse(Values("--gas-rounds", "5")).GasRounds)
        Assert.Equal(2, BenchmarkOptions.Parse(Values("--quick", "--gas-rounds", "2")).GasRounds)
    End Sub

    <Fact>
    Public Sub BaselineRounds_AreRead_AndOutnumberTheScalingsRounds()
        Dim plain = BenchmarkOptions.Parse(Array.Empty(Of String)())
        Assert.Equal(7, plain.BaselineRounds)
        Assert.True(plain.BaselineRounds > plain.GasRounds)
        Assert.Equal(4, BenchmarkOptions.Parse(Values("--baseline-rounds", "4")).BaselineRounds)
        Assert.Equal(7, BenchmarkOptions.Parse(Values("--gas-rounds", "2")).BaselineRounds)
    End Sub

    <Fact>
    Public Sub Lists_AreRead()
        Dim o = BenchmarkOptions.Parse(Values("--dts", "1/60,0.001", "--gas-sizes", "50", "--scenes", "projectile,cradle", "--json", "r.json", "--out", "x"))
        Assert.Equal(Values(1 / 60.0, 0.001), o.TimeSteps)
        Assert.Equal(Values(50), o.GasSizes)
        Assert.Equal(Values("projectile", "cradle"), o.Scenes)
        Assert.Equal("r.json", o.JsonPath)
        Assert.Equal("x", o.OutDir)
    End Sub

    <Theory>
    <InlineData("--dts|1/0", "--dts: '1/0' is not a time step greater than 0 (write 1/60 or 0.001)")>
    <InlineData("--scenes|nope", "--scenes: unknown scene 'nope'")>
    <InlineData("--repeats|0", "--repeats: '0' is not a whole number greater than 0")>
    <InlineData("--gas-rounds|three", "--gas-rounds: 'three' is not a whole number greater than 0")>
    <InlineData("--baseline-rounds|0", "--baseline-rounds: '0' is not a whole number greater than 0")>
    <InlineData("--json", "--json: needs a value")>
    <InlineData("--frobnicate", "unknown option '--frobnicate' (see --help)")>
    Public Sub BadInput_GivesAOneLineMessageNamingTheOption(args As String, message As String)
        Dim ex = Assert.Throws(Of OptionsException)(Function() BenchmarkOptions.Parse(args.Split("|"c)))
        Assert.StartsWith(message, ex.Message)
        Assert.DoesNotContain(vbLf, ex.Message)
    End Sub

    <Fact>
    Public Sub ChildArguments_CarryTheModeTheStepsAndTheRepeats()
        Dim o = BenchmarkOptions.Parse(Values("--quick", "--dts", "1/60", "--repeats", "2"))
        Dim child = BenchmarkOptions.Parse(o.ChildArguments())
        Assert.True(child.Quick)
        Assert.Equal(o.TimeSteps, child.TimeSteps)
        Assert.Equal(2, child.Repeats)
    End Sub
End Class

''' <summary>When the scaling run stops giving a stepping solver bigger gases.</summary>
Public Class ScalingGuardTests
    <Fact>
    Public Sub PredictedStep_AssumesNSquared_FromTheLastMeasuredSize()
        ' 2 800 ms per simulated second at 1/1000 s steps: 2.8 ms a step at N = 10 000; ×100 at ten times N.
        Dim previous As New BenchResult With {.BodyCount = 10000, .MsPerSimulatedSecond = 2800}
        Assert.Equal(0.28, Program.PredictedStepSeconds(previous, 100000, 0.001), 12)
    End Sub

    <Fact>
    Public Sub PredictedStep_IsZero_ForTheEventSolverOrTheFirstSize()
        Dim previous As New BenchResult With {.BodyCount = 100, .MsPerSimulatedSecond = 5}
        Assert.Equal(0.0, Program.PredictedStepSeconds(previous, 1000, Nothing))
        Assert.Equal(0.0, Program.PredictedStepSeconds(Nothing, 1000, 0.001))
    End Sub
End Class
