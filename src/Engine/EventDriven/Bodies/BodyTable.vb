Option Strict On

''' <summary>
''' The movable bodies as the event-driven solver sees them, numbered 0 … Count − 1: each one's
''' model body, its motion (what every prediction reads), its next event and grid cell
''' (<see cref="EventSlot"/>), its mode, its inverse mass, its shape, and what holds it while it is
''' supported. The arrays are Friend fields so the hot loops read them directly; they are reallocated
''' only by <see cref="Load"/>, so a caller may keep them in locals for the length of one event.
''' </summary>
Friend NotInheritable Class BodyTable
    Friend Count As Integer
    Friend Shapes As Shape() = Array.Empty(Of Shape)()
    Friend Motion As Motion() = Array.Empty(Of Motion)()
    Friend Slot As EventSlot() = Array.Empty(Of EventSlot)()
    ''' <summary>Each body's inverse mass, kind and last hits (see <see cref="BodyInfo"/>).</summary>
    Friend Info As BodyInfo() = Array.Empty(Of BodyInfo)()
    ''' <summary>Each body's reach and size (see <see cref="BodySize"/>).</summary>
    Friend Size As BodySize() = Array.Empty(Of BodySize)()
    ''' <summary>The body's outline (offsets from its reference point); its rounding radius is also Motion.R.</summary>
    Friend Outlines As Outline() = Array.Empty(Of Outline)()
    ''' <summary>True while a body is out of the grid for a long slide (see SolverState.Roam).</summary>
    Friend Roaming As Boolean() = Array.Empty(Of Boolean)()
    ''' <summary>What a supported body rests on: an obstacle index ≥ 0, <see cref="SupportFloor"/> or <see cref="SupportBody"/>.</summary>
    Friend Support As Integer() = Array.Empty(Of Integer)()
    ''' <summary>The support's face the body slides along (an edge of the pair's Minkowski difference), −1 for the floor or a body.</summary>
    Friend SupportEdge As Integer() = Array.Empty(Of Integer)()

    ''' <summary>Not supported.</summary>
    Friend Const SupportNone As Integer = -1
    ''' <summary>Supported by the container's floor.</summary>
    Friend Const SupportFloor As Integer = -2
    ''' <summary>Supported by another body at rest.</summary>
    Friend Const SupportBody As Integer = -3

    ''' <summary>How many bodies are sliding round a corner (they reach further than their cell, see Predictor.ReachOfPath).</summary>
    Friend Rounding As Integer

    Private ReadOnly _index As New Dictionary(Of Shape, Integer)()

    ''' <summary>Reads every movable body of the world, in the world's order, as free bodies at time <paramref name="now"/> (s).</summary>
    Friend Sub Load(world As World, now As Double)
        Dim n = world.Movables.Count
        Count = n
        If Shapes.Length < n Then Allocate(Math.Max(n, 2 * Shapes.Length))
        _index.Clear()
        Rounding = 0
        For i = 0 To n - 1
            Dim body = world.Movables(i)
            Shapes(i) = body
            _index(body) = i
            Dim o = body.Outline
            Outlines(i) = o
            Dim isCircle = body.Kind = ShapeKind.Circle
            Dim farthest = 0.0
            For Each v In o.Vertices
                farthest = Math.Max(farthest, v.Length)
            Next
            Info(i) = BodyInfo.Fresh(body.Kind)
            Size(i) = New BodySize() With {.Reach = farthest + o.Radius,
                                           .Scale = If(isCircle, o.Radius, Math.Sqrt(body.Area / Math.PI))}
            Slot(i) = New EventSlot() With {.ColTime = Double.PositiveInfinity, .CellTime = Double.PositiveInfinity}
            Roaming(i) = False
            Reload(i, world, now)
        Next
    End Sub

    ''' <summary>Reads body i's position and velocity from the model at time <paramref name="now"/> (s): free, or dragged.</summary>
    Friend Sub Reload(i As Integer, world As World, now As Double)
        Dim body = Shapes(i)
        Motion(i) = New Motion() With {.T0 = now, .Px = body.Position.X, .Py = body.Position.Y,
                                       .Vx = body.Velocity.X, .Vy = body.Velocity.Y, .R = body.Outline.Radius}
        Support(i) = SupportNone
        SupportEdge(i) = -1
        If body Is world.DraggedBody Then
            SetMode(i, BodyMode.Dragged)
            Info(i).InverseMass = 0
        Else
            SetMode(i, BodyMode.Free)
            Motion(i).Ay = -world.Gravity
            Info(i).InverseMass = body.InverseMass
        End If
    End Sub

    ''' <summary>The body's number, or −1 when it is not one of the movable bodies.</summary>
    Friend Function IndexOf(body As Shape) As Integer
        Dim i As Integer
        If body IsNot Nothing AndAlso _index.TryGetValue(body, i) Then Return i
        Return -1
    End Function

    Friend Function Mode(i As Integer) As BodyMode
        Return Slot(i).Mode
    End Function

    ''' <summary>Sets body i's mode, keeping count of the bodies sliding round a corner.</summary>
    Friend Sub SetMode(i As Integer, mode As BodyMode)
        If Slot(i).Mode = BodyMode.Rounding Then Rounding -= 1
        If mode = BodyMode.Rounding Then Rounding += 1
        Slot(i).Mode = mode
    End Sub

    ''' <summary>Where body k's reference point is at time t (s), m (not for a body sliding round a corner).</summary>
    Friend Function PositionAt(k As Integer, t As Double) As Vector
        Dim x, y, vx, vy As Double
        Motion(k).StateAt(t, x, y, vx, vy)
        Return New Vector(x, y)
    End Function

    Private Sub Allocate(capacity As Integer)
        ReDim Shapes(capacity - 1)
        ReDim Motion(capacity - 1)
        ReDim Slot(capacity - 1)
        ReDim Info(capacity - 1)
        ReDim Size(capacity - 1)
        ReDim Outlines(capacity - 1)
        ReDim Roaming(capacity - 1)
        ReDim Support(capacity - 1)
        ReDim SupportEdge(capacity - 1)
    End Sub
End Class
