Option Strict On
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>docs/benchmarks.md as written from a known set of results.</summary>
Public Class MarkdownReportTests
    Private Shared Function Render(Optional frame As FrameResult = Nothing) As String
        Return MarkdownReport.Render(SampleResults.Machine(), "full", 5, SampleResults.Scenes(), SampleResults.Results(),
                                     If(frame, New FrameResult With {.Note = "mono is not installed."}))
    End Function

    <Fact>
    Public Sub Render_StartsWithTheHeadline_GivingEventGasCollisionsPerSecondAtBothSizes()
        Dim md = Render()
        Dim headline = md.IndexOf("## Headline", StringComparison.Ordinal)
        Dim machine = md.IndexOf("## Machine", StringComparison.Ordinal)
        Assert.True(headline > 0 AndAlso headline < machine, "the headline comes before the machine section")
        Dim head = md.Substring(headline, machine - headline)
        Assert.Contains("N = 1,000: **1,234,567 collisions per second**", head)
        Assert.Contains("N = 10,000: **987,654 collisions per second**", head)
        ' The accuracy line compares the event solver with the most accurate stepping run (1/1000, not 1/60).
        Assert.Contains("| Projectile: position at landing | position error at landing (m) | 0 at 0.020 ms/s | 3.0e-3 (euler, dt = 1/1000) at 2.5 ms/s |", head)
    End Sub

    <Fact>
    Public Sub Render_Headline_GivesTheRangeWhenTheGasRanInRounds()
        Dim results = SampleResults.Results()
        results(4).Rounds = 3
        results(4).SlowestCollisionsPerSecond = 900000
        results(4).FastestCollisionsPerSecond = 1300000
        Dim md = MarkdownReport.Render(SampleResults.Machine(), "full", 5, SampleResults.Scenes(), results, New FrameResult)
        Assert.Contains("N = 1,000: **1,234,567 collisions per second** (0.81 µs per collision, 40.0 ms per simulated second; the median of 3 runs, which ranged from 900,000 to 1,300,000).", md)
        Assert.Contains("N = 10,000: **987,654 collisions per second** (1.01 µs per collision, 450 ms per simulated second).", md)
    End Sub

    <Fact>
    Public Sub Render_Headline_SaysWhyTheEventSolverHasNoResult()
        Dim results = SampleResults.Results()
        results(0) = New BenchResult With {.Scene = "projectile", .Solver = "event", .Runs = 0,
                                           .Note = "stopped at 0.5 s simulated: over the 30 s wall-clock budget"}
        Dim md = MarkdownReport.Render(SampleResults.Machine(), "full", 5, SampleResults.Scenes(), results, New FrameResult)
        Assert.Contains("| no result: stopped at 0.5 s simulated: over the 30 s wall-clock budget | 3.0e-3 (euler, dt = 1/1000)", md)
    End Sub

    <Fact>
    Public Sub Render_NamesTheMachine()
        Dim md = Render()
        Assert.Contains("| CPU | Test CPU 3000 |", md)
        Assert.Contains("| Cores | 2 |", md)
        Assert.Contains("| Memory | 23.5 GB |", md)
        Assert.Contains("| .NET | .NET 10.0.0 |", md)
        Assert.Contains("| Date | 2026-01-02 03:04 UTC |", md)
    End Sub

    <Fact>
    Public Sub Render_WritesOneTableRowPerCase_AndListsAMissingSolverAsNotAvailable()
        Dim md = Render()
        Assert.Contains("| euler | 1/60 | 5.0e-2 | 0.100 | 10 |  |", md)
        Assert.Contains("| event | — | 0 | 0.020 | 50 |  |", md)
        Assert.Contains("| verlet | — | — | — | — | not available in this build |", md)
        Assert.Contains("![Projectile: position at landing](benchmark-projectile.svg)", md)
    End Sub

    <Fact>
    Public Sub Render_WritesTheScalingTableWithMicrosecondsPerCollisionAndPeakMemory()
        Dim md = Render()
        Assert.Contains("| 1,000 | event | — | 40.0 | 1,234,567 | 0.81 | 40.50 |", md)
        Assert.Contains("| 10,000 | event | — | 450 | 987,654 | 1.01 | 60.25 |", md)
    End Sub

    <Fact>
    Public Sub Render_TheTextbookBaseline_IsListedBesideTheEventSolver_AndNamedInTheHeadlineForScale()
        Dim results = SampleResults.Results()
        results.Add(New BenchResult With {.Scene = "gas-scaling", .Solver = "verlet", .TimeStep = 0.001, .BodyCount = 1000, .MsPerSimulatedSecond = 900,
                                          .CollisionsPerSecond = 5000, .MicrosecondsPerCollision = 200, .PeakMegabytes = 40, .Runs = 5})
        results.Add(New BenchResult With {.Scene = "gas-scaling", .Solver = "textbook", .BodyCount = 10000, .MsPerSimulatedSecond = 600,
                                          .CollisionsPerSecond = 555555, .MicrosecondsPerCollision = 1.8, .PeakMegabytes = 38, .Runs = 5})
        results.Add(New BenchResult With {.Scene = "gas-scaling", .Solver = "textbook", .BodyCount = 1000, .MsPerSimulatedSecond = 50,
                                          .CollisionsPerSecond = 777777, .MicrosecondsPerCollision = 1.29, .PeakMegabytes = 34, .Runs = 5})
        Dim md = MarkdownReport.Render(SampleResults.Machine(), "full", 5, SampleResults.Scenes(), results, New FrameResult)
        Dim head = md.Substring(0, md.IndexOf("## Machine", StringComparison.Ordinal))
        Assert.Contains("- For scale, the textbook baseline (a plain event-driven gas, not the engine; see the scaling section) on the same machine: " &
                        "777,777 collisions per second at N = 1,000 and 555,555 collisions per second at N = 10,000.", head)
        ' The engine's figures stay the headline's own.
        Assert.Contains("N = 1,000: **1,234,567 collisions per second**", head)
        Dim order = Values("| 1,000 | event |", "| 10,000 | event |", "| 1,000 | textbook |", "| 10,000 | textbook |", "| 1,000 | verlet |").
            Select(Function(row) md.IndexOf(row, StringComparison.Ordinal)).ToList()
        Assert.DoesNotContain(-1, order)
        Assert.Equal(order.OrderBy(Function(k) k), order)
        Assert.Contains("The *textbook* rows are not the engine", md)
        Dim plot = MarkdownReport.Plots(SampleResults.Scenes(), results)("benchmark-gas-scaling.svg")
        Assert.Contains(">textbook baseline<", plot)
    End Sub

    <Fact>
    Public Sub Render_SaysWhyTheFrameBudgetWasNotMeasured_OrGivesIt()
        Assert.Contains("Not measured in this run: mono is not installed.", Render())
        Dim ran = Render(New FrameResult With {.Ran = True, .Circles = 1000, .StepMs = 3.25, .PaintMs = 9.5, .RawJson = "{""stepMs"":3.25}"})
        Assert.Contains("1000 circles: step 3.25 ms + paint 9.50 ms, target < 16 ms (met).", ran)
    End Sub

    <Fact>
    Public Sub Render_GivesTheTracesAndCentreOfMassRow_WhenTheAppMeasuredIt()
        Dim plain = New FrameResult With {.Ran = True, .Circles = 1000, .StepMs = 3.25, .PaintMs = 2.0, .RawJson = "{""stepMs"":3.25}"}
        Assert.DoesNotContain("Traces + COM on", Render(plain))
        plain.Views = New FrameResult With {.Ran = True, .Circles = 1000, .StepMs = 3.5, .PaintMs = 13.0, .RawJson = "{""views"":""traces+com""}"}
        Dim md = Render(plain)
        Assert.Contains("step 3.50 ms + paint 13.00 ms, target < 16 ms (missed).", md)
        Assert.Contains("{""views"":""traces+com""}", md)
    End Sub

    <Fact>
    Public Sub Plots_MakesOneWorkPrecisionPlotPerSceneAndOneScalingPlot()
        Dim files = MarkdownReport.Plots(SampleResults.Scenes(), SampleResults.Results())
        Assert.Equal(Values("benchmark-gas-scaling.svg", "benchmark-projectile.svg"), files.Keys.OrderBy(Function(k) k, StringComparer.Ordinal))
    End Sub
End Class
