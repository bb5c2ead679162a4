Option Strict On
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>
''' The gas of the engine before the event solver's restructure beside the engine now: reading the
''' baseline build's result lines, pairing the sizes, the ratio, and the report's table.
''' </summary>
Public Class BaselineComparisonTests
    ' A result line as the benchmark at the baseline commit prints it (its --child-gas mode, N = 100).
    Private Const BaselineLine As String =
        "RESULT {""scene"":""gas-scaling"",""solver"":""event"",""dt"":null,""available"":true,""error"":null,""errorMetric"":""""," &
        """msPerSimulatedSecond"":9.990673828125,""collisionsPerSecond"":97845.15832636882,""microsecondsPerCollision"":10.220229770229771," &
        """n"":100,""peakMB"":33.09765625,""simulatedSeconds"":4.096,""runs"":1,""rounds"":1,""slowestCollisionsPerSecond"":null," &
        """fastestCollisionsPerSecond"":null,""note"":""slice 4.096 s simulated per timed run; 2.09 events per collision, 4.39 cells searched per event""}"

    Private Shared Function Run(n As Integer, collisionsPerSecond As Double) As BenchResult
        Return New BenchResult With {.Scene = GasScaling.SceneName, .Solver = "event", .BodyCount = n, .CollisionsPerSecond = collisionsPerSecond,
                                     .MsPerSimulatedSecond = 1.0E+6 / collisionsPerSecond, .Runs = 5}
    End Function

    Private Shared Function Rounds(ParamArray rows As BenchResult()()) As IReadOnlyList(Of IReadOnlyList(Of BenchResult))
        Return rows.Select(Function(r) CType(r, IReadOnlyList(Of BenchResult))).ToList()
    End Function

    <Fact>
    Public Sub ReadResults_ReadsTheBaselineBuildsLine_AndSkipsOtherOutput()
        Dim results = ChildProcess.ReadResults({"warming up", BaselineLine, "", "RESULTS are above"})
        Dim r = Assert.Single(results)
        Assert.Equal(GasScaling.SceneName, r.Scene)
        Assert.Equal("event", r.Solver)
        Assert.True(r.Available)
        Assert.Null(r.TimeStep)
        Assert.Equal(100, r.BodyCount)
        Assert.Equal(97845.15832636882, r.CollisionsPerSecond)
        Assert.Equal(9.990673828125, r.MsPerSimulatedSecond)
        Assert.True(Double.IsNaN(r.Error))
        Assert.StartsWith("slice 4.096 s", r.Note, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub Combine_PairsEachSizesMedianRounds_AndTheRatioIsNowOverBefore()
        Dim c = BaselineComparison.Combine("4f483eebcd2f32da4c7cdaed442b4ff9934acc19",
            Rounds({Run(1000, 1200000), Run(10000, 800000)}, {Run(1000, 1000000), Run(10000, 900000)}, {Run(1000, 1100000), Run(10000, 700000)}),
            Rounds({Run(1000, 1000000), Run(10000, 1000000)}, {Run(1000, 900000), Run(10000, 600000)}, {Run(1000, 950000), Run(10000, 800000)}))
        Assert.Equal("4f483ee", c.ShortCommit)
        Assert.Equal(Values(1000, 10000), c.Rows.Select(Function(r) r.BodyCount))
        Assert.Equal(1100000, c.Rows(0).Now.CollisionsPerSecond)
        Assert.Equal(950000, c.Rows(0).Before.CollisionsPerSecond)
        Assert.Equal(1100000 / 950000.0, c.Rows(0).Ratio, 12)
        Assert.Equal(800000 / 800000.0, c.Rows(1).Ratio, 12)
        Assert.Equal(3, c.Rows(1).Before.Rounds)
        ' Each round's pair, in round order: now over before of that round's two runs.
        Assert.Equal(Values(1.2, 1000000 / 900000.0, 1100000 / 950000.0), c.Rows(0).PairRatios, New RatioComparer())
        Assert.Equal(Values(0.8, 1.5, 700000 / 800000.0), c.Rows(1).PairRatios, New RatioComparer())
        ' The median pair is the middle of the pairs' ratios, not the ratio of the medians.
        Assert.Equal(1100000 / 950000.0, c.Rows(0).MedianPairRatio, 12)
        Assert.Equal(700000 / 800000.0, c.Rows(1).MedianPairRatio, 12)
    End Sub

    Private NotInheritable Class RatioComparer
        Implements IEqualityComparer(Of Double)

        Public Overloads Function Equals(x As Double, y As Double) As Boolean Implements IEqualityComparer(Of Double).Equals
            Return Math.Abs(x - y) < 1.0E-12
        End Function

        Public Overloads Function GetHashCode(obj As Double) As Integer Implements IEqualityComparer(Of Double).GetHashCode
            Return 0
        End Function
    End Class

    <Fact>
    Public Sub Combine_MatchesSizesByN_AndASideWithoutAFigureHasNoRatio()
        Dim failed = SceneRunner.NotAvailable(GasScaling.SceneName, "event", Nothing, "failed (exit 1): no such option")
        failed.BodyCount = 10000
        ' The baseline's rows come in the other order: pairing by place would set N = 1 000 against N = 10 000.
        Dim c = BaselineComparison.Combine("", Rounds({Run(1000, 1000000), Run(10000, 500000)}), Rounds({failed, Run(1000, 2000000)}))
        Assert.Equal(1000, c.Rows(0).BodyCount)
        Assert.Equal(0.5, c.Rows(0).Ratio, 12)
        Assert.True(Double.IsNaN(c.Rows(1).Ratio))
        Assert.Empty(c.Rows(1).PairRatios)
        Assert.True(Double.IsNaN(c.Rows(1).MedianPairRatio))
        Assert.Equal("—", BaselineComparison.RatioText(c.Rows(1).Ratio))
        Assert.Equal("0.50×", BaselineComparison.RatioText(c.Rows(0).Ratio))
        ' A size only one side has is a row with nothing on the other.
        Dim lone = BaselineComparison.Combine("", Rounds({Run(1000, 1000000), Run(10000, 500000)}), Rounds({Run(1000, 1000000)}))
        Assert.Null(lone.Rows(1).Before)
        Assert.True(Double.IsNaN(lone.Rows(1).Ratio))
    End Sub

    <Fact>
    Public Sub SizesIn_AreTheHeadlineSizesThisRunMeasures()
        Assert.Equal(Values(1000, 10000), BaselineComparison.SizesIn(Values(100, 1000, 10000, 100000)))
        Assert.Equal(Values(1000), BaselineComparison.SizesIn(Values(100, 1000)))
        Assert.Empty(BaselineComparison.SizesIn(Values(100, 500)))
    End Sub

    <Fact>
    Public Sub Report_ShowsBothEnginesAndTheRatioInOneTable()
        Dim c = BaselineComparison.Combine("4f483eebcd2f32da4c7cdaed442b4ff9934acc19",
            Rounds({Run(1000, 1100000), Run(10000, 600000)}), Rounds({Run(1000, 1000000), Run(10000, 800000)}))
        Dim md = Render(c)
        Dim section = md.Substring(md.IndexOf("## Elastic gas: the engine before the event solver's restructure, and now", StringComparison.Ordinal))
        Assert.Contains("| N | collisions/s before (`4f483ee`) | collisions/s now | now ÷ before | median pair | pairs, round by round | ms per simulated s before | ms per simulated s now | note |", section)
        Assert.Contains("| 1,000 | 1,000,000 | 1,100,000 | **1.10×** | 1.10× | 1.10× | 1.0 | 0.909 |", section)
        Assert.Contains("| 10,000 | 800,000 | 600,000 | **0.75×** | 0.75× | 0.75× | 1.3 | 1.7 |", section)
        ' It comes after the scaling table and before the app's frame budget.
        Assert.True(md.IndexOf("## Scaling", StringComparison.Ordinal) < md.IndexOf("## Elastic gas: the engine before", StringComparison.Ordinal))
        Assert.True(md.IndexOf("## Elastic gas: the engine before", StringComparison.Ordinal) < md.IndexOf("## Frame budget", StringComparison.Ordinal))
    End Sub

    <Fact>
    Public Sub Report_SaysWhyWhenTheBaselineDidNotRun()
        Dim md = Render(BaselineComparison.NotRun("4f483eebcd2f32da4c7cdaed442b4ff9934acc19", "not run: commit 4f483ee is not in this clone (a shallow clone has no history)."))
        Assert.Contains("*Not measured in this run:* not run: commit 4f483ee is not in this clone (a shallow clone has no history).", md)
        Assert.DoesNotContain("| N | collisions/s before", md)
    End Sub

    <Fact>
    Public Sub Options_CarryTheBaselineBuild_ItsCommit_OrWhyThereIsNone()
        Dim o = BenchmarkOptions.Parse(Values("--baseline-dll", "/tmp/x/Benchmarks.dll", "--baseline-commit", "4f483ee", "--baseline-note", "not run: no build."))
        Assert.Equal("/tmp/x/Benchmarks.dll", o.BaselineDll)
        Assert.Equal("4f483ee", o.BaselineCommit)
        Assert.Equal("not run: no build.", o.BaselineNote)
        Dim none = BenchmarkOptions.Parse(Array.Empty(Of String)())
        Assert.Null(none.BaselineDll)
        Assert.Equal("", none.BaselineCommit)
        Dim ex = Assert.Throws(Of OptionsException)(Function() BenchmarkOptions.Parse(Values("--baseline-dll")))
        Assert.Equal("--baseline-dll: needs a value", ex.Message)
    End Sub

    Private Shared Function Render(baseline As BaselineComparison) As String
        Return MarkdownReport.Render(SampleResults.Machine(), "full", 5, SampleResults.Scenes(), SampleResults.Results(), New FrameResult With {.Note = "mono is not installed."},
                                     Nothing, baseline)
    End Function
End Class
