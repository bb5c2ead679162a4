Option Strict On

' How a body comes to rest in the linked event solver (docs/links.md, section 6). A body that touches a
' flat face pressed on by gravity, and would bounce off it less than four slops high, rests on it instead
' of bouncing on for ever: a level face holds it (it slides on at its speed along the face), a slope lets
' it slide down at g sin θ, exactly, until it leaves the face's end; two faces either side of the vertical
' (the bottom of a V) hold it still. A free body rests on every such face; a body on a slack string or a
' vertical spring on a level one. The rules are pure functions (RestingFaces); here they are
' applied to what the body touches.
Partial Friend NotInheritable Class LinkedEventSolver
    ' What each resting body rests on (Nothing while it does not rest).
    Private _restOn As RestSupport()() = Array.Empty(Of RestSupport())()
    ' Pair shapes of a support j's outline and a body i's for i > j (Minkowski differences, m), built when first wanted.
    Private ReadOnly _supportDifferences As New Dictionary(Of Long, Outline)

    ''' <summary>One face a body touches: of a wall, a fixed body or a movable body resting level.</summary>
    Private Structure TouchedFace
        Public Support As RestSupport
        ''' <summary>Unit normal from the support to the body.</summary>
        Public Normal As Vector
        ''' <summary>n·p (m) at which the body's reference point p touches the face now.</summary>
        Public Level As Double
        ''' <summary>Where d is along the face from its first vertex, and the face's length (m); unbounded for a wall.</summary>
        Public Along As Double
        Public Length As Double
        Public Bounded As Boolean
        ''' <summary>The support's velocity, m/s (zero but for a movable body).</summary>
        Public SupportVelocity As Vector
    End Structure

    ''' <summary>Whether body i rests on the given support now.</summary>
    Private Function RestsOn(i As Integer, kind As RestSupportKind, index As Integer) As Boolean
        Dim supports = _restOn(i)
        If supports Is Nothing Then Return False
        For Each s In supports
            If s.Kind = kind AndAlso s.Index = index Then Return True
        Next
        Return False
    End Function

    ''' <summary>
    ''' Group g's motion from <paramref name="t"/> if its body rests (its state, already written to it, is put
    ''' exactly on what holds it), or Nothing. Only groups of one body, free or on one link to a fixed point.
    ''' </summary>
    Private Function RestingMotion(g As Integer, t As Double) As LinkedMotion
        Dim group = _groups(g)
        For Each c In group.Bodies
            _restOn(Array.IndexOf(_bodies, c)) = Nothing
        Next
        Dim gravity = _world.Gravity
        If gravity <= 0 OrElse group.Bodies.Count <> 1 OrElse group.Links.Count > 1 Then Return Nothing
        Dim body = group.Bodies(0)
        Dim i = Array.IndexOf(_bodies, body)
        Dim tie = If(group.Links.Count = 1, group.Links(0), Nothing)
        Dim pressing = gravity
        Dim slack As Link = Nothing
        If tie IsNot Nothing Then
            If tie.A IsNot body Then Return Nothing
            Dim r = tie.EndB - body.CentreOfMass
            Select Case tie.Kind
                Case LinkKind.String
                    ' Slack (shorter than its length): it pulls nothing until it snaps taut, an event of its own.
                    If r.Length >= tie.Length * (1 - LinkedMotions.FullFraction) Then Return Nothing
                    slack = tie
                Case LinkKind.Spring
                    ' Only on the vertical through the anchor does the spring pull straight off a level face.
                    If r.X <> 0 OrElse r.Length = 0 Then Return Nothing
                    pressing = gravity - tie.Tension * r.Y / r.Length / body.Mass
                    If pressing <= 0 Then Return Nothing
                Case Else
                    Return Nothing
            End Select
        End If
        Dim faces = FacesTouched(i, t)
        If ForcedMotions.KeepsFromResting(body, _world, LinkedMotions.RestingSpeed(gravity, Slop), faces.Select(Function(f) f.Normal).ToList()) Then Return Nothing
        Dim p = body.Position
        Dim v = body.Velocity
        Dim restSpeed = LinkedMotions.RestingSpeed(pressing, Slop)
        ' A level face: the whole weight on it.
        Dim level = -1
        For k = 0 To faces.Count - 1
            Dim f = faces(k)
            If f.Normal.Y < RestingFaces.LevelCosine Then Continue For
            Dim w = v - f.SupportVelocity
            If Math.Abs(Vector.Dot(w, f.Normal)) > restSpeed Then Continue For
            If f.Bounded AndAlso RestingFaces.IsLeaving(f.Along, Vector.Dot(w, RestingFaces.Along(f.Normal)), 0, f.Length, Slop) Then Continue For
            If level < 0 OrElse (faces(level).Support.Kind = RestSupportKind.Body AndAlso f.Support.Kind <> RestSupportKind.Body) Then level = k
        Next
        If level >= 0 Then
            Dim f = faces(level)
            Dim w = v - f.SupportVelocity
            If tie IsNot Nothing AndAlso tie.Kind = LinkKind.Spring Then
                ' Held still: the spring pulls straight up, less than the weight; moving, or on a support that
                ' moves, it would not stay on the vertical.
                If v.Length > restSpeed OrElse f.SupportVelocity <> Vector.Zero Then Return Nothing
                w = Vector.Zero
            End If
            Return Rest(i, body, t, {f}, OnFace(p, f), f.SupportVelocity + (w - f.Normal * Vector.Dot(w, f.Normal)), Vector.Zero, slack)
        End If
        If tie IsNot Nothing Then Return Nothing
        ' A slope: gravity's part along it pulls the body down it; the bottom of a V holds it still.
        For k = 0 To faces.Count - 1
            Dim f = faces(k)
            If f.Support.Kind = RestSupportKind.Body OrElse f.Normal.Y <= 0 Then Continue For
            Dim w = v - f.SupportVelocity
            If Math.Abs(Vector.Dot(w, f.Normal)) > LinkedMotions.RestingSpeed(gravity * f.Normal.Y, Slop) Then Continue For
            For q = 0 To faces.Count - 1
                Dim other = faces(q)
                If q = k OrElse other.Support.Kind = RestSupportKind.Body OrElse Not RestingFaces.HoldsUp(f.Normal, other.Normal) Then Continue For
                ' Held from both sides: still once it is too slow to leave either face.
                If w.Length > restSpeed Then Continue For
                ' Exactly where the two faces cross; it touches both within the slop, so that is within a few slops
                ' (for a V far from shallow), else it stays where it is.
                Dim corner = RestingFaces.Crossing(f.Normal, f.Level, other.Normal, other.Level)
                Dim at = If(corner.HasValue AndAlso (corner.Value - p).Length <= 4 * Slop, corner.Value, p)
                Return Rest(i, body, t, {f, other}, at, Vector.Zero, Vector.Zero, Nothing)
            Next
            Dim a = RestingFaces.SlideAcceleration(f.Normal, gravity)
            Dim along = RestingFaces.Along(f.Normal)
            If f.Bounded AndAlso RestingFaces.IsLeaving(f.Along, Vector.Dot(w, along), Vector.Dot(a, along), f.Length, Slop) Then Continue For
            Return Rest(i, body, t, {f}, OnFace(p, f), w - f.Normal * Vector.Dot(w, f.Normal), a, Nothing)
        Next
        Return Nothing
    End Function

    ''' <summary>p (m) moved along the face's normal onto it; exactly at its height for a level one, so that a body resting there is never below it.</summary>
    Private Shared Function OnFace(p As Vector, f As TouchedFace) As Vector
        If f.Normal.Y = 1 Then Return New Vector(p.X, f.Level)
        Return p + f.Normal * (f.Level - Vector.Dot(f.Normal, p))
    End Function

    ''' <summary>Puts body i at <paramref name="p"/> with <paramref name="v"/> and returns its slide with <paramref name="a"/> until it leaves its face (never, held by two).</summary>
    Private Function Rest(i As Integer, body As Shape, t As Double, faces As TouchedFace(), p As Vector, v As Vector, a As Vector, slack As Link) As LinkedMotion
        Dim leaves = Double.PositiveInfinity
        If faces.Length = 1 AndAlso faces(0).Bounded Then
            Dim f = faces(0)
            Dim along = RestingFaces.Along(f.Normal)
            Dim start = f.Along + Vector.Dot(p - body.Position, along)
            leaves = t + RestingFaces.TimeOnFace(start, Vector.Dot(v - f.SupportVelocity, along), Vector.Dot(a, along), f.Length)
        End If
        body.Position = p
        body.Velocity = v
        _restOn(i) = faces.Select(Function(f) f.Support).ToArray()
        Return New FlightMotion(body, t, a, leaves, slack, Slop)
    End Function

    ''' <summary>
    ''' The faces body i touches at <paramref name="t"/> (within the slop) that push up or sideways, never
    ''' down: the container's floor and sides, the faces of fixed bodies (edges of their pair shapes), and the
    ''' top faces of movable bodies that rest level themselves (they neither rise nor fall).
    ''' </summary>
    Private Function FacesTouched(i As Integer, t As Double) As List(Of TouchedFace)
        Dim faces As New List(Of TouchedFace)
        Dim body = _bodies(i)
        Dim p = body.Position
        Dim o = body.Outline
        If _world.Walls Then
            AddWall(faces, p, New Vector(0, 1), 0 - o.MinY, WallSide.Bottom)
            AddWall(faces, p, New Vector(1, 0), 0 - o.MinX, WallSide.Left)
            AddWall(faces, p, New Vector(-1, 0), o.MaxX - _world.Width, WallSide.Right)
        End If
        For f = 0 To _fixed.Length - 1
            AddEdges(faces, _differences(i, f), _fixed(f).Position, p, Vector.Zero, New RestSupport(RestSupportKind.Fixed, f, Vector.Zero))
        Next
        For j = 0 To _bodies.Length - 1
            If j = i OrElse BothBalls(i, j) OrElse _groupOf(j) = _groupOf(i) Then Continue For
            Dim m = TryCast(_groups(_groupOf(j)).Motion, FlightMotion)
            If m Is Nothing OrElse m.Acceleration <> Vector.Zero OrElse RestsOn(j, RestSupportKind.Body, i) Then Continue For
            Dim centre As Vector, velocity As Vector
            m.StateAt(t, _slotOf(j), centre, velocity)
            If velocity.Y <> 0 Then Continue For
            Dim k = If(i < j, _pairDifferences(i, j), SupportDifference(j, i))
            AddEdges(faces, k, centre - _offset(j), p, velocity, New RestSupport(RestSupportKind.Body, j, Vector.Zero))
        Next
        Return faces
    End Function

    ''' <summary>The pair shape K of support j's outline and body i's, for i &gt; j (the pair table holds only i &lt; j), built once.</summary>
    Private Function SupportDifference(j As Integer, i As Integer) As Outline
        Dim key = CLng(j) * Integer.MaxValue + i
        Dim k As Outline = Nothing
        If Not _supportDifferences.TryGetValue(key, k) Then
            k = Outline.MinkowskiDifference(_bodies(j).Outline, _bodies(i).Outline)
            _supportDifferences(key) = k
        End If
        Return k
    End Function

    Private Shared Sub AddWall(faces As List(Of TouchedFace), p As Vector, n As Vector, level As Double, side As WallSide)
        If Vector.Dot(n, p) - level > Slop Then Return
        faces.Add(New TouchedFace With {.Support = New RestSupport(RestSupportKind.Wall, side, n), .Normal = n, .Level = level})
    End Sub

    ''' <summary>The edges of pair shape <paramref name="k"/> (support at <paramref name="origin"/>) that d = p − origin lies on, facing up or sideways.</summary>
    Private Shared Sub AddEdges(faces As List(Of TouchedFace), k As Outline, origin As Vector, p As Vector, supportVelocity As Vector, support As RestSupport)
        Dim first As Integer, second As Integer
        Dim d = p - origin
        If OutlineContact.TouchingEdges(k, d, Slop, first, second) = 0 Then Return
        For Each e In {first, second}
            If e < 0 Then Continue For
            Dim n = k.EdgeNormals(e)
            If n.Y < 0 Then Continue For
            Dim corner = k.Corners(e)
            faces.Add(New TouchedFace With {.Support = New RestSupport(support.Kind, support.Index, n), .Normal = n, .Level = Vector.Dot(n, origin + corner) + k.Radius,
                                            .Along = Vector.Dot(d - corner, RestingFaces.Along(n)), .Length = k.EdgeLengths(e),
                                            .Bounded = True, .SupportVelocity = supportVelocity})
        Next
    End Sub

    ''' <summary>
    ''' The contacts that hold body i at rest, and those holding what it rests on, as rows of the collision's
    ''' solve: each asks that the body not move into its support (restitution 0: they touch, nothing arrives).
    ''' So a blow from above on a body resting on the floor is taken by the floor, in the same solve, as it is
    ''' by a real stack, and a body sliding on a slope that is struck keeps to the slope or leaves it.
    ''' </summary>
    Private Sub AddSupportRows(i As Integer, added As HashSet(Of Integer))
        If _restOn(i) Is Nothing OrElse Not added.Add(i) Then Return
        For Each s In _restOn(i)
            Dim support = If(s.Kind = RestSupportKind.Body, _bodies(s.Index), Nothing)
            If support IsNot Nothing Then Sync(_groupOf(s.Index), _now)
            _impulse.AddContact(_bodies(i), support, -s.Normal, 0)
            If s.Kind = RestSupportKind.Body Then AddSupportRows(s.Index, added)
        Next
    End Sub

    ''' <summary>
    ''' Restarts, at <paramref name="t"/>, every group whose body rests on a body of the groups in
    ''' <paramref name="changed"/> (and, in turn, those resting on them): the support's motion has changed, so
    ''' the rest must be judged again. Returns the groups restarted, <paramref name="changed"/> among them.
    ''' </summary>
    Private Function RestartResting(changed As List(Of Integer), t As Double) As List(Of Integer)
        Dim all As New List(Of Integer)(changed)
        Dim head = 0
        Do While head < all.Count
            Dim g = all(head)
            head += 1
            For i = 0 To _bodies.Length - 1
                Dim gi = _groupOf(i)
                If all.Contains(gi) OrElse _restOn(i) Is Nothing Then Continue For
                If Not _restOn(i).Any(Function(s) s.Kind = RestSupportKind.Body AndAlso _groupOf(s.Index) = g) Then Continue For
                Sync(gi, t)
                Restart(gi, t, False)
                all.Add(gi)
            Next
        Loop
        Return all
    End Function
End Class
