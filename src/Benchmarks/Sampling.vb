Option Strict On

''' <summary>Runs a world in equal slices and lets a scene look at the state after each one.</summary>
Friend Module Sampling
    ''' <summary>
    ''' Advances <paramref name="world"/> by <paramref name="duration"/> seconds in slices of
    ''' <paramref name="slice"/> seconds (the last one shorter if need be) and calls
    ''' <paramref name="look"/> with the simulated time after each slice. Stops early when it returns False.
    ''' </summary>
    Public Sub Run(world As World, duration As Double, slice As Double, look As Func(Of Double, Boolean))
        Dim count = CLng(Math.Ceiling(duration / slice - 1.0E-9))
        Dim start = world.Time
        For k = 1L To count
            ' Aim at k·slice from the start rather than adding slices, so rounding never piles up.
            Dim target = If(k = count, start + duration, start + k * slice)
            world.Advance(target - world.Time)
            If Not look(world.Time) Then Return
        Next
    End Sub

    ''' <summary>
    ''' Height of the vertex of the parabola through three equally spaced samples y0, y1, y2 (y1 the
    ''' largest). The exact apex for a parabolic flight, whatever the sampling phase.
    ''' </summary>
    Public Function ParabolaPeak(y0 As Double, y1 As Double, y2 As Double) As Double
        Dim curvature = 2 * y1 - y0 - y2
        If curvature <= 0 Then Return y1
        Return y1 + (y2 - y0) * (y2 - y0) / (8 * curvature)
    End Function
End Module
