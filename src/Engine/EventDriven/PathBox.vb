Option Strict On

''' <summary>
''' The bounding box of a stretch of a body's path between events: x is linear in time and y a
''' parabola, p(t) = p + v t + ½ (0, a_y) t². The ends of the stretch bound x; y also reaches its
''' vertex if the vertical velocity v_y + a_y t changes sign inside the stretch.
''' </summary>
Friend Module PathBox
    ''' <summary>
    ''' The box (m) that holds p(t) for 0 ≤ t ≤ <paramref name="span"/> s, starting at (px, py) m with
    ''' velocity (vx, vy) m/s and vertical acceleration <paramref name="ay"/> m/s².
    ''' </summary>
    Friend Sub Bounds(px As Double, py As Double, vx As Double, vy As Double, ay As Double, span As Double,
                      ByRef xlo As Double, ByRef xhi As Double, ByRef ylo As Double, ByRef yhi As Double)
        Dim x1 = px + vx * span
        Dim y1 = py + (vy + 0.5 * ay * span) * span
        ' Plain comparisons rather than Math.Min and Math.Max, whose care for NaN and −0 costs more
        ' than the rest of this; a NaN end still gives a NaN bound.
        xlo = If(px < x1, px, x1)
        xhi = If(px > x1, px, x1)
        ylo = If(py < y1, py, y1)
        yhi = If(py > y1, py, y1)
        If ay <> 0 Then
            Dim tv = -vy / ay ' when the vertical velocity is zero
            If tv > 0 AndAlso tv < span Then
                Dim yv = py + 0.5 * vy * tv
                If yv < ylo Then ylo = yv
                If yv > yhi Then yhi = yv
            End If
        End If
    End Sub
End Module
