Option Strict On

''' <summary>
''' How long the velocity arrows are drawn: an arrow is the distance the ball would cover in
''' <see cref="Seconds"/> (so its length in metres is speed × Seconds). The scale follows the scene:
''' when the fastest ball's arrow would be longer than a quarter of the container, the scale drops
''' to a round value that fits; when balls slow down it grows back, up to a quarter of a second,
''' but only once the fastest arrow is a tenth of its room, so arrows do not flicker between scales.
''' The <see cref="LegendSpeed"/> is a round speed whose arrow is drawn, labelled, as the key.
''' </summary>
Public NotInheritable Class ArrowScale
    ''' <summary>The longest time an arrow stands for, s (slow scenes).</summary>
    Public Const MaxSeconds As Double = 0.25

    ''' <summary>Seconds of travel an arrow stands for.</summary>
    Public ReadOnly Property Seconds As Double = MaxSeconds

    ''' <summary>Follows the scene: <paramref name="fastest"/> m/s is the fastest ball, <paramref name="room"/> m the longest arrow wanted.</summary>
    Public Sub Update(fastest As Double, room As Double)
        If Not (room > 0) OrElse Double.IsInfinity(room) Then Return
        If Not (fastest > 0) OrElse Double.IsInfinity(fastest) Then
            _Seconds = MaxSeconds
            Return
        End If
        Dim length = fastest * Seconds
        If length <= room AndAlso (length >= room / 10 OrElse Seconds >= MaxSeconds) Then Return
        _Seconds = Math.Min(MaxSeconds, RoundDown(room / fastest))
    End Sub

    ''' <summary>A round speed (1, 2 or 5 × 10ⁿ m/s) whose arrow is at most <paramref name="maxPixels"/> long at <paramref name="pixelsPerMetre"/>.</summary>
    Public Function LegendSpeed(pixelsPerMetre As Double, maxPixels As Double) As Double
        If Not (pixelsPerMetre > 0) Then Return 0
        Return RoundDown(maxPixels / (pixelsPerMetre * Seconds))
    End Function

    ''' <summary>The largest 1, 2 or 5 × 10ⁿ (2.5 × 10ⁿ too) not above x.</summary>
    Private Shared Function RoundDown(x As Double) As Double
        If Not (x > 0) OrElse Double.IsInfinity(x) Then Return 0
        Dim decade = Math.Pow(10, Math.Floor(Math.Log10(x)))
        For Each m In {5.0, 2.5, 2.0, 1.0}
            If m * decade <= x * (1 + 1.0E-12) Then Return m * decade
        Next
        Return decade
    End Function
End Class
