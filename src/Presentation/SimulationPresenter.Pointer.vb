Option Strict On

' What the mouse does on the canvas: place a new body, delete one, carry one (right button) or
' push one with the cue (left button).
Partial Public NotInheritable Class SimulationPresenter
    ''' <summary>How far from the click a new body may be moved to find room, in its own sizes (at least <see cref="MinPlacementReach"/>).</summary>
    Private Const PlacementReachSizes As Double = 3.0
    ''' <summary>The least distance searched for room around a click, m.</summary>
    Private Const MinPlacementReach As Double = 0.5
    ''' <summary>
    ''' How fast a ball carried while time runs may follow the cursor, in container diagonals per
    ''' second of real time: a flick of the mouse does not fire the balls it meets across the room.
    ''' </summary>
    Private Const CarryDiagonalsPerSecond As Double = 2.0

    Private _dragged As Shape
    Private _grabOffset As Vector ' body reference point minus cursor, m
    Private _carryGoal As Vector ' where the cursor wants the carried body's reference point, m
    Private _aimCursor As Vector

    ''' <summary>The body waiting to be placed, or Nothing.</summary>
    Public ReadOnly Property Draft As BodyDraft

    ''' <summary>The body being carried with the right button, or Nothing.</summary>
    Public ReadOnly Property DraggedBody As Shape
        Get
            Return _dragged
        End Get
    End Property

    ''' <summary>The movable body being aimed at with the cue (any kind), or Nothing.</summary>
    Public ReadOnly Property AimedBody As Shape

    ''' <summary>Where the cursor is while aiming, m.</summary>
    Public ReadOnly Property AimCursor As Vector
        Get
            Return _aimCursor
        End Get
    End Property

    ''' <summary>The impulse the cue will give when released, N·s (zero when not aiming).</summary>
    Public ReadOnly Property CueImpulse As Vector
        Get
            If AimedBody Is Nothing Then Return Vector.Zero
            Return CueShot.ImpulseFor(AimedBody.CentreOfMass, _aimCursor)
        End Get
    End Property

    ''' <summary>"J = 2.40 N·s   Δv = J/m = 1.20 m/s" while aiming, "" otherwise.</summary>
    Public ReadOnly Property CueLabel As String
        Get
            If AimedBody Is Nothing Then Return ""
            Dim j = CueImpulse.Length
            Return "J = " & Units.Quantity(j, "N·s") & "   Δv = J/m = " & Units.Quantity(j * AimedBody.InverseMass, "m/s")
        End Get
    End Property

    ''' <summary>Whether the body waiting to be placed could go where the cursor is now (the preview is drawn red when not).</summary>
    Public ReadOnly Property DraftFits As Boolean
        Get
            If Draft Is Nothing OrElse Not Draft.HasCentre Then Return True
            Dim body = Draft.Build(Draft.Centre)
            Return Placement.IsFree(World, body, Vector.Zero)
        End Get
    End Property

    ''' <summary>Asks for a circle from the typed radius (m), mass (kg) and Fixed box; it then follows the cursor until a click.</summary>
    Public Sub BeginAddCircle()
        BeginAddCircle(Inputs.RadiusText, Inputs.MassText, Inputs.IsFixed)
    End Sub

    ''' <summary>Asks for a circle of the given radius (m) and mass (kg); it then follows the cursor until a click.</summary>
    Public Sub BeginAddCircle(radiusText As String, massText As String, isFixed As Boolean)
        If Draft IsNot Nothing Then
            ShowMessage(InputLimits.SpawnFirstMessage)
            Return
        End If
        Inputs.RadiusText = radiusText
        Inputs.MassText = massText
        Inputs.IsFixed = isFixed
        Guarded(
            Sub()
                Dim r = NumberInput.ReadPositive(radiusText, "radius (m)", InputLimits.MaxRadius, InputLimits.MinRadius)
                ' A fixed circle has no mass to ask for.
                Dim m = If(isFixed, NumberInput.ReadPositive("1", "mass (kg)", InputLimits.MaxMass),
                                    NumberInput.ReadPositive(massText, "mass (kg)", InputLimits.MaxMass, InputLimits.MinMass))
                If Not r.IsValid OrElse Not m.IsValid Then
                    ShowMessage(InputLimits.CircleMessage & " " & Problems(r, m))
                    Return
                End If
                ' The boxes keep what was typed; only a value brought to a limit is written back (and said).
                If r.WasClamped Then Inputs.RadiusText = Units.Input(r.Value)
                If m.WasClamped AndAlso Not isFixed Then Inputs.MassText = Units.Input(m.Value)
                If r.WasClamped OrElse (m.WasClamped AndAlso Not isFixed) Then _window.ShowInputs()
                _Draft = BodyDraft.ForCircle(r.Value, m.Value, isFixed, _colours.NextColour())
                EndGestures()
                _Mode = ClickMode.Move
                Dim clamped = ClampNote(("radius", r, "m"), ("mass", If(isFixed, Nothing, CType(m, NumberInput?)), "kg"))
                Emit("adding " & If(isFixed, "fixed ", "") & "circle r " & Units.Num(r.Value, 3) & " m" & If(isFixed, "", " m " & Units.Num(m.Value, 3) & " kg"))
                ShowMessage(clamped & "Click on the canvas to place the circle (Esc cancels).")
                _window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>
    ''' Asks for a rectangle from the typed width and height (m): a fixed obstacle when its Fixed box is
    ''' ticked, otherwise a movable box with the typed mass (kg). It then follows the cursor until a click.
    ''' </summary>
    Public Sub BeginAddRectangle()
        BeginAddRectangle(Inputs.WidthText, Inputs.HeightText, Inputs.RectangleFixed, Inputs.MassText)
    End Sub

    ''' <summary>Asks for a fixed rectangle of the given width and height, m; it then follows the cursor until a click.</summary>
    Public Sub BeginAddRectangle(widthText As String, heightText As String)
        BeginAddRectangle(widthText, heightText, True, Inputs.MassText)
    End Sub

    ''' <summary>
    ''' Asks for a rectangle of the given width and height (m): fixed, or a movable box of the given
    ''' mass (kg). It then follows the cursor until a click.
    ''' </summary>
    Public Sub BeginAddRectangle(widthText As String, heightText As String, isFixed As Boolean, massText As String)
        If Draft IsNot Nothing Then
            ShowMessage(InputLimits.SpawnFirstMessage)
            Return
        End If
        Inputs.WidthText = widthText
        Inputs.HeightText = heightText
        Inputs.RectangleFixed = isFixed
        If Not isFixed Then Inputs.MassText = massText
        Guarded(
            Sub()
                Dim w = NumberInput.ReadPositive(widthText, "width (m)", InputLimits.MaxSide, InputLimits.MinSide)
                Dim h = NumberInput.ReadPositive(heightText, "height (m)", InputLimits.MaxSide, InputLimits.MinSide)
                ' A fixed rectangle has no mass to ask for.
                Dim m = If(isFixed, NumberInput.ReadPositive("1", "mass (kg)", InputLimits.MaxMass),
                                    NumberInput.ReadPositive(massText, "mass (kg)", InputLimits.MaxMass, InputLimits.MinMass))
                If Not w.IsValid OrElse Not h.IsValid OrElse Not m.IsValid Then
                    ShowMessage(If(isFixed, InputLimits.RectangleMessage, InputLimits.BoxMessage) & " " & Problems(w, h, m))
                    Return
                End If
                If w.WasClamped Then Inputs.WidthText = Units.Input(w.Value)
                If h.WasClamped Then Inputs.HeightText = Units.Input(h.Value)
                If m.WasClamped AndAlso Not isFixed Then Inputs.MassText = Units.Input(m.Value)
                If w.WasClamped OrElse h.WasClamped OrElse (m.WasClamped AndAlso Not isFixed) Then _window.ShowInputs()
                _Draft = If(isFixed, BodyDraft.ForRectangle(w.Value, h.Value, _colours.NextColour()),
                                     BodyDraft.ForBox(w.Value, h.Value, m.Value, _colours.NextColour()))
                EndGestures()
                _Mode = ClickMode.Move
                Dim clamped = ClampNote(("width", w, "m"), ("height", h, "m"), ("mass", If(isFixed, Nothing, CType(m, NumberInput?)), "kg"))
                Emit("adding " & Draft.KindName & " " & Units.Num(w.Value, 3) & " x " & Units.Num(h.Value, 3) & " m" & If(isFixed, "", " m " & Units.Num(m.Value, 3) & " kg"))
                ShowMessage(clamped & "Click on the canvas to place the " & Draft.KindName & " (Esc cancels).")
                _window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>
    ''' "radius set to the maximum, 2.00 m. " for each value brought to a limit; "" when none was. A
    ''' count (no unit: the sides of a polygon) is written as the whole number it is, "3", not "3.00".
    ''' </summary>
    Private Shared Function ClampNote(ParamArray fields As (Name As String, Input As NumberInput?, Unit As String)()) As String
        Dim notes = fields.Where(Function(f) f.Input.HasValue AndAlso f.Input.Value.WasClamped).
            Select(Function(f) f.Name & " set to the " & If(f.Input.Value.WasRaised, "minimum", "maximum") & ", " &
                               If(f.Unit.Length = 0, f.Input.Value.Value.ToString("0", Globalization.CultureInfo.InvariantCulture), Units.Sig(f.Input.Value.Value) & " " & f.Unit)).ToList()
        If notes.Count = 0 Then Return ""
        Return String.Join(", ", notes) & ". "
    End Function

    ''' <summary>Drops the body waiting to be placed, or the ramp, link or polygon being drawn (Esc).</summary>
    Public Sub CancelPlacement()
        If Draft Is Nothing Then
            CancelTool()
            Return
        End If
        _Draft = Nothing
        Emit("placement cancelled")
        ShowMessage("")
        _window.ShowSettings()
    End Sub

    ''' <summary>A mouse button went down on the canvas at (x, y) px.</summary>
    Public Sub PointerDown(button As PointerButton, x As Double, y As Double)
        Guarded(
            Sub()
                Dim p = View.ToWorld(x, y)
                If Not p.IsFinite Then Return
                If Draft IsNot Nothing Then
                    If button = PointerButton.Left Then Place(p)
                    Return
                End If
                If ToolDown(button, p) Then Return
                Dim body = BodyAt(p)
                If button = PointerButton.Left Then
                    If Mode = ClickMode.Delete Then
                        If body IsNot Nothing Then
                            Delete(body)
                        Else
                            Dim link = LinkAt(p)
                            If link IsNot Nothing Then DeleteLink(link)
                        End If
                        Return
                    End If
                    If body IsNot Nothing AndAlso Not body.IsFixed AndAlso _dragged Is Nothing Then
                        _AimedBody = body
                        _aimCursor = p
                        Emit("aiming at " & body.Id)
                    End If
                ElseIf button = PointerButton.Right AndAlso body IsNot Nothing AndAlso AimedBody Is Nothing AndAlso Mode = ClickMode.Move Then
                    BeginCarry(body, p)
                End If
            End Sub)
    End Sub

    ''' <summary>The mouse moved over the canvas to (x, y) px.</summary>
    Public Sub PointerMove(x As Double, y As Double)
        Guarded(
            Sub()
                Dim p = View.ToWorld(x, y)
                If Not p.IsFinite Then Return
                If Draft IsNot Nothing Then
                    Draft.Centre = p
                    Draft.HasCentre = True
                End If
                If AimedBody IsNot Nothing Then _aimCursor = p
                ToolMove(p)
                If _dragged IsNot Nothing Then
                    _carryGoal = p + _grabOffset
                    ' While time runs, a movable ball follows in the frames (see CarryTowardsCursor); otherwise at once.
                    If Not IsCarriedByEngine Then CarryTo(_carryGoal, Double.PositiveInfinity)
                End If
            End Sub)
    End Sub

    ''' <summary>A mouse button came up at (x, y) px.</summary>
    Public Sub PointerUp(button As PointerButton, x As Double, y As Double)
        Guarded(
            Sub()
                Dim p = View.ToWorld(x, y)
                If ToolUp(button, p) Then Return
                If button = PointerButton.Left AndAlso AimedBody IsNot Nothing Then
                    If p.IsFinite Then _aimCursor = p
                    Fire()
                ElseIf button = PointerButton.Right AndAlso _dragged IsNot Nothing Then
                    If p.IsFinite AndAlso Not IsCarriedByEngine Then CarryTo(p + _grabOffset, Double.PositiveInfinity)
                    EndCarry()
                End If
            End Sub)
    End Sub

    ''' <summary>
    ''' The topmost body under point <paramref name="p"/> (m): circles over the other kinds, then
    ''' movable bodies over fixed ones, later over earlier.
    ''' </summary>
    Public Function BodyAt(p As Vector) As Shape
        ' A few pixels of slack so that small balls and thin ramps can still be picked on a projector.
        Dim slack = 4.0 * ScreenScale / View.Scale
        Dim circles = World.Circles
        For i = circles.Count - 1 To 0 Step -1
            Dim c = circles(i)
            Dim reach = c.Radius + slack
            If (c.Position - p).LengthSquared <= reach * reach Then Return c
        Next
        ' Every other kind through its outline: a disc of the slack's radius at p touches the body.
        Dim probe As New Circle(p, slack, 1.0)
        Dim bodies = World.Bodies
        For Each movable In {True, False}
            For i = bodies.Count - 1 To 0 Step -1
                Dim b = bodies(i)
                If b.Kind = ShapeKind.Circle OrElse b.IsFixed = movable Then Continue For
                If Placement.OverlapDepth(probe, Vector.Zero, b) > 0 Then Return b
            Next
        Next
        Return Nothing
    End Function

    ''' <summary>
    ''' Puts the body waiting to be placed where the teacher clicked, or, when it would overlap a body
    ''' it collides with there, at the nearest free place and says so; when there is no room near the
    ''' click it stays on the cursor and the message says why.
    ''' </summary>
    Private Sub Place(p As Vector)
        Dim body = Draft.Build(p)
        Dim size = Math.Max(Draft.Width, Draft.Height)
        Dim reach = Math.Max(MinPlacementReach, PlacementReachSizes * size)
        Dim clash = Placement.FirstOverlap(World, body, Vector.Zero)
        Dim place = Placement.NearestFree(World, body, Vector.Zero, reach)
        If Not place.HasValue Then
            Dim why = If(clash IsNot Nothing, "it would overlap " & Describe(clash), "it does not fit in the container")
            ShowMessage("There is no room for the " & Draft.KindName & " there: " & why & ". Click on a free place (Esc cancels).")
            Return
        End If
        Dim moved = place.Value.Length
        body = Draft.Build(p + place.Value)
        World.Add(body)
        Dim kindName = Draft.KindName
        _Draft = Nothing
        Emit("placed " & kindName & " " & body.Id & " at " & Units.Pair(body.CentreOfMass, 3))
        If clash IsNot Nothing AndAlso moved > Placement.Tolerance Then
            ShowMessage("Placed " & Units.Quantity(moved, "m") & " from the click, at the nearest free place: there it would have overlapped " & Describe(clash) & ".")
        Else
            ShowMessage("")
        End If
        TakeSnapshot()
        _window.ShowSettings()
    End Sub

    ''' <summary>"circle 3", "fixed rectangle table": the kind of body and its id, for messages.</summary>
    Private Shared Function Describe(body As Shape) As String
        Return If(body.IsFixed, "fixed ", "") & body.GetType().Name.ToLowerInvariant() & " " & body.Id
    End Function

    Private Sub Delete(body As Shape)
        If body Is _dragged Then EndCarry()
        If body Is AimedBody Then _AimedBody = Nothing
        World.Remove(body)
        Emit("deleted " & body.Id)
        TakeSnapshot()
    End Sub

    Private Sub Fire()
        Dim c = AimedBody
        _AimedBody = Nothing
        If Not World.Bodies.Contains(c) Then Return
        Dim j = CueShot.ImpulseFor(c.CentreOfMass, _aimCursor)
        If j.Length < 0.000001 Then
            Emit("cue released without a pull")
            Return
        End If
        World.ApplyImpulse(c, j)
        Emit("fired " & c.Id & " J " & Units.Pair(j, 3) & " N·s dv " & Units.Pair(j * c.InverseMass, 3) & " m/s v " & Units.Pair(c.Velocity, 3) & " m/s")
        ' The table, the totals and the arrow all show the new velocity at once, paused or not.
        TakeSnapshot()
    End Sub

    ''' <summary>True while a movable body is carried with time running: the engine moves it (balls that meet it bounce off).</summary>
    Private ReadOnly Property IsCarriedByEngine As Boolean
        Get
            Return _dragged IsNot Nothing AndAlso Not _dragged.IsFixed AndAlso Not IsPaused
        End Get
    End Property

    Private Sub BeginCarry(body As Shape, p As Vector)
        _dragged = body
        _grabOffset = body.Position - p
        _carryGoal = body.Position
        If Not body.IsFixed AndAlso Not IsPaused Then World.BeginDrag(body)
        Emit("drag start " & body.Id & " at " & Units.Pair(body.CentreOfMass, 3))
    End Sub

    ''' <summary>Once a frame while time runs: the carried body heads for the cursor, as far as it may this frame.</summary>
    Private Sub CarryTowardsCursor(realSeconds As Double)
        If Not IsCarriedByEngine Then Return
        Dim diagonal = Math.Sqrt(World.Width * World.Width + World.Height * World.Height)
        CarryTo(_carryGoal, CarryDiagonalsPerSecond * diagonal * realSeconds, realSeconds * Speed)
    End Sub

    ''' <summary>
    ''' Moves the carried body towards <paramref name="goal"/> (its reference point, m), at most
    ''' <paramref name="maxStep"/> metres, only as far as <see cref="CarryRule"/> lets it go in a
    ''' frame of <paramref name="frameSeconds"/> simulated seconds (0: at once, nothing else moving).
    ''' </summary>
    Private Sub CarryTo(goal As Vector, maxStep As Double, Optional frameSeconds As Double = 0)
        Dim body = _dragged
        Dim from = body.Position
        Dim wanted = goal - from
        If wanted.Length > maxStep Then wanted = wanted * (maxStep / wanted.Length)
        Dim reached = CarryRule.Reach(World, body, wanted, frameSeconds)
        If Not body.IsFixed Then
            If IsCarriedByEngine Then
                World.DragTo(from + reached)
            Else
                World.SetPosition(body, from + reached)
                TakeSnapshot()
            End If
            Return
        End If
        ' The engine never moves a fixed body, so it is carried by putting an identical one in its
        ' place at the new position (same id and colour, same row in the tables).
        If reached.LengthSquared = 0 Then Return
        Dim moved = MovedCopy(body, reached)
        moved.Color = body.Color
        World.Replace(body, moved)
        _dragged = moved
        TakeSnapshot()
    End Sub

    ''' <summary>A fixed body like <paramref name="body"/>, <paramref name="offset"/> m away: the one place that builds each kind.</summary>
    Private Shared Function MovedCopy(body As Shape, offset As Vector) As Shape
        Select Case body.Kind
            Case ShapeKind.Circle
                Return Circle.CreateFixed(body.Position + offset, DirectCast(body, Circle).Radius, body.Id)
            Case ShapeKind.Rectangle
                Dim r = DirectCast(body, Rectangle)
                Return New Rectangle(r.Position + offset, r.Width, r.Height, r.Id)
            Case ShapeKind.Segment
                Dim s = DirectCast(body, Segment)
                Return New Segment(s.StartPoint + offset, s.EndPoint + offset, s.Id)
            Case Else
                Dim corners = DirectCast(body, Polygon).Vertices.Select(Function(v) v + offset).ToArray()
                Return Polygon.CreateFixed(corners, body.Id)
        End Select
    End Function

    Private Sub EndCarry()
        Dim body = _dragged
        _dragged = Nothing
        If World.DraggedBody IsNot Nothing Then World.EndDrag(Vector.Zero)
        If Not body.IsFixed AndAlso World.Bodies.Contains(body) Then World.SetVelocity(body, Vector.Zero)
        Emit("drag end " & body.Id & " at " & Units.Pair(body.CentreOfMass, 3))
        TakeSnapshot()
    End Sub

    ''' <summary>Ends any drag or aim in progress (before a reset, a mode change or a new scene).</summary>
    Private Sub EndGestures()
        _AimedBody = Nothing
        If _dragged IsNot Nothing Then EndCarry()
        CancelTool()
    End Sub
End Class
