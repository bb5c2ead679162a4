Option Strict On

''' <summary>
''' The bodies' speeds counted into equal bins from 0 m/s. The bins reach past the fastest body
''' (more bins of the same width are added for it), so every body is in one bin and the counts add
''' up to the number of bodies.
''' </summary>
Public NotInheritable Class SpeedHistogram
    ''' <summary>Bins up to the top the Graphs tab asks for, at most: about √1000, a smooth shape with 1000 balls.</summary>
    Public Const DefaultBins As Integer = 30

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
    ''' <paramref name="top"/> m/s, and as many more bins of the same width as reach past a speed at
    ''' or beyond the top, so no speed is dropped.
    ''' </summary>
    Public Shared Function Count(speeds As IEnumerable(Of Double), top As Double, Optional bins As Integer = DefaultBins) As SpeedHistogram
        If speeds Is Nothing Then Throw New ArgumentNullException(NameOf(speeds))
        If bins < 1 Then Throw New ArgumentOutOfRangeException(NameOf(bins))
        Dim list = speeds.Where(Function(v) v >= 0 AndAlso Not Double.IsInfinity(v)).ToList()
        Dim fastest = If(list.Count = 0, 0.0, list.Max())
        Dim reach = If(top > 0 AndAlso Not Double.IsInfinity(top), top, 1.0)
        Dim width = reach / bins
        If fastest >= reach Then bins = CInt(Math.Floor(fastest / width)) + 1
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
