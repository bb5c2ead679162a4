Option Strict On

''' <summary>
''' The one model↔screen transform: metres to pixels with y flipped (the model's y points up, the
''' screen's down), the container fitted and centred in the canvas with a margin.
''' </summary>
Public NotInheritable Class ViewTransform
    ''' <summary>Pixels per metre.</summary>
    Public ReadOnly Property Scale As Double
    ''' <summary>Screen x of the model's x = 0, px.</summary>
    Public ReadOnly Property OffsetX As Double
    ''' <summary>Screen y of the model's y = 0 (the floor), px.</summary>
    Public ReadOnly Property OffsetY As Double

    Public Sub New(scale As Double, offsetX As Double, offsetY As Double)
        Me.Scale = scale
        Me.OffsetX = offsetX
        Me.OffsetY = offsetY
    End Sub

    ''' <summary>Fits a container of worldWidth × worldHeight m into a canvas of the given pixel size.</summary>
    Public Shared Function Fit(worldWidth As Double, worldHeight As Double, canvasWidth As Integer, canvasHeight As Integer,
                               Optional marginPx As Integer = 12) As ViewTransform
        Dim w = Math.Max(1, canvasWidth - 2 * marginPx)
        Dim h = Math.Max(1, canvasHeight - 2 * marginPx)
        Dim s = Math.Min(w / worldWidth, h / worldHeight)
        Dim ox = (canvasWidth - worldWidth * s) / 2
        Dim oy = (canvasHeight + worldHeight * s) / 2
        Return New ViewTransform(s, ox, oy)
    End Function

    ''' <summary>Model point (m) to screen point (px).</summary>
    Public Function ToScreen(p As Vector) As Vector
        Return New Vector(OffsetX + p.X * Scale, OffsetY - p.Y * Scale)
    End Function

    ''' <summary>Screen point (px) to model point (m).</summary>
    Public Function ToWorld(screenX As Double, screenY As Double) As Vector
        Return New Vector((screenX - OffsetX) / Scale, (OffsetY - screenY) / Scale)
    End Function

    ''' <summary>A length in m to px.</summary>
    Public Function ToPixels(metres As Double) As Double
        Return metres * Scale
    End Function
End Class
