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
    Implements IDisposable

    Private ReadOnly _kit As WindowKit
    Private ReadOnly _button As Button
    Private ReadOnly _menu As New ContextMenuStrip()

    ''' <param name="button">the Liquid button the menu drops down from</param>
    Public Sub New(kit As WindowKit, button As Button)
        _kit = kit
        _button = button
        AddHandler _menu.Closed, Sub(s, e) _kit.Emit("liquid menu closed")
    End Sub

    ''' <summary>Drops the menu down under its button, kept on the screen.</summary>
    Public Sub Show()
        Dim p = _kit.Presenter
        Dim theme = p.Theme
        _kit.Prepare(_menu, theme)
        Dim back = ScenePainter.Rgb(theme.Panel), fore = ScenePainter.Rgb(theme.PanelText)
        Dim water As New ToolStripMenuItem("Water, " & Units.Input(SimulationPresenter.WaterDensity) & " kg/m²") With {.BackColor = back, .ForeColor = fore, .ToolTipText = SimulationPresenter.LiquidTip}
        AddHandler water.Click, Sub(s, e) _kit.Act(Sub() _kit.Presenter.BeginAddWater())
        Dim oil As New ToolStripMenuItem("Oil, " & Units.Input(SimulationPresenter.OilDensity) & " kg/m² (floats on water)") With {.BackColor = back, .ForeColor = fore, .ToolTipText = SimulationPresenter.LiquidTip}
        AddHandler oil.Click, Sub(s, e) _kit.Act(Sub() _kit.Presenter.BeginAddOil())
        Dim box As New ToolStripTextBox() With {.Text = p.Inputs(InputField.LiquidDensity), .ToolTipText = "ρ, kg/m²"}
        Dim typed As New ToolStripMenuItem("Density typed above, kg/m²") With {.BackColor = back, .ForeColor = fore, .ToolTipText = SimulationPresenter.LiquidTip}
        Dim useTyped = Sub()
                           Dim text = box.Text
                           _menu.Close()
                           _kit.Act(Sub() _kit.Presenter.BeginAddLiquid(text))
                       End Sub
        AddHandler typed.Click, Sub(s, e) useTyped()
        AddHandler box.KeyDown, Sub(s, e)
                                    If e.KeyCode = Keys.Enter Then
                                        e.SuppressKeyPress = True
                                        useTyped()
                                    End If
                                End Sub
        _menu.Items.AddRange(New ToolStripItem() {water, oil, New ToolStripSeparator(), box, typed})
        _menu.Show(_kit.OnScreen(_button, _menu.GetPreferredSize(Size.Empty)))
        If _kit.Trace IsNot Nothing Then
            For i = 0 To _menu.Items.Count - 1
                Dim b = _menu.Items(i).Bounds
                Dim at = _menu.PointToScreen(b.Location)
                _kit.Emit("liquid item " & i & " " & at.X & " " & at.Y & " " & b.Width & " " & b.Height)
            Next
            _kit.Emit("liquid menu shown " & _menu.Items.Count)
        End If
    End Sub

    Public Sub Dispose() Implements IDisposable.Dispose
        _menu.Dispose()
    End Sub
End Class
