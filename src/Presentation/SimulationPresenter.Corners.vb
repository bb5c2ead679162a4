Option Strict On

' The corner tool: a polygon drawn by clicking its corners one after another on the canvas. Each
' left click adds a corner; clicking the first corner again, clicking the last one again (the second
' click of a double click) or Enter finishes; Esc or a right click cancels. The polygon is the convex
' hull of the corners (the engine's polygons are convex), and the message says when that differs
' from what was clicked. It is placed with the same checks as every new body.
Partial Public NotInheritable Class SimulationPresenter
    ''' <summary>How near the first or the last corner a click finishes the polygon, in canvas pixels at 96 dpi.</summary>
    Public Const CornerSnapPixels As Double = 8

    ''' <summary>While a polygon is drawn by its corners: the corners so far and what it will be; Nothing otherwise.</summary>
    Public ReadOnly Property CornerDraft As CornerDraft

    ''' <summary>Starts the corner tool with the typed mass (kg) and the circle's Fixed box.</summary>
    Public Sub BeginAddCorners()
        BeginAddCorners(Inputs.MassText, Inputs.IsFixed)
    End Sub

    ''' <summary>
    ''' Starts the corner tool: the next left clicks on the canvas are the corners of a polygon, fixed or
    ''' of <paramref name="massText"/> kg, until the teacher finishes it (first corner again, a double
    ''' click, or Enter) or cancels (Esc, a right click).
    ''' </summary>
    Public Sub BeginAddCorners(massText As String, isFixed As Boolean)
        If Draft IsNot Nothing Then
            ShowMessage(InputLimits.SpawnFirstMessage)
            Return
        End If
        Inputs.IsFixed = isFixed
        If Not isFixed Then Inputs.MassText = massText
        Guarded(
            Sub()
                ' A fixed polygon has no mass to ask for.
                Dim m = If(isFixed, NumberInput.ReadPositive("1", "mass (kg)", InputLimits.MaxMass),
                                    NumberInput.ReadPositive(massText, "mass (kg)", InputLimits.MaxMass, InputLimits.MinMass))
                If Not m.IsValid Then
                    ShowMessage(InputLimits.CornersMessage & " " & Problems(m))
                    Return
                End If
                If m.WasClamped AndAlso Not isFixed Then
                    Inputs.MassText = Units.Input(m.Value)
                    _window.ShowInputs()
                End If
                EndGestures()
                _Mode = ClickMode.Corners
                _CornerDraft = New CornerDraft(m.Value, isFixed, _colours.NextColour())
                Emit("mode corners" & If(isFixed, " fixed", " m " & Units.Num(m.Value, 3) & " kg"))
                Dim clamped = ClampNote(("mass", If(isFixed, Nothing, CType(m, NumberInput?)), "kg"))
                ShowMessage(clamped & "Click the polygon's first corner on the canvas (Esc or a right click cancels).")
                _window.ShowSettings()
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
                Return Placement.IsFree(World, CornerDraft.Build(outline), Vector.Zero)
            Catch ex As ArgumentException
                Return True ' not a polygon yet (a corner that barely turns): nothing to judge
            End Try
        End Get
    End Property

    ''' <summary>Finishes the polygon being drawn by its corners (Enter). Does nothing when the corner tool is off.</summary>
    Public Sub FinishCorners()
        If Mode <> ClickMode.Corners OrElse CornerDraft Is Nothing Then Return
        Guarded(AddressOf CompleteCorners)
    End Sub

    ''' <summary>A left click of the corner tool at <paramref name="p"/> (m): a new corner, or the end of the outline.</summary>
    Private Sub CornerClick(p As Vector)
        Dim d = CornerDraft
        Dim corner = World.Inside(p, 0)
        _toolCursor = corner
        If d.Count > 0 Then
            Dim snap = CornerSnapPixels * ScreenScale / View.Scale
            Dim nearFirst = (corner - d.Corners(0)).Length <= snap
            Dim nearLast = (corner - d.Corners(d.Count - 1)).Length <= snap
            If nearFirst OrElse nearLast Then
                If d.Count >= 3 Then
                    CompleteCorners()
                Else
                    ShowMessage(TooFewCorners(d.Count) & " Click the next corner somewhere else (Esc cancels).")
                End If
                Return
            End If
        End If
        d.Add(corner)
        Emit("corner " & d.Count & " at " & Units.Pair(corner, 3))
        If d.Count < 3 Then
            ShowMessage("Corner " & d.Count & " is set. Click the next corner (Esc or a right click cancels).")
        Else
            ShowMessage("Corner " & d.Count & " is set. Click the next corner, or finish: click the first corner again, double-click, or press Enter (Esc or a right click cancels).")
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
            ShowMessage(TooFewCorners(d.Count) & " Click more corners (Esc cancels).")
            Return
        End If
        Dim outline = d.Outline()
        If outline.Length < 3 Then
            ShowMessage("These corners lie on one straight line, so they enclose no area. Click another corner off the line (Esc starts again).")
            Return
        End If
        Dim thinnest = ConvexHull.LeastWidth(outline)
        If thinnest < InputLimits.MinSide Then
            ShowMessage("This polygon would be only " & Units.Quantity(thinnest, "m") & " across at its thinnest; it must be at least " & Units.Quantity(InputLimits.MinSide, "m") &
                        ". Click another corner farther from the line of the others (Esc starts again).")
            Return
        End If
        Dim width = outline.Max(Function(v) v.X) - outline.Min(Function(v) v.X)
        Dim height = outline.Max(Function(v) v.Y) - outline.Min(Function(v) v.Y)
        If width > InputLimits.MaxSide OrElse height > InputLimits.MaxSide Then
            d.Clear()
            ShowMessage("This polygon would be " & Units.Sig(width) & " × " & Units.Sig(height) & " m; each way it may be at most " & Units.Quantity(InputLimits.MaxSide, "m") &
                        ". Click its first corner again (Esc cancels).")
            Return
        End If
        Dim body = d.Build(outline)
        Dim clash = Placement.FirstOverlap(World, body, Vector.Zero)
        Dim place = Placement.NearestFree(World, body, Vector.Zero, MinPlacementReach)
        If Not place.HasValue Then
            Dim why = If(clash IsNot Nothing, "it would overlap " & Describe(clash), "it does not fit in the container")
            d.Clear()
            Emit("corners refused: " & why)
            ShowMessage("There is no room for the polygon there: " & why & ". Click its corners again on a free place (Esc cancels).")
            Return
        End If
        Dim moved = place.Value.Length
        If moved > 0 Then body = d.Build(outline.Select(Function(v) v + place.Value).ToArray())
        Dim leftOut = d.LeftOut()
        Dim reordered = leftOut.Length = 0 AndAlso Not d.IsConvexAsClicked
        World.Add(body)
        _Mode = ClickMode.Move
        _CornerDraft = Nothing
        _toolCursor = Nothing
        Emit("placed polygon " & body.Id & " at " & Units.Pair(body.CentreOfMass, 3) & " corners " & String.Join(" ", body.Vertices.Select(Function(v) Units.Pair(v, 3))))
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
        ShowMessage(String.Join(" ", notes))
        TakeSnapshot()
        _window.ShowSettings()
    End Sub

    ''' <summary>"2, 4 and 5".</summary>
    Private Shared Function JoinNumbers(numbers As Integer()) As String
        Dim words = numbers.Select(Function(n) n.ToString(Globalization.CultureInfo.InvariantCulture)).ToList()
        If words.Count = 1 Then Return words(0)
        Return String.Join(", ", words.Take(words.Count - 1)) & " and " & words(words.Count - 1)
    End Function
End Class
