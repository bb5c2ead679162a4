Option Strict On

''' <summary>
''' The recorded run, for stepping back and scrubbing: checkpoints in time order (see
''' <see cref="Checkpoint"/>) and the latest moment reached. Between two checkpoints nothing but the
''' solver acted, so the state at any time is the earlier checkpoint replayed forward, exactly.
''' <para>
''' Memory is bounded: at most <see cref="MaxCheckpoints"/> checkpoints and <see cref="MaxBytes"/>
''' bytes of them. Past either limit the oldest checkpoint is dropped, and the earliest moment one can
''' go back to (<see cref="Earliest"/>) moves forward to the next one.
''' </para>
''' </summary>
Public NotInheritable Class Timeline
    ''' <summary>The most checkpoints kept.</summary>
    Public Const MaxCheckpoints As Integer = 2000
    ''' <summary>The most memory the checkpoints may hold, bytes (64 MB).</summary>
    Public Const MaxBytes As Long = 64L * 1024 * 1024
    ''' <summary>
    ''' The fewest events of the event solver between two checkpoints the run makes of its own accord
    ''' (see <see cref="EventsBetweenCheckpoints"/>).
    ''' </summary>
    Public Const EventsPerCheckpoint As Long = 100000
    ''' <summary>
    ''' Events per body between two such checkpoints, when that is more: a checkpoint costs about as much
    ''' as a few dozen events per body (the scene written out, every prediction made again), so 500
    ''' keeps recording within a few per cent of the solver's speed.
    ''' </summary>
    Public Const EventsPerBodyPerCheckpoint As Long = 500

    ''' <summary>
    ''' Events between two checkpoints the run makes of its own accord, for a world of
    ''' <paramref name="bodies"/> bodies: replaying from one to any moment before the next takes at
    ''' most this many events.
    ''' </summary>
    Public Shared Function EventsBetweenCheckpoints(bodies As Integer) As Long
        Return Math.Max(EventsPerCheckpoint, EventsPerBodyPerCheckpoint * bodies)
    End Function
    ''' <summary>Simulated seconds between two checkpoints of a stepping solver (which counts no events).</summary>
    Public Const SecondsPerCheckpoint As Double = 2.0

    Private ReadOnly _points As New List(Of Checkpoint)

    ''' <summary>The checkpoints, oldest first.</summary>
    Public ReadOnly Property Points As IReadOnlyList(Of Checkpoint)
        Get
            Return _points
        End Get
    End Property

    ''' <summary>The latest moment of the run reached, s: one can scrub forward up to here.</summary>
    Public ReadOnly Property Latest As Double

    ''' <summary>Bytes held by the checkpoints.</summary>
    Public ReadOnly Property Bytes As Long

    ''' <summary>Checkpoints dropped at the memory limit since the run started.</summary>
    Public ReadOnly Property Dropped As Integer

    ''' <summary>The earliest moment one can go back to, s (the oldest checkpoint; the latest moment while there is none).</summary>
    Public ReadOnly Property Earliest As Double
        Get
            Return If(_points.Count > 0, _points(0).Time, Latest)
        End Get
    End Property

    ''' <summary>Adds a checkpoint: it ends the recorded future after its time, and replaces one taken at the same time.</summary>
    Public Sub Add(point As Checkpoint)
        If point Is Nothing Then Throw New ArgumentNullException(NameOf(point))
        Truncate(point.Time)
        If _points.Count > 0 AndAlso _points(_points.Count - 1).Time = point.Time Then RemoveAt(_points.Count - 1)
        _points.Add(point)
        _Bytes += point.Bytes
        Do While _points.Count > 1 AndAlso (_points.Count > MaxCheckpoints OrElse _Bytes > MaxBytes)
            RemoveAt(0)
            _Dropped += 1
        Loop
    End Sub

    ''' <summary>Something changed at <paramref name="time"/> (s): what was recorded after it no longer happens.</summary>
    Public Sub Truncate(time As Double)
        Do While _points.Count > 0 AndAlso _points(_points.Count - 1).Time > time
            RemoveAt(_points.Count - 1)
        Loop
        _Latest = time
    End Sub

    ''' <summary>The run reached <paramref name="time"/> (s).</summary>
    Public Sub Reached(time As Double)
        If time > _Latest Then _Latest = time
    End Sub

    ''' <summary>The last checkpoint at or before <paramref name="time"/>, or Nothing.</summary>
    Public Function AtOrBefore(time As Double) As Checkpoint
        For i = _points.Count - 1 To 0 Step -1
            If _points(i).Time <= time Then Return _points(i)
        Next
        Return Nothing
    End Function

    ''' <summary>The last checkpoint strictly before <paramref name="time"/>, or Nothing.</summary>
    Public Function Before(time As Double) As Checkpoint
        For i = _points.Count - 1 To 0 Step -1
            If _points(i).Time < time Then Return _points(i)
        Next
        Return Nothing
    End Function

    ''' <summary>The first checkpoint strictly after <paramref name="time"/>, or Nothing.</summary>
    Public Function After(time As Double) As Checkpoint
        For Each p In _points
            If p.Time > time Then Return p
        Next
        Return Nothing
    End Function

    Private Sub RemoveAt(index As Integer)
        _Bytes -= _points(index).Bytes
        _points.RemoveAt(index)
    End Sub

    ''' <summary>
    ''' The world of a checkpoint, its clock at the checkpoint's time to the last bit and its carried
    ''' body carried again; no solver yet (attaching one must not count as a change).
    ''' </summary>
    Public Shared Function Build(point As Checkpoint) As World
        If point Is Nothing Then Throw New ArgumentNullException(NameOf(point))
        Dim w = Scenes.SceneFile.Load(point.Scene)
        ' World.Time has no setter: a solver that moves nothing advances the clock from 0, and 0 + t is t.
        w.Solver = New ClockOnlySolver()
        w.Advance(point.Time)
        If point.DraggedId IsNot Nothing Then
            Dim body = w.Find(point.DraggedId)
            If body IsNot Nothing AndAlso Not body.IsFixed Then
                Dim velocity = body.Velocity
                w.BeginDrag(body)
                w.DragTo(point.DragTarget)
                body.Velocity = velocity
            End If
        End If
        Return w
    End Function

    ''' <summary>Takes a checkpoint of <paramref name="world"/> as it is now.</summary>
    Public Shared Function Take(world As World, solverName As String, collisions As Long) As Checkpoint
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim dragged = world.DraggedBody
        Return New Checkpoint(world.Time, Scenes.SceneFile.Save(world), solverName, dragged?.Id, world.DragTarget, collisions)
    End Function
End Class
