Option Strict On
Imports System.Globalization
Imports System.Text
Imports PhysicsEngine.Presentation

''' <summary>
''' The cost of recording a run for rewind (see docs/time-travel.md): the 1000-ball gas advanced in
''' frames of 1/60 s by the event solver alone, and by the same solver wrapped in the app's
''' <see cref="TimelineSolver"/>, which restarts it and takes a checkpoint every
''' <see cref="Timeline.EventsBetweenCheckpoints"/> events. The runs alternate, so a busy spell of a
''' shared machine falls on both.
''' </summary>
Friend Module RecordingOverhead
    ''' <summary>Runs the comparison: <paramref name="seconds"/> simulated seconds of an N-ball gas, <paramref name="repeats"/> times each.</summary>
    Public Function Measure(Optional balls As Integer = 1000, Optional seconds As Double = 20, Optional repeats As Integer = 3) As RecordingResult
        Dim plain As New List(Of Double), recorded As New List(Of Double)
        Dim result As New RecordingResult With {.Balls = balls, .SimulatedSeconds = seconds, .Repeats = repeats}
        For r = 1 To repeats
            plain.Add(Run(balls, seconds, Nothing, result))
            Dim timeline As New Timeline()
            recorded.Add(Run(balls, seconds, timeline, result))
            result.Checkpoints = timeline.Points.Count
            result.Bytes = timeline.Bytes
        Next
        result.PlainSeconds = Statistics.Median(plain)
        result.RecordedSeconds = Statistics.Median(recorded)
        result.EventsBetween = Timeline.EventsBetweenCheckpoints(balls)
        result.CheckpointMs = CheckpointCost(balls, 5 * repeats)
        Return result
    End Function

    ''' <summary>Median wall-clock time of one checkpoint of the gas after a second of running, ms: written out, then every prediction made again.</summary>
    Private Function CheckpointCost(balls As Integer, times As Integer) As Double
        Dim w = Scenarios.ElasticGas(balls, 0.1, 0.01, 1)
        Dim solver As New EventDrivenSolver()
        w.Solver = solver
        w.Advance(1.0)
        Dim costs As New List(Of Double)
        For k = 1 To times
            Dim clock = Diagnostics.Stopwatch.StartNew()
            Dim point = Timeline.Take(w, "event", 0)
            solver.Invalidate(Nothing)
            w.Advance(1.0E-9) ' the rebuild comes with the next advance; a nanosecond holds almost no events
            clock.Stop()
            If point.Scene.Length = 0 Then Throw New InvalidOperationException("an empty checkpoint")
            costs.Add(clock.Elapsed.TotalMilliseconds)
        Next
        Return Statistics.Median(costs)
    End Function

    ''' <summary>One run; returns its wall-clock seconds.</summary>
    Private Function Run(balls As Integer, seconds As Double, timeline As Timeline, result As RecordingResult) As Double
        Dim w = Scenarios.ElasticGas(balls, 0.1, 0.01, 1)
        Dim solver As New EventDrivenSolver()
        If timeline Is Nothing Then
            w.Solver = solver
        Else
            w.Solver = New TimelineSolver(solver, timeline, Function(x) Timeline.Take(x, "event", 0), restartFirst:=True)
        End If
        Dim frames = CInt(Math.Round(seconds * 60))
        Dim clock = Diagnostics.Stopwatch.StartNew()
        For k = 1 To frames
            w.Advance(1 / 60.0)
        Next
        clock.Stop()
        result.Events = solver.EventCount
        Return clock.Elapsed.TotalSeconds
    End Function

    ''' <summary>The report's section on it.</summary>
    Public Function Section(r As RecordingResult) As String
        Dim inv = CultureInfo.InvariantCulture
        Dim sb As New StringBuilder()
        sb.Append("## Recording for rewind (the app)").Append(ControlChars.Lf).Append(ControlChars.Lf)
        If r Is Nothing Then
            sb.Append("Not measured in this run.").Append(ControlChars.Lf)
            Return sb.ToString()
        End If
        sb.Append("The ").Append(r.Balls.ToString(inv)).Append("-ball gas (e = 1, no gravity), ").Append(r.SimulatedSeconds.ToString("0.#", inv)).
           Append(" s of simulated time in frames of 1/60 s with the event solver, without and with the recording that lets the app step back and scrub its timeline; median of ").
           Append(r.Repeats.ToString(inv)).Append(" alternating runs. The target is an overhead of at most 10 %.").Append(ControlChars.Lf).Append(ControlChars.Lf)
        sb.Append("| run | wall time (s) | events per second | checkpoints | memory |").Append(ControlChars.Lf)
        sb.Append("|---|---:|---:|---:|---:|").Append(ControlChars.Lf)
        sb.Append("| without recording | ").Append(r.PlainSeconds.ToString("0.00", inv)).Append(" | ").Append((r.Events / r.PlainSeconds).ToString("N0", inv)).Append(" | — | — |").Append(ControlChars.Lf)
        sb.Append("| recorded for rewind | ").Append(r.RecordedSeconds.ToString("0.00", inv)).Append(" | ").Append((r.Events / r.RecordedSeconds).ToString("N0", inv)).
           Append(" | ").Append(r.Checkpoints.ToString(inv)).Append(" | ").Append((r.Bytes / 1048576.0).ToString("0.0", inv)).Append(" MB |").Append(ControlChars.Lf)
        sb.Append(ControlChars.Lf).Append("Overhead of recording, the two runs compared: **").Append((100 * r.Overhead).ToString("0.0", inv)).Append(" %**. ").
           Append("From its parts: one checkpoint (the scene written out, every prediction made again) takes ").Append(r.CheckpointMs.ToString("0.0", inv)).
           Append(" ms, and comes every ").Append(r.EventsBetween.ToString("N0", inv)).Append(" events, which the plain run processes in ").
           Append((1000 * r.EventsBetween * r.PlainSeconds / r.Events).ToString("0", inv)).Append(" ms: **").Append((100 * r.OverheadFromParts).ToString("0.0", inv)).
           Append(" %**. On a busy machine the difference of two runs is noisier than that estimate.").Append(ControlChars.Lf)
        Return sb.ToString()
    End Function
End Module
