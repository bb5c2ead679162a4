Option Strict On

''' <summary>
''' How much of a body lies inside a liquid's rectangle: the area A_sub (m²) and its first moment ∫ y dA
''' (m³), from which buoyancy ρ_l g A_sub and its potential energy follow (<see cref="Buoyancy"/>). Pure
''' functions of the body's outline, where it is, and the rectangle. A polygon (a box among them) is clipped
''' to the rectangle edge by edge; a disc is measured exactly by Green's theorem along the boundary of the
''' part inside (straight pieces of the rectangle's edges and arcs of the circle), so no circle is ever
''' replaced by a polygon. docs/forces.md, "Buoyancy".
''' </summary>
Public Module SubmergedArea
    ''' <summary>
    ''' The part of <paramref name="outline"/>, with its reference point at <paramref name="position"/> (m),
    ''' inside the rectangle from <paramref name="lower"/> to <paramref name="upper"/> (m). A circle (a point
    ''' core with a radius) or a polygon (a radius of 0); a segment has no area.
    ''' </summary>
    Public Function Inside(outline As Outline, position As Vector, lower As Vector, upper As Vector) As Submerged
        If outline Is Nothing Then Throw New ArgumentNullException(NameOf(outline))
        ' Quick answers: wholly apart, or wholly inside (the usual case for a body deep in a tank).
        If position.X + outline.MaxX <= lower.X OrElse position.X + outline.MinX >= upper.X OrElse
           position.Y + outline.MaxY <= lower.Y OrElse position.Y + outline.MinY >= upper.Y Then Return New Submerged(0, 0)
        If outline.VertexCount = 1 Then
            Dim centre = position + outline.Vertices(0)
            Return Disc(centre, outline.Radius, lower, upper)
        End If
        If outline.Radius <> 0 Then Throw New ArgumentException("only a circle or a polygon has a submerged area", NameOf(outline))
        If outline.VertexCount < 3 Then Return New Submerged(0, 0)
        Return Polygon(outline.Vertices, position, lower, upper)
    End Function

    ''' <summary>
    ''' A convex polygon (corners as offsets from <paramref name="position"/>, anticlockwise) clipped to the
    ''' rectangle by the four half-planes of its sides (Sutherland–Hodgman); area and ∫ y dA by the shoelace
    ''' formula, measured from <paramref name="position"/> so that large coordinates cancel less.
    ''' </summary>
    Private Function Polygon(corners As IReadOnlyList(Of Vector), position As Vector, lower As Vector, upper As Vector) As Submerged
        Dim pts As New List(Of Vector)(corners.Count + 4)
        For Each c In corners
            pts.Add(c)
        Next
        Dim lo = lower - position, hi = upper - position
        pts = Clip(pts, New Vector(1, 0), lo.X)   ' x ≥ lo.X
        pts = Clip(pts, New Vector(-1, 0), -hi.X) ' x ≤ hi.X
        pts = Clip(pts, New Vector(0, 1), lo.Y)
        pts = Clip(pts, New Vector(0, -1), -hi.Y)
        If pts.Count < 3 Then Return New Submerged(0, 0)
        Dim twiceArea = 0.0, sixMoment = 0.0
        For i = 0 To pts.Count - 1
            Dim p = pts(i), q = pts((i + 1) Mod pts.Count)
            Dim c = Vector.Cross(p, q)
            twiceArea += c
            sixMoment += c * (p.Y + q.Y)
        Next
        Dim area = Math.Max(0.5 * twiceArea, 0)
        ' ∫ y dA about the reference point, then moved to absolute y: ∫ (y' + p_y) dA.
        Return New Submerged(area, sixMoment / 6 + position.Y * area)
    End Function

    ''' <summary>The part of a closed convex polygon where n·p ≥ <paramref name="offset"/>.</summary>
    Private Function Clip(pts As List(Of Vector), n As Vector, offset As Double) As List(Of Vector)
        Dim result As New List(Of Vector)(pts.Count + 1)
        If pts.Count = 0 Then Return result
        For i = 0 To pts.Count - 1
            Dim p = pts(i), q = pts((i + 1) Mod pts.Count)
            Dim dp = Vector.Dot(n, p) - offset, dq = Vector.Dot(n, q) - offset
            If dp >= 0 Then result.Add(p)
            If (dp >= 0) <> (dq >= 0) Then
                Dim s = dp / (dp - dq)
                result.Add(p + (q - p) * s)
            End If
        Next
        Return result
    End Function

    ''' <summary>
    ''' A disc of radius r at <paramref name="centre"/> inside the rectangle, measured about the centre. By
    ''' Green's theorem the area is ½∮(x dy − y dx) and ∫ y dA is ∮ −½ y² dx round the boundary of the
    ''' part inside, anticlockwise. That boundary is the pieces of the rectangle's sides inside the disc
    ''' and the arcs of the circle inside the rectangle: on a straight piece from a to b the integrals are
    ''' ½ a×b and −(b_x − a_x)(a_y² + a_y b_y + b_y²)/6; on an arc from θ₁ to θ₂, ½ r²(θ₂ − θ₁) and
    ''' ½ r³ [cos³θ/3 − cos θ] from θ₁ to θ₂.
    ''' </summary>
    Private Function Disc(centre As Vector, r As Double, lower As Vector, upper As Vector) As Submerged
        Dim lo = lower - centre, hi = upper - centre
        ' Wholly inside: the whole disc.
        If lo.X <= -r AndAlso hi.X >= r AndAlso lo.Y <= -r AndAlso hi.Y >= r Then Return New Submerged(Math.PI * r * r, centre.Y * Math.PI * r * r)
        Dim corners = {New Vector(lo.X, lo.Y), New Vector(hi.X, lo.Y), New Vector(hi.X, hi.Y), New Vector(lo.X, hi.Y)}
        Dim area = 0.0, moment = 0.0
        Dim angles As New List(Of Double)(8)
        Dim r2 = r * r
        For i = 0 To 3
            Dim p = corners(i), q = corners((i + 1) Mod 4)
            Dim d = q - p
            ' |p + s d|² = r²: s² |d|² + 2 s p·d + |p|² − r² = 0.
            Dim a = d.LengthSquared, b = Vector.Dot(p, d), c = p.LengthSquared - r2
            Dim discriminant = b * b - a * c
            If discriminant <= 0 Then Continue For
            Dim root = Math.Sqrt(discriminant)
            ' Both roots without cancellation: s₀ s₁ = c/a.
            Dim big = -(b + If(b >= 0, root, -root))
            Dim s0 = big / a, s1 = If(big <> 0, c / big, s0)
            If s0 > s1 Then
                Dim t = s0 : s0 = s1 : s1 = t
            End If
            Dim from = Math.Max(s0, 0), upto = Math.Min(s1, 1)
            If from >= upto Then Continue For
            Dim u = p + d * from, w = p + d * upto
            area += 0.5 * Vector.Cross(u, w)
            moment -= (w.X - u.X) * (u.Y * u.Y + u.Y * w.Y + w.Y * w.Y) / 6
            If s0 >= 0 Then angles.Add(Math.Atan2(u.Y, u.X))
            If s1 <= 1 Then angles.Add(Math.Atan2(w.Y, w.X))
        Next
        If angles.Count = 0 Then
            ' The circle meets no side: either it is wholly inside (handled above) or the rectangle lies
            ' inside the disc, whose boundary the pieces of the sides already are.
            If InRectangle(New Vector(r, 0), lo, hi) Then Return New Submerged(Math.PI * r2, centre.Y * Math.PI * r2)
        Else
            angles.Sort()
            For k = 0 To angles.Count - 1
                Dim t1 = angles(k)
                Dim t2 = If(k + 1 < angles.Count, angles(k + 1), angles(0) + 2 * Math.PI)
                If t2 <= t1 Then Continue For
                Dim mid = 0.5 * (t1 + t2)
                If Not InRectangle(New Vector(r * Math.Cos(mid), r * Math.Sin(mid)), lo, hi) Then Continue For
                area += 0.5 * r2 * (t2 - t1)
                Dim c1 = Math.Cos(t1), c2 = Math.Cos(t2)
                moment += 0.5 * r2 * r * ((c2 * c2 * c2 - c1 * c1 * c1) / 3 - (c2 - c1))
            Next
        End If
        area = Math.Min(Math.Max(area, 0), Math.PI * r2)
        Return New Submerged(area, moment + centre.Y * area)
    End Function

    Private Function InRectangle(p As Vector, lo As Vector, hi As Vector) As Boolean
        Return p.X >= lo.X AndAlso p.X <= hi.X AndAlso p.Y >= lo.Y AndAlso p.Y <= hi.Y
    End Function
End Module
