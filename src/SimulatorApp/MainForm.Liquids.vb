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

    ''' <summary>The rectangle's buttons with the ramp's and the liquid's: one row when they fit, else the liquid's on a row of its own.</summary>
    Private Sub LayOutRectangleRow(rh As Integer, pairs As Boolean)
        If pairs AndAlso _rows.FitRow(rh + S(2), _rectFixed, _addRectangle, _addRamp, _addLiquid) Then Return
        If pairs Then
            _rows.Row(rh + S(2), (_rectFixed, 0.2), (_addRectangle, 0.4), (_addRamp, 0.4))
            _rows.Row(rh + S(2), (Nothing, 0.2), (Nothing, 0.4), (_addLiquid, 0.4))
        Else
            _rows.Row(rh + S(2), (_rectFixed, 0.35), (_addRectangle, 0.65))
            _rows.Row(rh + S(2), (Nothing, 0.35), (_addRamp, 0.65))
            _rows.Row(rh + S(2), (Nothing, 0.35), (_addLiquid, 0.65))
        End If
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
