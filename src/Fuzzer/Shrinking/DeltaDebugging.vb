Option Strict On

Namespace Shrinking
    ''' <summary>
    ''' Zeller and Hildebrandt's ddmin (2002): the smallest subset of a failing list that still fails, by
    ''' trying its parts and their complements at ever finer granularity. The result is 1-minimal: leaving
    ''' out any single item makes the failure go away (unless the deadline stopped it first).
    ''' </summary>
    Friend Module DeltaDebugging
        ''' <param name="items">a list that fails</param>
        ''' <param name="fails">whether a sublist (in the original order) still fails; never asked twice about the same sublist</param>
        ''' <param name="deadline">when to stop and return the smallest failing list found so far</param>
        Friend Function Minimize(Of T)(items As IReadOnlyList(Of T), fails As Func(Of IReadOnlyList(Of T), Boolean), deadline As DateTime) As IReadOnlyList(Of T)
            If items Is Nothing Then Throw New ArgumentNullException(NameOf(items))
            If fails Is Nothing Then Throw New ArgumentNullException(NameOf(fails))
            ' Work on positions in the original list, so that every candidate keeps the original order and is remembered by them.
            Dim current = Enumerable.Range(0, items.Count).ToList()
            Dim asked As New Dictionary(Of String, Boolean)(StringComparer.Ordinal)
            Dim test =
                Function(candidate As List(Of Integer)) As Boolean
                    Dim key = String.Join(",", candidate)
                    Dim known As Boolean
                    If asked.TryGetValue(key, known) Then Return known
                    Dim answer = fails(candidate.Select(Function(i) items(i)).ToList())
                    asked(key) = answer
                    Return answer
                End Function
            Dim granularity = 2
            Do While current.Count >= 2 AndAlso DateTime.UtcNow < deadline
                Dim parts = Split(current, granularity)
                Dim reduced = False
                For Each part In parts
                    If DateTime.UtcNow >= deadline Then Exit For
                    If test(part) Then
                        current = part
                        granularity = 2
                        reduced = True
                        Exit For
                    End If
                Next
                If Not reduced Then
                    For Each part In parts
                        If DateTime.UtcNow >= deadline Then Exit For
                        Dim complement = current.Except(part).ToList()
                        If complement.Count > 0 AndAlso test(complement) Then
                            current = complement
                            granularity = Math.Max(granularity - 1, 2)
                            reduced = True
                            Exit For
                        End If
                    Next
                End If
                If Not reduced Then
                    If granularity >= current.Count Then Exit Do
                    granularity = Math.Min(granularity * 2, current.Count)
                End If
            Loop
            Return current.Select(Function(i) items(i)).ToList()
        End Function

        ''' <summary>The list cut into <paramref name="count"/> runs of nearly equal length, in order.</summary>
        Friend Function Split(Of T)(list As List(Of T), count As Integer) As List(Of List(Of T))
            Dim parts As New List(Of List(Of T))
            Dim start = 0
            For k = 0 To count - 1
                Dim [end] = CInt((CLng(list.Count) * (k + 1)) \ count)
                If [end] > start Then parts.Add(list.GetRange(start, [end] - start))
                start = [end]
            Next
            Return parts
        End Function
    End Module
End Namespace
