Option Strict On

''' <summary>
''' An indexed 4-ary min-heap of bodies keyed by the time of each body's next event: one entry per
''' body, updated in place when the body is rescheduled, so nothing is allocated per event and the
''' heap never fills with stale entries. Each entry carries its key, so sifting compares within the
''' heap array (no lookup per comparison), and a node's four children share one cache line; the
''' heap is half as deep as a binary one. Times are kept as integers that sort like the doubles
''' (<see cref="SortKey"/>), so the earliest of four children is picked with conditional moves
''' rather than unpredictable branches, and four padding entries that never win spare the checks
''' for a node with fewer than four children.
''' </summary>
Friend NotInheritable Class EventQueue
    Private Structure Entry
        Friend Key As Long
        Friend Body As Integer
    End Structure

    ''' <summary>Sorts after every real time: the padding behind the last entry.</summary>
    Private Const Padding As Long = Long.MaxValue

    Private _heap As Entry() = Array.Empty(Of Entry)()
    Private _pos As Integer() = Array.Empty(Of Integer)()
    Private _time As Double()
    Private _count As Integer

    ''' <summary>Holds bodies 0 … n − 1 keyed by <paramref name="time"/> (read, never written).</summary>
    Friend Sub Reset(time As Double(), n As Integer)
        _time = time
        If _heap.Length < n + 4 Then
            _heap = New Entry(n + 3) {}
            _pos = New Integer(n - 1) {}
        End If
        _count = n
        For i = 0 To n - 1
            _heap(i).Key = SortKey(time(i))
            _heap(i).Body = i
            _pos(i) = i
        Next
        For i = n To _heap.Length - 1
            _heap(i).Key = Padding
            _heap(i).Body = -1
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
        item.Key = SortKey(_time(i))
        item.Body = i
        If k > 0 AndAlso _heap((k - 1) >> 2).Key > item.Key Then SiftUp(k, item) Else SiftDown(k, item)
    End Sub

    ''' <summary>
    ''' An integer that orders like the time t (s): the IEEE bits of a double already order like the
    ''' number for t ≥ 0 (and +∞); for t &lt; 0 the bits below the sign are flipped.
    ''' </summary>
    Private Shared Function SortKey(t As Double) As Long
        Dim bits = BitConverter.DoubleToInt64Bits(t)
        Return bits Xor ((bits >> 63) And Long.MaxValue)
    End Function

    Private Sub SiftUp(k As Integer, item As Entry)
        Dim heap = _heap, pos = _pos
        While k > 0
            Dim parent = (k - 1) >> 2
            Dim p = heap(parent)
            If p.Key <= item.Key Then Exit While
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
        Dim key = item.Key
        Do
            Dim first = 4 * k + 1
            If first >= count Then Exit Do
            ' The earliest of the four children (padding never wins; the first one wins a tie), as
            ' a small tournament of selects the JIT compiles to conditional moves.
            Dim k0 = heap(first).Key, k1 = heap(first + 1).Key, k2 = heap(first + 2).Key, k3 = heap(first + 3).Key
            Dim a = If(k1 < k0, first + 1, first)
            Dim ka = If(k1 < k0, k1, k0)
            Dim b = If(k3 < k2, first + 3, first + 2)
            Dim kb = If(k3 < k2, k3, k2)
            Dim child = If(kb < ka, b, a)
            Dim kc = If(kb < ka, kb, ka)
            If key <= kc Then Exit Do
            Dim moved = heap(child)
            heap(k) = moved
            pos(moved.Body) = k
            k = child
        Loop
        heap(k) = item
        pos(item.Body) = k
    End Sub
End Class
