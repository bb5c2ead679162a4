Option Strict On

''' <summary>
''' Any pair of outlines (polygons, boxes, segments, and circles against them): relative to B, A's
''' reference point must enter K = B ⊕ (−A) rounded by R_A + R_B, a fixed rounded convex polygon,
''' because nothing rotates. Faces give quadratics (linear when both feel the same acceleration),
''' rounded corners quartics; see <see cref="OutlineContact.EarliestEntry"/>. The normal is a face's,
''' the line from a rounded corner, or, corner on corner, the symmetric rule of
''' <see cref="OutlineContact.ContactNormal"/>.
''' </summary>
Friend NotInheritable Class OutlineRule
    Implements IContactRule

    Public Function TimeOfImpact(ByRef q As ContactQuery, ByRef feature As Integer) As Double Implements IContactRule.TimeOfImpact
        Return OutlineContact.EarliestEntry(q.K, q.D, q.Dv, q.Da, q.Slop, q.SpeedScale, q.Horizon, feature)
    End Function

    Public Function Normal(ByRef q As ContactQuery, feature As Integer, ByRef correction As Double) As Vector Implements IContactRule.Normal
        Dim k = q.K
        Dim n = OutlineContact.ContactNormal(k, q.D, feature, q.Slop)
        correction = 0
        If feature >= 0 AndAlso feature < k.EdgeCount Then
            Dim gap = Vector.Dot(k.EdgeNormals(feature), q.D) - Vector.Dot(k.EdgeNormals(feature), k.Corners(feature)) - k.Radius
            If gap < 0 Then correction = -gap
        End If
        Return n
    End Function
End Class
