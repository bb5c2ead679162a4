Option Strict On

''' <summary>Colour tests on screenshot pixels (&amp;HRRGGBB).</summary>
Public Module Pixels
    ''' <summary>Perceived brightness, 0 to 255.</summary>
    Public Function Luma(p As Integer) As Integer
        Return (((p >> 16) And 255) * 299 + ((p >> 8) And 255) * 587 + (p And 255) * 114) \ 1000
    End Function

    ''' <summary>True for a clearly coloured pixel (a body), false for greys (background, ink).</summary>
    Public Function IsSaturated(p As Integer) As Boolean
        Dim r = (p >> 16) And 255, g = (p >> 8) And 255, b = p And 255
        Return Math.Max(r, Math.Max(g, b)) - Math.Min(r, Math.Min(g, b)) > 60
    End Function

    ''' <summary>The fraction of coloured pixels in a square of half-side <paramref name="half"/> around (x, y).</summary>
    Public Function ColouredAround(shot As Screenshot, x As Integer, y As Integer, Optional half As Integer = 4) As Double
        Return shot.Fraction(x - half, y - half, x + half + 1, y + half + 1, AddressOf IsSaturated)
    End Function
End Module
