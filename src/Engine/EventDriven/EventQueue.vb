Option Strict On

''' <summary>
''' An indexed 4-ary min-heap of bodies keyed by the time of each body's next event: one entry per
''' body, updated in place when the body is rescheduled, so nothing is allocated per event and the
''' heap never fills with stale entries. Each entry carries its time, so sifting compares within the
''' heap array (no lookup per comparison), and a node's four children share one cache line; the
''' heap is half as deep as a binary one.
''' </summary>
Friend NotInheritable Class EventQueue
    Private Structure Entry
        Friend Time As Double
        Friend Body As Integer
    End Structure

    Private _heap As Entry() = Array.Empty(Of Entry)()
    Private _pos As Integer() = Array.Empty(Of Integer)()
    Private _time As Double()
    Private _count As Integer

    ''' <summary>Holds bodies 0 … n − 1 keyed by <paramref name="time"/> (read, never written).</summary>
    Friend Sub Reset(time As Double(), n As Integer)
        _time = time
        If _heap.Length < n Then
            _heap = New Entry(n - 1) {}
            _pos = New Integer(n - 1) {}
        End If
        _count = n
        For i = 0 To n - 1
            _heap(i).Time = time(i)
            _heap(i).Body = i
            _pos(i) = i
        Next
        ' The last parent is (n − 2) \ 4; with fewer than two entries there is none (and VB's \
        ' truncates −2 \ 4 to 0, which would touch an empty heap).
        If n < 2 Then Return
        For k = (n - 2) \ 4 To 0 Step -1
            SiftDown(k, _heap(k))
        Next
    End Sub

    ''' <summary>The body with the earliest event, or −1 when empty.</summary>
    Friend ReadOnly Property Top As Integer
        Get
            Return If(_count = 0, -1, _heap(0).Body)
        End Get
    End Property

    ''' <summary>Restores heap order after body i's time changed.</summary>
    Friend Sub Update(i As Integer)
        Dim k = _pos(i)
        Dim item As Entry
        item.Time = _time(i)
        item.Body = i
        If k > 0 AndAlso _heap((k - 1) >> 2).Time > item.Time Then SiftUp(k, item) Else SiftDown(k, item)
    End Sub

    Private Sub SiftUp(k As Integer, item As Entry)
        Dim heap = _heap, pos = _pos
        While k > 0
            Dim parent = (k - 1) >> 2
            Dim p = heap(parent)
            If p.Time <= item.Time Then Exit While
            heap(k) = p
            pos(p.Body) = k
            k = parent
        End While
        heap(k) = item
        pos(item.Body) = k
    End Sub

    Private Sub SiftDown(k As Integer, item As Entry)
        Dim heap = _heap, pos = _pos
        Dim count = _count
        Dim t = item.Time
        Do
            Dim first = 4 * k + 1
            If first >= count Then Exit Do
            ' The earliest of up to four children (the first one wins a tie).
            Dim child = first
            Dim ct = heap(first).Time
            Dim last = Math.Min(first + 3, count - 1)
            For c = first + 1 To last
                Dim tc = heap(c).Time
                If tc < ct Then
                    ct = tc
                    child = c
                End If
            Next
            If t <= ct Then Exit Do
            Dim moved = heap(child)
            heap(k) = moved
            pos(moved.Body) = k
            k = child
        Loop
        heap(k) = item
        pos(item.Body) = k
    End Sub
End Class
