Option Strict On

''' <summary>
''' The bodies one event changed, each listed once in the order it first changed, so the solver
''' reschedules them together after the event is resolved: every prediction is then made with the
''' final courses of every body the event moved. A stamp per body makes adding O(1) with no search.
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

    Friend Sub Add(i As Integer)
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
