Option Strict On

''' <summary>
''' Which feature of a pair shape a touching contact lies on, as the <see cref="Constraint"/> that keeps it
''' (docs/contact.md, "Features"). Pure functions. Body A touches B (or a fixed body) where d = c_A − c_B − shift,
''' the difference of their reference points, lies on the boundary of their pair shape K (the Minkowski
''' difference of the outlines, rounded by R): on an edge (a flat face: <see cref="ConstraintShape.Plane"/>) or
''' on a rounded corner (<see cref="ConstraintShape.Round"/>); two balls touch on the corner of a point. Where d
''' is at the end of an edge, the feature is the one it is moving onto.
''' </summary>
Friend Module ContactFeatures
    ''' <summary>
    ''' The contact of slot <paramref name="a"/> with slot <paramref name="b"/> (−1: a fixed body) on pair shape
    ''' <paramref name="k"/>, for d = c_A − c_B − <paramref name="shift"/> (m) moving at <paramref name="w"/> = ḋ
    ''' (m/s) with <paramref name="q"/> = d̈ (m/s², or zero when not known); within <paramref name="slop"/> (m) of
    ''' the boundary, or pressed in. Nothing where d is on a sharp corner (R = 0) and not on an edge it stays on: a
    ''' corner of one box on a corner of another holds nothing.
    ''' </summary>
    Friend Function OnOutline(a As Integer, b As Integer, shift As Vector, k As Outline, d As Vector, w As Vector, q As Vector, slop As Double,
                              Optional offFace As Boolean = False) As Constraint
        Dim corners = k.Corners, normals = k.EdgeNormals, lengths = k.EdgeLengths
        Dim r = k.Radius
        Dim m = corners.Length
        If m = 1 Then Return Constraint.Round(a, b, shift, corners(0), r, Vector.Zero, Vector.Zero)
        ' The nearest edge d lies along (within its extent), if d is on it (pressed in or not) and not leaving by one
        ' of its ends. Of a polygon's edges the nearest is the one d is least deep behind, as for the contact normal:
        ' an edge further behind than that by more than a slop is the far side of the outline (d past the end of the
        ' near edge is at a rounded corner, never on a face across the body).
        Dim least = Double.NegativeInfinity
        For i = 0 To normals.Length - 1
            least = Math.Max(least, Vector.Dot(normals(i), d - corners(i)) - r)
        Next
        Dim edge = -1, nearest = Double.NegativeInfinity
        For i = 0 To normals.Length - 1
            Dim n = normals(i)
            Dim rel = d - corners(i)
            Dim gap = Vector.Dot(n, rel) - r
            If gap > slop OrElse gap <= nearest OrElse gap < least - slop Then Continue For
            Dim t = RestingFaces.Along(n)
            Dim s = Vector.Dot(t, rel)
            If s < -slop OrElse s > lengths(i) + slop Then Continue For
            edge = i
            nearest = gap
        Next
        If edge >= 0 Then
            Dim n = normals(edge)
            Dim t = RestingFaces.Along(n)
            Dim s = Vector.Dot(t, d - corners(edge))
            ' offFace: the contact has just gone off an end of this face; at that end, with neither speed nor acceleration
            ' along the face to say so again, it is on the corner.
            Dim atAnEnd = s <= slop OrElse s >= lengths(edge) - slop
            Dim undecided = Vector.Dot(t, w) = 0 AndAlso Vector.Dot(t, q) = 0
            If Not RestingFaces.IsLeaving(s, Vector.Dot(t, w), Vector.Dot(t, q), lengths(edge), slop) AndAlso
               Not (offFace AndAlso atAnEnd AndAlso undecided) Then
                Return Constraint.Plane(a, b, shift, n, Vector.Dot(n, corners(edge)) + r, corners(edge), t, lengths(edge))
            End If
        End If
        If r <= 0 Then Return Nothing
        ' The rounded corner whose region d is in (or nearest to).
        Dim best = -1, bestMargin = Double.NegativeInfinity
        For c = 0 To m - 1
            Dim before = RestingFaces.Along(normals((c + m - 1) Mod m)), after = RestingFaces.Along(normals(c))
            Dim rel = d - corners(c)
            Dim margin = Math.Min(Vector.Dot(rel, before), -Vector.Dot(rel, after))
            If margin > bestMargin Then bestMargin = margin : best = c
        Next
        Dim prev = RestingFaces.Along(normals((best + m - 1) Mod m)), nxt = RestingFaces.Along(normals(best))
        Return Constraint.Round(a, b, shift, corners(best), r, prev, nxt)
    End Function

    ''' <summary>A body's contact with a wall of the container: slot <paramref name="a"/>, its extents <paramref name="low"/> and <paramref name="high"/> from its centre (m).</summary>
    Friend Function OnWall(a As Integer, side As WallSide, low As Vector, high As Vector, width As Double, height As Double) As Constraint
        Select Case side
            Case WallSide.Left : Return Constraint.Plane(a, -1, Vector.Zero, New Vector(1, 0), -low.X, Vector.Zero, RestingFaces.Along(New Vector(1, 0)), Double.PositiveInfinity)
            Case WallSide.Right : Return Constraint.Plane(a, -1, Vector.Zero, New Vector(-1, 0), high.X - width, Vector.Zero, RestingFaces.Along(New Vector(-1, 0)), Double.PositiveInfinity)
            Case WallSide.Bottom : Return Constraint.Plane(a, -1, Vector.Zero, New Vector(0, 1), -low.Y, Vector.Zero, RestingFaces.Along(New Vector(0, 1)), Double.PositiveInfinity)
            Case Else : Return Constraint.Plane(a, -1, Vector.Zero, New Vector(0, -1), high.Y - height, Vector.Zero, RestingFaces.Along(New Vector(0, -1)), Double.PositiveInfinity)
        End Select
    End Function
End Module
