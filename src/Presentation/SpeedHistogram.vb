Option Strict On

''' <summary>
''' The bodies' speeds counted into equal bins from 0 m/s. The bins reach past the fastest body, so
''' every body is in one bin and the counts add up to the number of bodies.
''' </summary>
Public NotInheritable Class SpeedHistogram
    ''' <summary>Bins the Graphs tab uses: about √1000 / 1.3, enough for a smooth shape with 1000 balls.</summary>
    Public Const DefaultBins As Integer = 24

    Private Sub New(edges As Double(), counts As Integer())
        Me.Edges = edges
        Me.Counts = counts
        Total = counts.Sum()
    End Sub

    ''' <summary>The bins' edges, m/s: Edges(i) to Edges(i + 1) is bin i.</summary>
    Public ReadOnly Property Edges As IReadOnlyList(Of Double)
    ''' <summary>How many speeds fell in each bin.</summary>
    Public ReadOnly Property Counts As IReadOnlyList(Of Integer)
    ''' <summary>Σ counts: the number of speeds binned.</summary>
    Public ReadOnly Property Total As Integer

    ''' <summary>Width of every bin, m/s.</summary>
    Public ReadOnly Property BinWidth As Double
        Get
            Return Edges(1) - Edges(0)
        End Get
    End Property

    ''' <summary>
    ''' Counts <paramref name="speeds"/> (m/s) into <paramref name="bins"/> bins from 0 to
    ''' <paramref name="top"/> m/s, or further when a speed is at or beyond it (the top then grows to
    ''' a round number past the fastest, so no speed is dropped).
    ''' </summary>
    Public Shared Function Count(speeds As IEnumerable(Of Double), top As Double, Optional bins As Integer = DefaultBins) As SpeedHistogram
        If speeds Is Nothing Then Throw New ArgumentNullException(NameOf(speeds))
        If bins < 1 Then Throw New ArgumentOutOfRangeException(NameOf(bins))
        Dim list = speeds.Where(Function(v) v >= 0 AndAlso Not Double.IsInfinity(v)).ToList()
        Dim fastest = If(list.Count = 0, 0.0, list.Max())
        Dim reach = If(top > 0 AndAlso Not Double.IsInfinity(top), top, 1.0)
        If fastest >= reach Then reach = AxisTicks.RoundUp(fastest * 1.0001)
        Dim width = reach / bins
        Dim edges(bins) As Double
        For i = 0 To bins
            edges(i) = i * width
        Next
        Dim counts(bins - 1) As Integer
        For Each v In list
            counts(Math.Min(bins - 1, CInt(Math.Floor(v / width)))) += 1
        Next
        Return New SpeedHistogram(edges, counts)
    End Function
End Class
