Option Strict On

''' <summary>
''' Typing values into the tables: a movable body's x, y, vx, vy, mass and (for a circle) radius,
''' checked as the Add panel checks what is typed there. This is the precise way to set a velocity.
''' </summary>
Friend NotInheritable Class TableEditor
    Private ReadOnly _stage As Stage
    Private ReadOnly _snapshot As Func(Of TableSnapshot)
    Private ReadOnly _built As Action
    Private ReadOnly _history As EditHistory

    ''' <param name="snapshot">the tables as the window shows them now (rows are found by their place there)</param>
    ''' <param name="built">told after an edit: it is building, and Restart comes back to it</param>
    Public Sub New(stage As Stage, history As EditHistory, snapshot As Func(Of TableSnapshot), built As Action)
        _stage = stage
        _history = history
        _snapshot = snapshot
        _built = built
    End Sub

    ''' <summary>The largest speed that can be typed into a table, m/s (larger is set to it, and the message says so).</summary>
    Public Const MaxTypedSpeed As Double = 1000.0
    ''' <summary>The farthest from the origin a position can be typed, m (only a box without walls lets a body go beyond the container).</summary>
    Public Const MaxTypedPosition As Double = 1000.0
    ''' <summary>What may stand between a typed width and height: "0.8 × 0.5", "0.8 x 0.5", "0.8*0.5", "0.8 0.5".</summary>
    Private Shared ReadOnly SizeSeparators As Char() = {"×"c, "x"c, "X"c, "*"c, " "c}

    ''' <summary>What column <paramref name="column"/> of table <paramref name="table"/> (an index into <see cref="BodyTable.All"/>) holds, when it can be typed into.</summary>
    Public Shared Function EditableQuantity(table As Integer, column As Integer) As TableQuantity
        If table < 0 OrElse table >= BodyTable.All.Count Then Return TableQuantity.None
        Dim headers = BodyTable.All(table).Headers
        If column < 0 OrElse column >= headers.Count Then Return TableQuantity.None
        Select Case headers(column)
            Case "x (m)" : Return TableQuantity.X
            Case "y (m)" : Return TableQuantity.Y
            Case "vx (m/s)" : Return TableQuantity.Vx
            Case "vy (m/s)" : Return TableQuantity.Vy
            Case BodyTable.MassHeader : Return TableQuantity.Mass
            Case BodyTable.RadiusHeader : Return TableQuantity.Radius
            Case BodyTable.SizeHeader, "Size (m)" : Return TableQuantity.Size
            Case BodyTable.KineticHeader : Return TableQuantity.KineticFriction
            Case BodyTable.StaticHeader : Return TableQuantity.StaticFriction
        End Select
        Return TableQuantity.None
    End Function

    ''' <summary>The column of table <paramref name="table"/> that holds <paramref name="quantity"/>, or −1.</summary>
    Public Shared Function ColumnOf(table As Integer, quantity As TableQuantity) As Integer
        If table < 0 OrElse table >= BodyTable.All.Count OrElse quantity = TableQuantity.None Then Return -1
        For c = 0 To BodyTable.All(table).Headers.Count - 1
            If EditableQuantity(table, c) = quantity Then Return c
        Next
        Return -1
    End Function

    ''' <summary>The body listed in row <paramref name="row"/> of table <paramref name="table"/> of the last snapshot, or Nothing.</summary>
    Private Function BodyInRow(table As Integer, row As Integer) As Shape
        If table < 0 OrElse table >= BodyTable.All.Count OrElse row < 0 OrElse row >= _snapshot().RowCount(table) Then Return Nothing
        Return _stage.World.Find(_snapshot().Row(table, row).Id)
    End Function

    ''' <summary>Whether the cell can be typed into: an editable column of a movable body's row.</summary>
    Public Function CanEditCell(table As Integer, row As Integer, column As Integer) As Boolean
        Dim q = EditableQuantity(table, column)
        Dim body = BodyInRow(table, row)
        ' A surface's μ is its own, fixed or not; a ball takes none.
        If IsFriction(q) Then Return body IsNot Nothing AndAlso body.Kind <> ShapeKind.Circle
        Return q <> TableQuantity.None AndAlso body IsNot Nothing AndAlso Not body.IsFixed AndAlso
               (q <> TableQuantity.Radius OrElse body.Kind = ShapeKind.Circle)
    End Function

    ''' <summary>The text an edit box opens with: the cell's value with more figures than the table shows ("" when it cannot be edited).</summary>
    Public Function CellEditText(table As Integer, row As Integer, column As Integer) As String
        If Not CanEditCell(table, row, column) Then Return ""
        Dim body = BodyInRow(table, row)
        Select Case EditableQuantity(table, column)
            Case TableQuantity.KineticFriction : Return If(body.Friction.HasValue, body.Friction.Value.ToString("R", Globalization.CultureInfo.InvariantCulture), "")
            Case TableQuantity.StaticFriction : Return If(body.StaticFriction.HasValue, body.StaticFriction.Value.ToString("R", Globalization.CultureInfo.InvariantCulture), "")
        End Select
        If EditableQuantity(table, column) = TableQuantity.Size AndAlso body.Kind <> ShapeKind.Circle Then
            Dim size = body.BoundsMax - body.BoundsMin
            Return size.X.ToString("G6", Globalization.CultureInfo.InvariantCulture) & " × " & size.Y.ToString("G6", Globalization.CultureInfo.InvariantCulture)
        End If
        Return CurrentValue(BodyInRow(table, row), table, EditableQuantity(table, column)).ToString("G6", Globalization.CultureInfo.InvariantCulture)
    End Function

    ''' <summary>The value the cell stands for now, in full precision.</summary>
    Private Shared Function CurrentValue(body As Shape, table As Integer, q As TableQuantity) As Double
        Dim point = ListedPoint(body, table)
        Select Case q
            Case TableQuantity.X : Return point.X
            Case TableQuantity.Y : Return point.Y
            Case TableQuantity.Vx : Return body.Velocity.X
            Case TableQuantity.Vy : Return body.Velocity.Y
            Case TableQuantity.Mass : Return body.Mass
            Case TableQuantity.Radius, TableQuantity.Size : Return DirectCast(body, Circle).Radius
        End Select
        Return 0
    End Function

    ''' <summary>The point a table lists a body by: Circles and Rectangles its reference point (centre, lower-left corner), Bodies its centre of mass.</summary>
    Private Shared Function ListedPoint(body As Shape, table As Integer) As Vector
        Return If(BodyTable.All(table) Is BodyTable.Bodies, body.CentreOfMass, body.Position)
    End Function

    ''' <summary>
    ''' Sets the quantity of the cell to what was typed. It is checked as the Add panel checks its
    ''' boxes (the same messages, limits brought to with a note); a position must keep the body
    ''' inside a walled container and clear of every other body, and a new radius too. A refusal is a
    ''' message and changes nothing. An edit is building: Restart comes back to it. Returns whether
    ''' the world changed.
    ''' </summary>
    Public Function EditCell(table As Integer, row As Integer, column As Integer, text As String) As Boolean
        Dim body = BodyInRow(table, row)
        Dim q = EditableQuantity(table, column)
        If body Is Nothing OrElse q = TableQuantity.None Then
            _stage.ShowMessage("That cell cannot be typed into: the position, velocity, mass and size of a moving body can, and the μk and μs of a surface.")
            Return False
        End If
        If IsFriction(q) Then
            If body.Kind = ShapeKind.Circle Then
                _stage.ShowMessage(body.Id & "'s " & LabelOf(q) & " cannot be set. " & WorldSettings.BallsNote)
                Return False
            End If
            Dim applied = False
            _stage.Guarded(Sub() applied = ApplyFriction(body, q, text))
            Return applied
        End If
        If body.IsFixed Then
            _stage.ShowMessage(body.Id & " is fixed: it has no velocity or mass. Carry it with the right mouse button to move it.")
            Return False
        End If
        If q = TableQuantity.Radius AndAlso body.Kind <> ShapeKind.Circle Then Return False
        Dim changed = False
        _stage.Guarded(Sub() changed = ApplyEdit(body, table, q, text))
        Return changed
    End Function

    Private Function ApplyEdit(body As Shape, table As Integer, q As TableQuantity, text As String) As Boolean
        If q = TableQuantity.Size Then
            If body.Kind = ShapeKind.Circle Then Return ApplyEdit(body, table, TableQuantity.Radius, text)
            Return ApplySize(body, text)
        End If
        Dim label = LabelOf(q)
        Dim read As NumberInput
        Select Case q
            Case TableQuantity.X, TableQuantity.Y : read = NumberInput.ReadFinite(text, label, MaxTypedPosition)
            Case TableQuantity.Vx, TableQuantity.Vy : read = NumberInput.ReadFinite(text, label, MaxTypedSpeed)
            Case TableQuantity.Mass : read = NumberInput.ReadPositive(text, label, InputLimits.MaxMass, InputLimits.MinMass)
            Case Else : read = NumberInput.ReadPositive(text, label, InputLimits.MaxRadius, InputLimits.MinRadius)
        End Select
        If Not read.IsValid Then
            _stage.ShowMessage(AskingMessage(body, q) & " " & Stage.Problems(read))
            Return False
        End If
        Dim value = read.Value
        _stage.EndGestures()
        Dim before = _history.Capture()
        Select Case q
            Case TableQuantity.X, TableQuantity.Y
                Dim now = ListedPoint(body, table)
                Dim offset = If(q = TableQuantity.X, New Vector(value - now.X, 0), New Vector(0, value - now.Y))
                Dim refusal = PlacementRefusal(body, body, offset)
                If refusal IsNot Nothing Then
                    _stage.ShowMessage(label & " = " & Units.Sig(value) & " would put " & body.Id & " " & refusal & "; it stays where it was.")
                    Return False
                End If
                _stage.World.SetPosition(body, body.Position + offset)
            Case TableQuantity.Vx
                _stage.World.SetVelocity(body, New Vector(value, body.Velocity.Y))
            Case TableQuantity.Vy
                _stage.World.SetVelocity(body, New Vector(body.Velocity.X, value))
            Case Else
                Dim replacement = Rebuilt(body, If(q = TableQuantity.Mass, value, body.Mass), If(q = TableQuantity.Radius, value, 0))
                If q = TableQuantity.Radius Then
                    Dim refusal = PlacementRefusal(replacement, body, Vector.Zero)
                    If refusal IsNot Nothing Then
                        _stage.ShowMessage(label & " = " & Units.Sig(value) & " would put " & body.Id & " " & refusal & "; it keeps its size.")
                        Return False
                    End If
                End If
                _stage.World.Replace(body, replacement)
        End Select
        _stage.Emit("edited " & body.Id & " " & label & " = " & value.ToString("R", Globalization.CultureInfo.InvariantCulture))
        _history.Commit(body.Id & "'s " & label & " typed", before)
        Dim note = If(read.WasClamped, LabelOf(q) & " set to the " & If(read.WasRaised, "minimum", "maximum") & ", " & Units.Sig(value) & ". ", "")
        _stage.ShowMessage(note & body.Id & ": " & label & " is now " & Units.Sig(value) & ". Restart comes back to this.")
        _built()
        _stage.TakeSnapshot()
        Return True
    End Function

    ''' <summary>Whether the quantity is a surface's μk or μs.</summary>
    Private Shared Function IsFriction(q As TableQuantity) As Boolean
        Return q = TableQuantity.KineticFriction OrElse q = TableQuantity.StaticFriction
    End Function

    ''' <summary>
    ''' Sets a surface's own μk or μs (boxes, polygons, fixed bodies, ramps). Empty text (or "world")
    ''' gives the surface back the world's value. A value that is not a number or is negative, or a μs
    ''' below the surface's μk (or a μk above its own μs), is refused naming the cell, and nothing
    ''' changes; a value above <see cref="WorldSettings.MaxFriction"/> is brought to it and said. An
    ''' undoable edit, kept by Save… (the body's friction and static_friction).
    ''' </summary>
    Private Function ApplyFriction(body As Shape, q As TableQuantity, text As String) As Boolean
        Dim label = body.Id & "'s " & LabelOf(q)
        Dim t = If(text, "").Trim()
        Dim value As Double? = Nothing
        Dim clamped = False
        If t.Length > 0 AndAlso Not String.Equals(t, "world", StringComparison.OrdinalIgnoreCase) Then
            Dim read = NumberInput.ReadFinite(t, label, WorldSettings.MaxFriction)
            If Not read.IsValid Then
                _stage.ShowMessage(label & " is unchanged: " & read.Problem & ".")
                Return False
            End If
            If read.Value < 0 Then
                _stage.ShowMessage(label & " is unchanged: it must be 0 or more, not " & Stage.OneLine(t) & ".")
                Return False
            End If
            value = read.Value
            clamped = read.WasClamped
        End If
        Dim kinetic = If(q = TableQuantity.KineticFriction, value, body.Friction)
        Dim [static] = If(q = TableQuantity.StaticFriction, value, body.StaticFriction)
        Dim k = If(kinetic, _stage.World.Friction)
        If [static].HasValue AndAlso [static].Value < k Then
            _stage.ShowMessage(label & " is unchanged: μs (" & Units.Input([static].Value) & ") must be at least μk (" & Units.Input(k) &
                               "): a surface grips at least as hard before it slides as while it slides.")
            Return False
        End If
        If Nullable.Equals(kinetic, body.Friction) AndAlso Nullable.Equals([static], body.StaticFriction) Then Return False
        _stage.EndGestures()
        Dim before = _history.Capture()
        _stage.World.SetFriction(body, kinetic, [static])
        Dim said = If(value.HasValue, value.Value.ToString("R", Globalization.CultureInfo.InvariantCulture), "world")
        _stage.Emit("edited " & body.Id & " " & LabelOf(q) & " = " & said)
        _history.Commit(label & " typed", before)
        Dim note = If(clamped, "μ above " & Units.Input(WorldSettings.MaxFriction) & " was brought to " & Units.Input(WorldSettings.MaxFriction) & ". ", "")
        Dim now = If(value.HasValue, Units.Input(value.Value), "the world's (" & Units.Input(If(q = TableQuantity.KineticFriction, _stage.World.KineticFrictionOf(body), _stage.World.StaticFrictionOf(body))) & ")")
        _stage.ShowMessage(note & label & " is now " & now & ". Restart comes back to this.")
        _built()
        _stage.TakeSnapshot()
        Return True
    End Function

    ''' <summary>
    ''' A box's or polygon's new width × height, m ("0.8 × 0.5"; x, * or a space between them also do),
    ''' each checked as the Add panel checks a rectangle's sides. The body keeps its centre of mass,
    ''' mass and velocity; a polygon is stretched about its centre of mass (it stays convex). Refused
    ''' with the reason when it would overlap another body or leave a walled container.
    ''' </summary>
    Private Function ApplySize(body As Shape, text As String) As Boolean
        Dim asking = If(body.Kind = ShapeKind.Rectangle, InputLimits.BoxMessage, InputLimits.PolygonMessage)
        Dim parts = If(text, "").Split(SizeSeparators, StringSplitOptions.RemoveEmptyEntries)
        If parts.Length <> 2 Then
            _stage.ShowMessage(asking & " Type the width and the height in metres, as 0.8 × 0.5, not '" & Stage.OneLine(text) & "'.")
            Return False
        End If
        Dim width = NumberInput.ReadPositive(parts(0), "width (m)", InputLimits.MaxSide, InputLimits.MinSide)
        Dim height = NumberInput.ReadPositive(parts(1), "height (m)", InputLimits.MaxSide, InputLimits.MinSide)
        If Not width.IsValid OrElse Not height.IsValid Then
            _stage.ShowMessage(asking & " " & Stage.Problems(width, height))
            Return False
        End If
        _stage.EndGestures()
        Dim centre = body.CentreOfMass
        Dim replacement As Shape
        If body.Kind = ShapeKind.Rectangle Then
            replacement = Rectangle.CreateMovable(centre - New Vector(width.Value / 2, height.Value / 2), width.Value, height.Value, body.Mass, body.Velocity, body.Id)
        Else
            Dim old = body.BoundsMax - body.BoundsMin
            Dim sx = width.Value / old.X, sy = height.Value / old.Y
            Dim corners = DirectCast(body, Polygon).Vertices.Select(Function(v) centre + New Vector((v.X - centre.X) * sx, (v.Y - centre.Y) * sy)).ToList()
            replacement = New Polygon(corners, body.Mass, body.Velocity, body.Id)
        End If
        KeepOwnValues(body, replacement)
        Dim said = Units.Sig(width.Value) & " × " & Units.Sig(height.Value) & " m"
        Dim refusal = PlacementRefusal(replacement, body, Vector.Zero)
        If refusal IsNot Nothing Then
            _stage.ShowMessage("A size of " & said & " would put " & body.Id & " " & refusal & "; it keeps its size.")
            Return False
        End If
        Dim before = _history.Capture()
        _stage.World.Replace(body, replacement)
        _history.Commit(body.Id & "'s size typed", before)
        _stage.Emit("edited " & body.Id & " size (m) = " & width.Value.ToString("R", Globalization.CultureInfo.InvariantCulture) & " × " & height.Value.ToString("R", Globalization.CultureInfo.InvariantCulture))
        Dim note = If(width.WasClamped OrElse height.WasClamped, "A side was brought to its limit (" & Units.Sig(InputLimits.MinSide) & " to " & Units.Sig(InputLimits.MaxSide) & " m). ", "")
        _stage.ShowMessage(note & body.Id & ": its size is now " & said & ". Restart comes back to this.")
        _built()
        _stage.TakeSnapshot()
        Return True
    End Function

    ''' <summary>"vx (m/s)": the field's name with its unit, as the messages give it.</summary>
    Private Shared Function LabelOf(q As TableQuantity) As String
        Select Case q
            Case TableQuantity.X : Return "x (m)"
            Case TableQuantity.Y : Return "y (m)"
            Case TableQuantity.Vx : Return "vx (m/s)"
            Case TableQuantity.Vy : Return "vy (m/s)"
            Case TableQuantity.Mass : Return "mass (kg)"
            Case TableQuantity.KineticFriction : Return "μk"
            Case TableQuantity.StaticFriction : Return "μs"
            Case Else : Return "radius (m)"
        End Select
    End Function

    ''' <summary>The Add panel's request for a suitable value, for this kind of body (positions and velocities: the circle's).</summary>
    Private Shared Function AskingMessage(body As Shape, q As TableQuantity) As String
        If q = TableQuantity.Mass Then
            Select Case body.Kind
                Case ShapeKind.Rectangle : Return InputLimits.BoxMessage
                Case ShapeKind.Polygon : Return InputLimits.PolygonMessage
            End Select
        End If
        If q = TableQuantity.Mass OrElse q = TableQuantity.Radius Then Return InputLimits.CircleMessage
        Return "Please enter a suitable value for " & LabelOf(q) & "!"
    End Function

    ''' <summary>
    ''' Why <paramref name="candidate"/>, moved by <paramref name="offset"/>, cannot stand where the
    ''' world's <paramref name="original"/> is (it leaves a walled container, or overlaps another body
    ''' it collides with), or Nothing when it can.
    ''' </summary>
    Private Function PlacementRefusal(candidate As Shape, original As Shape, offset As Vector) As String
        If Not Placement.IsInside(_stage.World, candidate, offset) Then
            Return "outside the container (0 to " & Units.Sig(_stage.World.Width) & " m across, 0 to " & Units.Sig(_stage.World.Height) & " m up)"
        End If
        For Each other In _stage.World.Bodies
            If other Is original OrElse Not Placement.Collide(candidate, other) Then Continue For
            If Placement.OverlapDepth(candidate, offset, other) > Placement.Tolerance Then Return "into " & other.Id
        Next
        Return Nothing
    End Function

    ''' <summary>A copy of a movable body with another mass (kg) and, for a circle, radius (m; 0 keeps it): same place, velocity, id and colour.</summary>
    Private Shared Function Rebuilt(body As Shape, mass As Double, radius As Double) As Shape
        Dim copy As Shape
        Select Case body.Kind
            Case ShapeKind.Circle
                Dim c = DirectCast(body, Circle)
                copy = New Circle(c.Position, If(radius > 0, radius, c.Radius), mass, c.Velocity, c.Id)
            Case ShapeKind.Rectangle
                Dim r = DirectCast(body, Rectangle)
                copy = Rectangle.CreateMovable(r.Position, r.Width, r.Height, mass, r.Velocity, r.Id)
            Case Else
                Dim p = DirectCast(body, Polygon)
                copy = New Polygon(p.Vertices, mass, p.Velocity, p.Id)
        End Select
        KeepOwnValues(body, copy)
        Return copy
    End Function

    ''' <summary>
    ''' A body rebuilt for a new mass or size keeps what is its own and not typed: its colour, its surface's
    ''' μk and μs, and its drag (C_d and b).
    ''' </summary>
    Private Shared Sub KeepOwnValues(body As Shape, rebuilt As Shape)
        rebuilt.Color = body.Color
        rebuilt.Friction = body.Friction
        rebuilt.StaticFriction = body.StaticFriction
        rebuilt.DragCoefficient = body.DragCoefficient
        rebuilt.LinearDrag = body.LinearDrag
    End Sub
End Class
