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
