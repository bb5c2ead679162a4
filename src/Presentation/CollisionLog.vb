Option Strict On

''' <summary>
''' The last few hundred collisions, newest first, kept readable and cheap. A collision of a pair
''' that is already among the newest rows joins that row, which counts it and moves to the top ("3
''' bounced 180 times on the floor"), so a ball resting at e = 1 does not flood the log. Within one
''' frame only the first few new rows are made; the rest are counted into one summary row. The
''' oldest rows fall off the end.
''' </summary>
Public NotInheritable Class CollisionLog
    ''' <summary>Rows kept.</summary>
    Public Const Capacity As Integer = 300
    ''' <summary>Rows itemised per frame; further collisions are counted.</summary>
    Public Const PerFrame As Integer = 12
    ''' <summary>How many of the newest rows a repeated pair is looked for in.</summary>
    Public Const GroupWithin As Integer = 12

    Private ReadOnly _rows As New List(Of CollisionLogEntry)(Capacity + 1) ' oldest first
    Private _inFrame As Integer
    Private _skipped As Long
    Private _lastTime As Double

    ''' <summary>Rows held, at most <see cref="Capacity"/>.</summary>
    Public ReadOnly Property Count As Integer
        Get
            Return _rows.Count
        End Get
    End Property

    ''' <summary>Every collision seen since the last <see cref="Clear"/>, itemised or not.</summary>
    Public ReadOnly Property TotalSeen As Long

    ''' <summary>Bumped on every change, so the window redraws the list only when needed.</summary>
    Public ReadOnly Property Version As Long

    ''' <summary>The i-th row, newest first (i = 0 is the latest).</summary>
    Default Public ReadOnly Property Item(index As Integer) As CollisionLogEntry
        Get
            If index < 0 OrElse index >= _rows.Count Then Throw New ArgumentOutOfRangeException(NameOf(index))
            Return _rows(_rows.Count - 1 - index)
        End Get
    End Property

    ''' <summary>Takes one collision from the engine's listener. Cheap after the first few of a frame.</summary>
    Public Sub Record(record As CollisionRecord, dragged As Shape)
        _TotalSeen += 1
        _lastTime = record.Time
        Dim entry = CollisionLogEntry.FromRecord(record, dragged)
        ' A repeat of a recent pair joins its row (and brings it to the top), whatever the frame.
        For i = _rows.Count - 1 To Math.Max(0, _rows.Count - GroupWithin) Step -1
            Dim row = _rows(i)
            If row.SkippedCount = 0 AndAlso row.AName = entry.AName AndAlso row.BName = entry.BName Then
                _rows.RemoveAt(i)
                Push(entry.Following(row))
                Return
            End If
        Next
        If _inFrame >= PerFrame Then
            _skipped += 1
            Return
        End If
        _inFrame += 1
        Push(entry)
    End Sub

    ''' <summary>Closes a frame: the collisions that were only counted become one summary row.</summary>
    Public Sub EndFrame()
        If _skipped > 0 Then Push(CollisionLogEntry.Skipped(_lastTime, _skipped))
        _skipped = 0
        _inFrame = 0
    End Sub

    ''' <summary>Empties the log.</summary>
    Public Sub Clear()
        _rows.Clear()
        _inFrame = 0
        _skipped = 0
        _TotalSeen = 0
        _Version += 1
    End Sub

    ''' <summary>Empties the rows and goes on counting from <paramref name="total"/> collisions (a run taken up again at a recorded moment).</summary>
    Public Sub ContinueFrom(total As Long)
        Clear()
        _TotalSeen = total
    End Sub

    Private Sub Push(entry As CollisionLogEntry)
        _rows.Add(entry)
        If _rows.Count > Capacity Then _rows.RemoveAt(0)
        _Version += 1
    End Sub
End Class
