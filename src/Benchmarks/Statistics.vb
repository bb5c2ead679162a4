Option Strict On

''' <summary>The summary statistics the benchmark reports.</summary>
Friend Module Statistics
    ''' <summary>
    ''' The median: the middle value, or the mean of the two middle values for an even count. Used for
    ''' timings because one slow run (another process on the machine, a GC) must not move the result.
    ''' </summary>
    Public Function Median(values As IEnumerable(Of Double)) As Double
        If values Is Nothing Then Throw New ArgumentNullException(NameOf(values))
        Dim sorted = values.ToList()
        If sorted.Count = 0 Then Throw New ArgumentException("the median of no values is undefined", NameOf(values))
        If sorted.Any(Function(v) Double.IsNaN(v)) Then Throw New ArgumentException("values must not contain NaN", NameOf(values))
        sorted.Sort()
        Dim mid = sorted.Count \ 2
        If sorted.Count Mod 2 = 1 Then Return sorted(mid)
        Return (sorted(mid - 1) + sorted(mid)) / 2
    End Function
End Module
