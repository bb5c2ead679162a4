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
