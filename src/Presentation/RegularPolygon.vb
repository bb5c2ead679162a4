Option Strict On

''' <summary>The corners of a regular polygon, as the Add polygon tool builds it.</summary>
Public Module RegularPolygon
    ''' <summary>
    ''' The <paramref name="sides"/> corners of a regular polygon around the origin, anticlockwise,
    ''' each <paramref name="size"/> m from the centre, the first turned <paramref name="angleDegrees"/>
    ''' anticlockwise from straight up: at 0° a triangle points up and a square stands on a corner; at
    ''' 45° the square stands on a side.
    ''' </summary>
    Public Function Corners(sides As Integer, size As Double, angleDegrees As Double) As Vector()
        If sides < 3 Then Throw New ArgumentOutOfRangeException(NameOf(sides), "a polygon has at least 3 sides")
        If Not (size > 0) OrElse Double.IsInfinity(size) Then Throw New ArgumentOutOfRangeException(NameOf(size), "size must be a finite number > 0")
        Dim start = Math.PI / 2 + angleDegrees * Math.PI / 180
        Dim result(sides - 1) As Vector
        For i = 0 To sides - 1
            Dim a = start + 2 * Math.PI * i / sides
            result(i) = New Vector(size * Math.Cos(a), size * Math.Sin(a))
        Next
        Return result
    End Function
End Module
