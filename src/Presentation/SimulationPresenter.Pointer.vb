Option Strict On

' What the mouse does on the canvas: place a new body, delete one, carry one (right button) or
' push one with the cue (left button).
Partial Public NotInheritable Class SimulationPresenter
    Private _dragged As Shape
    Private _grabOffset As Vector ' body reference point minus cursor, m
    Private _aimCursor As Vector

    ''' <summary>The body waiting to be placed, or Nothing.</summary>
    Public ReadOnly Property Draft As BodyDraft

    ''' <summary>The body being carried with the right button, or Nothing.</summary>
    Public ReadOnly Property DraggedBody As Shape
        Get
            Return _dragged
        End Get
    End Property

    ''' <summary>The ball being aimed at with the cue, or Nothing.</summary>
    Public ReadOnly Property AimedCircle As Circle

    ''' <summary>Where the cursor is while aiming, m.</summary>
    Public ReadOnly Property AimCursor As Vector
        Get
            Return _aimCursor
        End Get
    End Property

    ''' <summary>The impulse the cue will give when released, N·s (zero when not aiming).</summary>
    Public ReadOnly Property CueImpulse As Vector
        Get
            If AimedCircle Is Nothing Then Return Vector.Zero
            Return CueShot.ImpulseFor(AimedCircle.Position, _aimCursor)
        End Get
    End Property

    ''' <summary>"J = 2.40 N·s, Δv = 1.20 m/s" while aiming, "" otherwise.</summary>
    Public ReadOnly Property CueLabel As String
        Get
            If AimedCircle Is Nothing Then Return ""
            Dim j = CueImpulse.Length
            Return "J = " & Units.Num(j) & " N·s   Δv = J/m = " & Units.Num(j * AimedCircle.InverseMass) & " m/s"
        End Get
    End Property

    ''' <summary>Asks for a circle from the typed radius (m) and mass (kg); it then follows the cursor until a click.</summary>
    Public Sub BeginAddCircle(radiusText As String, massText As String, isFixed As Boolean)
        If Draft IsNot Nothing Then
            ShowMessage(InputLimits.SpawnFirstMessage)
            Return
        End If
        Dim r = NumberInput.ReadPositive(radiusText, "radius (m)", InputLimits.MaxRadius)
        ' A fixed circle has no mass to ask for.
        Dim m = If(isFixed, NumberInput.ReadPositive("1", "mass (kg)", InputLimits.MaxMass), NumberInput.ReadPositive(massText, "mass (kg)", InputLimits.MaxMass))
        Inputs.IsFixed = isFixed
        If Not r.IsValid OrElse Not m.IsValid Then
            ShowMessage(InputLimits.CircleMessage & " " & Problems(r, m))
            Return
        End If
        Inputs.RadiusText = Units.Input(r.Value)
        If Not isFixed Then Inputs.MassText = Units.Input(m.Value)
        _Draft = BodyDraft.ForCircle(r.Value, m.Value, isFixed, _colours.NextColour())
        EndGestures()
        _Mode = ClickMode.Move
        Dim clamped = ClampNote(("radius", r, InputLimits.MaxRadius, "m"), ("mass", If(isFixed, Nothing, CType(m, NumberInput?)), InputLimits.MaxMass, "kg"))
        Emit("adding " & If(isFixed, "fixed ", "") & "circle r " & Units.Num(r.Value, 3) & " m" & If(isFixed, "", " m " & Units.Num(m.Value, 3) & " kg"))
        ShowMessage(clamped & "Click on the canvas to place the circle (Esc cancels).")
        _window.ShowSettings()
    End Sub

    ''' <summary>Asks for a fixed rectangle from the typed width and height, m; it then follows the cursor until a click.</summary>
    Public Sub BeginAddRectangle(widthText As String, heightText As String)
        If Draft IsNot Nothing Then
            ShowMessage(InputLimits.SpawnFirstMessage)
            Return
        End If
        Dim w = NumberInput.ReadPositive(widthText, "width (m)", InputLimits.MaxSide)
        Dim h = NumberInput.ReadPositive(heightText, "height (m)", InputLimits.MaxSide)
        If Not w.IsValid OrElse Not h.IsValid Then
            ShowMessage(InputLimits.RectangleMessage & " " & Problems(w, h))
            Return
        End If
        Inputs.WidthText = Units.Input(w.Value)
        Inputs.HeightText = Units.Input(h.Value)
        _Draft = BodyDraft.ForRectangle(w.Value, h.Value, _colours.NextColour())
        EndGestures()
        _Mode = ClickMode.Move
        Dim clamped = ClampNote(("width", w, InputLimits.MaxSide, "m"), ("height", h, InputLimits.MaxSide, "m"))
        Emit("adding rectangle " & Units.Num(w.Value, 3) & " x " & Units.Num(h.Value, 3) & " m")
        ShowMessage(clamped & "Click on the canvas to place the rectangle (Esc cancels).")
        _window.ShowSettings()
    End Sub

    Private Shared Function ClampNote(ParamArray fields As (Name As String, Input As NumberInput?, Max As Double, Unit As String)()) As String
        Dim notes = fields.Where(Function(f) f.Input.HasValue AndAlso f.Input.Value.WasClamped).
            Select(Function(f) f.Name & " set to the maximum, " & Units.Num(f.Max, 0) & " " & f.Unit).ToList()
        If notes.Count = 0 Then Return ""
        Return String.Join(", ", notes) & ". "
    End Function

    ''' <summary>Drops the body waiting to be placed (Esc).</summary>
    Public Sub CancelPlacement()
        If Draft Is Nothing Then Return
        _Draft = Nothing
        Emit("placement cancelled")
        ShowMessage("")
        _window.ShowSettings()
    End Sub

    ''' <summary>A mouse button went down on the canvas at (x, y) px.</summary>
    Public Sub PointerDown(button As PointerButton, x As Double, y As Double)
        Dim p = View.ToWorld(x, y)
        If Not p.IsFinite Then Return
        If Draft IsNot Nothing Then
            If button = PointerButton.Left Then Place(p)
            Return
        End If
        Dim body = BodyAt(p)
        If button = PointerButton.Left Then
            If Mode = ClickMode.Delete Then
                If body IsNot Nothing Then Delete(body)
                Return
            End If
            Dim c = TryCast(body, Circle)
            If c IsNot Nothing AndAlso Not c.IsFixed AndAlso _dragged Is Nothing Then
                _AimedCircle = c
                _aimCursor = p
                Emit("aiming at " & c.Id)
            End If
        ElseIf button = PointerButton.Right AndAlso body IsNot Nothing AndAlso AimedCircle Is Nothing AndAlso Mode = ClickMode.Move Then
            BeginCarry(body, p)
        End If
    End Sub

    ''' <summary>The mouse moved over the canvas to (x, y) px.</summary>
    Public Sub PointerMove(x As Double, y As Double)
        Dim p = View.ToWorld(x, y)
        If Not p.IsFinite Then Return
        If Draft IsNot Nothing Then
            Draft.Centre = p
            Draft.HasCentre = True
        End If
        If AimedCircle IsNot Nothing Then _aimCursor = p
        If _dragged IsNot Nothing Then Carry(p)
    End Sub

    ''' <summary>A mouse button came up at (x, y) px.</summary>
    Public Sub PointerUp(button As PointerButton, x As Double, y As Double)
        Dim p = View.ToWorld(x, y)
        If button = PointerButton.Left AndAlso AimedCircle IsNot Nothing Then
            If p.IsFinite Then _aimCursor = p
            Fire()
        ElseIf button = PointerButton.Right AndAlso _dragged IsNot Nothing Then
            If p.IsFinite Then Carry(p)
            EndCarry()
        End If
    End Sub

    ''' <summary>The topmost body under point <paramref name="p"/> (m): circles over rectangles, later over earlier.</summary>
    Public Function BodyAt(p As Vector) As Shape
        ' A few pixels of slack so that small balls can still be picked on a projector.
        Dim slack = 4.0 / View.Scale
        Dim circles = World.Circles
        For i = circles.Count - 1 To 0 Step -1
            Dim c = circles(i)
            Dim reach = c.Radius + slack
            If (c.Position - p).LengthSquared <= reach * reach Then Return c
        Next
        Dim rects = World.Rectangles
        For i = rects.Count - 1 To 0 Step -1
            Dim r = rects(i)
            If p.X >= r.Min.X - slack AndAlso p.X <= r.Max.X + slack AndAlso p.Y >= r.Min.Y - slack AndAlso p.Y <= r.Max.Y + slack Then Return r
        Next
        Return Nothing
    End Function

    Private Sub Place(p As Vector)
        Dim body = Draft.Build(p)
        Try
            World.Add(body)
        Catch ex As ArgumentException
            ' For example a ball wider than the container: say so, and keep it on the cursor (Esc cancels).
            ShowMessage("It cannot go there: " & ex.Message & ".")
            Return
        End Try
        _Draft = Nothing
        Emit("placed " & If(TypeOf body Is Circle, "circle", "rectangle") & " " & body.Id & " at " & Units.Pair(Centre(body), 3))
        ShowMessage("")
        _window.ShowBodies()
        _window.ShowSettings()
    End Sub

    Private Sub Delete(body As Shape)
        If body Is _dragged Then EndCarry()
        If body Is AimedCircle Then _AimedCircle = Nothing
        World.Remove(body)
        Emit("deleted " & body.Id)
        _window.ShowBodies()
    End Sub

    Private Sub Fire()
        Dim c = AimedCircle
        _AimedCircle = Nothing
        If Not World.Bodies.Contains(c) Then Return
        Dim j = CueShot.ImpulseFor(c.Position, _aimCursor)
        If j.Length < 0.000001 Then
            Emit("cue released without a pull")
            Return
        End If
        World.ApplyImpulse(c, j)
        Emit("fired " & c.Id & " J " & Units.Pair(j, 3) & " N·s dv " & Units.Pair(j * c.InverseMass, 3) & " m/s v " & Units.Pair(c.Velocity, 3) & " m/s")
    End Sub

    Private Sub BeginCarry(body As Shape, p As Vector)
        _dragged = body
        _grabOffset = Reference(body) - p
        Dim c = TryCast(body, Circle)
        If c IsNot Nothing AndAlso Not c.IsFixed AndAlso Not IsPaused Then World.BeginDrag(c)
        Emit("drag start " & body.Id & " at " & Units.Pair(Centre(body), 3))
    End Sub

    Private Sub Carry(p As Vector)
        Dim target = p + _grabOffset
        Dim c = TryCast(_dragged, Circle)
        If c IsNot Nothing AndAlso Not c.IsFixed Then
            If World.DraggedCircle Is c Then World.DragTo(target) Else World.SetPosition(c, target)
            Return
        End If
        ' The engine moves only movable circles, so a fixed body is carried by replacing it with
        ' an identical one at the new place (same id and colour).
        Dim moved As Shape
        If c IsNot Nothing Then
            moved = Circle.CreateFixed(target, c.Radius, c.Id)
        Else
            Dim r = DirectCast(_dragged, Rectangle)
            moved = New Rectangle(target, r.Width, r.Height, r.Id)
        End If
        moved.Color = _dragged.Color
        World.Replace(_dragged, moved) ' in its own place: it keeps its row in the tables
        _dragged = moved
    End Sub

    Private Sub EndCarry()
        Dim body = _dragged
        _dragged = Nothing
        If World.DraggedCircle IsNot Nothing Then World.EndDrag(Vector.Zero)
        Dim c = TryCast(body, Circle)
        If c IsNot Nothing AndAlso Not c.IsFixed AndAlso World.Bodies.Contains(c) Then World.SetVelocity(c, Vector.Zero)
        Emit("drag end " & body.Id & " at " & Units.Pair(Centre(body), 3))
        _window.ShowBodies()
    End Sub

    ''' <summary>Ends any drag or aim in progress (before a reset, a mode change or a new scene).</summary>
    Private Sub EndGestures()
        _AimedCircle = Nothing
        If _dragged IsNot Nothing Then EndCarry()
    End Sub

    ''' <summary>Where a body is named from: a circle's centre, a rectangle's centre, m.</summary>
    Private Shared Function Centre(body As Shape) As Vector
        Dim c = TryCast(body, Circle)
        If c IsNot Nothing Then Return c.Position
        Dim r = DirectCast(body, Rectangle)
        Return New Vector(r.Position.X + r.Width / 2, r.Position.Y + r.Height / 2)
    End Function

    ''' <summary>The point a body is moved by: a circle's centre, a rectangle's lower-left corner, m.</summary>
    Private Shared Function Reference(body As Shape) As Vector
        Dim c = TryCast(body, Circle)
        If c IsNot Nothing Then Return c.Position
        Return DirectCast(body, Rectangle).Position
    End Function
End Class
