Option Strict On

''' <summary>
''' A circle A against an axis-aligned box B (a rectangle, fixed or movable): the rounded rectangle of
''' <see cref="TimeOfImpact.CircleRectangle(Double, Double, Double, Double, Double, Double, Double, Double, Double, Double, Double, Double, ByRef Integer)"/>,
''' in the box's own frame (its lower-left corner at the origin). The same answer as
''' <see cref="OutlineRule"/> gives, by a shorter road; when the circle's relative acceleration has a
''' sideways part (it slides on a slope) that road does not exist, and <see cref="OutlineRule"/> answers.
''' </summary>
Friend NotInheritable Class CircleBoxRule
    Implements IContactRule

    Private ReadOnly _general As New OutlineRule()

    Public Function TimeOfImpact(ByRef q As ContactQuery, ByRef feature As Integer) As Double Implements IContactRule.TimeOfImpact
        If q.Da.X <> 0 Then Return _general.TimeOfImpact(q, feature)
        Dim w = q.B.MaxX, h = q.B.MaxY
        Dim face As Integer
        Dim t = Global.PhysicsEngine.TimeOfImpact.CircleRectangle(q.D.X, q.D.Y, q.Dv.X, q.Dv.Y, q.Da.Y, q.A.Radius, 0, 0, w, h, q.Slop, q.Horizon, face)
        feature = If(face < 0, -1, FeatureOf(q.K, face, w, h))
        Return t
    End Function

    Public Function Normal(ByRef q As ContactQuery, feature As Integer, ByRef correction As Double) As Vector Implements IContactRule.Normal
        Return _general.Normal(q, feature, correction)
    End Function

    ''' <summary>
    ''' The feature of K (here the box's own core, rounded by the circle's radius) for a face or corner as
    ''' <see cref="TimeOfImpact.CircleRectangle(Double, Double, Double, Double, Double, Double, Double, Double, Double, Double, Double, ByRef Integer)"/>
    ''' numbers them (0 left, 1 right, 2 bottom, 3 top; 4 + k for corner k: bit 0 right, bit 1 top).
    ''' </summary>
    Private Shared Function FeatureOf(k As Outline, face As Integer, w As Double, h As Double) As Integer
        If face < 4 Then
            Dim n As Vector
            Select Case face
                Case 0 : n = New Vector(-1, 0)
                Case 1 : n = New Vector(1, 0)
                Case 2 : n = New Vector(0, -1)
                Case Else : n = New Vector(0, 1)
            End Select
            For e = 0 To k.EdgeCount - 1
                If k.EdgeNormals(e) = n Then Return e
            Next
        Else
            Dim c = New Vector(If(((face - 4) And 1) = 0, 0, w), If(((face - 4) And 2) = 0, 0, h))
            For v = 0 To k.VertexCount - 1
                If k.Corners(v) = c Then Return k.EdgeCount + v
            Next
        End If
        Return -1
    End Function
End Class
