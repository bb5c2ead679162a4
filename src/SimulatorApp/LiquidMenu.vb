Option Strict On
Imports System.Drawing
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>
''' The liquid menu: water, oil, or a density typed into the menu's own box; each starts the liquid tool
''' (drag a rectangle on the canvas). A menu, not a row of the side panel, which has no room left on a
''' 1280 × 720 screen.
''' </summary>
Friend NotInheritable Class LiquidMenu
    Inherits DropDownMenu

    ''' <param name="button">the Liquid button the menu drops down from</param>
    Public Sub New(kit As WindowKit, button As Button)
        MyBase.New(kit, button, "liquid")
    End Sub

    ''' <summary>Drops the menu down under its button, kept on the screen.</summary>
    Public Sub Show()
        Begin()
        Dim p = Kit.Presenter
        Dim water = NewItem("Water, " & Units.Input(SimulationPresenter.WaterDensity) & " kg/m²", SimulationPresenter.LiquidTip, Sub() p.BeginAddWater())
        Dim oil = NewItem("Oil, " & Units.Input(SimulationPresenter.OilDensity) & " kg/m² (floats on water)", SimulationPresenter.LiquidTip, Sub() p.BeginAddOil())
        Dim box As New ToolStripTextBox() With {.Text = p.Inputs(InputField.LiquidDensity), .ToolTipText = "ρ, kg/m²"}
        Dim typed As New ToolStripMenuItem("Density typed above, kg/m²") With {.BackColor = Back, .ForeColor = Fore, .ToolTipText = SimulationPresenter.LiquidTip}
        Dim useTyped = Sub()
                           Dim text = box.Text
                           Strip.Close()
                           Kit.Act(Sub() p.BeginAddLiquid(text))
                       End Sub
        AddHandler typed.Click, Sub(s, e) useTyped()
        AddHandler box.KeyDown, Sub(s, e)
                                    If e.KeyCode = Keys.Enter Then
                                        e.SuppressKeyPress = True
                                        useTyped()
                                    End If
                                End Sub
        Strip.Items.AddRange(New ToolStripItem() {water, oil, New ToolStripSeparator(), box, typed})
        Drop()
    End Sub
End Class
