Option Strict On
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

' The liquid tool's row of the side panel: "Liquid ρ (kg/m²) [1000] [Water] [Oil] [Add liquid]".
Partial Friend NotInheritable Class MainForm
    Private ReadOnly _liquidLabel As New Label()
    Private ReadOnly _liquidDensity As New TextBox()
    Private ReadOnly _addWater As New Button()
    Private ReadOnly _addOil As New Button()
    Private ReadOnly _addLiquid As New Button()

    ''' <summary>Makes the liquid row's controls, with the tip that says what they do.</summary>
    Private Sub SetUpLiquidControls()
        AddField(_liquidLabel, SimulationPresenter.LiquidDensityCaption, _liquidDensity, InputField.LiquidDensity)
        AddButton(_addWater, "Water", Sub() _presenter.BeginAddWater())
        AddButton(_addOil, "Oil", Sub() _presenter.BeginAddOil())
        AddButton(_addLiquid, "Add liquid", Sub() _presenter.BeginAddLiquid())
        For Each c In New Control() {_liquidLabel, _liquidDensity, _addWater, _addOil, _addLiquid}
            _kit.Tips.SetToolTip(c, SimulationPresenter.LiquidTip)
        Next
    End Sub

    ''' <summary>Lays out the liquid row: one row when it fits, else the box on one and the three buttons on the next.</summary>
    Private Sub LayOutLiquidRow(rh As Integer, pairs As Boolean)
        If pairs AndAlso _rows.FitRow(rh + S(2), _liquidLabel, _liquidDensity, _addWater, _addOil, _addLiquid) Then Return
        _rows.Row(rh, (_liquidLabel, 0.55), (_liquidDensity, 0.45))
        _rows.Row(rh + S(2), (_addWater, 1 / 3), (_addOil, 1 / 3), (_addLiquid, 1 / 3))
    End Sub

    ''' <summary>The liquid row's controls by the names the --trace output gives them.</summary>
    Private Function LiquidControls() As IEnumerable(Of (Name As String, Control As Control))
        Return {("liquid-label", CType(_liquidLabel, Control)), ("liquid-density", _liquidDensity), ("add-water", _addWater), ("add-oil", _addOil), ("add-liquid", _addLiquid)}
    End Function
End Class
