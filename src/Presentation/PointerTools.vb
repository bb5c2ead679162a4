Option Strict On

''' <summary>
''' What the mouse does on the canvas: place a new body, delete one, carry one (right button) or
''' push one with the cue (left button); draw a ramp, a link or a polygon by its corners. It holds
''' the mode a left click is in, the body waiting to be placed, the body carried or aimed at, and
''' what a tool has drawn so far.
''' </summary>
Partial Friend NotInheritable Class PointerTools
    Private ReadOnly _stage As Stage
    Private ReadOnly _view As Func(Of ViewTransform)
    Private ReadOnly _screenScale As Func(Of Double)
    Private ReadOnly _speed As Func(Of Double)
    Private ReadOnly _colours As BodyColours
    Private ReadOnly _history As EditHistory
    Private ReadOnly _arrowSeconds As Func(Of Double)

    ''' <param name="history">where each edit is kept for Undo</param>
    ''' <param name="view">metres ↔ canvas pixels now</param>
    ''' <param name="screenScale">pixels per 96-dpi pixel of the window's screen</param>
    ''' <param name="speed">simulated seconds per real second now</param>
    ''' <param name="colourSeed">seed of the random colours of new bodies</param>
    ''' <param name="arrowSeconds">the seconds of travel a velocity arrow stands for now, or 0 when arrows are not drawn</param>
    Public Sub New(stage As Stage, history As EditHistory, view As Func(Of ViewTransform), screenScale As Func(Of Double), speed As Func(Of Double), colourSeed As Integer,
                   arrowSeconds As Func(Of Double))
        _stage = stage
        _history = history
        _arrowSeconds = arrowSeconds
        _view = view
        _screenScale = screenScale
        _speed = speed
        _colours = New BodyColours(colourSeed)
    End Sub

    ' What the mouse does on the canvas: place a new body, delete one, carry one (right button) or
    ' push one with the cue (left button).
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

    ''' <summary>What a left click on a body does.</summary>
    Public ReadOnly Property Mode As ClickMode = ClickMode.Move

    ''' <summary>The message while Delete mode is on: short enough for the message area's first lines at any panel width.</summary>
    Public Const DeleteModeMessage As String = "Delete mode: click a body or a link to remove it. Press Delete mode again to stop."

    ''' <summary>The Delete mode button's caption while it is off.</summary>
    Public Const DeleteModeOffCaption As String = "Delete mode"
    ''' <summary>The Delete mode button's caption while it is on.</summary>
    Public Const DeleteModeOnCaption As String = "Delete mode: ON"

    ''' <summary>"Delete mode" or "Delete mode: ON".</summary>
    Public ReadOnly Property DeleteModeText As String
        Get
            Return If(_Mode = ClickMode.Delete, DeleteModeOnCaption, DeleteModeOffCaption)
        End Get
    End Property

    ''' <summary>Switches between moving and deleting.</summary>
    Public Sub ToggleDeleteMode()
        _stage.Guarded(
            Sub()
                EndGestures()
                _Mode = If(_Mode = ClickMode.Delete, ClickMode.Move, ClickMode.Delete)
                _stage.Emit("mode " & If(_Mode = ClickMode.Delete, "delete", "move"))
                If _Mode = ClickMode.Delete Then
                    _stage.ShowMessage(DeleteModeMessage, Function() _Mode = ClickMode.Delete)
                Else
                    _stage.ShowMessage("")
                End If
                _stage.Window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>Back to moving, with nothing being placed or drawn (Reset, a new scene).</summary>
    Public Sub Reset()
        EndGestures()
        _Draft = Nothing
        _Mode = ClickMode.Move
    End Sub

    ''' <summary>Drops the body being placed and ends every gesture, keeping the mode (a new world goes on show).</summary>
    Public Sub DropAll()
        EndGestures()
        _Draft = Nothing
    End Sub

    ''' <summary>A moment of the recorded run was put on show: a cue being aimed keeps aiming at the same body of the new world.</summary>
    Public Sub FollowWorld(w As World)
        If _AimedBody IsNot Nothing Then _AimedBody = w.Find(_AimedBody.Id)
    End Sub

    ''' <summary>
    ''' Time stopped or started: a body carried across the change keeps following the cursor. While
    ''' paused it is moved directly, while running the engine carries it (balls that meet it bounce off).
    ''' </summary>
    Public Sub PauseChanged()
        If _dragged Is Nothing OrElse _dragged.IsFixed Then Return
        If _stage.IsPaused Then _stage.World.EndDrag(Vector.Zero) Else _stage.World.BeginDrag(_dragged)
    End Sub

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
            Return Placement.IsFree(_stage.World, body, Vector.Zero)
        End Get
    End Property

    ''' <summary>Asks for a circle from the typed radius (m), mass (kg) and Fixed box; it then follows the cursor until a click.</summary>
    Public Sub BeginAddCircle()
        BeginAddCircle(_stage.Inputs.RadiusText, _stage.Inputs.MassText, _stage.Inputs.IsFixed)
    End Sub

    ''' <summary>Asks for a circle of the given radius (m) and mass (kg); it then follows the cursor until a click.</summary>
    Public Sub BeginAddCircle(radiusText As String, massText As String, isFixed As Boolean)
        If Draft IsNot Nothing Then
            _stage.ShowMessage(InputLimits.SpawnFirstMessage)
            Return
        End If
        _stage.Inputs.RadiusText = radiusText
        _stage.Inputs.MassText = massText
        _stage.Inputs.IsFixed = isFixed
        _stage.Guarded(
            Sub()
                Dim r = NumberInput.ReadPositive(radiusText, "radius (m)", InputLimits.MaxRadius, InputLimits.MinRadius)
                ' A fixed circle has no mass to ask for.
                Dim m = If(isFixed, NumberInput.ReadPositive("1", "mass (kg)", InputLimits.MaxMass),
                                    NumberInput.ReadPositive(massText, "mass (kg)", InputLimits.MaxMass, InputLimits.MinMass))
                If Not r.IsValid OrElse Not m.IsValid Then
                    _stage.ShowMessage(InputLimits.CircleMessage & " " & Stage.Problems(r, m))
                    Return
                End If
                ' The boxes keep what was typed; only a value brought to a limit is written back (and said).
                If r.WasClamped Then _stage.Inputs.RadiusText = Units.Input(r.Value)
                If m.WasClamped AndAlso Not isFixed Then _stage.Inputs.MassText = Units.Input(m.Value)
                If r.WasClamped OrElse (m.WasClamped AndAlso Not isFixed) Then _stage.Window.ShowInputs()
                _Draft = BodyDraft.ForCircle(r.Value, m.Value, isFixed, _colours.NextColour())
                EndGestures()
                _Mode = ClickMode.Move
                Dim clamped = Stage.ClampNote(("radius", r, "m"), ("mass", If(isFixed, Nothing, CType(m, NumberInput?)), "kg"))
                _stage.Emit("adding " & If(isFixed, "fixed ", "") & "circle r " & Units.Num(r.Value, 3) & " m" & If(isFixed, "", " m " & Units.Num(m.Value, 3) & " kg"))
                _stage.ShowMessage(clamped & "Click on the canvas to place the circle (Esc cancels).")
                _stage.Window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>
    ''' Asks for a rectangle from the typed width and height (m): a fixed obstacle when its Fixed box is
    ''' ticked, otherwise a movable box with the typed mass (kg). It then follows the cursor until a click.
    ''' </summary>
    Public Sub BeginAddRectangle()
        BeginAddRectangle(_stage.Inputs.WidthText, _stage.Inputs.HeightText, _stage.Inputs.RectangleFixed, _stage.Inputs.MassText)
    End Sub

    ''' <summary>Asks for a fixed rectangle of the given width and height, m; it then follows the cursor until a click.</summary>
    Public Sub BeginAddRectangle(widthText As String, heightText As String)
        BeginAddRectangle(widthText, heightText, True, _stage.Inputs.MassText)
    End Sub

    ''' <summary>
    ''' Asks for a rectangle of the given width and height (m): fixed, or a movable box of the given
    ''' mass (kg). It then follows the cursor until a click.
    ''' </summary>
    Public Sub BeginAddRectangle(widthText As String, heightText As String, isFixed As Boolean, massText As String)
        If Draft IsNot Nothing Then
            _stage.ShowMessage(InputLimits.SpawnFirstMessage)
            Return
        End If
        _stage.Inputs.WidthText = widthText
        _stage.Inputs.HeightText = heightText
        _stage.Inputs.RectangleFixed = isFixed
        If Not isFixed Then _stage.Inputs.MassText = massText
        _stage.Guarded(
            Sub()
                Dim w = NumberInput.ReadPositive(widthText, "width (m)", InputLimits.MaxSide, InputLimits.MinSide)
                Dim h = NumberInput.ReadPositive(heightText, "height (m)", InputLimits.MaxSide, InputLimits.MinSide)
                ' A fixed rectangle has no mass to ask for.
                Dim m = If(isFixed, NumberInput.ReadPositive("1", "mass (kg)", InputLimits.MaxMass),
                                    NumberInput.ReadPositive(massText, "mass (kg)", InputLimits.MaxMass, InputLimits.MinMass))
                If Not w.IsValid OrElse Not h.IsValid OrElse Not m.IsValid Then
                    _stage.ShowMessage(If(isFixed, InputLimits.RectangleMessage, InputLimits.BoxMessage) & " " & Stage.Problems(w, h, m))
                    Return
                End If
                If w.WasClamped Then _stage.Inputs.WidthText = Units.Input(w.Value)
                If h.WasClamped Then _stage.Inputs.HeightText = Units.Input(h.Value)
                If m.WasClamped AndAlso Not isFixed Then _stage.Inputs.MassText = Units.Input(m.Value)
                If w.WasClamped OrElse h.WasClamped OrElse (m.WasClamped AndAlso Not isFixed) Then _stage.Window.ShowInputs()
                _Draft = If(isFixed, BodyDraft.ForRectangle(w.Value, h.Value, _colours.NextColour()),
                                     BodyDraft.ForBox(w.Value, h.Value, m.Value, _colours.NextColour()))
                EndGestures()
                _Mode = ClickMode.Move
                Dim clamped = Stage.ClampNote(("width", w, "m"), ("height", h, "m"), ("mass", If(isFixed, Nothing, CType(m, NumberInput?)), "kg"))
                _stage.Emit("adding " & Draft.KindName & " " & Units.Num(w.Value, 3) & " x " & Units.Num(h.Value, 3) & " m" & If(isFixed, "", " m " & Units.Num(m.Value, 3) & " kg"))
                _stage.ShowMessage(clamped & "Click on the canvas to place the " & Draft.KindName & " (Esc cancels).")
                _stage.Window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>Drops the body waiting to be placed, or the ramp, link or polygon being drawn (Esc).</summary>
    Public Sub CancelPlacement()
        If Draft Is Nothing Then
            CancelTool()
            Return
        End If
        _Draft = Nothing
        _stage.Emit("placement cancelled")
        _stage.ShowMessage("")
        _stage.Window.ShowSettings()
    End Sub

    ''' <summary>A mouse button went down on the canvas at (x, y) px.</summary>
    Public Sub PointerDown(button As PointerButton, x As Double, y As Double)
        _stage.Guarded(
            Sub()
                Dim p = _view().ToWorld(x, y)
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
                            If link IsNot Nothing Then
                                DeleteLink(link)
                            Else
                                Dim liquid = LiquidAt(p)
                                If liquid IsNot Nothing Then DeleteLiquid(liquid)
                            End If
                        End If
                        Return
                    End If
                    ' While paused the tip of a velocity arrow can be dragged, to set the velocity.
                    Dim tipOf = If(_stage.IsPaused AndAlso _dragged Is Nothing AndAlso Mode = ClickMode.Move, ArrowTipAt(p), Nothing)
                    If tipOf IsNot Nothing Then
                        BeginArrowDrag(tipOf, p)
                        Return
                    End If
                    If body IsNot Nothing AndAlso Not body.IsFixed AndAlso _dragged Is Nothing Then
                        _AimedBody = body
                        _aimCursor = p
                        _stage.Emit("aiming at " & body.Id)
                    End If
                ElseIf button = PointerButton.Right AndAlso body IsNot Nothing AndAlso AimedBody Is Nothing AndAlso Mode = ClickMode.Move Then
                    BeginCarry(body, p)
                End If
            End Sub)
    End Sub

    ''' <summary>The mouse moved over the canvas to (x, y) px.</summary>
    Public Sub PointerMove(x As Double, y As Double)
        _stage.Guarded(
            Sub()
                Dim p = _view().ToWorld(x, y)
                If Not p.IsFinite Then Return
                If Draft IsNot Nothing Then
                    Draft.Centre = p
                    Draft.HasCentre = True
                End If
                If AimedBody IsNot Nothing Then _aimCursor = p
                If _ArrowBody IsNot Nothing Then ArrowTo(p)
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
        _stage.Guarded(
            Sub()
                Dim p = _view().ToWorld(x, y)
                If button = PointerButton.Left AndAlso _ArrowBody IsNot Nothing Then
                    If p.IsFinite Then ArrowTo(p)
                    EndArrowDrag()
                    Return
                End If
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
        Dim slack = 4.0 * _screenScale() / _view().Scale
        Dim circles = _stage.World.Circles
        For i = circles.Count - 1 To 0 Step -1
            Dim c = circles(i)
            Dim reach = c.Radius + slack
            If (c.Position - p).LengthSquared <= reach * reach Then Return c
        Next
        ' Every other kind through its outline: a disc of the slack's radius at p touches the body.
        Dim probe As New Circle(p, slack, 1.0)
        Dim bodies = _stage.World.Bodies
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
        Dim clash = Placement.FirstOverlap(_stage.World, body, Vector.Zero)
        Dim place = Placement.NearestFree(_stage.World, body, Vector.Zero, reach)
        If Not place.HasValue Then
            Dim why = If(clash IsNot Nothing, "it would overlap " & Describe(clash), "it does not fit in the container")
            _stage.ShowMessage("There is no room for the " & Draft.KindName & " there: " & why & ". Click on a free place (Esc cancels).")
            Return
        End If
        Dim moved = place.Value.Length
        body = Draft.Build(p + place.Value)
        Dim before = _history.Capture()
        _stage.World.Add(body)
        Dim kindName = Draft.KindName
        _Draft = Nothing
        _stage.Emit("placed " & kindName & " " & body.Id & " at " & Units.Pair(body.CentreOfMass, 3))
        _history.Commit("the " & kindName & " " & body.Id & " added", before)
        If clash IsNot Nothing AndAlso moved > Placement.Tolerance Then
            _stage.ShowMessage("Placed " & Units.Quantity(moved, "m") & " from the click, at the nearest free place: there it would have overlapped " & Describe(clash) & ".")
        Else
            _stage.ShowMessage("")
        End If
        _stage.TakeSnapshot()
        _stage.Window.ShowSettings()
    End Sub

    ''' <summary>"circle 3", "fixed rectangle table": the kind of body and its id, for messages.</summary>
    Private Shared Function Describe(body As Shape) As String
        Return If(body.IsFixed, "fixed ", "") & body.GetType().Name.ToLowerInvariant() & " " & body.Id
    End Function

    Private Sub Delete(body As Shape)
        If body Is _dragged Then EndCarry()
        If body Is AimedBody Then _AimedBody = Nothing
        Undoably(body.Id & " deleted", "deleted " & body.Id, Sub() _stage.World.Remove(body))
    End Sub

    ''' <summary>
    ''' Makes one deletion (a body, a link, a liquid) an edit Ctrl+Z takes back: the world before it is kept, the
    ''' trace says <paramref name="traced"/>, and the history names it <paramref name="what"/>.
    ''' </summary>
    Private Sub Undoably(what As String, traced As String, remove As Action)
        Dim before = _history.Capture()
        remove()
        _stage.Emit(traced)
        _history.Commit(what, before)
        _stage.TakeSnapshot()
    End Sub

    Private Sub Fire()
        Dim c = AimedBody
        _AimedBody = Nothing
        If Not _stage.World.Bodies.Contains(c) Then Return
        Dim j = CueShot.ImpulseFor(c.CentreOfMass, _aimCursor)
        If j.Length < 0.000001 Then
            _stage.Emit("cue released without a pull")
            Return
        End If
        Dim before = _history.Capture()
        _stage.World.ApplyImpulse(c, j)
        _history.Commit("the push on " & c.Id, before)
        _stage.Emit("fired " & c.Id & " J " & Units.Pair(j, 3) & " N·s dv " & Units.Pair(j * c.InverseMass, 3) & " m/s v " & Units.Pair(c.Velocity, 3) & " m/s")
        ' The table, the totals and the arrow all show the new velocity at once, paused or not.
        _stage.TakeSnapshot()
    End Sub

    ''' <summary>True while a movable body is carried with time running: the engine moves it (balls that meet it bounce off).</summary>
    Private ReadOnly Property IsCarriedByEngine As Boolean
        Get
            Return _dragged IsNot Nothing AndAlso Not _dragged.IsFixed AndAlso Not _stage.IsPaused
        End Get
    End Property

    ''' <summary>The world before the carry in progress (for Undo), or Nothing.</summary>
    Private _carryBefore As Checkpoint

    Private Sub BeginCarry(body As Shape, p As Vector)
        _carryBefore = _history.Capture()
        _dragged = body
        _grabOffset = body.Position - p
        _carryGoal = body.Position
        If Not body.IsFixed AndAlso Not _stage.IsPaused Then _stage.World.BeginDrag(body)
        _stage.Emit("drag start " & body.Id & " at " & Units.Pair(body.CentreOfMass, 3))
    End Sub

    ''' <summary>Once a frame while time runs: the carried body heads for the cursor, as far as it may this frame.</summary>
    Public Sub CarryTowardsCursor(realSeconds As Double)
        If Not IsCarriedByEngine Then Return
        Dim diagonal = Math.Sqrt(_stage.World.Width * _stage.World.Width + _stage.World.Height * _stage.World.Height)
        CarryTo(_carryGoal, CarryDiagonalsPerSecond * diagonal * realSeconds, realSeconds * _speed())
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
        Dim reached = CarryRule.Reach(_stage.World, body, wanted, frameSeconds)
        If Not body.IsFixed Then
            If IsCarriedByEngine Then
                _stage.World.DragTo(from + reached)
            Else
                _stage.World.SetPosition(body, from + reached)
                _stage.TakeSnapshot()
            End If
            Return
        End If
        ' The engine never moves a fixed body, so it is carried by putting an identical one in its
        ' place at the new position (same id and colour, same row in the tables).
        If reached.LengthSquared = 0 Then Return
        Dim moved = MovedCopy(body, reached)
        moved.Color = body.Color
        _stage.World.Replace(body, moved)
        _dragged = moved
        _stage.TakeSnapshot()
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
        If _stage.World.DraggedBody IsNot Nothing Then _stage.World.EndDrag(Vector.Zero)
        If Not body.IsFixed AndAlso _stage.World.Bodies.Contains(body) Then _stage.World.SetVelocity(body, Vector.Zero)
        _stage.Emit("drag end " & body.Id & " at " & Units.Pair(body.CentreOfMass, 3))
        If _stage.World.Bodies.Contains(body) Then _history.Commit(body.Id & " moved", _carryBefore)
        _carryBefore = Nothing
        _stage.TakeSnapshot()
    End Sub

    ''' <summary>How near the tip of a velocity arrow a press grabs it, in canvas pixels at 96 dpi.</summary>
    Public Const ArrowGrabPixels As Double = 9

    ''' <summary>The body whose velocity arrow is being dragged by its tip, or Nothing.</summary>
    Public ReadOnly Property ArrowBody As Shape

    ''' <summary>The world before the arrow drag in progress (for Undo).</summary>
    Private _arrowBefore As Checkpoint
    ''' <summary>The arrows' scale when the drag began, s: kept while dragging, so the tip stays under the cursor.</summary>
    Private _arrowDragSeconds As Double
    ''' <summary>The tip minus the cursor when the drag began, m: the tip does not jump to the cursor.</summary>
    Private _arrowGrab As Vector

    ''' <summary>"v = (1.20, −0.500) m/s   |v| = 1.30 m/s" while an arrow is dragged, "" otherwise: the velocity it sets, as the tables will show it.</summary>
    Public ReadOnly Property ArrowLabel As String
        Get
            If ArrowBody Is Nothing Then Return ""
            Dim v = ArrowBody.Velocity
            Return "v = " & Units.SigPair(v) & " m/s   |v| = " & Units.Quantity(v.Length, "m/s")
        End Get
    End Property

    ''' <summary>The movable body whose velocity arrow's tip is within reach of <paramref name="p"/> (m), or Nothing; an arrow too short to tell from its body is not grabbed.</summary>
    Private Function ArrowTipAt(p As Vector) As Shape
        Dim seconds = _arrowSeconds()
        If Not (seconds > 0) Then Return Nothing
        Dim view = _view()
        Dim reach = ArrowGrabPixels * _screenScale()
        Dim best As Shape = Nothing
        For Each b In _stage.World.Movables
            Dim tip = b.CentreOfMass + b.Velocity * seconds
            Dim fromCentre = view.ToPixels((tip - b.CentreOfMass).Length)
            If fromCentre < 2 * reach Then Continue For
            Dim d = view.ToPixels((tip - p).Length)
            If d <= reach Then
                reach = d
                best = b
            End If
        Next
        Return best
    End Function

    Private Sub BeginArrowDrag(body As Shape, p As Vector)
        _arrowBefore = _history.Capture()
        _arrowDragSeconds = _arrowSeconds()
        _arrowGrab = body.CentreOfMass + body.Velocity * _arrowDragSeconds - p
        _ArrowBody = body
        _stage.Emit("arrow drag " & body.Id)
    End Sub

    ''' <summary>The cursor is at <paramref name="p"/> (m), and the tip with it: the velocity is the arrow over the arrows' time.</summary>
    Private Sub ArrowTo(p As Vector)
        Dim body = ArrowBody
        Dim v = (p + _arrowGrab - body.CentreOfMass) / _arrowDragSeconds
        ' No faster than a typed speed may be.
        If v.Length > TableEditor.MaxTypedSpeed Then v = v * (TableEditor.MaxTypedSpeed / v.Length)
        _stage.World.SetVelocity(body, v)
        _stage.TakeSnapshot()
    End Sub

    Private Sub EndArrowDrag()
        Dim body = ArrowBody
        _ArrowBody = Nothing
        If body Is Nothing Then Return
        Dim v = body.Velocity
        _stage.Emit("arrow set " & body.Id & " v " & v.X.ToString("R", Globalization.CultureInfo.InvariantCulture) & " " & v.Y.ToString("R", Globalization.CultureInfo.InvariantCulture))
        _history.Commit(body.Id & "'s velocity set with its arrow", _arrowBefore)
        _arrowBefore = Nothing
        _stage.TakeSnapshot()
    End Sub

    ''' <summary>Ends any drag or aim in progress (before a reset, a mode change or a new scene).</summary>
    Public Sub EndGestures()
        If _ArrowBody IsNot Nothing Then EndArrowDrag()
        _AimedBody = Nothing
        If _dragged IsNot Nothing Then EndCarry()
        CancelTool()
    End Sub

    ' The tools beyond Add circle and Add rectangle: a regular polygon placed by a click, a ramp drawn by
    ' dragging from one end to the other, and a link (spring, rod or string) made by clicking its two
    ' ends. Every new body goes where Placement says it may, like a circle.
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
        _stage.Inputs.RectangleFixed = isFixed
        _stage.Emit("rectangle fixed " & If(isFixed, "on", "off"))
        _stage.Window.ShowSettings()
    End Sub

    ''' <summary>
    ''' Asks for a regular polygon from the typed sides and angle (°) and the circle's radius (m, the
    ''' polygon's corners lie on that circle), mass (kg) and Fixed box; it then follows the cursor until a click.
    ''' </summary>
    Public Sub BeginAddPolygon()
        BeginAddPolygon(_stage.Inputs.SidesText, _stage.Inputs.RadiusText, _stage.Inputs.PolygonAngleText, _stage.Inputs.MassText, _stage.Inputs.IsFixed)
    End Sub

    ''' <summary>
    ''' Asks for a regular polygon of <paramref name="sidesText"/> sides, each corner
    ''' <paramref name="sizeText"/> m from its centre, turned <paramref name="angleText"/> degrees
    ''' anticlockwise, fixed or of <paramref name="massText"/> kg; it then follows the cursor until a click.
    ''' </summary>
    Public Sub BeginAddPolygon(sidesText As String, sizeText As String, angleText As String, massText As String, isFixed As Boolean)
        If Draft IsNot Nothing Then
            _stage.ShowMessage(InputLimits.SpawnFirstMessage)
            Return
        End If
        _stage.Inputs.SidesText = sidesText
        _stage.Inputs.RadiusText = sizeText
        _stage.Inputs.PolygonAngleText = angleText
        _stage.Inputs.IsFixed = isFixed
        If Not isFixed Then _stage.Inputs.MassText = massText
        _stage.Guarded(
            Sub()
                Dim n = NumberInput.ReadWhole(sidesText, "sides", InputLimits.MinSides, InputLimits.MaxSides)
                ' The circle's radius and its bounds: the polygon's corners lie on that circle.
                Dim r = NumberInput.ReadPositive(sizeText, "radius (m)", InputLimits.MaxRadius, InputLimits.MinRadius)
                Dim a = NumberInput.ReadFinite(angleText, "angle (°)", InputLimits.MaxAngle)
                Dim m = If(isFixed, NumberInput.ReadPositive("1", "mass (kg)", InputLimits.MaxMass),
                                    NumberInput.ReadPositive(massText, "mass (kg)", InputLimits.MaxMass, InputLimits.MinMass))
                If Not n.IsValid OrElse Not r.IsValid OrElse Not a.IsValid OrElse Not m.IsValid Then
                    _stage.ShowMessage(InputLimits.PolygonMessage & " " & Stage.Problems(n, r, a, m))
                    Return
                End If
                If n.WasClamped Then _stage.Inputs.SidesText = Units.Input(n.Value)
                If r.WasClamped Then _stage.Inputs.RadiusText = Units.Input(r.Value)
                If a.WasClamped Then _stage.Inputs.PolygonAngleText = Units.Input(a.Value)
                If m.WasClamped AndAlso Not isFixed Then _stage.Inputs.MassText = Units.Input(m.Value)
                If n.WasClamped OrElse r.WasClamped OrElse a.WasClamped OrElse (m.WasClamped AndAlso Not isFixed) Then _stage.Window.ShowInputs()
                Dim sides = CInt(n.Value)
                Dim corners = RegularPolygon.Corners(sides, r.Value, a.Value)
                _Draft = BodyDraft.ForPolygon(corners, m.Value, isFixed, _colours.NextColour())
                EndGestures()
                _Mode = ClickMode.Move
                Dim clamped = Stage.ClampNote(("sides", n, ""), ("radius", r, "m"), ("angle", a, "°"), ("mass", If(isFixed, Nothing, CType(m, NumberInput?)), "kg"))
                _stage.Emit("adding " & If(isFixed, "fixed ", "") & "polygon n " & sides & " r " & Units.Num(r.Value, 3) & " m angle " & Units.Num(a.Value, 1) &
                     If(isFixed, "", " m " & Units.Num(m.Value, 3) & " kg"))
                _stage.ShowMessage(clamped & "Click on the canvas to place the polygon (Esc cancels).")
                _stage.Window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>The ramp tool: the next left drag on the canvas draws a fixed line from where it starts to where it ends.</summary>
    Public Sub BeginAddRamp()
        If Draft IsNot Nothing Then
            _stage.ShowMessage(InputLimits.SpawnFirstMessage)
            Return
        End If
        _stage.Guarded(
            Sub()
                EndGestures()
                _Mode = ClickMode.Ramp
                _stage.Emit("mode ramp")
                _stage.ShowMessage("Press where the ramp starts, drag to where it ends and let go (Esc cancels).")
                _stage.Window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>The link tool with the typed stiffness (used by springs only), N/m.</summary>
    Public Sub BeginAddLink(kind As LinkKind)
        BeginAddLink(kind, _stage.Inputs.StiffnessText)
    End Sub

    ''' <summary>
    ''' The link tool: the next two left clicks join a body to another body, or to a fixed anchor
    ''' where the second click finds no body, with a link of this kind as long as the ends are apart.
    ''' A spring has the stiffness <paramref name="stiffnessText"/> (N/m) and rests at that length.
    ''' </summary>
    Public Sub BeginAddLink(kind As LinkKind, stiffnessText As String)
        If Draft IsNot Nothing Then
            _stage.ShowMessage(InputLimits.SpawnFirstMessage)
            Return
        End If
        If kind = LinkKind.Spring Then _stage.Inputs.StiffnessText = stiffnessText
        _stage.Guarded(
            Sub()
                Dim k = NumberInput.ReadPositive(If(kind = LinkKind.Spring, stiffnessText, "1"), "stiffness k (N/m)", InputLimits.MaxStiffness, InputLimits.MinStiffness)
                If Not k.IsValid Then
                    _stage.ShowMessage(InputLimits.SpringMessage & " " & Stage.Problems(k))
                    Return
                End If
                If k.WasClamped AndAlso kind = LinkKind.Spring Then
                    _stage.Inputs.StiffnessText = Units.Input(k.Value)
                    _stage.Window.ShowInputs()
                End If
                EndGestures()
                _Mode = ClickMode.Link
                _linkKind = kind
                _linkStiffness = k.Value
                Dim name = KindName(kind)
                _stage.Emit("mode link " & name & If(kind = LinkKind.Spring, " k " & Units.Num(k.Value, 3) & " N/m", ""))
                Dim clamped = If(kind = LinkKind.Spring, Stage.ClampNote(("stiffness k", k, "N/m")), "")
                _stage.ShowMessage(clamped & "Click the first body of the " & name & ", then the second body, or an empty place for a fixed anchor (Esc cancels).")
                _stage.Window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>Ends the ramp, link or corner tool without making anything.</summary>
    Private Sub CancelTool()
        If _Mode <> ClickMode.Ramp AndAlso _Mode <> ClickMode.Link AndAlso _Mode <> ClickMode.Corners AndAlso _Mode <> ClickMode.Liquid Then Return
        _Mode = ClickMode.Move
        _rampStart = Nothing
        _toolCursor = Nothing
        _LinkStart = Nothing
        _CornerDraft = Nothing
        _stage.Emit("tool cancelled")
        _stage.ShowMessage("")
        _stage.Window.ShowSettings()
    End Sub

    ''' <summary>A button went down at <paramref name="p"/> (m) while a tool is on; True when the tool took it.</summary>
    Private Function ToolDown(button As PointerButton, p As Vector) As Boolean
        If _Mode = ClickMode.Ramp OrElse _Mode = ClickMode.Liquid Then
            If button = PointerButton.Left Then
                _rampStart = _stage.World.Inside(p, 0)
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
        If _Mode = ClickMode.Ramp OrElse _Mode = ClickMode.Link OrElse _Mode = ClickMode.Corners OrElse _Mode = ClickMode.Liquid Then _toolCursor = _stage.World.Inside(p, 0)
    End Sub

    ''' <summary>A button came up at <paramref name="p"/> (m) while a tool is on; True when the tool took it.</summary>
    Private Function ToolUp(button As PointerButton, p As Vector) As Boolean
        If _Mode = ClickMode.Link OrElse _Mode = ClickMode.Corners Then Return True
        If _Mode = ClickMode.Liquid Then Return LiquidUp(button, p)
        If _Mode <> ClickMode.Ramp Then Return False
        If button <> PointerButton.Left OrElse Not _rampStart.HasValue Then Return True
        Dim a = _rampStart.Value
        Dim b = If(p.IsFinite, _stage.World.Inside(p, 0), a)
        _rampStart = Nothing
        If _view().ToPixels((b - a).Length) < MinRampPixels * _screenScale() Then
            _stage.ShowMessage("That ramp would be too short to see: press where it starts, drag to where it ends and let go (Esc cancels).")
            Return True
        End If
        AddRamp(a, b)
        Return True
    End Function

    ''' <summary>Adds a ramp from <paramref name="a"/> to <paramref name="b"/> (m), moved to the nearest free place when it would cross a movable body.</summary>
    Private Sub AddRamp(a As Vector, b As Vector)
        Dim ramp As New Segment(a, b) With {.Color = _colours.NextColour()}
        Dim clash = Placement.FirstOverlap(_stage.World, ramp, Vector.Zero)
        Dim place = Placement.NearestFree(_stage.World, ramp, Vector.Zero, MinPlacementReach)
        If Not place.HasValue Then
            _stage.ShowMessage("There is no room for the ramp there: it would cross " & Describe(clash) & ". Draw it elsewhere (Esc cancels).")
            Return
        End If
        Dim moved = place.Value.Length
        If moved > 0 Then ramp = New Segment(a + place.Value, b + place.Value) With {.Color = ramp.Color}
        Dim before = _history.Capture()
        _stage.World.Add(ramp)
        _history.Commit("the ramp " & ramp.Id & " added", before)
        _Mode = ClickMode.Move
        _toolCursor = Nothing
        _stage.Emit("placed ramp " & ramp.Id & " from " & Units.Pair(ramp.StartPoint, 3) & " to " & Units.Pair(ramp.EndPoint, 3))
        If clash IsNot Nothing AndAlso moved > Placement.Tolerance Then
            _stage.ShowMessage("Placed " & Units.Quantity(moved, "m") & " from where you drew it: there it would have crossed " & Describe(clash) & ".")
        Else
            _stage.ShowMessage("")
        End If
        _stage.TakeSnapshot()
        _stage.Window.ShowSettings()
    End Sub

    ''' <summary>A left click of the link tool at <paramref name="p"/> (m): the first end, then the second.</summary>
    Private Sub LinkClick(p As Vector)
        Dim body = BodyAt(p)
        Dim name = KindName(_linkKind)
        If LinkStart Is Nothing Then
            If body Is Nothing Then
                _stage.ShowMessage("Click a body to start the " & name & " (Esc cancels).")
                Return
            End If
            _LinkStart = body
            _toolCursor = p
            _stage.Emit("link from " & body.Id)
            _stage.ShowMessage("Now click the second body, or an empty place for a fixed anchor (Esc cancels).")
            Return
        End If
        If body Is LinkStart Then
            _stage.ShowMessage("A " & name & " joins two different bodies: click another body, or an empty place for a fixed anchor (Esc cancels).")
            Return
        End If
        Dim first = LinkStart
        ' End A must move: a fixed body can only be end B.
        Dim a = If(first.IsFixed AndAlso body IsNot Nothing, body, first)
        Dim b = If(a Is first, body, first)
        If a.IsFixed Then
            _stage.ShowMessage(If(body Is Nothing,
                "A fixed body cannot hang from an anchor: click a body that moves, or start again with one (Esc cancels).",
                "Both bodies are fixed, so the " & name & " would do nothing: click a body that moves (Esc cancels)."))
            Return
        End If
        Dim anchor = _stage.World.Inside(p, 0)
        Dim length = If(b Is Nothing, (anchor - a.CentreOfMass).Length, (b.CentreOfMass - a.CentreOfMass).Length)
        If _linkKind <> LinkKind.Spring AndAlso Not (length > Placement.Tolerance) Then
            _stage.ShowMessage("A " & name & " needs its two ends apart: click farther from the first body (Esc cancels).")
            Return
        End If
        Dim link As Link
        If _linkKind = LinkKind.Spring Then
            link = If(b Is Nothing, Link.CreateSpring(a, anchor, _linkStiffness, length), Link.CreateSpring(a, b, _linkStiffness, length))
        Else
            link = If(b Is Nothing, Link.CreateTie(_linkKind, a, anchor, length), Link.CreateTie(_linkKind, a, b, length))
        End If
        Dim before = _history.Capture()
        _stage.World.Add(link)
        _history.Commit("the " & name & " " & link.Id & " added", before)
        _Mode = ClickMode.Move
        _LinkStart = Nothing
        _toolCursor = Nothing
        _stage.Emit("linked " & link.Id & " " & name & " " & a.Id & " to " & If(b Is Nothing, "anchor " & Units.Pair(anchor, 3), b.Id) & " length " & Units.Num(length, 3) & " m")
        ' A spring between light bodies (from a scene file) can be too stiff for a stepping solver's step: say so now.
        _stage.ShowMessage(If(_linkKind = LinkKind.Spring, SolverChoice.StiffSpringWarning(_stage.World), ""))
        _stage.TakeSnapshot()
        _stage.Window.ShowSettings()
    End Sub

    ''' <summary>The link whose line passes nearest <paramref name="p"/> (m), within a few pixels, or Nothing.</summary>
    Public Function LinkAt(p As Vector) As Link
        Dim reach = LinkPickPixels * _screenScale() / _view().Scale
        Dim best As Link = Nothing
        For Each l In _stage.World.Links
            Dim d = Vector.DistanceToSegment(p, l.EndA, l.EndB)
            If d <= reach Then
                reach = d
                best = l
            End If
        Next
        Return best
    End Function

    Private Sub DeleteLink(link As Link)
        Undoably("the link " & link.Id & " deleted", "deleted link " & link.Id, Sub() _stage.World.Remove(link))
    End Sub

    ''' <summary>"spring", "rod" or "string".</summary>
    Private Shared Function KindName(kind As LinkKind) As String
        Select Case kind
            Case LinkKind.Spring : Return "spring"
            Case LinkKind.Rod : Return "rod"
            Case Else : Return "string"
        End Select
    End Function

    ' The corner tool: a polygon drawn by clicking its corners one after another on the canvas. Each
    ' left click adds a corner; clicking the first corner again, clicking the last one again (the second
    ' click of a double click) or Enter finishes; Esc or a right click cancels. The polygon is the convex
    ' hull of the corners (the engine's polygons are convex), and the message says when that differs
    ' from what was clicked. It is placed with the same checks as every new body.
    ''' <summary>How near the first or the last corner a click finishes the polygon, in canvas pixels at 96 dpi.</summary>
    Public Const CornerSnapPixels As Double = 8

    ''' <summary>While a polygon is drawn by its corners: the corners so far and what it will be; Nothing otherwise.</summary>
    Public ReadOnly Property CornerDraft As CornerDraft

    ''' <summary>Starts the corner tool with the typed mass (kg) and the circle's Fixed box.</summary>
    Public Sub BeginAddCorners()
        BeginAddCorners(_stage.Inputs.MassText, _stage.Inputs.IsFixed)
    End Sub

    ''' <summary>
    ''' Starts the corner tool: the next left clicks on the canvas are the corners of a polygon, fixed or
    ''' of <paramref name="massText"/> kg, until the teacher finishes it (first corner again, a double
    ''' click, or Enter) or cancels (Esc, a right click).
    ''' </summary>
    Public Sub BeginAddCorners(massText As String, isFixed As Boolean)
        If Draft IsNot Nothing Then
            _stage.ShowMessage(InputLimits.SpawnFirstMessage)
            Return
        End If
        _stage.Inputs.IsFixed = isFixed
        If Not isFixed Then _stage.Inputs.MassText = massText
        _stage.Guarded(
            Sub()
                ' A fixed polygon has no mass to ask for.
                Dim m = If(isFixed, NumberInput.ReadPositive("1", "mass (kg)", InputLimits.MaxMass),
                                    NumberInput.ReadPositive(massText, "mass (kg)", InputLimits.MaxMass, InputLimits.MinMass))
                If Not m.IsValid Then
                    _stage.ShowMessage(InputLimits.CornersMessage & " " & Stage.Problems(m))
                    Return
                End If
                If m.WasClamped AndAlso Not isFixed Then
                    _stage.Inputs.MassText = Units.Input(m.Value)
                    _stage.Window.ShowInputs()
                End If
                EndGestures()
                _Mode = ClickMode.Corners
                _CornerDraft = New CornerDraft(m.Value, isFixed, _colours.NextColour())
                _stage.Emit("mode corners" & If(isFixed, " fixed", " m " & Units.Num(m.Value, 3) & " kg"))
                Dim clamped = Stage.ClampNote(("mass", If(isFixed, Nothing, CType(m, NumberInput?)), "kg"))
                _stage.ShowMessage(clamped & "Click the polygon's first corner on the canvas (Esc or a right click cancels).")
                _stage.Window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>The polygon the corners and the cursor would make now, anticlockwise, m (empty before it has area): the preview.</summary>
    Public ReadOnly Property CornerPreview As IReadOnlyList(Of Vector)
        Get
            If CornerDraft Is Nothing Then Return Array.Empty(Of Vector)()
            Return CornerDraft.Outline(_toolCursor)
        End Get
    End Property

    ''' <summary>Whether the polygon of the preview could stand where it is (the preview is outlined in red when not).</summary>
    Public ReadOnly Property CornerPreviewFits As Boolean
        Get
            Dim outline = CornerPreview
            If outline.Count < 3 Then Return True
            Try
                Return Placement.IsFree(_stage.World, CornerDraft.Build(outline), Vector.Zero)
            Catch ex As ArgumentException
                Return True ' not a polygon yet (a corner that barely turns): nothing to judge
            End Try
        End Get
    End Property

    ''' <summary>Finishes the polygon being drawn by its corners (Enter). Does nothing when the corner tool is off.</summary>
    Public Sub FinishCorners()
        If Mode <> ClickMode.Corners OrElse CornerDraft Is Nothing Then Return
        _stage.Guarded(AddressOf CompleteCorners)
    End Sub

    ''' <summary>A left click of the corner tool at <paramref name="p"/> (m): a new corner, or the end of the outline.</summary>
    Private Sub CornerClick(p As Vector)
        Dim d = CornerDraft
        Dim corner = _stage.World.Inside(p, 0)
        _toolCursor = corner
        If d.Count > 0 Then
            Dim snap = CornerSnapPixels * _screenScale() / _view().Scale
            Dim nearFirst = (corner - d.Corners(0)).Length <= snap
            Dim nearLast = (corner - d.Corners(d.Count - 1)).Length <= snap
            If nearFirst OrElse nearLast Then
                If d.Count >= 3 Then
                    CompleteCorners()
                Else
                    _stage.ShowMessage(TooFewCorners(d.Count) & " Click the next corner somewhere else (Esc cancels).")
                End If
                Return
            End If
        End If
        d.Add(corner)
        _stage.Emit("corner " & d.Count & " at " & Units.Pair(corner, 3))
        If d.Count < 3 Then
            _stage.ShowMessage("Corner " & d.Count & " is set. Click the next corner (Esc or a right click cancels).")
        Else
            _stage.ShowMessage("Corner " & d.Count & " is set. Click the next corner, or finish: click the first corner again, double-click, or press Enter (Esc or a right click cancels).")
        End If
    End Sub

    ''' <summary>"A polygon needs at least 3 corners: you have clicked 2."</summary>
    Private Shared Function TooFewCorners(count As Integer) As String
        Return "A polygon needs at least 3 corners: you have clicked " & count & "."
    End Function

    ''' <summary>
    ''' Makes the polygon of the corners clicked: refused (and the corners kept, to add more) when they
    ''' are fewer than 3, on one line, or make a sliver thinner than the least side; refused (and the
    ''' corners forgotten, to draw it again) when larger than the largest side, or when it would overlap
    ''' a body with no free place within <see cref="MinPlacementReach"/>. Otherwise it is added, moved
    ''' to the nearest free place when it would overlap, and the message says what changed.
    ''' </summary>
    Private Sub CompleteCorners()
        Dim d = CornerDraft
        If d.Count < 3 Then
            _stage.ShowMessage(TooFewCorners(d.Count) & " Click more corners (Esc cancels).")
            Return
        End If
        Dim outline = d.Outline()
        If outline.Length < 3 Then
            _stage.ShowMessage("These corners lie on one straight line, so they enclose no area. Click another corner off the line (Esc starts again).")
            Return
        End If
        Dim thinnest = ConvexHull.LeastWidth(outline)
        If thinnest < InputLimits.MinSide Then
            _stage.ShowMessage("This polygon would be only " & Units.Quantity(thinnest, "m") & " across at its thinnest; it must be at least " & Units.Quantity(InputLimits.MinSide, "m") &
                        ". Click another corner farther from the line of the others (Esc starts again).")
            Return
        End If
        Dim width = outline.Max(Function(v) v.X) - outline.Min(Function(v) v.X)
        Dim height = outline.Max(Function(v) v.Y) - outline.Min(Function(v) v.Y)
        If width > InputLimits.MaxSide OrElse height > InputLimits.MaxSide Then
            d.Clear()
            _stage.ShowMessage("This polygon would be " & Units.Sig(width) & " × " & Units.Sig(height) & " m; each way it may be at most " & Units.Quantity(InputLimits.MaxSide, "m") &
                        ". Click its first corner again (Esc cancels).")
            Return
        End If
        Dim body = d.Build(outline)
        Dim clash = Placement.FirstOverlap(_stage.World, body, Vector.Zero)
        Dim place = Placement.NearestFree(_stage.World, body, Vector.Zero, MinPlacementReach)
        If Not place.HasValue Then
            Dim why = If(clash IsNot Nothing, "it would overlap " & Describe(clash), "it does not fit in the container")
            d.Clear()
            _stage.Emit("corners refused: " & why)
            _stage.ShowMessage("There is no room for the polygon there: " & why & ". Click its corners again on a free place (Esc cancels).")
            Return
        End If
        Dim moved = place.Value.Length
        If moved > 0 Then body = d.Build(outline.Select(Function(v) v + place.Value).ToArray())
        Dim leftOut = d.LeftOut()
        Dim reordered = leftOut.Length = 0 AndAlso Not d.IsConvexAsClicked
        Dim before = _history.Capture()
        _stage.World.Add(body)
        _history.Commit("the polygon " & body.Id & " added", before)
        _Mode = ClickMode.Move
        _CornerDraft = Nothing
        _toolCursor = Nothing
        _stage.Emit("placed polygon " & body.Id & " at " & Units.Pair(body.CentreOfMass, 3) & " corners " & String.Join(" ", body.Vertices.Select(Function(v) Units.Pair(v, 3))))
        Dim notes As New List(Of String)
        If leftOut.Length > 0 Then
            notes.Add("The corners you clicked do not make a convex shape, so the polygon is their convex hull (the outline of a rubber band stretched round them): " &
                      If(leftOut.Length = 1, "corner " & leftOut(0) & " lies", "corners " & JoinNumbers(leftOut) & " lie") & " inside it or on a side, and " &
                      If(leftOut.Length = 1, "was", "were") & " left out.")
        ElseIf reordered Then
            notes.Add("The sides you clicked crossed, so the corners were joined in order round the outline.")
        End If
        If clash IsNot Nothing AndAlso moved > Placement.Tolerance Then
            notes.Add("Placed " & Units.Quantity(moved, "m") & " from where you drew it: there it would have overlapped " & Describe(clash) & ".")
        End If
        _stage.ShowMessage(String.Join(" ", notes))
        _stage.TakeSnapshot()
        _stage.Window.ShowSettings()
    End Sub

    ''' <summary>"2, 4 and 5".</summary>
    Private Shared Function JoinNumbers(numbers As Integer()) As String
        Dim words = numbers.Select(Function(n) n.ToString(Globalization.CultureInfo.InvariantCulture)).ToList()
        If words.Count = 1 Then Return words(0)
        Return String.Join(", ", words.Take(words.Count - 1)) & " and " & words(words.Count - 1)
    End Function
End Class
