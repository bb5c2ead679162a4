Option Strict On
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>
''' The app's lesson-scene frame lines (--frame-benchmark galton|rope|cradle): reading them, checking
''' that the app timed the report's scene, the verdict against 16 ms, and the report's table.
''' </summary>
Public Class SceneFramesTests
    ' Shaped as the app prints it; every number distinct, so a field read into the wrong place shows.
    Private Const CradleLine As String =
        "{""benchmark"":""frame"",""scene"":""cradle"",""bodies"":5,""links"":5,""energy_j"":74.889290788874661,""frames"":300," &
        """frame_s"":0.016666666666666666,""simulated_s"":4.950,""solver"":""event"",""canvas"":""860x496""," &
        """step_median_ms"":0.032,""step_p95_ms"":0.081,""step_max_ms"":4.131," &
        """paint_median_ms"":0.401,""paint_p95_ms"":2.251,""paint_max_ms"":6.331," &
        """total_median_ms"":0.436,""total_p95_ms"":3.998,""total_max_ms"":17.366," &
        """target_ms"":16,""over_target_frames"":2,""slow_frames"":3,""lag_s"":0.125}"

    ' The scenes' energies at the start from their definitions, J: the cradle's first ball 1 − cos 30° m
    ' above the four others at 1.5 m (1 kg each), the rope's ten 0.2 kg balls at 4 m and three 1 kg at 0.15 m.
    Private Const CradleEnergy As Double = 9.81 * ((2.5 - 0.86602540378443865) + 4 * 1.5)
    Private Const RopeEnergy As Double = 9.81 * (10 * 0.2 * 4.0 + 3 * 1.0 * 0.15)

    Private Shared Function Scene(name As String) As IBenchScene
        Return SceneCatalog.Create(name, BenchmarkOptions.Parse(Array.Empty(Of String)()))
    End Function

    <Fact>
    Public Sub InterpretScene_ReadsEveryFieldIntoItsPlace()
        Dim r = FrameBenchmark.InterpretScene(CradleLine, New SceneFrameResult With {.Scene = "cradle"})
        Assert.True(r.Ran, r.Note)
        Assert.Equal("", r.Note)
        Assert.Equal(300, r.Frames)
        Assert.Equal(4.95, r.SimulatedSeconds)
        Assert.Equal("event", r.Solver)
        Assert.Equal(Values(0.032, 0.081, 4.131), Values(r.StepMs.Median, r.StepMs.P95, r.StepMs.Worst))
        Assert.Equal(Values(0.401, 2.251, 6.331), Values(r.PaintMs.Median, r.PaintMs.P95, r.PaintMs.Worst))
        Assert.Equal(Values(0.436, 3.998, 17.366), Values(r.TotalMs.Median, r.TotalMs.P95, r.TotalMs.Worst))
        Assert.Equal(16, r.TargetMs)
        Assert.Equal(2, r.OverTargetFrames)
        Assert.Equal(3, r.SlowFrames)
        Assert.Equal(0.125, r.LagSeconds)
        Assert.Equal(5, r.Bodies)
        Assert.Equal(5, r.Links)
        Assert.Equal(74.889290788874661, r.EnergyJoules)
        Assert.Equal(CradleLine, r.RawJson)
    End Sub

    <Fact>
    Public Sub InterpretScene_SaysWhatIsWrongWithALineItCannotUse()
        Dim broken = FrameBenchmark.InterpretScene("{""benchmark"":""frame"",", New SceneFrameResult With {.Scene = "rope"})
        Assert.False(broken.Ran)
        Assert.StartsWith("the app's line is not JSON", broken.Note, StringComparison.Ordinal)
        ' The gas's line has medians and p95s but no worst frame and no target: not a scene's line.
        Dim gas = "{""benchmark"":""frame"",""circles"":1000,""frames"":300,""step_median_ms"":4.1,""step_p95_ms"":6.5,""paint_median_ms"":8.2," &
                  """paint_p95_ms"":11.0,""total_median_ms"":12.3,""total_p95_ms"":17.0,""views"":""none""}"
        Dim noWorst = FrameBenchmark.InterpretScene(gas, New SceneFrameResult With {.Scene = "rope"})
        Assert.False(noWorst.Ran)
        Assert.StartsWith("no frame count, target and median, 95th-percentile and worst", noWorst.Note, StringComparison.Ordinal)
        Dim other = FrameBenchmark.InterpretScene(CradleLine, New SceneFrameResult With {.Scene = "galton"})
        Assert.False(other.Ran)
        Assert.Equal("the app timed the scene 'cradle', not 'galton'.", other.Note)
    End Sub

    <Fact>
    Public Sub SceneRows_NameTheAppsScenes_AndTheReportsScenesTheyBuild()
        Assert.Equal(Values("galton", "rope", "cradle"), FrameBenchmark.SceneRows.Select(Function(r) r.AppName))
        For Each row In FrameBenchmark.SceneRows
            Assert.Contains(row.ReportScene, BenchmarkOptions.AllScenes)
        Next
    End Sub

    <Theory>
    <InlineData("cradle-strings", 5, 5, CradleEnergy)>
    <InlineData("rope", 13, 10, RopeEnergy)>
    Public Sub CheckSameScene_AcceptsTheReportsScene_ByItsClosedFormEnergy(name As String, bodies As Integer, links As Integer, energy As Double)
        ' The app's test holds its scenes to the same closed forms, so the two builders agree through them.
        Dim r As New SceneFrameResult With {.Bodies = bodies, .Links = links, .EnergyJoules = energy}
        Assert.True(FrameBenchmark.CheckSameScene(r, Scene(name)), r.Note)
        Assert.Equal("", r.Note)
    End Sub

    <Fact>
    Public Sub CheckSameScene_SaysSoWhenTheAppBuiltAnotherScene()
        ' The rope lesson file's start (e = 0.8, hanging at an angle) is not the report's rope, released level.
        Dim r As New SceneFrameResult With {.Bodies = 13, .Links = 10, .EnergyJoules = RopeEnergy - 5, .Note = "remark."}
        Assert.False(FrameBenchmark.CheckSameScene(r, Scene("rope")))
        Assert.StartsWith("remark. the app's scene is not the report's rope scene (13 bodies, 10 links, ", r.Note, StringComparison.Ordinal)
        Dim fewer As New SceneFrameResult With {.Bodies = 12, .Links = 10, .EnergyJoules = RopeEnergy}
        Assert.False(FrameBenchmark.CheckSameScene(fewer, Scene("rope")))
    End Sub

    <Fact>
    Public Sub Verdict_IsMetOnlyWhenEveryFrameIsUnderTheTarget_AndSaysHowManyWereNot()
        Dim r = FrameBenchmark.InterpretScene(CradleLine, New SceneFrameResult With {.Scene = "cradle"})
        ' p95 3.998 ms, worst 17.366 ms, 2 frames over.
        Assert.Equal("met by 95 % of frames, not by the worst 2.", MarkdownReport.Verdict(r))
        r.TotalMs.Worst = 15.9
        r.OverTargetFrames = 0
        Assert.Equal("met: every frame under 16 ms.", MarkdownReport.Verdict(r))
        r.TotalMs.P95 = 16.0
        r.TotalMs.Worst = 40
        r.OverTargetFrames = 30
        Assert.Equal("missed: 30 of 300 frames took 16 ms or more.", MarkdownReport.Verdict(r))
        Assert.Equal("not measured", MarkdownReport.Verdict(New SceneFrameResult))
    End Sub

    <Fact>
    Public Sub Report_HasOneRowPerScene_WithTheTargetBesideIt_AndTheAppsLines()
        Dim cradle = FrameBenchmark.InterpretScene(CradleLine, New SceneFrameResult With {.Scene = "cradle", .ReportScene = "cradle-strings"})
        Dim galton As New SceneFrameResult With {.Scene = "galton", .ReportScene = "galton", .Note = "the app did not finish within 5 minutes."}
        Dim md = MarkdownReport.Render(SampleResults.Machine(), "full", 5, SampleResults.Scenes(), SampleResults.Results(), New FrameResult With {.Note = "mono is not installed."},
                                       {galton, cradle})
        Dim section = md.Substring(md.IndexOf("### Lesson scenes in the app", StringComparison.Ordinal))
        Assert.True(section.IndexOf("| galton |", StringComparison.Ordinal) < section.IndexOf("| cradle |", StringComparison.Ordinal))
        Assert.Contains("| galton | — | — | — | — | — | < 16 ms | — | — | not measured: the app did not finish within 5 minutes. |", section)
        Assert.Contains("| cradle | 300 (4.95) | event | 0.03 / 0.08 / 4.13 | 0.40 / 2.25 / 6.33 | 0.44 / 4.00 / 17.37 | < 16 ms | 2 | 3 (0.13 s) | met by 95 % of frames, not by the worst 2. |", section)
        Assert.Contains(CradleLine, section)
        ' A line from before the app reported the time held back has no lag beside its lagging frames.
        Dim older = FrameBenchmark.InterpretScene(CradleLine.Replace(",""lag_s"":0.125", ""), New SceneFrameResult With {.Scene = "cradle", .ReportScene = "cradle-strings"})
        Assert.True(Double.IsNaN(older.LagSeconds))
        Dim olderMd = MarkdownReport.Render(SampleResults.Machine(), "full", 5, SampleResults.Scenes(), SampleResults.Results(), New FrameResult With {.Note = "mono is not installed."}, {older})
        Assert.Contains("| < 16 ms | 2 | 3 | met by 95 % of frames", olderMd)
        ' Without scene rows (an older caller) the section is left out.
        Assert.DoesNotContain("### Lesson scenes", MarkdownReport.Render(SampleResults.Machine(), "full", 5, SampleResults.Scenes(), SampleResults.Results(), New FrameResult))
    End Sub
End Class
