Option Strict On

''' <summary>
''' The bodies one event changed, each listed once in the order it first changed, so the solver
''' reschedules them together after the event is resolved: every prediction is then made with the
''' final courses of every body the event moved. A short list is searched; a long one (a cluster) keeps
''' a stamp per body, so that adding stays O(1).
''' </summary>
Friend NotInheritable Class TouchedList
    Private _items As Integer() = Array.Empty(Of Integer)()
    Private _stamp As Integer() = Array.Empty(Of Integer)()
    Private _current As Integer = 1
    Friend Count As Integer

    ''' <summary>Room for bodies 0 … n − 1; empties the list.</summary>
    Friend Sub Reset(n As Integer)
        If _items.Length < n Then
            _items = New Integer(n - 1) {}
            _stamp = New Integer(n - 1) {}
        Else
            Array.Clear(_stamp, 0, _stamp.Length)
        End If
        _current = 1
        Count = 0
    End Sub

    ''' <summary>
    ''' Up to this many bodies, a repeat is found by searching the list; from then on by the stamps.
    ''' An event usually changes two bodies, and a search of two items costs less than reading a stamp
    ''' of a body far away in memory.
    ''' </summary>
    Private Const SearchLimit As Integer = 8

    Friend Sub Add(i As Integer)
        If Count < SearchLimit Then
            For k = 0 To Count - 1
                If _items(k) = i Then Return
            Next
            _items(Count) = i
            Count += 1
            If Count = SearchLimit Then
                For k = 0 To Count - 1
                    _stamp(_items(k)) = _current
                Next
            End If
            Return
        End If
        If _stamp(i) = _current Then Return
        _stamp(i) = _current
        _items(Count) = i
        Count += 1
    End Sub

    Default Friend ReadOnly Property Item(k As Integer) As Integer
        Get
            Return _items(k)
        End Get
    End Property

    ''' <summary>Empties the list for the next event.</summary>
    Friend Sub Clear()
        Count = 0
        _current += 1
        If _current = Integer.MaxValue Then
            Array.Clear(_stamp, 0, _stamp.Length)
            _current = 1
        End If
    End Sub
End Class
