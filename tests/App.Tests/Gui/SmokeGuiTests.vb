Option Strict On
Imports Xunit

''' <summary>The real window comes up and draws: a canvas with bodies on it and the controls beside it.</summary>
<Collection(RealWindow.Name)>
Public Class SmokeGuiTests
    <GuiFact>
    Public Sub App_StartsAndDrawsItsCanvasAndControls()
        Using x As New XSession(Array.Empty(Of String)())
            Dim shot = x.Shoot("smoke")
            Dim why = x.AppOutput()
            Assert.True(shot.Width >= 800 AndAlso shot.Height >= 500, $"window is {shot.Width}x{shot.Height}" & vbLf & why)
            ' The canvas (left part): the demo scene's bodies give several colours, not a blank fill.
            Dim canvasColours = shot.DistinctColours(0, 0, shot.Width * 2 \ 3, shot.Height)
            Assert.True(canvasColours >= 20, $"canvas has only {canvasColours} colours: blank?" & vbLf & why)
            Dim saturated = shot.Fraction(0, 0, shot.Width * 2 \ 3, shot.Height, AddressOf IsSaturated)
            Assert.True(saturated > 0.002, $"canvas shows no coloured bodies ({saturated:P3} coloured pixels)" & vbLf & why)
            ' The controls (right part): text and borders are dark pixels on a light panel.
            Dim dark = shot.Fraction(shot.Width * 3 \ 4, 0, shot.Width, shot.Height, Function(p) Luma(p) < 90)
            Assert.True(dark > 0.001, $"no controls drawn on the right ({dark:P3} dark pixels)" & vbLf & why)
            Assert.True(x.AppIsRunning, "the app died" & vbLf & why)
        End Using
    End Sub

    Private Shared Function Luma(p As Integer) As Integer
        Return (((p >> 16) And 255) * 299 + ((p >> 8) And 255) * 587 + (p And 255) * 114) \ 1000
    End Function

    Private Shared Function IsSaturated(p As Integer) As Boolean
        Dim r = (p >> 16) And 255, g = (p >> 8) And 255, b = p And 255
        Return Math.Max(r, Math.Max(g, b)) - Math.Min(r, Math.Min(g, b)) > 60
    End Function
End Class
