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

    <GuiFact>
    Public Sub FrameBenchmark_BadCount_IsAOneLineError()
        Dim r = ProcessRunner.Run("mono", {XSession.AppExe, "--frame-benchmark", "lots"}, Nothing, TimeSpan.FromMinutes(1))
        Assert.Equal(2, r.ExitCode)
        Assert.Contains("--frame-benchmark needs a number of circles", r.StdErr, StringComparison.Ordinal)
    End Sub
End Class
