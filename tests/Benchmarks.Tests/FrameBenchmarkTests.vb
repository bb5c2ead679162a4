Option Strict On
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>Reading the app's frame-benchmark line, and finding an X display number for it.</summary>
Public Class FrameBenchmarkTests
    <Fact>
    Public Sub Interpret_PrefersMedianStepAndPaintTimes()
        Dim r = FrameBenchmark.Interpret("{""circles"":1000,""frames"":200,""stepMsMedian"":2.5,""stepMsMax"":9,""paintMsMedian"":7.25,""paintMsMax"":20}", New FrameResult)
        Assert.True(r.Ran)
        Assert.Equal(1000, r.Circles)
        Assert.Equal(2.5, r.StepMs)
        Assert.Equal(7.25, r.PaintMs)
    End Sub

    <Fact>
    Public Sub Interpret_ReadsTheAppsOwnLine_MediansNotP95()
        Dim line = "{""benchmark"":""frame"",""circles"":1000,""frames"":300,""frame_s"":0.016666666666666666,""solver"":""euler"",""canvas"":""860x496""," &
                   """step_median_ms"":4.125,""step_p95_ms"":6.500,""paint_median_ms"":8.250,""paint_p95_ms"":11.000,""total_median_ms"":12.375,""total_p95_ms"":17.000}"
        Dim r = FrameBenchmark.Interpret(line, New FrameResult)
        Assert.True(r.Ran)
        Assert.Equal(1000, r.Circles)
        Assert.Equal(4.125, r.StepMs)
        Assert.Equal(8.25, r.PaintMs)
        Assert.Equal(line, r.RawJson)
    End Sub

    <Fact>
    Public Sub Interpret_ReadsNestedFields()
        Dim r = FrameBenchmark.Interpret("{""n"":500,""step"":{""mean"":1.5},""paint"":{""mean"":4}}", New FrameResult)
        Assert.True(r.Ran)
        Assert.Equal(500, r.Circles)
        Assert.Equal(1.5, r.StepMs)
        Assert.Equal(4.0, r.PaintMs)
    End Sub

    <Fact>
    Public Sub Interpret_SaysSoWhenTheLineIsNotUsable()
        Dim broken = FrameBenchmark.Interpret("{not json", New FrameResult)
        Assert.False(broken.Ran)
        Assert.StartsWith("the app's line is not JSON", broken.Note)
        Dim noTimes = FrameBenchmark.Interpret("{""fps"":60}", New FrameResult)
        Assert.False(noTimes.Ran)
        Assert.Contains("no step and paint times", noTimes.Note)
    End Sub

    <Fact>
    Public Sub FreeDisplay_SkipsALiveServersLock_AndClearsADeadOnesLock()
        Dim d = XDisplays.FreeDisplay(91, 160)
        Assert.InRange(d, 91, 160)
        Dim lockFile = "/tmp/.X" & d & "-lock"
        Try
            ' A lock naming a running process (this one): taken.
            IO.File.WriteAllText(lockFile, Environment.ProcessId.ToString(Globalization.CultureInfo.InvariantCulture).PadLeft(10) & vbLf)
            Assert.NotEqual(d, XDisplays.FreeDisplay(91, 160))
            ' A lock naming a process that has exited (an Xvfb killed without cleaning up): free again.
            Dim gone As Integer
            Using p = Diagnostics.Process.Start("true")
                p.WaitForExit()
                gone = p.Id
            End Using
            IO.File.WriteAllText(lockFile, gone.ToString(Globalization.CultureInfo.InvariantCulture).PadLeft(10) & vbLf)
            Assert.Equal(d, XDisplays.FreeDisplay(91, 160))
            Assert.False(IO.File.Exists(lockFile))
        Finally
            IO.File.Delete(lockFile)
        End Try
    End Sub
End Class

''' <summary>The check that keeps the benchmark from starting an app that does not know the option.</summary>
Public Class FrameBenchmarkOptionCheckTests
    <Fact>
    Public Sub KnowsOption_FindsTheOptionStoredAsUtf16_AndNothingElse()
        Dim path = IO.Path.GetTempFileName()
        Try
            Dim bytes As New List(Of Byte)(Text.Encoding.ASCII.GetBytes("MZ header"))
            bytes.AddRange(Text.Encoding.Unicode.GetBytes("--frame-benchmark"))
            IO.File.WriteAllBytes(path, bytes.ToArray())
            Assert.True(FrameBenchmark.KnowsOption(path, "--frame-benchmark"))
            Assert.False(FrameBenchmark.KnowsOption(path, "--other-option"))
            IO.File.WriteAllBytes(path, Text.Encoding.ASCII.GetBytes("--frame-benchmark")) ' one byte per char: not a .NET literal
            Assert.False(FrameBenchmark.KnowsOption(path, "--frame-benchmark"))
        Finally
            IO.File.Delete(path)
        End Try
    End Sub
End Class
