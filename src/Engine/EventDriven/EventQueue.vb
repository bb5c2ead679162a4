Option Strict On

''' <summary>
''' The event-driven solver's queue: which body has the earliest next event. One entry per body,
''' moved in place when the body is rescheduled, so nothing is allocated per event and no stale
''' entries pile up.
''' <para>
''' It is a calendar queue (R. Brown, 1988): time is cut into buckets of equal width, a "year" of
''' <c>nb</c> buckets is laid over the near future, and each body sits in the unsorted list of the
''' bucket its time falls in. Filing a body is O(1) (unlink, link); finding the earliest scans only
''' the current bucket, which holds a couple of entries, and moves on to the next when it is empty.
''' Times beyond the year wait in an overflow list that is sorted into the buckets as each new year
''' begins; +∞ waits in a list of its own. The bucket width adapts to the traffic: it halves when
''' buckets get crowded and doubles when most are empty. A 4-ary heap costs O(log N) per event and
''' touches a cache line per level; at N = 10 000 it took a sixth of the solver's time.
''' </para>
''' The earliest is exact whatever the width. Counting buckets from time 0, every entry in a bucket
''' belongs to the window of <c>nb</c> buckets that starts at the current one (an earlier time is
''' filed into the current bucket), so the current bucket holds the earliest times, and it is
''' scanned whole; everything later in the window is in later buckets, and the overflow is later still.
''' </summary>
Friend NotInheritable Class EventQueue
    ''' <summary>
    ''' One body's entry, in one place: scanning a bucket and moving an entry touch one small struct
    ''' per body instead of a line of each of four arrays.
    ''' </summary>
    Private Structure Node
        Friend Time As Double
        Friend List As Integer
        Friend NextBody As Integer
        Friend PrevBody As Integer
    End Structure

    Private _n As Integer
    ''' <summary>Buckets (a power of two), then the overflow list, then the list of +∞.</summary>
    Private _buckets As Integer
    Private _mask As Long
    Private _head As Integer() = Array.Empty(Of Integer)()
    ''' <summary>Per body: its time as filed, the list it is in, and its neighbours there (−1 at the ends).</summary>
    Private _node As Node() = Array.Empty(Of Node)()
    ''' <summary>1 / bucket width, 1/s; 0 until the first <see cref="Top"/> after <see cref="Reset"/> measures the times.</summary>
    Private _perSecond As Double
    ''' <summary>The current bucket, counted from time 0 (a bucket index before the modulo).</summary>
    Private _current As Long
    ' Traffic since the width was last reviewed: tops answered, entries scanned, empty buckets skipped.
    Private _tops As Long
    Private _scanned As Long
    Private _skipped As Long
    ''' <summary>The last time answered, s.</summary>
    Private _lastTop As Double

    Private ReadOnly Property OverflowList As Integer
        Get
            Return _buckets
        End Get
    End Property

    Private ReadOnly Property NeverList As Integer
        Get
            Return _buckets + 1
        End Get
    End Property

    ''' <summary>Holds bodies 0 … n − 1 at times <paramref name="time"/> (s; read, never written).</summary>
    Friend Sub Reset(time As Double(), n As Integer)
        _n = n
        Dim nb = 16
        While nb < 2 * n
            nb *= 2
        End While
        _buckets = nb
        _mask = nb - 1
        If _head.Length < nb + 2 Then _head = New Integer(nb + 1) {}
        For b = 0 To nb + 1
            _head(b) = -1
        Next
        If _node.Length < n Then _node = New Node(n - 1) {}
        _perSecond = 0
        _current = 0
        _tops = 0
        _scanned = 0
        _skipped = 0
        For i = 0 To n - 1
            _node(i).Time = time(i)
            Link(i, If(time(i) < Double.PositiveInfinity, OverflowList, NeverList))
        Next
    End Sub

    ''' <summary>Files body i again at time t (s).</summary>
    Friend Sub Update(i As Integer, t As Double)
        _node(i).Time = t
        Dim target = ListFor(t)
        If target = _node(i).List Then Return
        Unlink(i)
        Link(i, target)
    End Sub

    ''' <summary>The time (s) body i is filed at.</summary>
    Friend Function TimeOf(i As Integer) As Double
        Return _node(i).Time
    End Function

    ''' <summary>
    ''' The body with the earliest time, the lowest-numbered on a tie; −1 when there are no bodies.
    ''' The answer depends only on the times filed, never on the buckets' layout (which adapts to the
    ''' traffic, and so to how a run is cut into advances): a run is the same however it is sampled.
    ''' </summary>
    Friend Function Top() As Integer
        If _n = 0 Then Return -1
        If _perSecond = 0 Then
            Calibrate()
            If _perSecond = 0 Then Return _head(NeverList) ' no finite time at all
        ElseIf _tops >= _buckets Then
            ReviewWidth()
        End If
        Dim head = _head, node = _node
        Dim empty = 0
        Do
            Dim j = head(CInt(_current And _mask))
            If j >= 0 Then
                Dim best = j
                Dim bestTime = node(j).Time
                j = node(j).NextBody
                While j >= 0
                    _scanned += 1
                    If node(j).Time < bestTime OrElse (node(j).Time = bestTime AndAlso j < best) Then
                        best = j
                        bestTime = node(j).Time
                    End If
                    j = node(j).NextBody
                End While
                _tops += 1
                _lastTop = bestTime
                Return best
            End If
            _skipped += 1
            empty += 1
            _current += 1
            ' A new year: its overflow entries may land in buckets passed in this search.
            If (_current And _mask) = 0 AndAlso SortOverflow() Then empty = 0
            If empty >= _buckets Then
                ' A whole year of empty buckets: go straight to the earliest time left over.
                If head(OverflowList) < 0 Then Return head(NeverList)
                JumpToOverflow()
                empty = 0
            End If
        Loop
    End Function

    Private Function ListFor(t As Double) As Integer
        If Not (t < Double.PositiveInfinity) Then Return NeverList
        If _perSecond = 0 Then Return OverflowList
        Dim b = BucketOf(t)
        If b < _current Then b = _current ' late: the current bucket, which is scanned whole
        If b - _current >= _buckets Then Return OverflowList
        Return CInt(b And _mask)
    End Function

    ''' <summary>The bucket of time t counted from 0 (clamped far beyond any year, so it cannot overflow).</summary>
    Private Function BucketOf(t As Double) As Long
        Const Limit = 4.0E+18
        Dim x = t * _perSecond
        If x >= Limit Then Return CLng(Limit)
        If x <= -Limit Then Return CLng(-Limit)
        Return CLng(Math.Floor(x))
    End Function

    ''' <summary>
    ''' First width: twice the mean time ahead of the earliest, over the number of bodies, so about
    ''' two entries share a bucket near the front.
    ''' </summary>
    Private Sub Calibrate()
        Dim count = 0
        Dim earliest = Double.PositiveInfinity, sum = 0.0
        Dim j = _head(OverflowList)
        While j >= 0
            count += 1
            earliest = Math.Min(earliest, _node(j).Time)
            sum += _node(j).Time
            j = _node(j).NextBody
        End While
        If count = 0 Then Return
        Dim width = 2 * (sum / count - earliest) / count
        If Not (width > 0 AndAlso width < Double.PositiveInfinity) Then width = 1.0E-9 * Math.Max(1.0, Math.Abs(earliest))
        _perSecond = 1 / width
        If Double.IsInfinity(_perSecond) Then _perSecond = Double.MaxValue
        JumpToOverflow()
    End Sub

    ''' <summary>
    ''' Every <c>nb</c> answers: halve the width if buckets are crowded, double it if they are mostly
    ''' empty. Crowding by equal times cannot be helped by narrower buckets: the width never goes
    ''' below 10⁻¹⁵ of the time itself (what a double can tell apart).
    ''' </summary>
    Private Sub ReviewWidth()
        Dim factor = 1.0
        If _scanned > 4 * _tops Then
            factor = 2
            If 2 * _perSecond * Math.Max(1.0, Math.Abs(_lastTop)) > 1.0E+15 Then factor = 1
        ElseIf _skipped > 4 * _tops Then
            factor = 0.5
        End If
        _tops = 0
        _scanned = 0
        _skipped = 0
        If factor = 1 Then Return
        Dim perSecond = _perSecond * factor
        If Not (perSecond > 0 AndAlso perSecond < Double.PositiveInfinity) Then Return
        _perSecond = perSecond
        ' Every bucket's entry goes back to the overflow list and is sorted in again at the new width.
        For b = 0 To _buckets - 1
            Dim j = _head(b)
            While j >= 0
                Dim nx = _node(j).NextBody
                Unlink(j)
                Link(j, OverflowList)
                j = nx
            End While
        Next
        JumpToOverflow()
    End Sub

    ''' <summary>Makes the bucket of the earliest overflow time current and sorts the overflow in.</summary>
    Private Sub JumpToOverflow()
        Dim first = Long.MaxValue
        Dim j = _head(OverflowList)
        While j >= 0
            first = Math.Min(first, BucketOf(_node(j).Time))
            j = _node(j).NextBody
        End While
        If first = Long.MaxValue Then Return
        _current = first
        SortOverflow()
    End Sub

    ''' <summary>Moves every overflow entry that falls in the current year into its bucket; True if any moved.</summary>
    Private Function SortOverflow() As Boolean
        Dim moved = False
        Dim yearEnd = (_current And Not _mask) + _buckets
        Dim j = _head(OverflowList)
        While j >= 0
            Dim nx = _node(j).NextBody
            Dim b = BucketOf(_node(j).Time)
            If b < yearEnd Then
                Unlink(j)
                Link(j, CInt(Math.Max(b, _current) And _mask))
                moved = True
            End If
            j = nx
        End While
        Return moved
    End Function

    Private Sub Link(i As Integer, list As Integer)
        Dim h = _head(list)
        _node(i).NextBody = h
        _node(i).PrevBody = -1
        If h >= 0 Then _node(h).PrevBody = i
        _head(list) = i
        _node(i).List = list
    End Sub

    Private Sub Unlink(i As Integer)
        Dim p = _node(i).PrevBody, n = _node(i).NextBody
        If p >= 0 Then _node(p).NextBody = n Else _head(_node(i).List) = n
        If n >= 0 Then _node(n).PrevBody = p
    End Sub
End Class
