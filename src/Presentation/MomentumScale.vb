Option Strict On

''' <summary>
''' How long momentum arrows are drawn (the total momentum at the centre of mass, the momenta
''' diagram and the impulses Δp share it, so they can be compared by eye): a round number of pixels
''' per kg·m/s (1, 2, 2.5 or 5 × 10ⁿ). It follows the scene: when the longest arrow would not fit its
''' room the scale drops to a round value that fits; it grows back only once the longest arrow is
''' shorter than a tenth of its room, so arrows do not flicker between scales.
''' <see cref="LegendMomentum"/> is a round momentum whose arrow is drawn, labelled, as the key.
''' </summary>
Public NotInheritable Class MomentumScale
    ''' <summary>The largest scale, px per kg·m/s (a scene with almost no momentum).</summary>
    Public Const MaxPixelsPerUnit As Double = 1000.0

    ''' <summary>Pixels per kg·m/s.</summary>
    Public ReadOnly Property PixelsPerUnit As Double = 100.0

    ''' <summary>Follows the scene: <paramref name="longest"/> kg·m/s is the longest arrow, <paramref name="roomPixels"/> the most it may take.</summary>
    Public Sub Update(longest As Double, roomPixels As Double)
        If Not (roomPixels > 0) OrElse Double.IsInfinity(roomPixels) OrElse Double.IsInfinity(longest) OrElse Double.IsNaN(longest) Then Return
        If Not (longest > 0) Then Return ' nothing moves: keep the scale, so a paused scene does not rescale
        Dim length = longest * PixelsPerUnit
        If length <= roomPixels AndAlso (length >= roomPixels / 10 OrElse PixelsPerUnit >= MaxPixelsPerUnit) Then Return
        _PixelsPerUnit = Math.Min(MaxPixelsPerUnit, RoundDown(roomPixels / longest))
    End Sub

    ''' <summary>A round momentum (1, 2, 2.5 or 5 × 10ⁿ kg·m/s) whose arrow is at most <paramref name="maxPixels"/> long.</summary>
    Public Function LegendMomentum(maxPixels As Double) As Double
        Return RoundDown(maxPixels / PixelsPerUnit)
    End Function

    ''' <summary>The largest 1, 2, 2.5 or 5 × 10ⁿ not above x (0 for no positive finite x).</summary>
    Public Shared Function RoundDown(x As Double) As Double
        If Not (x > 0) OrElse Double.IsInfinity(x) Then Return 0
        Dim decade = Math.Pow(10, Math.Floor(Math.Log10(x)))
        For Each m In {5.0, 2.5, 2.0, 1.0}
            If m * decade <= x * (1 + 1.0E-12) Then Return m * decade
        Next
        Return decade
    End Function
End Class
