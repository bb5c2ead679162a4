Option Strict On
Imports System.IO
Imports System.Text
Imports System.Text.Encodings.Web
Imports System.Text.Json

''' <summary>
''' The results as JSON, for comparing runs: one object per case with scene, solver, dt, error, error
''' metric, ms per simulated second, collisions per second, N and peak MB, and for a case run in several
''' rounds (the gas scaling) how many and their slowest and fastest, for a settling scene its time at
''' rest and the wall-clock time to reach it. NaN is written as null.
''' The same object, on one line, carries a result from a child process to its parent.
''' </summary>
Friend Module JsonReport
    ''' <summary>Version of the file's shape; bump it when a field changes meaning.</summary>
    Public Const FormatVersion As Integer = 1

    ' The file is read by people and by diff tools, not embedded in HTML: keep "+", "µ" and "²" as they are.
    Private ReadOnly Readable As JavaScriptEncoder = JavaScriptEncoder.UnsafeRelaxedJsonEscaping

    ''' <summary>The whole report: machine, mode and every result.</summary>
    Public Function ToJson(machine As MachineInfo, mode As String, results As IEnumerable(Of BenchResult)) As String
        If machine Is Nothing Then Throw New ArgumentNullException(NameOf(machine))
        If results Is Nothing Then Throw New ArgumentNullException(NameOf(results))
        Using buffer As New MemoryStream()
            Using w As New Utf8JsonWriter(buffer, New JsonWriterOptions With {.Indented = True, .Encoder = Readable})
                w.WriteStartObject()
                w.WriteNumber("formatVersion", FormatVersion)
                w.WriteString("mode", mode)
                w.WriteStartObject("machine")
                w.WriteString("date", machine.Date)
                w.WriteString("cpu", machine.CpuModel)
                w.WriteNumber("cores", machine.Cores)
                w.WriteNumber("memoryGB", Math.Round(machine.MemoryGigabytes, 1))
                w.WriteString("os", machine.OperatingSystem)
                w.WriteString("dotnet", machine.DotNet)
                w.WriteEndObject()
                w.WriteStartArray("results")
                For Each r In results
                    WriteResult(w, r)
                Next
                w.WriteEndArray()
                w.WriteEndObject()
            End Using
            Return Encoding.UTF8.GetString(buffer.ToArray())
        End Using
    End Function

    ''' <summary>One result on one line (no line breaks inside).</summary>
    Public Function ToLine(result As BenchResult) As String
        Using buffer As New MemoryStream()
            Using w As New Utf8JsonWriter(buffer, New JsonWriterOptions With {.Encoder = Readable})
                WriteResult(w, result)
            End Using
            Return Encoding.UTF8.GetString(buffer.ToArray())
        End Using
    End Function

    ''' <summary>Reads a result written by <see cref="ToLine"/> or found in the results array.</summary>
    Public Function Parse(json As String) As BenchResult
        Using doc = JsonDocument.Parse(json)
            Return Parse(doc.RootElement)
        End Using
    End Function

    ''' <summary>Reads one result object.</summary>
    Public Function Parse(e As JsonElement) As BenchResult
        Return New BenchResult With {
            .Scene = e.GetProperty("scene").GetString(),
            .Solver = e.GetProperty("solver").GetString(),
            .TimeStep = NullableNumber(e, "dt"),
            .Available = e.GetProperty("available").GetBoolean(),
            .Error = Number(e, "error"),
            .ErrorMetric = e.GetProperty("errorMetric").GetString(),
            .MsPerSimulatedSecond = Number(e, "msPerSimulatedSecond"),
            .CollisionsPerSecond = Number(e, "collisionsPerSecond"),
            .MicrosecondsPerCollision = Number(e, "microsecondsPerCollision"),
            .BodyCount = e.GetProperty("n").GetInt32(),
            .PeakMegabytes = Number(e, "peakMB"),
            .SimulatedSeconds = Number(e, "simulatedSeconds"),
            .Runs = e.GetProperty("runs").GetInt32(),
            .Rounds = RoundsOf(e),
            .SlowestCollisionsPerSecond = Number(e, "slowestCollisionsPerSecond"),
            .FastestCollisionsPerSecond = Number(e, "fastestCollisionsPerSecond"),
            .RestSeconds = Number(e, "restSeconds"),
            .RestWallMs = Number(e, "restWallMs"),
            .Note = e.GetProperty("note").GetString()}
    End Function

    Private Sub WriteResult(w As Utf8JsonWriter, r As BenchResult)
        w.WriteStartObject()
        w.WriteString("scene", r.Scene)
        w.WriteString("solver", r.Solver)
        If r.TimeStep.HasValue Then w.WriteNumber("dt", r.TimeStep.Value) Else w.WriteNull("dt")
        w.WriteBoolean("available", r.Available)
        WriteNumber(w, "error", r.Error)
        w.WriteString("errorMetric", r.ErrorMetric)
        WriteNumber(w, "msPerSimulatedSecond", r.MsPerSimulatedSecond)
        WriteNumber(w, "collisionsPerSecond", r.CollisionsPerSecond)
        WriteNumber(w, "microsecondsPerCollision", r.MicrosecondsPerCollision)
        w.WriteNumber("n", r.BodyCount)
        WriteNumber(w, "peakMB", r.PeakMegabytes)
        WriteNumber(w, "simulatedSeconds", r.SimulatedSeconds)
        w.WriteNumber("runs", r.Runs)
        w.WriteNumber("rounds", r.Rounds)
        WriteNumber(w, "slowestCollisionsPerSecond", r.SlowestCollisionsPerSecond)
        WriteNumber(w, "fastestCollisionsPerSecond", r.FastestCollisionsPerSecond)
        WriteNumber(w, "restSeconds", r.RestSeconds)
        WriteNumber(w, "restWallMs", r.RestWallMs)
        w.WriteString("note", r.Note)
        w.WriteEndObject()
    End Sub

    Private Sub WriteNumber(w As Utf8JsonWriter, name As String, value As Double)
        If Double.IsNaN(value) OrElse Double.IsInfinity(value) Then w.WriteNull(name) Else w.WriteNumber(name, value)
    End Sub

    ''' <summary>The "rounds" field; 1 when absent (files written before it existed).</summary>
    Private Function RoundsOf(e As JsonElement) As Integer
        Dim p As JsonElement
        If Not e.TryGetProperty("rounds", p) OrElse p.ValueKind <> JsonValueKind.Number Then Return 1
        Return p.GetInt32()
    End Function

    Private Function Number(e As JsonElement, name As String) As Double
        Dim n = NullableNumber(e, name)
        Return If(n.HasValue, n.Value, Double.NaN)
    End Function

    Private Function NullableNumber(e As JsonElement, name As String) As Double?
        Dim p As JsonElement
        If Not e.TryGetProperty(name, p) OrElse p.ValueKind = JsonValueKind.Null Then Return Nothing
        Return p.GetDouble()
    End Function
End Module
