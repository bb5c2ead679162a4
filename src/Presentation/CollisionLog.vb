Option Strict On

''' <summary>
''' The last few hundred collisions, newest first, kept cheap when thousands happen each second:
''' within one frame only the first few are itemised and the rest are counted into one summary line,
''' and the oldest lines fall off the end.
''' </summary>
Public NotInheritable Class CollisionLog
    ''' <summary>Lines kept.</summary>
    Public Const Capacity As Integer = 300
    ''' <summary>Collisions itemised per frame; the rest are counted.</summary>
    Public Const PerFrame As Integer = 12

    Private ReadOnly _ring(Capacity - 1) As CollisionLogEntry
    Private _head As Integer ' index of the next write
    Private _count As Integer
    Private _inFrame As Integer
    Private _skipped As Long
    Private _lastTime As Double

    ''' <summary>Lines held, at most <see cref="Capacity"/>.</summary>
    Public ReadOnly Property Count As Integer
        Get
            Return _count
        End Get
    End Property

    ''' <summary>Every collision seen since the last <see cref="Clear"/>, itemised or not.</summary>
    Public ReadOnly Property TotalSeen As Long

    ''' <summary>Bumped on every change, so the window redraws the list only when needed.</summary>
    Public ReadOnly Property Version As Long

    ''' <summary>The i-th line, newest first (i = 0 is the latest).</summary>
    Default Public ReadOnly Property Item(index As Integer) As CollisionLogEntry
        Get
            If index < 0 OrElse index >= _count Then Throw New ArgumentOutOfRangeException(NameOf(index))
            Return _ring((_head - 1 - index + 2 * Capacity) Mod Capacity)
        End Get
    End Property

    ''' <summary>Takes one collision from the engine's listener. Cheap after the first few of a frame.</summary>
    Public Sub Record(record As CollisionRecord, draggedCircle As Circle)
        _TotalSeen += 1
        _lastTime = record.Time
        If _inFrame >= PerFrame Then
            _skipped += 1
            Return
        End If
        _inFrame += 1
        Push(CollisionLogEntry.FromRecord(record, draggedCircle))
    End Sub

    ''' <summary>Closes a frame: the collisions that were only counted become one summary line.</summary>
    Public Sub EndFrame()
        If _skipped > 0 Then Push(CollisionLogEntry.Skipped(_lastTime, _skipped))
        _skipped = 0
        _inFrame = 0
    End Sub

    ''' <summary>Empties the log.</summary>
    Public Sub Clear()
        Array.Clear(_ring, 0, Capacity)
        _head = 0
        _count = 0
        _inFrame = 0
        _skipped = 0
        _TotalSeen = 0
        _Version += 1
    End Sub

    Private Sub Push(entry As CollisionLogEntry)
        _ring(_head) = entry
        _head = (_head + 1) Mod Capacity
        If _count < Capacity Then _count += 1
        _Version += 1
    End Sub
End Class
