Option Strict On

''' <summary>
''' An indexed binary min-heap of bodies keyed by the time of each body's next event: one entry per
''' body, updated in place when the body is rescheduled, so nothing is allocated per event and the
''' heap never fills with stale entries.
''' </summary>
Friend NotInheritable Class EventQueue
    Private _heap As Integer() = Array.Empty(Of Integer)()
    Private _pos As Integer() = Array.Empty(Of Integer)()
    Private _time As Double()
    Private _count As Integer

    ''' <summary>Holds bodies 0 … n − 1 keyed by <paramref name="time"/> (read, never written).</summary>
    Friend Sub Reset(time As Double(), n As Integer)
        _time = time
        If _heap.Length < n Then
            _heap = New Integer(n - 1) {}
            _pos = New Integer(n - 1) {}
        End If
        _count = n
        For i = 0 To n - 1
            _heap(i) = i
            _pos(i) = i
        Next
        For k = n \ 2 - 1 To 0 Step -1
            SiftDown(k)
        Next
    End Sub

    ''' <summary>The body with the earliest event, or −1 when empty.</summary>
    Friend ReadOnly Property Top As Integer
        Get
            Return If(_count = 0, -1, _heap(0))
        End Get
    End Property

    ''' <summary>Restores heap order after body i's time changed.</summary>
    Friend Sub Update(i As Integer)
        Dim k = _pos(i)
        If k > 0 AndAlso _time(_heap((k - 1) >> 1)) > _time(i) Then SiftUp(k) Else SiftDown(k)
    End Sub

    Private Sub SiftUp(k As Integer)
        Dim item = _heap(k)
        Dim t = _time(item)
        While k > 0
            Dim parent = (k - 1) >> 1
            Dim p = _heap(parent)
            If _time(p) <= t Then Exit While
            _heap(k) = p
            _pos(p) = k
            k = parent
        End While
        _heap(k) = item
        _pos(item) = k
    End Sub

    Private Sub SiftDown(k As Integer)
        Dim item = _heap(k)
        Dim t = _time(item)
        Dim half = _count >> 1
        While k < half
            Dim child = 2 * k + 1
            Dim c = _heap(child)
            Dim ct = _time(c)
            Dim right = child + 1
            If right < _count Then
                Dim rc = _heap(right)
                If _time(rc) < ct Then
                    child = right
                    c = rc
                    ct = _time(rc)
                End If
            End If
            If t <= ct Then Exit While
            _heap(k) = c
            _pos(c) = k
            k = child
        End While
        _heap(k) = item
        _pos(item) = k
    End Sub
End Class
