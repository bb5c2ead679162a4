Option Strict On
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>The gas-scaling rows made from several rounds: the median run, its range, and what failed.</summary>
Public Class GasRoundsTests
    Private Shared Function Run(n As Integer, collisionsPerSecond As Double, Optional note As String = "") As BenchResult
        Return New BenchResult With {.Scene = GasScaling.SceneName, .Solver = "event", .BodyCount = n, .CollisionsPerSecond = collisionsPerSecond,
                                     .MsPerSimulatedSecond = 1.0E+6 / collisionsPerSecond, .Runs = 5, .Note = note}
    End Function

    Private Shared Function Failed(n As Integer, why As String) As BenchResult
        Return New BenchResult With {.Scene = GasScaling.SceneName, .Solver = "event", .BodyCount = n, .Available = False, .Note = why}
    End Function

    Private Shared Function Rounds(ParamArray rows As BenchResult()()) As IReadOnlyList(Of IReadOnlyList(Of BenchResult))
        Return rows.Select(Function(r) CType(r, IReadOnlyList(Of BenchResult))).ToList()
    End Function

    <Fact>
    Public Sub ThreeRounds_GiveTheMedianRunOfEachSize_WithItsRangeFirstInTheNote()
        Dim combined = GasScaling.CombineRounds(Rounds(
            {Run(1000, 900000, "slice 1 s"), Run(10000, 500000, "slice 2 s")},
            {Run(1000, 1100000, "slice 3 s"), Run(10000, 700000, "slice 4 s")},
            {Run(1000, 1000000, "slice 5 s"), Run(10000, 600000, "slice 6 s")}))
        Assert.Equal(2, combined.Count)
        Assert.Equal(1000000, combined(0).CollisionsPerSecond)
        Assert.Equal("median of 3 runs, 900,000 to 1,100,000 collisions/s; slice 5 s", combined(0).Note)
        Assert.Equal(3, combined(0).Rounds)
        Assert.Equal(900000, combined(0).SlowestCollisionsPerSecond)
        Assert.Equal(1100000, combined(0).FastestCollisionsPerSecond)
        ' The whole row comes from the median run, so its figures belong together.
        Assert.Equal(600000, combined(1).CollisionsPerSecond)
        Assert.Equal(1.0E+6 / 600000, combined(1).MsPerSimulatedSecond)
        Assert.Equal("median of 3 runs, 500,000 to 700,000 collisions/s; slice 6 s", combined(1).Note)
    End Sub

    <Fact>
    Public Sub ARunThatFailed_IsLeftOut_AndCounted()
        Dim combined = GasScaling.CombineRounds(Rounds(
            {Run(1000, 800000)}, {Failed(1000, "timed out after 240 s")}, {Run(1000, 1200000)}))
        ' Of two runs the slower one is the median: a lucky spell does not make the figure.
        Assert.Equal(800000, combined(0).CollisionsPerSecond)
        Assert.Equal("median of 2 runs (1 more failed), 800,000 to 1,200,000 collisions/s", combined(0).Note)
        Assert.Equal(2, combined(0).Rounds)
    End Sub

    <Fact>
    Public Sub ASizeNoRoundMeasured_KeepsTheFirstRoundsReason()
        Dim skipped = Failed(100000, "skipped: one step could take 9 s")
        Dim combined = GasScaling.CombineRounds(Rounds({skipped}, {skipped}, {skipped}))
        Assert.False(combined(0).Available)
        Assert.Equal("skipped: one step could take 9 s", combined(0).Note)
        Assert.Equal(1, combined(0).Rounds)
    End Sub

    <Fact>
    Public Sub OneRound_IsReportedAsItIs()
        Dim only = Run(1000, 950000, "slice 1 s")
        Dim combined = GasScaling.CombineRounds(Rounds({only}))
        Assert.Same(only, combined(0))
        Assert.Equal("slice 1 s", combined(0).Note)
        Assert.Equal(1, combined(0).Rounds)
        Assert.True(Double.IsNaN(combined(0).SlowestCollisionsPerSecond))
    End Sub
End Class
