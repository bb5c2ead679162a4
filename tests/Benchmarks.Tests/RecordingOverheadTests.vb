Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit
Imports Xunit.Abstractions

''' <summary>The recording benchmark runs both kinds of run and reports what the recorded one kept (its timing is the benchmark's, not checked here).</summary>
Public Class RecordingOverheadTests
    Private ReadOnly _output As ITestOutputHelper

    Public Sub New(output As ITestOutputHelper)
        _output = output
    End Sub

    <Fact>
    Public Sub Measure_TakesACheckpointEveryFiveHundredEventsPerBall_AndReportsTheOverhead()
        Dim r = RecordingOverhead.Measure(balls:=1000, seconds:=60, repeats:=1)
        _output.WriteLine($"checkpoint {r.CheckpointMs:0.0} ms, from parts {100 * r.OverheadFromParts:0.0} %, plain {r.PlainSeconds:0.000} s, recorded {r.RecordedSeconds:0.000} s, overhead {100 * r.Overhead:0.0} %, {r.Events} events, {r.Checkpoints} checkpoints, {r.Bytes} bytes")
        Dim between = Timeline.EventsBetweenCheckpoints(1000)
        Assert.Equal(500000L, between)
        Assert.True(r.Events > 2 * between, "a run long enough for several checkpoints")
        ' One at the start, then one at the first frame after each further 500 000 events.
        Dim expected = 1 + r.Events \ between
        Assert.InRange(r.Checkpoints, CInt(expected) - 1, CInt(expected) + 1)
        Assert.True(r.Bytes > r.Checkpoints * 1000L * 50, "each checkpoint holds the 1000 balls")
        Dim text = RecordingOverhead.Section(r)
        Assert.Contains("| recorded for rewind |", text)
        Assert.Contains("Overhead of recording, the two runs compared: **", text)
        Assert.True(r.CheckpointMs > 0)
        Assert.Equal(r.CheckpointMs / 1000 / (between * r.PlainSeconds / r.Events), r.OverheadFromParts, 9)
    End Sub
End Class
