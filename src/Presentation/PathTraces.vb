Option Strict On

''' <summary>
''' Where each movable body has been: its centre of mass sampled every <see cref="SampleSeconds"/>
''' of real time, the last <see cref="Capacity"/> samples kept in a ring (older ones are dropped, so
''' memory is bounded however long the run), drawn fading with age. In a crowded scene only the
''' first <see cref="MaxBodies"/> movable bodies are traced (enough for a pool break's sixteen balls):
''' the traces of a whole gas would cost it its frame rate and hide it under scribble.
''' </summary>
Public NotInheritable Class PathTraces
    ''' <summary>Samples kept per body.</summary>
    Public Const Capacity As Integer = 90
    ''' <summary>Real time between samples, s (30 a second: a trace covers the last 3 s).</summary>
    Public Const SampleSeconds As Double = 1.0 / 30
    ''' <summary>The most bodies traced.</summary>
    Public Const MaxBodies As Integer = 16

    Private ReadOnly _trails As New Dictionary(Of Shape, Ring)
    Private ReadOnly _order As New List(Of Shape)
    Private _sinceSample As Double = SampleSeconds

    ''' <summary>The bodies traced, in the world's order.</summary>
    Public ReadOnly Property Bodies As IReadOnlyList(Of Shape)
        Get
            Return _order
        End Get
    End Property

    ''' <summary>Samples of <paramref name="body"/>, oldest first, m (empty when it is not traced).</summary>
    Public Function Points(body As Shape) As IReadOnlyList(Of Vector)
        Dim ring As Ring = Nothing
        If body Is Nothing OrElse Not _trails.TryGetValue(body, ring) Then Return Array.Empty(Of Vector)()
        Return ring.ToList()
    End Function

    ''' <summary>Samples held for <paramref name="body"/> (at most <see cref="Capacity"/>).</summary>
    Public Function Count(body As Shape) As Integer
        Dim ring As Ring = Nothing
        Return If(body IsNot Nothing AndAlso _trails.TryGetValue(body, ring), ring.Count, 0)
    End Function

    ''' <summary>
    ''' Called every frame while time runs: after <see cref="SampleSeconds"/> of real time, appends
    ''' each traced body's centre of mass; bodies that left the world lose their trace.
    ''' </summary>
    Public Sub Follow(world As World, realSeconds As Double)
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If realSeconds > 0 Then _sinceSample += realSeconds
        If _sinceSample < SampleSeconds Then Return
        _sinceSample = 0
        Sample(world)
    End Sub

    ''' <summary>Appends every traced body's centre of mass now.</summary>
    Public Sub Sample(world As World)
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim movables = world.Movables
        Dim wanted = Math.Min(MaxBodies, movables.Count)
        ' The traced set is the first MaxBodies movable bodies: rebuilt only when the world changed.
        Dim same = _order.Count = wanted
        For i = 0 To wanted - 1
            If Not same Then Exit For
            same = ReferenceEquals(_order(i), movables(i))
        Next
        If Not same Then
            Dim kept As New Dictionary(Of Shape, Ring)
            _order.Clear()
            For i = 0 To wanted - 1
                Dim b = movables(i)
                Dim ring As Ring = Nothing
                If Not _trails.TryGetValue(b, ring) Then ring = New Ring()
                kept(b) = ring
                _order.Add(b)
            Next
            _trails.Clear()
            For Each entry In kept
                _trails(entry.Key) = entry.Value
            Next
        End If
        For Each b In _order
            _trails(b).Add(b.CentreOfMass)
        Next
    End Sub

    ''' <summary>Forgets every trace (a new scene, a reset, a restart).</summary>
    Public Sub Clear()
        _trails.Clear()
        _order.Clear()
        _sinceSample = SampleSeconds
    End Sub

    ''' <summary>A fixed-size ring of positions: adding to a full ring overwrites the oldest.</summary>
    Private NotInheritable Class Ring
        Private ReadOnly _items(Capacity - 1) As Vector
        Private _start As Integer

        Public ReadOnly Property Count As Integer

        Public Sub Add(p As Vector)
            If Count < Capacity Then
                _items((_start + Count) Mod Capacity) = p
                _Count += 1
            Else
                _items(_start) = p
                _start = (_start + 1) Mod Capacity
            End If
        End Sub

        Public Function ToList() As IReadOnlyList(Of Vector)
            Dim list(Count - 1) As Vector
            For i = 0 To Count - 1
                list(i) = _items((_start + i) Mod Capacity)
            Next
            Return list
        End Function
    End Class
End Class
