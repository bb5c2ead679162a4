Option Strict On

' The liquid tool: a region of liquid drawn by dragging from one corner to the opposite one, with the
' density typed (or chosen as water or oil) before; refused where it would overlap another liquid, as a
' scene file is. Delete mode removes a liquid clicked where no body or link is.
Partial Friend NotInheritable Class PointerTools
    ''' <summary>Water's density, kg/m² (densities are areal in this 2D world, as a body's mass ÷ area).</summary>
    Public Const WaterDensity As Double = 1000.0
    ''' <summary>A cooking oil's density, kg/m²: lighter than water, so it floats on it.</summary>
    Public Const OilDensity As Double = 900.0
    ''' <summary>The densest liquid the box takes, kg/m² (mercury is 13 600 kg/m³).</summary>
    Public Const MaxLiquidDensity As Double = 100000.0
    ''' <summary>Asked when the liquid's density is missing, not above 0 or not a number.</summary>
    Public Const LiquidMessage As String = "Please enter a suitable value for the liquid's density!"

    Private _liquidDensity As Double

    ''' <summary>The liquid tool with the typed density.</summary>
    Public Sub BeginAddLiquid()
        BeginAddLiquid(_stage.Inputs(InputField.LiquidDensity))
    End Sub

    ''' <summary>
    ''' The liquid tool: the next left drag on the canvas draws a region of liquid of density
    ''' <paramref name="densityText"/> (kg/m²) from the corner where it starts to the one where it ends.
    ''' </summary>
    Public Sub BeginAddLiquid(densityText As String)
        If Draft IsNot Nothing Then
            _stage.ShowMessage(InputLimits.SpawnFirstMessage)
            Return
        End If
        If Not String.Equals(_stage.Inputs(InputField.LiquidDensity), densityText, StringComparison.Ordinal) Then
            _stage.Inputs(InputField.LiquidDensity) = densityText
            _stage.Window.ShowInputs()
        End If
        _stage.Guarded(
            Sub()
                Dim rho = NumberInput.ReadPositive(densityText, "liquid density (kg/m²)", MaxLiquidDensity)
                If Not rho.IsValid Then
                    _stage.ShowMessage(LiquidMessage & " " & Stage.Problems(rho))
                    Return
                End If
                If rho.WasClamped Then
                    _stage.Inputs(InputField.LiquidDensity) = Units.Input(rho.Value)
                    _stage.Window.ShowInputs()
                End If
                EndGestures()
                _Mode = ClickMode.Liquid
                _liquidDensity = rho.Value
                _stage.Emit("mode liquid density " & Units.Input(rho.Value) & " kg/m²")
                _stage.ShowMessage(Stage.ClampNote(("liquid density", rho, "kg/m²")) & "Press at one corner of the liquid, drag to the opposite corner and let go (Esc cancels). Its top is its surface.")
                _stage.Window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>The density of the liquid the tool draws, kg/m² (set when the tool starts).</summary>
    Public ReadOnly Property LiquidToolDensity As Double
        Get
            Return _liquidDensity
        End Get
    End Property

    ''' <summary>The left button came up at <paramref name="p"/> (m) while the liquid tool is on: the region is made, or refused with the reason.</summary>
    Private Function LiquidUp(button As PointerButton, p As Vector) As Boolean
        If button <> PointerButton.Left OrElse Not _rampStart.HasValue Then Return True
        Dim a = _rampStart.Value
        Dim b = If(p.IsFinite, _stage.World.Inside(p, 0), a)
        _rampStart = Nothing
        Dim lower = New Vector(Math.Min(a.X, b.X), Math.Min(a.Y, b.Y))
        Dim w = Math.Abs(b.X - a.X), h = Math.Abs(b.Y - a.Y)
        Dim least = MinRampPixels * _screenScale()
        If _view().ToPixels(w) < least OrElse _view().ToPixels(h) < least Then
            _stage.ShowMessage("That liquid would be too small to see: press at one corner, drag to the opposite corner and let go (Esc cancels).")
            Return True
        End If
        AddLiquid(New Liquid(lower, w, h, _liquidDensity))
        Return True
    End Function

    ''' <summary>Adds a drawn liquid, unless it overlaps a liquid already there (a body there would feel which density?).</summary>
    Private Sub AddLiquid(liquid As Liquid)
        For Each other In _stage.World.Liquids
            If other.Overlaps(liquid) Then
                _stage.Emit("liquid refused: overlaps " & other.Id)
                _stage.ShowMessage("Liquids may not overlap: the one drawn from " & Units.Pair(liquid.Min, 2) & " to " & Units.Pair(liquid.Max, 2) & " m overlaps the liquid " & other.Id &
                                   " (" & Units.Pair(other.Min, 2) & " to " & Units.Pair(other.Max, 2) & " m). Draw it beside or above it (Esc cancels).")
                Return
            End If
        Next
        Dim before = _history.Capture()
        _stage.World.Add(liquid)
        _history.Commit("the liquid " & liquid.Id & " added", before)
        _Mode = ClickMode.Move
        _toolCursor = Nothing
        _stage.Emit("placed liquid " & liquid.Id & " density " & Units.Input(liquid.Density) & " from " & Units.Pair(liquid.Min, 3) & " to " & Units.Pair(liquid.Max, 3))
        _stage.ShowMessage("")
        _stage.TakeSnapshot()
        _stage.Window.ShowSettings()
    End Sub

    ''' <summary>The liquid region holding <paramref name="p"/> (m), or Nothing.</summary>
    Private Function LiquidAt(p As Vector) As Liquid
        For Each l In _stage.World.Liquids
            If p.X >= l.Min.X AndAlso p.X <= l.Max.X AndAlso p.Y >= l.Min.Y AndAlso p.Y <= l.Max.Y Then Return l
        Next
        Return Nothing
    End Function

    Private Sub DeleteLiquid(liquid As Liquid)
        Undoably("the liquid " & liquid.Id & " deleted", "deleted liquid " & liquid.Id, Sub() _stage.World.Remove(liquid))
    End Sub
End Class
