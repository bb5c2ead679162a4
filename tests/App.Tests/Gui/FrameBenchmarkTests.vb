Option Strict On
Imports System.Text.RegularExpressions
Imports Xunit

''' <summary>The app's --frame-benchmark switch: no window, one JSON line, then exit.</summary>
<Collection(RealWindow.Name)>
Public Class FrameBenchmarkTests
    <GuiFact>
    Public Sub FrameBenchmark_PrintsTwoJsonLines_WithAndWithoutTheMomentumViews_WithoutADisplay()
        Dim env As New Dictionary(Of String, String) From {{"DISPLAY", ""}}
        Dim r = ProcessRunner.Run("mono", {XSession.AppExe, "--frame-benchmark", "30"}, env, TimeSpan.FromMinutes(2))
        Assert.True(r.ExitCode = 0, r.ToString())
        Dim lines = r.StdOut.Split({vbLf}, StringSplitOptions.RemoveEmptyEntries).Select(Function(l) l.Trim()).ToArray()
        Assert.Equal(2, lines.Length)
        ' The views' row first; the plain row is the last line.
        Assert.EndsWith(",""views"":""traces+com""}", lines(0), StringComparison.Ordinal)
        Assert.EndsWith(",""views"":""none""}", lines(1), StringComparison.Ordinal)
        For Each line In lines
            Assert.StartsWith("{""benchmark"":""frame"",""circles"":30,""frames"":300,", line, StringComparison.Ordinal)
            For Each key In {"step_median_ms", "step_p95_ms", "paint_median_ms", "paint_p95_ms", "total_median_ms", "total_p95_ms"}
                Dim m = Regex.Match(line, """" & key & """:(\d+\.\d+)")
                Assert.True(m.Success, key & " missing in " & line)
                Assert.True(AppDriver.Dbl(m.Groups(1).Value) > 0, key & " is zero in " & line)
            Next
        Next
    End Sub

    ' The scenes' energies from their definitions: the cradle's first ball 1 − cos 30° m above the
    ' other four at 1.5 m (1 kg each); the rope's ten 0.2 kg balls level at 4 m and three 1 kg balls at 0.15 m.
    <GuiTheory>
    <InlineData("cradle", 5, 5, 9.81 * ((2.5 - 0.86602540378443865) + 4 * 1.5))>
    <InlineData("rope", 13, 10, 9.81 * (10 * 0.2 * 4.0 + 3 * 1.0 * 0.15))>
    Public Sub FrameBenchmark_Scene_PrintsOneJsonLine_OfItsWholeSpan(scene As String, bodies As Integer, links As Integer, energy As Double)
        Dim env As New Dictionary(Of String, String) From {{"DISPLAY", ""}}
        Dim r = ProcessRunner.Run("mono", {XSession.AppExe, "--frame-benchmark", scene}, env, TimeSpan.FromMinutes(2))
        Assert.True(r.ExitCode = 0, r.ToString())
        Dim lines = r.StdOut.Split({vbLf}, StringSplitOptions.RemoveEmptyEntries).Select(Function(l) l.Trim()).ToArray()
        Dim line = Assert.Single(lines)
        Assert.StartsWith("{""benchmark"":""frame"",""scene"":""" & scene & """,""bodies"":" & bodies & ",""links"":" & links & ",", line, StringComparison.Ordinal)
        Assert.Contains(",""solver"":""event"",", line, StringComparison.Ordinal)
        Assert.Equal(energy, Field(line, "energy_j"), 6)
        Dim frames = Field(line, "frames")
        Assert.Equal(300, frames)
        ' Every frame advances 1/60 s unless the presenter had to let time lag (its slow frames).
        If Field(line, "slow_frames") = 0 Then Assert.Equal(frames / 60, Field(line, "simulated_s"), 3)
        ' What the budget held back is what the frames asked for and the world did not do (both printed to 1 ms).
        Dim lag = Field(line, "lag_s")
        Assert.InRange(lag, 0, frames / 60)
        Assert.InRange(frames / 60 - Field(line, "simulated_s") - lag, -0.0011, 0.0011)
        If Field(line, "slow_frames") = 0 Then Assert.Equal(0, lag)
        For Each part In {"step", "paint", "total"}
            Dim median = Field(line, part & "_median_ms"), p95 = Field(line, part & "_p95_ms"), worst = Field(line, part & "_max_ms")
            Assert.True(median > 0 AndAlso median <= p95 AndAlso p95 <= worst, part & ": median, p95 and worst out of order in " & line)
        Next
        ' A frame is its step and its paint: the worst frame is at least the worst of either, at most both.
        Dim worstFrame = Field(line, "total_max_ms")
        Assert.InRange(worstFrame, Math.Max(Field(line, "step_max_ms"), Field(line, "paint_max_ms")) - 0.002, Field(line, "step_max_ms") + Field(line, "paint_max_ms") + 0.002)
        Assert.Equal(16, Field(line, "target_ms"))
        Assert.InRange(Field(line, "over_target_frames"), 0, frames)
        If worstFrame < 16 Then Assert.Equal(0, Field(line, "over_target_frames"))
    End Sub

    <GuiFact>
    Public Sub FrameBenchmark_BadSceneName_IsAOneLineError_NamingTheScenes()
        Dim r = ProcessRunner.Run("mono", {XSession.AppExe, "--frame-benchmark", "galtn"}, Nothing, TimeSpan.FromMinutes(1))
        Assert.Equal(2, r.ExitCode)
        Assert.Equal("", r.StdOut.Trim())
        Dim message = Assert.Single(r.StdErr.Split({vbLf}, StringSplitOptions.RemoveEmptyEntries))
        Assert.Contains("--frame-benchmark needs a number of circles from 1 to 100000 or a scene (galton, rope, cradle), not 'galtn'", message, StringComparison.Ordinal)
    End Sub

    Private Shared Function Field(line As String, key As String) As Double
        Dim m = Regex.Match(line, """" & key & """:(-?\d+(\.\d+)?([eE][-+]?\d+)?)[,}]")
        Assert.True(m.Success, key & " missing in " & line)
        Return AppDriver.Dbl(m.Groups(1).Value)
    End Function

    <GuiFact>
    Public Sub FrameBenchmark_BadCount_IsAOneLineError()
        Dim r = ProcessRunner.Run("mono", {XSession.AppExe, "--frame-benchmark", "lots"}, Nothing, TimeSpan.FromMinutes(1))
        Assert.Equal(2, r.ExitCode)
        Assert.Contains("--frame-benchmark needs a number of circles", r.StdErr, StringComparison.Ordinal)
    End Sub
End Class
