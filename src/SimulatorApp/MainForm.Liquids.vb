Option Strict On
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

' The liquid tool's button, beside Add ramp: "Liquid ▾" drops down water, oil or a typed density.
Partial Friend NotInheritable Class MainForm
    Private ReadOnly _addLiquid As New Button()
    Private _liquidMenu As LiquidMenu

    ''' <summary>Makes the liquid button and its menu, with the tip that says what it does.</summary>
    Private Sub SetUpLiquidControls()
        _liquidMenu = New LiquidMenu(_kit, _addLiquid)
        AddButton(_addLiquid, SimulationPresenter.LiquidCaption, Sub() _liquidMenu.Show())
        _kit.Tips.SetToolTip(_addLiquid, SimulationPresenter.LiquidTip)
    End Sub

    ''' <summary>The liquid button by the name the --trace output gives it.</summary>
    Private Function LiquidControls() As IEnumerable(Of (Name As String, Control As Control))
        Return {("add-liquid", CType(_addLiquid, Control))}
    End Function

    ''' <summary>Closes the liquid menu with the window.</summary>
    Private Sub DisposeLiquidMenu()
        _liquidMenu?.Dispose()
    End Sub
End Class
