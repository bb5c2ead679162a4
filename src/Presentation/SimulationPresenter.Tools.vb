Option Strict On

' The tools beyond Add circle and Add rectangle: a regular polygon placed by a click, a ramp drawn by
' dragging from one end to the other, and a link (spring, rod or string) made by clicking its two
' ends. Every new body goes where Placement says it may, like a circle.
Partial Public NotInheritable Class SimulationPresenter
    ''' <summary>The shortest ramp a drag makes, in canvas pixels at 96 dpi: a shorter drag is taken for a slip of the hand.</summary>
    Private Const MinRampPixels As Double = 8
    ''' <summary>How near a click must be to a link's line to pick it, in canvas pixels at 96 dpi.</summary>
    Private Const LinkPickPixels As Double = 6

    Private _rampStart As Vector?
    Private _toolCursor As Vector?
    Private _linkKind As LinkKind = LinkKind.Spring
    Private _linkStiffness As Double

    ''' <summary>While a ramp is drawn: its first end, m (Nothing before the button goes down).</summary>
    Public ReadOnly Property RampStart As Vector?
        Get
            Return _rampStart
        End Get
    End Property

    ''' <summary>Where the cursor is while a ramp, link or polygon is drawn, m (Nothing before it has moved over the canvas).</summary>
    Public ReadOnly Property ToolCursor As Vector?
        Get
            Return _toolCursor
        End Get
    End Property

    ''' <summary>The kind of link the link tool makes.</summary>
    Public ReadOnly Property LinkToolKind As LinkKind
        Get
            Return _linkKind
        End Get
    End Property

    ''' <summary>While a link is made: the body clicked first, or Nothing.</summary>
    Public ReadOnly Property LinkStart As Shape

    ''' <summary>The Fixed box of the rectangle tool was ticked (an obstacle) or cleared (a movable box).</summary>
    Public Sub RectangleFixedChanged(isFixed As Boolean)
        Inputs.RectangleFixed = isFixed
        Emit("rectangle fixed " & If(isFixed, "on", "off"))
        _window.ShowSettings()
    End Sub

    ''' <summary>
    ''' Asks for a regular polygon from the typed sides and angle (°) and the circle's radius (m, the
    ''' polygon's corners lie on that circle), mass (kg) and Fixed box; it then follows the cursor until a click.
    ''' </summary>
    Public Sub BeginAddPolygon()
        BeginAddPolygon(Inputs.SidesText, Inputs.RadiusText, Inputs.PolygonAngleText, Inputs.MassText, Inputs.IsFixed)
    End Sub

    ''' <summary>
    ''' Asks for a regular polygon of <paramref name="sidesText"/> sides, each corner
    ''' <paramref name="sizeText"/> m from its centre, turned <paramref name="angleText"/> degrees
    ''' anticlockwise, fixed or of <paramref name="massText"/> kg; it then follows the cursor until a click.
    ''' </summary>
    Public Sub BeginAddPolygon(sidesText As String, sizeText As String, angleText As String, massText As String, isFixed As Boolean)
        If Draft IsNot Nothing Then
            ShowMessage(InputLimits.SpawnFirstMessage)
            Return
        End If
        Inputs.SidesText = sidesText
        Inputs.RadiusText = sizeText
        Inputs.PolygonAngleText = angleText
        Inputs.IsFixed = isFixed
        If Not isFixed Then Inputs.MassText = massText
        Guarded(
            Sub()
                Dim n = NumberInput.ReadWhole(sidesText, "sides", InputLimits.MinSides, InputLimits.MaxSides)
                ' The circle's radius and its bounds: the polygon's corners lie on that circle.
                Dim r = NumberInput.ReadPositive(sizeText, "radius (m)", InputLimits.MaxRadius, InputLimits.MinRadius)
                Dim a = NumberInput.ReadFinite(angleText, "angle (°)", InputLimits.MaxAngle)
                Dim m = If(isFixed, NumberInput.ReadPositive("1", "mass (kg)", InputLimits.MaxMass),
                                    NumberInput.ReadPositive(massText, "mass (kg)", InputLimits.MaxMass, InputLimits.MinMass))
                If Not n.IsValid OrElse Not r.IsValid OrElse Not a.IsValid OrElse Not m.IsValid Then
                    ShowMessage(InputLimits.PolygonMessage & " " & Problems(n, r, a, m))
                    Return
                End If
                If n.WasClamped Then Inputs.SidesText = Units.Input(n.Value)
                If r.WasClamped Then Inputs.RadiusText = Units.Input(r.Value)
                If a.WasClamped Then Inputs.PolygonAngleText = Units.Input(a.Value)
                If m.WasClamped AndAlso Not isFixed Then Inputs.MassText = Units.Input(m.Value)
                If n.WasClamped OrElse r.WasClamped OrElse a.WasClamped OrElse (m.WasClamped AndAlso Not isFixed) Then _window.ShowInputs()
                Dim sides = CInt(n.Value)
                Dim corners = RegularPolygon.Corners(sides, r.Value, a.Value)
                _Draft = BodyDraft.ForPolygon(corners, m.Value, isFixed, _colours.NextColour())
                EndGestures()
                _Mode = ClickMode.Move
                Dim clamped = ClampNote(("sides", n, ""), ("radius", r, "m"), ("angle", a, "°"), ("mass", If(isFixed, Nothing, CType(m, NumberInput?)), "kg"))
                Emit("adding " & If(isFixed, "fixed ", "") & "polygon n " & sides & " r " & Units.Num(r.Value, 3) & " m angle " & Units.Num(a.Value, 1) &
                     If(isFixed, "", " m " & Units.Num(m.Value, 3) & " kg"))
                ShowMessage(clamped & "Click on the canvas to place the polygon (Esc cancels).")
                _window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>The ramp tool: the next left drag on the canvas draws a fixed line from where it starts to where it ends.</summary>
    Public Sub BeginAddRamp()
        If Draft IsNot Nothing Then
            ShowMessage(InputLimits.SpawnFirstMessage)
            Return
        End If
        Guarded(
            Sub()
                EndGestures()
                _Mode = ClickMode.Ramp
                Emit("mode ramp")
                ShowMessage("Press where the ramp starts, drag to where it ends and let go (Esc cancels).")
                _window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>The link tool with the typed stiffness (used by springs only), N/m.</summary>
    Public Sub BeginAddLink(kind As LinkKind)
        BeginAddLink(kind, Inputs.StiffnessText)
    End Sub

    ''' <summary>
    ''' The link tool: the next two left clicks join a body to another body, or to a fixed anchor
    ''' where the second click finds no body, with a link of this kind as long as the ends are apart.
    ''' A spring has the stiffness <paramref name="stiffnessText"/> (N/m) and rests at that length.
    ''' </summary>
    Public Sub BeginAddLink(kind As LinkKind, stiffnessText As String)
        If Draft IsNot Nothing Then
            ShowMessage(InputLimits.SpawnFirstMessage)
            Return
        End If
        If kind = LinkKind.Spring Then Inputs.StiffnessText = stiffnessText
        Guarded(
            Sub()
                Dim k = NumberInput.ReadPositive(If(kind = LinkKind.Spring, stiffnessText, "1"), "stiffness k (N/m)", InputLimits.MaxStiffness, InputLimits.MinStiffness)
                If Not k.IsValid Then
                    ShowMessage(InputLimits.SpringMessage & " " & Problems(k))
                    Return
                End If
                If k.WasClamped AndAlso kind = LinkKind.Spring Then
                    Inputs.StiffnessText = Units.Input(k.Value)
                    _window.ShowInputs()
                End If
                EndGestures()
                _Mode = ClickMode.Link
                _linkKind = kind
                _linkStiffness = k.Value
                Dim name = KindName(kind)
                Emit("mode link " & name & If(kind = LinkKind.Spring, " k " & Units.Num(k.Value, 3) & " N/m", ""))
                Dim clamped = If(kind = LinkKind.Spring, ClampNote(("stiffness k", k, "N/m")), "")
                ShowMessage(clamped & "Click the first body of the " & name & ", then the second body, or an empty place for a fixed anchor (Esc cancels).")
                _window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>Ends the ramp, link or corner tool without making anything.</summary>
    Private Sub CancelTool()
        If _Mode <> ClickMode.Ramp AndAlso _Mode <> ClickMode.Link AndAlso _Mode <> ClickMode.Corners Then Return
        _Mode = ClickMode.Move
        _rampStart = Nothing
        _toolCursor = Nothing
        _LinkStart = Nothing
        _CornerDraft = Nothing
        Emit("tool cancelled")
        ShowMessage("")
        _window.ShowSettings()
    End Sub

    ''' <summary>A button went down at <paramref name="p"/> (m) while a tool is on; True when the tool took it.</summary>
    Private Function ToolDown(button As PointerButton, p As Vector) As Boolean
        If _Mode = ClickMode.Ramp Then
            If button = PointerButton.Left Then
                _rampStart = World.Inside(p, 0)
                _toolCursor = _rampStart
            End If
            Return True
        End If
        If _Mode = ClickMode.Link Then
            If button = PointerButton.Left Then LinkClick(p)
            Return True
        End If
        If _Mode = ClickMode.Corners Then
            ' A right click gives up the polygon, as Esc does.
            If button = PointerButton.Left Then
                CornerClick(p)
            ElseIf button = PointerButton.Right Then
                CancelTool()
            End If
            Return True
        End If
        Return False
    End Function

    ''' <summary>The cursor moved to <paramref name="p"/> (m): a ramp, link or polygon being drawn follows it.</summary>
    Private Sub ToolMove(p As Vector)
        If _Mode = ClickMode.Ramp OrElse _Mode = ClickMode.Link OrElse _Mode = ClickMode.Corners Then _toolCursor = World.Inside(p, 0)
    End Sub

    ''' <summary>A button came up at <paramref name="p"/> (m) while a tool is on; True when the tool took it.</summary>
    Private Function ToolUp(button As PointerButton, p As Vector) As Boolean
        If _Mode = ClickMode.Link OrElse _Mode = ClickMode.Corners Then Return True
        If _Mode <> ClickMode.Ramp Then Return False
        If button <> PointerButton.Left OrElse Not _rampStart.HasValue Then Return True
        Dim a = _rampStart.Value
        Dim b = If(p.IsFinite, World.Inside(p, 0), a)
        _rampStart = Nothing
        If View.ToPixels((b - a).Length) < MinRampPixels * ScreenScale Then
            ShowMessage("That ramp would be too short to see: press where it starts, drag to where it ends and let go (Esc cancels).")
            Return True
        End If
        AddRamp(a, b)
        Return True
    End Function

    ''' <summary>Adds a ramp from <paramref name="a"/> to <paramref name="b"/> (m), moved to the nearest free place when it would cross a movable body.</summary>
    Private Sub AddRamp(a As Vector, b As Vector)
        Dim ramp As New Segment(a, b) With {.Color = _colours.NextColour()}
        Dim clash = Placement.FirstOverlap(World, ramp, Vector.Zero)
        Dim place = Placement.NearestFree(World, ramp, Vector.Zero, MinPlacementReach)
        If Not place.HasValue Then
            ShowMessage("There is no room for the ramp there: it would cross " & Describe(clash) & ". Draw it elsewhere (Esc cancels).")
            Return
        End If
        Dim moved = place.Value.Length
        If moved > 0 Then ramp = New Segment(a + place.Value, b + place.Value) With {.Color = ramp.Color}
        World.Add(ramp)
        _Mode = ClickMode.Move
        _toolCursor = Nothing
        Emit("placed ramp " & ramp.Id & " from " & Units.Pair(ramp.StartPoint, 3) & " to " & Units.Pair(ramp.EndPoint, 3))
        If clash IsNot Nothing AndAlso moved > Placement.Tolerance Then
            ShowMessage("Placed " & Units.Quantity(moved, "m") & " from where you drew it: there it would have crossed " & Describe(clash) & ".")
        Else
            ShowMessage("")
        End If
        TakeSnapshot()
        _window.ShowSettings()
    End Sub

    ''' <summary>A left click of the link tool at <paramref name="p"/> (m): the first end, then the second.</summary>
    Private Sub LinkClick(p As Vector)
        Dim body = BodyAt(p)
        Dim name = KindName(_linkKind)
        If LinkStart Is Nothing Then
            If body Is Nothing Then
                ShowMessage("Click a body to start the " & name & " (Esc cancels).")
                Return
            End If
            _LinkStart = body
            _toolCursor = p
            Emit("link from " & body.Id)
            ShowMessage("Now click the second body, or an empty place for a fixed anchor (Esc cancels).")
            Return
        End If
        If body Is LinkStart Then
            ShowMessage("A " & name & " joins two different bodies: click another body, or an empty place for a fixed anchor (Esc cancels).")
            Return
        End If
        Dim first = LinkStart
        ' End A must move: a fixed body can only be end B.
        Dim a = If(first.IsFixed AndAlso body IsNot Nothing, body, first)
        Dim b = If(a Is first, body, first)
        If a.IsFixed Then
            ShowMessage(If(body Is Nothing,
                "A fixed body cannot hang from an anchor: click a body that moves, or start again with one (Esc cancels).",
                "Both bodies are fixed, so the " & name & " would do nothing: click a body that moves (Esc cancels)."))
            Return
        End If
        Dim anchor = World.Inside(p, 0)
        Dim length = If(b Is Nothing, (anchor - a.CentreOfMass).Length, (b.CentreOfMass - a.CentreOfMass).Length)
        If _linkKind <> LinkKind.Spring AndAlso Not (length > Placement.Tolerance) Then
            ShowMessage("A " & name & " needs its two ends apart: click farther from the first body (Esc cancels).")
            Return
        End If
        Dim link As Link
        If _linkKind = LinkKind.Spring Then
            link = If(b Is Nothing, Link.CreateSpring(a, anchor, _linkStiffness, length), Link.CreateSpring(a, b, _linkStiffness, length))
        Else
            link = If(b Is Nothing, Link.CreateTie(_linkKind, a, anchor, length), Link.CreateTie(_linkKind, a, b, length))
        End If
        World.Add(link)
        _Mode = ClickMode.Move
        _LinkStart = Nothing
        _toolCursor = Nothing
        Emit("linked " & link.Id & " " & name & " " & a.Id & " to " & If(b Is Nothing, "anchor " & Units.Pair(anchor, 3), b.Id) & " length " & Units.Num(length, 3) & " m")
        ShowMessage("")
        TakeSnapshot()
        _window.ShowSettings()
    End Sub

    ''' <summary>The link whose line passes nearest <paramref name="p"/> (m), within a few pixels, or Nothing.</summary>
    Public Function LinkAt(p As Vector) As Link
        Dim reach = LinkPickPixels * ScreenScale / View.Scale
        Dim best As Link = Nothing
        For Each l In World.Links
            Dim d = DistanceToLine(p, l.EndA, l.EndB)
            If d <= reach Then
                reach = d
                best = l
            End If
        Next
        Return best
    End Function

    ''' <summary>Distance from <paramref name="p"/> to the line segment from <paramref name="a"/> to <paramref name="b"/>, m.</summary>
    Friend Shared Function DistanceToLine(p As Vector, a As Vector, b As Vector) As Double
        Dim ab = b - a
        Dim lengthSquared = ab.LengthSquared
        Dim t = If(lengthSquared > 0, Math.Max(0.0, Math.Min(1.0, Vector.Dot(p - a, ab) / lengthSquared)), 0.0)
        Return (p - (a + ab * t)).Length
    End Function

    Private Sub DeleteLink(link As Link)
        World.Remove(link)
        Emit("deleted link " & link.Id)
        TakeSnapshot()
    End Sub

    ''' <summary>"spring", "rod" or "string".</summary>
    Private Shared Function KindName(kind As LinkKind) As String
        Select Case kind
            Case LinkKind.Spring : Return "spring"
            Case LinkKind.Rod : Return "rod"
            Case Else : Return "string"
        End Select
    End Function
End Class
