Option Strict On

''' <summary>
''' The bounding box of a stretch of a body's path between events: x is linear in time and y a
''' parabola, p(t) = p + v t + ½ (0, a_y) t². The ends of the stretch bound x; y also reaches its
''' vertex if the vertical velocity v_y + a_y t changes sign inside the stretch.
''' </summary>
Public Module PathBox
    ''' <summary>
    ''' The box (m) that holds p(t) for 0 ≤ t ≤ <paramref name="span"/> s, starting at (px, py) m with
    ''' velocity (vx, vy) m/s and vertical acceleration <paramref name="ay"/> m/s².
    ''' </summary>
    Public Sub Bounds(px As Double, py As Double, vx As Double, vy As Double, ay As Double, span As Double,
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

    ''' <summary>
    ''' The box (m) that holds p(t) = p + v t + ½ a t² for 0 ≤ t ≤ <paramref name="span"/> s when the
    ''' acceleration (ax, ay) m/s² may have a horizontal part too (a body sliding down a slope): each
    ''' coordinate is a parabola of its own, bounded by its ends and, inside the stretch, its vertex.
    ''' </summary>
    Public Sub Bounds(px As Double, py As Double, vx As Double, vy As Double, ax As Double, ay As Double, span As Double,
                      ByRef xlo As Double, ByRef xhi As Double, ByRef ylo As Double, ByRef yhi As Double)
        Axis(px, vx, ax, span, xlo, xhi)
        Axis(py, vy, ay, span, ylo, yhi)
    End Sub

    ''' <summary>The range of q + u t + ½ a t² over 0 ≤ t ≤ span.</summary>
    Private Sub Axis(q As Double, u As Double, a As Double, span As Double, ByRef lo As Double, ByRef hi As Double)
        Dim q1 = q + (u + 0.5 * a * span) * span
        lo = If(q < q1, q, q1)
        hi = If(q > q1, q, q1)
        If a <> 0 Then
            Dim tv = -u / a
            If tv > 0 AndAlso tv < span Then
                Dim qv = q + 0.5 * u * tv
                If qv < lo Then lo = qv
                If qv > hi Then hi = qv
            End If
        End If
    End Sub

    ''' <summary>
    ''' Whether a path that starts at (px, py) with velocity (vx, vy) and acceleration (ax, ay) can come
    ''' within <paramref name="reach"/> m of the box [xmin, xmax] × [ymin, ymax] in the next
    ''' <paramref name="span"/> s. False means certainly not; True means it may. A span of +∞ (or NaN
    ''' anywhere) always gives True. Used to skip time-of-impact root finding that cannot succeed.
    ''' </summary>
    Public Function MayReach(px As Double, py As Double, vx As Double, vy As Double, ax As Double, ay As Double, span As Double,
                             xmin As Double, ymin As Double, xmax As Double, ymax As Double, reach As Double) As Boolean
        If Not (span < Double.PositiveInfinity) Then Return True
        Dim xlo, xhi, ylo, yhi As Double
        Bounds(px, py, vx, vy, ax, ay, span, xlo, xhi, ylo, yhi)
        ' Written so that NaN gives True.
        Return Not (xhi + reach < xmin OrElse xlo - reach > xmax OrElse yhi + reach < ymin OrElse ylo - reach > ymax)
    End Function
End Module
