Option Strict On

''' <summary>
''' The graph series of a run in bounded memory. A sample is kept when at least
''' <see cref="Interval"/> of simulated time has passed since the last one kept. When
''' <see cref="Capacity"/> samples are held, every second one is dropped and the interval doubles:
''' the whole run stays on the graph, at half the resolution, and memory never grows past
''' <see cref="Capacity"/> samples (4096 × 64 bytes = 256 KB). Time that goes backwards (a restart,
''' a step back) drops the samples after the new time, so the series always describes one history.
''' </summary>
Public NotInheritable Class SeriesRecorder
    ''' <summary>Samples held at most.</summary>
    Public Const Capacity As Integer = 4096
    ''' <summary>The interval between kept samples at the start of a run, s (about one per frame at 1× speed).</summary>
    Public Const FirstInterval As Double = 1.0 / 60

    Private ReadOnly _samples As New List(Of SeriesSample)(Capacity)

    ''' <summary>Simulated time between kept samples now, s.</summary>
    Public ReadOnly Property Interval As Double = FirstInterval

    ''' <summary>Samples held, oldest first.</summary>
    Public ReadOnly Property Samples As IReadOnlyList(Of SeriesSample)
        Get
            Return _samples
        End Get
    End Property

    ''' <summary>Bumped on every change, so a graph is redrawn only when needed.</summary>
    Public ReadOnly Property Version As Long

    ''' <summary>Offers a sample; returns whether it was kept.</summary>
    Public Function Offer(sample As SeriesSample) As Boolean
        Dim t = sample.Time
        If Double.IsNaN(t) OrElse Double.IsInfinity(t) Then Return False
        ' A history that went back in time is cut at the new time.
        Dim cut = _samples.Count
        While cut > 0 AndAlso _samples(cut - 1).Time > t
            cut -= 1
        End While
        If cut < _samples.Count Then
            _samples.RemoveRange(cut, _samples.Count - cut)
            _Version += 1
        End If
        If _samples.Count > 0 AndAlso t - _samples(_samples.Count - 1).Time < Interval * (1 - 1.0E-9) Then Return False
        If _samples.Count = Capacity Then Thin()
        _samples.Add(sample)
        _Version += 1
        Return True
    End Function

    ''' <summary>Forgets every sample and goes back to the first interval.</summary>
    Public Sub Clear()
        _samples.Clear()
        _Interval = FirstInterval
        _Version += 1
    End Sub

    ''' <summary>Keeps the first sample and every second one after it, and doubles the interval.</summary>
    Private Sub Thin()
        Dim kept = 0
        For i = 0 To _samples.Count - 1 Step 2
            _samples(kept) = _samples(i)
            kept += 1
        Next
        _samples.RemoveRange(kept, _samples.Count - kept)
        _Interval *= 2
    End Sub
End Class
