Option Strict On

''' <summary>
''' Contact geometry as pure functions: values in, a <see cref="Contact"/> out. No state, no response.
''' </summary>
Public Module Collider
    ''' <summary>Contact between circle A (centre pa, radius ra) and circle B; the normal points from B to A.
    ''' Coincident centres get the fallback normal +y instead of a division by zero.</summary>
    Public Function CircleCircle(pa As Vector, ra As Double, pb As Vector, rb As Double) As Contact
        Dim d = pa - pb
        Dim dist = d.Length
        Dim n = d.Normalized(New Vector(0, 1))
        Return New Contact(n, ra + rb - dist)
    End Function

    ''' <summary>
    ''' Contact between a circle and an axis-aligned rectangle by the closest-point method: the point
    ''' of the rectangle nearest the centre is on a face (normal along that face's normal) or a corner
    ''' (normal along the corner-to-centre line). A centre inside the rectangle is pushed out through the
    ''' nearest face.
    ''' </summary>
    Public Function CircleRectangle(p As Vector, r As Double, min As Vector, max As Vector) As Contact
        Dim cx = Math.Min(Math.Max(p.X, min.X), max.X)
        Dim cy = Math.Min(Math.Max(p.Y, min.Y), max.Y)
        If cx <> p.X OrElse cy <> p.Y Then
            Dim d = p - New Vector(cx, cy)
            Dim dist = d.Length
            Return New Contact(d / dist, r - dist)
        End If
        ' Centre inside: leave through the nearest face.
        Dim toLeft = p.X - min.X, toRight = max.X - p.X, toBottom = p.Y - min.Y, toTop = max.Y - p.Y
        Dim best = Math.Min(Math.Min(toLeft, toRight), Math.Min(toBottom, toTop))
        If best = toTop Then Return New Contact(New Vector(0, 1), r + toTop)
        If best = toBottom Then Return New Contact(New Vector(0, -1), r + toBottom)
        If best = toLeft Then Return New Contact(New Vector(-1, 0), r + toLeft)
        Return New Contact(New Vector(1, 0), r + toRight)
    End Function

    ''' <summary>
    ''' How deep two axis-aligned boxes [aMin, aMax] and [bMin, bMax] overlap, m: the smaller of their
    ''' overlaps along x and along y, the shorter way to part them; zero when they touch, negative when apart.
    ''' </summary>
    Public Function BoxBoxDepth(aMin As Vector, aMax As Vector, bMin As Vector, bMax As Vector) As Double
        Dim ox = Math.Min(aMax.X, bMax.X) - Math.Max(aMin.X, bMin.X)
        Dim oy = Math.Min(aMax.Y, bMax.Y) - Math.Max(aMin.Y, bMin.Y)
        Return Math.Min(ox, oy)
    End Function

    ''' <summary>
    ''' <see cref="CircleRectangle"/> for a circle that moved to p from <paramref name="from"/> during a
    ''' time step. If the centre's path crossed into the rectangle (it ended inside it, or went right
    ''' through it), the circle is sent back out through the face its path came in by, not the nearest
    ''' one, so neither a fast step nor a push can carry it through a thin rectangle to its far side.
    ''' A path that started inside falls back to the nearest face.
    ''' </summary>
    Public Function CircleRectangleFrom(p As Vector, r As Double, min As Vector, max As Vector, from As Vector) As Contact
        Dim contact = CircleRectangle(p, r, min, max)
        If Not from.IsFinite Then Return contact
        Dim startedInside = from.X > min.X AndAlso from.X < max.X AndAlso from.Y > min.Y AndAlso from.Y < max.Y
        If startedInside Then Return contact
        ' Slab method: the segment from + s (p − from), 0 ≤ s ≤ 1, is inside the box for s in [enter, leave].
        Dim d = p - from
        Dim enter = 0.0, leave = 1.0
        Dim normal = Vector.Zero
        If Not Slab(from.X, d.X, min.X, max.X, enter, leave, normal, New Vector(-1, 0), New Vector(1, 0)) Then Return contact
        If Not Slab(from.Y, d.Y, min.Y, max.Y, enter, leave, normal, New Vector(0, -1), New Vector(0, 1)) Then Return contact
        If normal = Vector.Zero OrElse enter >= leave Then Return contact
        ' Depth: how far the centre is behind the entry face, plus the radius.
        Dim behind As Double
        If normal.X < 0 Then
            behind = p.X - min.X
        ElseIf normal.X > 0 Then
            behind = max.X - p.X
        ElseIf normal.Y < 0 Then
            behind = p.Y - min.Y
        Else
            behind = max.Y - p.Y
        End If
        Return New Contact(normal, r + behind)
    End Function

    ''' <summary>
    ''' Clips [enter, leave] to where q + s dq lies in [lo, hi]; the face crossed at the latest entry
    ''' sets <paramref name="normal"/>. False when the segment misses the slab.
    ''' </summary>
    Private Function Slab(q As Double, dq As Double, lo As Double, hi As Double, ByRef enter As Double, ByRef leave As Double,
                          ByRef normal As Vector, lowNormal As Vector, highNormal As Vector) As Boolean
        If dq = 0 Then Return q > lo AndAlso q < hi
        Dim s0 = (lo - q) / dq, s1 = (hi - q) / dq
        Dim n0 = lowNormal, n1 = highNormal
        If s0 > s1 Then
            Dim ts = s0 : s0 = s1 : s1 = ts
            Dim tn = n0 : n0 = n1 : n1 = tn
        End If
        If s0 > enter Then
            enter = s0
            normal = n0
        End If
        If s1 < leave Then leave = s1
        Return enter < leave
    End Function

    ''' <summary>
    ''' <see cref="CircleCircle"/> against a fixed circle (centre pb, radius rb) for a circle that moved
    ''' to pa from <paramref name="from"/> during a time step: if its centre's path crossed into the
    ''' fixed disc (ending inside it or going through), it is sent back out at the point where the path
    ''' entered, so a push can never carry it through to the far side.
    ''' </summary>
    Public Function CircleCircleFrom(pa As Vector, ra As Double, pb As Vector, rb As Double, from As Vector) As Contact
        Dim contact = CircleCircle(pa, ra, pb, rb)
        If Not from.IsFinite OrElse (from - pb).LengthSquared <= rb * rb Then Return contact
        ' Entry of from + s (pa − from), 0 ≤ s ≤ 1, into the disc: |from − pb + s d|² = rb².
        Dim d = pa - from
        Dim f = from - pb
        Dim a = Vector.Dot(d, d), b = Vector.Dot(f, d), c = Vector.Dot(f, f) - rb * rb
        Dim disc = b * b - a * c
        If Not (a > 0 AndAlso disc > 0) Then Return contact
        Dim s = (-b - Math.Sqrt(disc)) / a
        If Not (s >= 0 AndAlso s <= 1) Then Return contact
        Dim n = (f + d * s).Normalized(contact.Normal)
        Return New Contact(n, ra + rb - Vector.Dot(pa - pb, n))
    End Function

    ''' <summary>
    ''' Contact between any two bodies that never rotate: body A (outline a, reference point pa) and body B
    ''' (outline b, reference point pb). They touch exactly when pa − pb lies in the Minkowski difference
    ''' of their outlines, so the contact is that point's <see cref="OutlineContact.Penetration"/>: the
    ''' depth, and the normal from B towards A (a face's own normal, or from a corner towards the point).
    ''' </summary>
    Public Function OutlineOutline(a As Outline, pa As Vector, b As Outline, pb As Vector) As Contact
        Return OutlineOutline(Outline.MinkowskiDifference(b, a), pa, pb)
    End Function

    ''' <summary>
    ''' <see cref="OutlineOutline(Outline, Vector, Outline, Vector)"/> with the Minkowski difference of B's and
    ''' A's outlines already made (<c>Outline.MinkowskiDifference(b, a)</c>), for callers that keep it.
    ''' </summary>
    Public Function OutlineOutline(difference As Outline, pa As Vector, pb As Vector) As Contact
        If difference Is Nothing Then Throw New ArgumentNullException(NameOf(difference))
        Return OutlineContact.Penetration(difference, pa - pb)
    End Function

    ''' <summary>
    ''' The core of an outline: the same shape without its rounding (radius 0). A circle's core is its
    ''' centre; a polygon's, box's or segment's is the outline itself.
    ''' </summary>
    Public Function OutlineCore(shape As Outline) As Outline
        If shape Is Nothing Then Throw New ArgumentNullException(NameOf(shape))
        If shape.Radius = 0 Then Return shape
        Dim v = shape.Vertices
        If v.Count = 1 Then Return Outline.Point(0).Translated(v(0))
        If v.Count = 2 Then Return Outline.Segment(v(0), v(1))
        Return Outline.Polygon(v)
    End Function

    ''' <summary>
    ''' The contact of a body A that moved (its reference point) from <paramref name="from"/> to
    ''' <paramref name="pa"/> during a time step with a fixed body B at <paramref name="pb"/>, for every
    ''' pair of shapes. <paramref name="difference"/> is <c>Outline.MinkowskiDifference(b, a)</c>, where
    ''' d = p_A − p_B must be for the bodies to touch, and <paramref name="coreDifference"/> is
    ''' <c>Outline.MinkowskiDifference(b, OutlineCore(a))</c>, where d is when A's core (a circle's centre, the
    ''' whole of a box or polygon) is inside B itself. When the straight path of d during the step crossed
    ''' into that region (it ended inside, or went right through: a circle's centre reached the body, a box
    ''' entered it), A is sent back out by the side its path came in by (the normal of the feature it
    ''' entered, <see cref="OutlineContact.ContactNormal"/>), not by the nearest side, so neither a fast
    ''' step nor a push can carry it through a thin body to its far side; a segment, which has no
    ''' thickness, is the extreme case. The depth is how far d must move along that normal to be A's own
    ''' rounding (a circle's radius) beyond the entry point's tangent line. A path that started inside has
    ''' no side it came in by and gets the nearest way out, as does a path that never got there (then the
    ''' nearest point is right: a circle's centre is still outside the body). For a circle against a fixed
    ''' circle or rectangle this is the rule of <see cref="CircleCircleFrom"/> and
    ''' <see cref="CircleRectangleFrom"/>, which give it in closed form.
    ''' </summary>
    Public Function OutlineOutlineFrom(difference As Outline, coreDifference As Outline, pa As Vector, pb As Vector, from As Vector) As Contact
        If difference Is Nothing Then Throw New ArgumentNullException(NameOf(difference))
        If coreDifference Is Nothing Then Throw New ArgumentNullException(NameOf(coreDifference))
        Dim d = pa - pb
        Dim nearest = OutlineContact.Penetration(difference, d)
        If Not from.IsFinite OrElse from = pa Then Return nearest
        Dim d0 = from - pb
        Dim path = d - d0
        ' Touching is decided to a part in 10¹² of the sizes involved: rounding, not geometry.
        Dim slop = PathSlop * (d0.Length + path.Length + (difference.MaxX - difference.MinX) + (difference.MaxY - difference.MinY))
        If OutlineContact.Penetration(coreDifference, d0).Depth > slop Then Return nearest
        Dim feature As Integer
        Dim t = OutlineContact.EarliestEntry(coreDifference, d0, path, Vector.Zero, slop, 0, 1.0, feature)
        If feature < 0 OrElse Not (t <= 1.0) Then Return nearest
        Dim entry = d0 + t * path
        Dim n = OutlineContact.ContactNormal(coreDifference, entry, feature, slop)
        ' A's rounding: the difference's radius is A's plus B's, the core difference's B's alone.
        Return New Contact(n, difference.Radius - coreDifference.Radius + Vector.Dot(n, entry - d))
    End Function

    ''' <summary>Touching tolerance of <see cref="OutlineOutlineFrom(Outline, Outline, Vector, Vector, Vector)"/>, as a fraction of the sizes involved.</summary>
    Private Const PathSlop As Double = 0.000000000001

    ''' <summary>
    ''' <see cref="OutlineOutlineFrom(Outline, Outline, Vector, Vector, Vector)"/> for body A (outline a) against
    ''' fixed body B (outline b), making both Minkowski differences here.
    ''' </summary>
    Public Function OutlineOutlineFrom(a As Outline, pa As Vector, b As Outline, pb As Vector, from As Vector) As Contact
        Return OutlineOutlineFrom(Outline.MinkowskiDifference(b, a), Outline.MinkowskiDifference(b, OutlineCore(a)), pa, pb, from)
    End Function

    ''' <summary>
    ''' Contact of any body (reference point p, outline <paramref name="shape"/>) with one side of a
    ''' container of the given size (m): nothing rotates, so the depth comes from the outline's extents.
    ''' The normal points into the container.
    ''' </summary>
    Public Function OutlineWall(p As Vector, shape As Outline, side As WallSide, width As Double, height As Double) As Contact
        If shape Is Nothing Then Throw New ArgumentNullException(NameOf(shape))
        Select Case side
            Case WallSide.Left : Return New Contact(New Vector(1, 0), -(p.X + shape.MinX))
            Case WallSide.Right : Return New Contact(New Vector(-1, 0), p.X + shape.MaxX - width)
            Case WallSide.Bottom : Return New Contact(New Vector(0, 1), -(p.Y + shape.MinY))
            Case WallSide.Top : Return New Contact(New Vector(0, -1), p.Y + shape.MaxY - height)
            Case Else : Throw New ArgumentOutOfRangeException(NameOf(side))
        End Select
    End Function

    ''' <summary>Contact of a circle with one side of a container of the given size; the normal points into the container.</summary>
    Public Function CircleWall(p As Vector, r As Double, side As WallSide, width As Double, height As Double) As Contact
        Select Case side
            Case WallSide.Left : Return New Contact(New Vector(1, 0), r - p.X)
            Case WallSide.Right : Return New Contact(New Vector(-1, 0), r - (width - p.X))
            Case WallSide.Bottom : Return New Contact(New Vector(0, 1), r - p.Y)
            Case WallSide.Top : Return New Contact(New Vector(0, -1), r - (height - p.Y))
            Case Else : Throw New ArgumentOutOfRangeException(NameOf(side))
        End Select
    End Function
End Module
