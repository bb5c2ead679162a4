Option Strict On
Imports System.Globalization
Imports System.IO

''' <summary>
''' --stats S: every S seconds one line of how the window keeps up, for the soak script: the
''' frames' interval (median and 95th percentile, ms), the time spent in the frame's own work
''' (the step and the tables, ms), the canvas's paint (ms), the managed heap and the process's resident memory (MB).
''' </summary>
Friend NotInheritable Class FrameStats
    Private ReadOnly _every As Double
    Private ReadOnly _out As TextWriter
    Private ReadOnly _intervals As New List(Of Double)
    Private ReadOnly _work As New List(Of Double)
    Private ReadOnly _paint As New List(Of Double)
    Private ReadOnly _clock As Diagnostics.Stopwatch = Diagnostics.Stopwatch.StartNew()
    Private _next As Double

    Public Sub New(everySeconds As Double, output As TextWriter)
        _every = everySeconds
        _out = output
        _next = everySeconds
    End Sub

    ''' <summary>One paint of the canvas took <paramref name="seconds"/>.</summary>
    Public Sub RecordPaint(seconds As Double)
        _paint.Add(seconds * 1000)
    End Sub

    ''' <summary>One frame: <paramref name="interval"/> s since the last, <paramref name="work"/> s spent in it.</summary>
    Public Sub Record(interval As Double, work As Double)
        _intervals.Add(interval * 1000)
        _work.Add(work * 1000)
        Dim now = _clock.Elapsed.TotalSeconds
        If now < _next Then Return
        _next = now + _every
        Using p = Diagnostics.Process.GetCurrentProcess()
            Dim line = String.Format(CultureInfo.InvariantCulture,
                "stats t={0:F0}s frames={1} interval_median_ms={2:F2} interval_p95_ms={3:F2} step_median_ms={4:F2} step_p95_ms={5:F2} paint_median_ms={6:F2} paint_p95_ms={7:F2} heap_mb={8:F1} rss_mb={9:F1}",
                now, _intervals.Count, Quantile(_intervals, 0.5), Quantile(_intervals, 0.95), Quantile(_work, 0.5), Quantile(_work, 0.95),
                Quantile(_paint, 0.5), Quantile(_paint, 0.95), GC.GetTotalMemory(False) / 1048576.0, p.WorkingSet64 / 1048576.0)
            _out.WriteLine(line)
            _out.Flush()
        End Using
        _intervals.Clear()
        _work.Clear()
        _paint.Clear()
    End Sub

    Private Shared Function Quantile(values As List(Of Double), q As Double) As Double
        If values.Count = 0 Then Return 0
        Dim sorted = values.ToArray()
        Array.Sort(sorted)
        Return sorted(Math.Max(0, Math.Min(sorted.Length - 1, CInt(Math.Ceiling(q * sorted.Length)) - 1)))
    End Function
End Class
