Option Strict On

''' <summary>
''' The impulses of the last collisions, each shown for <see cref="Lifetime"/> real seconds and
''' fading. Each collision gives one mark per movable body in it: Δp = m·(v_after − v_before), read
''' from the engine's collision record. Two balls get equal and opposite marks (momentum is passed
''' from one to the other); a ball at a wall gets one mark, the wall's impulse on it. The list is
''' bounded: in a gas only the newest <see cref="MaxMarks"/> are kept.
''' </summary>
Public NotInheritable Class ImpulseMarks
    ''' <summary>How long a mark is shown, real seconds.</summary>
    Public Const Lifetime As Double = 1.0
    ''' <summary>The most marks kept (the oldest go first).</summary>
    Public Const MaxMarks As Integer = 60

    Private ReadOnly _marks As New List(Of ImpulseMark)

    ''' <summary>Marks on show, oldest first.</summary>
    Public ReadOnly Property Marks As IReadOnlyList(Of ImpulseMark)
        Get
            Return _marks
        End Get
    End Property

    ''' <summary>Notes the impulses of one collision.</summary>
    Public Sub Record(record As CollisionRecord)
        If record.A Is Nothing Then Return
        If Not record.A.IsFixed Then Add(New ImpulseMark(record.A, record.B, record.Wall, ImpulseOf(record.A, record.AVelocityBefore, record.AVelocityAfter), record.Time))
        If record.B IsNot Nothing AndAlso Not record.B.IsFixed Then
            Add(New ImpulseMark(record.B, record.A, WallSide.None, ImpulseOf(record.B, record.BVelocityBefore, record.BVelocityAfter), record.Time))
        End If
    End Sub

    ''' <summary>Δp = m·(v_after − v_before), kg·m/s.</summary>
    Public Shared Function ImpulseOf(body As Shape, before As Vector, after As Vector) As Vector
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        Return body.Mass * (after - before)
    End Function

    Private Sub Add(mark As ImpulseMark)
        If _marks.Count >= MaxMarks Then _marks.RemoveAt(0)
        _marks.Add(mark)
    End Sub

    ''' <summary>
    ''' Places the marks recorded during the frame at their points of contact, from the bodies'
    ''' positions after it (during a frame the solver keeps positions of its own; a body has moved at
    ''' most one frame since): between two circles, on the first's rim towards the second; at a side
    ''' of the container, on that side; otherwise at the body's centre of mass.
    ''' </summary>
    Public Sub Locate(world As World)
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        For Each m In _marks
            If m.IsLocated Then Continue For
            m.At = ContactOf(m, world)
            m.IsLocated = True
        Next
    End Sub

    Private Shared Function ContactOf(m As ImpulseMark, world As World) As Vector
        Dim c = m.Body.CentreOfMass
        Dim circle = TryCast(m.Body, Circle)
        If circle Is Nothing Then Return c
        If m.Other Is Nothing Then
            Select Case m.Wall
                Case WallSide.Left : Return New Vector(0, c.Y)
                Case WallSide.Right : Return New Vector(world.Width, c.Y)
                Case WallSide.Bottom : Return New Vector(c.X, 0)
                Case WallSide.Top : Return New Vector(c.X, world.Height)
            End Select
            Return c
        End If
        Dim towards = (m.Other.CentreOfMass - c).Normalized(Vector.Zero)
        Return c + circle.Radius * towards
    End Function

    ''' <summary>Ages the marks by <paramref name="realSeconds"/> and drops those older than <see cref="Lifetime"/>.</summary>
    Public Sub Age(realSeconds As Double)
        If Not (realSeconds > 0) Then Return
        For Each m In _marks
            m.Age += realSeconds
        Next
        _marks.RemoveAll(Function(m) m.Age >= Lifetime)
    End Sub

    ''' <summary>How opaque a mark is drawn: 1 when new, falling to 0 at <see cref="Lifetime"/>.</summary>
    Public Shared Function Opacity(mark As ImpulseMark) As Double
        If mark Is Nothing Then Return 0
        Return Math.Max(0.0, Math.Min(1.0, 1 - mark.Age / Lifetime))
    End Function

    ''' <summary>
    ''' After a jump in time (a scrub of the timeline, a step back): only the marks of the latest
    ''' instant stay. Replaying to the moment gives every collision on the way at once, with no real
    ''' time between them to fade in; shown together they would pile up at each body. Marks of bodies
    ''' not in <paramref name="world"/> (the run before the jump) go too.
    ''' </summary>
    Public Sub KeepLatestInstant(world As World)
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        ' The very bodies on show: a body of the run before has the same id, not the same object.
        Dim bodies = world.Bodies
        _marks.RemoveAll(Function(m) Not bodies.Any(Function(b) ReferenceEquals(b, m.Body)))
        If _marks.Count = 0 Then Return
        Dim latest = _marks.Max(Function(m) m.Time)
        _marks.RemoveAll(Function(m) m.Time < latest)
    End Sub

    ''' <summary>Removes every mark.</summary>
    Public Sub Clear()
        _marks.Clear()
    End Sub
End Class
