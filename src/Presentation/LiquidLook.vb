Option Strict On

''' <summary>
''' How a liquid region looks on the canvas: its colour (its own, else water blue or oil amber by its
''' density) and the label that gives its density. The fill is translucent so the bodies in it and the
''' grid behind it still show.
''' </summary>
Public Module LiquidLook
    ''' <summary>Water's blue, &amp;HRRGGBB.</summary>
    Public Const Water As Integer = &H1E88E5
    ''' <summary>Oil's amber, &amp;HRRGGBB.</summary>
    Public Const Oil As Integer = &HFFA000
    ''' <summary>Below this density (kg/m²) a liquid with no colour of its own is drawn as oil, at or above it as water.</summary>
    Public Const OilBelow As Double = 950.0
    ''' <summary>The fill's opacity, 0–255: enough to read as liquid, little enough to see the bodies and grid through.</summary>
    Public Const FillAlpha As Integer = 80
    ''' <summary>The fill's opacity in high contrast: stronger, for a projector.</summary>
    Public Const HighContrastFillAlpha As Integer = 120

    ''' <summary>The liquid's colour, &amp;HRRGGBB: its own "#rrggbb" when it has one, else oil amber below <see cref="OilBelow"/> and water blue otherwise.</summary>
    Public Function ColourOf(liquid As Liquid) As Integer
        If liquid Is Nothing Then Throw New ArgumentNullException(NameOf(liquid))
        Return BodyColours.Parse(liquid.Color, If(liquid.Density < OilBelow, Oil, Water))
    End Function

    ''' <summary>"ρ = 1000 kg/m²": the label drawn inside the liquid.</summary>
    Public Function Label(liquid As Liquid) As String
        If liquid Is Nothing Then Throw New ArgumentNullException(NameOf(liquid))
        Return "ρ = " & Units.Input(liquid.Density) & Units.Nbsp & "kg/m²"
    End Function
End Module
