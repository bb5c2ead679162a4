Option Strict On

' The liquid tool and the air's resistance, as the window's buttons and boxes reach them.
Partial Public NotInheritable Class SimulationPresenter
    ''' <summary>The liquid button, which drops down water, oil or a typed density.</summary>
    Public Const LiquidCaption As String = Captions.Liquid
    ''' <summary>Water's density, kg/m² (areal, as every density in this 2D world).</summary>
    Public Const WaterDensity As Double = PointerTools.WaterDensity
    ''' <summary>A cooking oil's density, kg/m².</summary>
    Public Const OilDensity As Double = PointerTools.OilDensity
    ''' <summary>The liquid buttons' tip: what the tool does, in a short line.</summary>
    Public Const LiquidTip As String = "Drag a rectangle on the canvas to fill it with liquid of this density (water 1000, oil 900 kg/m²): bodies float in it at depth m/(ρ w), or sink."

    ''' <summary>Asked when the liquid's density is missing, not above 0 or not a number (the reason follows).</summary>
    Public Const LiquidMessage As String = PointerTools.LiquidMessage

    ''' <summary>The liquid tool with the typed density, kg/m².</summary>
    Public Sub BeginAddLiquid()
        _pointer.BeginAddLiquid()
    End Sub

    ''' <summary>The liquid tool with the density <paramref name="densityText"/>, kg/m² (also put in the box).</summary>
    Public Sub BeginAddLiquid(densityText As String)
        _pointer.BeginAddLiquid(densityText)
    End Sub

    ''' <summary>The liquid tool for water, 1000 kg/m².</summary>
    Public Sub BeginAddWater()
        _pointer.BeginAddLiquid(Units.Input(PointerTools.WaterDensity))
    End Sub

    ''' <summary>The liquid tool for oil, 900 kg/m².</summary>
    Public Sub BeginAddOil()
        _pointer.BeginAddLiquid(Units.Input(PointerTools.OilDensity))
    End Sub

    ''' <summary>While a liquid is dragged out: its first corner, m (Nothing otherwise).</summary>
    Public ReadOnly Property LiquidStart As Vector?
        Get
            Return If(Mode = ClickMode.Liquid, _pointer.RampStart, Nothing)
        End Get
    End Property

    ''' <summary>The density of the liquid the tool draws, kg/m².</summary>
    Public ReadOnly Property LiquidToolDensity As Double
        Get
            Return _pointer.LiquidToolDensity
        End Get
    End Property
End Class
