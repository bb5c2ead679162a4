Option Strict On
Imports System.Text.Json
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>The JSON file other runs are compared against: its shape is a contract.</summary>
Public Class JsonReportTests
    <Fact>
    Public Sub ToJson_HasTheMachineAndOneObjectPerResult_WithEveryComparedField()
        Using doc = JsonDocument.Parse(JsonReport.ToJson(SampleResults.Machine(), "quick", SampleResults.Results()))
            Dim root = doc.RootElement
            Assert.Equal(1, root.GetProperty("formatVersion").GetInt32())
            Assert.Equal("quick", root.GetProperty("mode").GetString())
            Assert.Equal("Test CPU 3000", root.GetProperty("machine").GetProperty("cpu").GetString())
            Assert.Equal(2, root.GetProperty("machine").GetProperty("cores").GetInt32())
            Dim results = root.GetProperty("results").EnumerateArray().ToList()
            Assert.Equal(6, results.Count)
            For Each r In results
                For Each field In {"scene", "solver", "dt", "error", "errorMetric", "msPerSimulatedSecond", "collisionsPerSecond",
                                   "microsecondsPerCollision", "n", "peakMB", "available", "note"}
                    Dim p As JsonElement
                    Assert.True(r.TryGetProperty(field, p), "missing " & field)
                Next
            Next
            Dim euler = results(1)
            Assert.Equal("euler", euler.GetProperty("solver").GetString())
            Assert.Equal(1 / 60.0, euler.GetProperty("dt").GetDouble(), 15)
            Assert.Equal(0.05, euler.GetProperty("error").GetDouble())
            Assert.Equal("position error at landing (m)", euler.GetProperty("errorMetric").GetString())
            ' The event solver has no step; a value that was not measured is null, never NaN (which JSON cannot hold).
            Assert.Equal(JsonValueKind.Null, results(0).GetProperty("dt").ValueKind)
            Assert.Equal(JsonValueKind.Null, results(0).GetProperty("peakMB").ValueKind)
            Assert.False(results(3).GetProperty("available").GetBoolean())
            Assert.Equal(1000, results(4).GetProperty("n").GetInt32())
            Assert.Equal(40.5, results(4).GetProperty("peakMB").GetDouble())
        End Using
    End Sub

    <Fact>
    Public Sub ToLine_IsOneLine_AndParsesBackToTheSameResult()
        Dim r = SampleResults.Results()(1)
        r.Note = "a note with + and µ"
        r.Rounds = 3
        r.SlowestCollisionsPerSecond = 8.5
        r.FastestCollisionsPerSecond = 12.25
        Dim line = JsonReport.ToLine(r)
        Assert.DoesNotContain(vbLf, line)
        Assert.Contains("+ and µ", line)
        Dim back = JsonReport.Parse(line)
        Assert.Equal(r.Scene, back.Scene)
        Assert.Equal(r.Solver, back.Solver)
        Assert.Equal(r.TimeStep, back.TimeStep)
        Assert.Equal(r.Error, back.Error)
        Assert.Equal(r.MsPerSimulatedSecond, back.MsPerSimulatedSecond)
        Assert.True(Double.IsNaN(back.PeakMegabytes))
        Assert.Equal(3, back.Rounds)
        Assert.Equal(8.5, back.SlowestCollisionsPerSecond)
        Assert.Equal(12.25, back.FastestCollisionsPerSecond)
        Assert.Equal(r.Note, back.Note)
    End Sub

    <Fact>
    Public Sub Parse_ReadsAResultWrittenBeforeRoundsExisted_AsOneRun()
        Dim back = JsonReport.Parse("{""scene"":""gas-scaling"",""solver"":""event"",""dt"":null,""available"":true,""error"":null,""errorMetric"":""none"",""msPerSimulatedSecond"":40,""collisionsPerSecond"":1000,""microsecondsPerCollision"":1,""n"":1000,""peakMB"":null,""simulatedSeconds"":1,""runs"":5,""note"":""old""}")
        Assert.Equal(1, back.Rounds)
        Assert.True(Double.IsNaN(back.SlowestCollisionsPerSecond))
        Assert.Equal(1000, back.CollisionsPerSecond)
    End Sub
End Class
