Option Strict On

''' <summary>A scale bar: a round length (1, 2 or 5 × 10^k m) whose drawn length is near a target in pixels.</summary>
Public Structure ScaleBar
    ''' <summary>The length the bar stands for, m.</summary>
    Public ReadOnly Property Metres As Double
    ''' <summary>Its drawn length, px.</summary>
    Public ReadOnly Property Pixels As Double

    Private Sub New(metres As Double, pixels As Double)
        Me.Metres = metres
        Me.Pixels = pixels
    End Sub

    ''' <summary>The round length whose drawn length is the largest not over <paramref name="maxPixels"/>.</summary>
    Public Shared Function Choose(pixelsPerMetre As Double, maxPixels As Double) As ScaleBar
        Dim best = New ScaleBar(0, 0)
        If Not (pixelsPerMetre > 0) Then Return best
        For k = -4 To 4
            For Each m In {1.0, 2.0, 5.0}
                Dim metres = m * Math.Pow(10, k)
                Dim px = metres * pixelsPerMetre
                If px <= maxPixels AndAlso px > best.Pixels Then best = New ScaleBar(metres, px)
            Next
        Next
        Return best
    End Function

    ''' <summary>"50 cm", "1 m", "20 m".</summary>
    Public ReadOnly Property Label As String
        Get
            If Metres < 0.01 Then Return Units.Num(Metres * 1000, 0) & " mm"
            If Metres < 1 Then Return Units.Num(Metres * 100, 0) & " cm"
            Return Units.Num(Metres, 0) & " m"
        End Get
    End Property
End Structure
