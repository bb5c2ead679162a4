Option Strict On

' Air resistance in the Forces tab: the air's density (a setting, like friction) and a body's drag C_d and b (an edit, undoable).
Partial Public NotInheritable Class SimulationPresenter
    ''' <summary>The air's density when air is switched on with nothing typed, kg/m² (areal, like every density here; the scene format's world.air_density).</summary>
    Public Const DefaultAirDensity As Double = 1.2

    ''' <summary>The largest air density typed, kg/m²: denser is a liquid (water is 1000), drawn with the liquid tool.</summary>
    Public Const MaxAirDensity As Double = 100.0

    ''' <summary>The largest drag coefficient C_d typed: a flat plate across the flow is about 2.</summary>
    Public Const MaxDragCoefficient As Double = 100.0

    ''' <summary>The largest linear drag b typed, N·s/m.</summary>
    Public Const MaxLinearDrag As Double = 10000.0

    ''' <summary>Says what C_d and b do, where they are typed.</summary>
    Public Const DragNote As String = "C_d: quadratic drag ½ρC_d L v², needs air on; b: linear drag b·v, in air and liquids."

    ''' <summary>The air's density now, kg/m² (0: no air).</summary>
    Public ReadOnly Property AirDensity As Double
        Get
            Return World.AirDensity
        End Get
    End Property

    ''' <summary>"Air ρ = 1.2 kg/m²", or "No air".</summary>
    Public ReadOnly Property AirText As String
        Get
            Return DescribeAir(World)
        End Get
    End Property

    ''' <summary>The world's air in words, as <see cref="AirText"/> shows it.</summary>
    Public Shared Function DescribeAir(w As World) As String
        If w Is Nothing Then Throw New ArgumentNullException(NameOf(w))
        If w.AirDensity = 0 Then Return "No air (no quadratic drag)"
        Return "Air ρ = " & Units.Input(w.AirDensity) & " kg/m²"
    End Function

    ''' <summary>
    ''' Air on (with the typed density, kg/m²; empty: <see cref="DefaultAirDensity"/>) or off (density 0), as a scene
    ''' file's world.air_density. A negative or unreadable density is refused naming its box and nothing changes; one
    ''' above <see cref="MaxAirDensity"/> is brought to it and said. Like friction, the air is a setting, not an edit:
    ''' Undo and Restart leave it as set.
    ''' </summary>
    Public Sub SetAir(airOn As Boolean, densityText As String)
        Guarded(
            Sub()
                Dim density = 0.0, clamped = False
                If airOn Then
                    Dim t = If(densityText, "").Trim()
                    If t.Length = 0 Then
                        density = DefaultAirDensity
                    Else
                        Dim problems As New List(Of String)
                        Dim read = NumberInput.ReadNonNegative(t, "air density ρ (kg/m²)", MaxAirDensity, problems)
                        If problems.Count > 0 Then
                            ShowMessage("The air is unchanged: " & String.Join("; ", problems) & ".")
                            Return
                        End If
                        density = read.Value
                        clamped = read.WasClamped
                    End If
                End If
                World.AirDensity = density
                Emit("air " & Units.Num(density, 3))
                Dim note = If(clamped, "An air density above " & Units.Input(MaxAirDensity) & " kg/m² was brought to it (a denser fluid is a liquid). ", "")
                ShowMessage(note & DescribeAir(World) & ". " & DragNote)
                TakeSnapshot()
                _window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>The drag coefficient C_d and linear drag b (N·s/m) of the movable body <paramref name="id"/>, or Nothing when there is none.</summary>
    Public Function DragOf(id As String) As (DragCoefficient As Double, LinearDrag As Double)?
        Dim b = World.Movables.FirstOrDefault(Function(m) m.Id = id)
        If b Is Nothing Then Return Nothing
        Return (b.DragCoefficient, b.LinearDrag)
    End Function

    ''' <summary>
    ''' Sets the drag of the movable body <paramref name="id"/> from the typed C_d and b (N·s/m), as a scene file's
    ''' drag_coefficient and linear_drag. A negative or unreadable value is refused naming its box and nothing
    ''' changes; one above its limit is brought to it and said. An edit: Undo puts the old values back.
    ''' </summary>
    Public Sub SetDrag(id As String, dragCoefficientText As String, linearDragText As String)
        Guarded(
            Sub()
                Dim body = World.Movables.FirstOrDefault(Function(m) m.Id = id)
                If body Is Nothing Then
                    ShowMessage("Drag is unchanged: there is no movable body '" & id & "' (choose one in the Body list).")
                    Return
                End If
                Dim problems As New List(Of String)
                Dim cd = NumberInput.ReadNonNegative(dragCoefficientText, "drag coefficient C_d", MaxDragCoefficient, problems)
                Dim b = NumberInput.ReadNonNegative(linearDragText, "linear drag b (N·s/m)", MaxLinearDrag, problems)
                If problems.Count > 0 Then
                    ShowMessage("The drag of " & id & " is unchanged: " & String.Join("; ", problems) & ".")
                    Return
                End If
                If cd.Value = body.DragCoefficient AndAlso b.Value = body.LinearDrag Then
                    ShowMessage(id & " already has C_d = " & Units.Input(cd.Value) & " and b = " & Units.Input(b.Value) & " N·s/m.")
                    Return
                End If
                Dim before = _history.Capture()
                World.SetDrag(body, cd.Value, b.Value)
                Emit("drag of " & id & " cd " & Units.Num(cd.Value, 3) & " b " & Units.Num(b.Value, 3))
                _history.Commit("the drag of " & id, before)
                Dim note = ""
                If cd.WasClamped Then note &= "C_d above " & Units.Input(MaxDragCoefficient) & " was brought to it. "
                If b.WasClamped Then note &= "b above " & Units.Input(MaxLinearDrag) & " N·s/m was brought to it. "
                Dim noAir = If(cd.Value > 0 AndAlso World.AirDensity = 0, " C_d acts only with air on (and in liquids).", "")
                ShowMessage(note & id & ": C_d = " & Units.Input(cd.Value) & ", b = " & Units.Input(b.Value) & " N·s/m." & noAir)
                TakeSnapshot()
                _window.ShowSettings()
            End Sub)
    End Sub
End Class
