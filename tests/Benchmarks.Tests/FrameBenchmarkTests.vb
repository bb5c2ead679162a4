Option Strict On
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>Reading the app's frame-benchmark line.</summary>
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
End Class
