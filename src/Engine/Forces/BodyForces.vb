Option Strict On

''' <summary>
''' The free-body diagram of a movable body in a world as it is now (docs/contact.md, "The forces shown"). Its
''' weight, its springs, drag and buoyancy follow from the state alone. The pushes of the contacts it rests on,
''' the friction there and the pulls of its rods and taut strings are what keeps the bodies touching it from
''' moving into one another: they are found by the same complementarity solve the event solver uses for the
''' accelerations (<see cref="FrictionSolve"/>), over the bodies joined to it by touching contacts, rods and taut
''' strings. A contact counts as touching within <see cref="TouchSlop"/> and moving apart or together no faster
''' than <see cref="TouchSpeed"/>. A pure function of the world's state: nothing is changed.
''' </summary>
Public Module BodyForces
    ''' <summary>How far apart (m) two surfaces may be, or pressed into one another, and still touch.</summary>
    Public Const TouchSlop As Double = 0.000001

    ''' <summary>How fast (m/s) touching surfaces may part or close and still be in lasting contact (a faster one is a blow, or flight).</summary>
    Public Const TouchSpeed As Double = 0.000001

    ''' <summary>A touching contact or taut link found, on the members' slots.</summary>
    Private NotInheritable Class Holder
        Friend Row As Constraint
        Friend Kind As ForceKind
        Friend SourceA As String
        Friend SourceB As String
        Friend OtherShape As Shape
    End Class

    ''' <summary>The forces on <paramref name="body"/>, a movable body of <paramref name="world"/>, now.</summary>
    Public Function Diagram(world As World, body As Shape) As FreeBodyDiagram
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        If body.IsFixed OrElse Not world.Movables.Contains(body) Then Throw New ArgumentException("a free-body diagram is of a movable body of the world", NameOf(body))

        ' 1. The bodies held together with it: joined by a touching contact, a rod or a taut string, repeatedly.
        Dim members As New List(Of Shape) From {body}
        Dim holders As New List(Of Holder)
        Dim seenPairs As New HashSet(Of Long)
        Dim tied As New HashSet(Of Link)
        Dim head = 0
        Do
            head = GatherContacts(world, members, holders, seenPairs, head)
            If Not GatherTies(world, members, holders, tied) AndAlso head = members.Count Then Exit Do
        Loop

        ' 2. The known forces on each member, and the free accelerations they give.
        Dim field = If(world.HasDragOrLiquids, New ForceField(world), Nothing)
        Dim known As New List(Of BodyForce)
        Dim free(members.Count - 1) As Vector
        For k = 0 To members.Count - 1
            Dim s = members(k)
            Dim total = New Vector(0, -world.Gravity * s.Mass)
            If k = 0 AndAlso world.Gravity <> 0 Then known.Add(New BodyForce(ForceKind.Weight, "Earth", total, s.CentreOfMass))
            If field IsNot Nothing AndAlso field.Acts(s) Then
                Dim resistance As Double, lift As Double
                field.Evaluate(s, s.Position, s.Velocity, resistance, lift)
                Dim drag = s.Velocity * -resistance
                total += drag + New Vector(0, lift)
                If k = 0 Then
                    If drag <> Vector.Zero Then known.Add(New BodyForce(ForceKind.Drag, If(world.Liquids.Count > 0 AndAlso lift > 0, "liquid", "air"), drag, s.CentreOfMass))
                    If lift > 0 Then known.Add(New BodyForce(ForceKind.Buoyancy, LiquidName(world, s), New Vector(0, lift), s.CentreOfMass))
                End If
            End If
            free(k) = total
        Next
        For Each l In world.Links
            If l.Kind <> LinkKind.Spring Then Continue For
            Dim r = l.EndB - l.EndA
            If r.Length = 0 Then Continue For
            Dim onA = r / r.Length * l.Tension
            Dim a = members.IndexOf(l.A), b = If(l.B Is Nothing, -1, members.IndexOf(l.B))
            If a >= 0 Then free(a) += onA
            If b >= 0 Then free(b) -= onA
            If a = 0 Then known.Add(New BodyForce(ForceKind.Spring, l.Id, onA, body.CentreOfMass))
            If b = 0 Then known.Add(New BodyForce(ForceKind.Spring, l.Id, -onA, body.CentreOfMass))
        Next
        Dim inverse = members.Select(Function(s) s.InverseMass).ToArray()
        For k = 0 To members.Count - 1
            free(k) *= inverse(k)
        Next

        ' 3. The contact forces and tensions: the complementarity solve for the accelerations, with friction.
        Dim y = Constraint.StateOf(members)
        Dim rows = holders.Select(Function(h) h.Row).ToList()
        Dim solveRows(rows.Count - 1) As ContactRow
        Dim scale = world.Gravity
        For Each a In free
            scale = Math.Max(scale, a.Length)
        Next
        For k = 0 To rows.Count - 1
            Dim u As Vector, value As Double, rate As Double, curvature As Double
            rows(k).Measure(y, u, value, rate, curvature)
            solveRows(k) = New ContactRow(rows(k).A, rows(k).B, u, curvature, rows(k).Holds)
            scale = Math.Max(scale, Math.Abs(curvature))
        Next
        Dim result(members.Count - 1) As Vector
        Dim forces(rows.Count - 1) As Double, friction(rows.Count - 1) As Double
        FrictionSolve.Solve(New ContactSolve(), inverse, free, rows, solveRows, y, ContactSolve.ApproachTolerance * scale, result, forces, friction)

        ' 4. Those on the body itself.
        Dim found As New List(Of BodyForce)(known)
        For k = 0 To rows.Count - 1
            Dim c = rows(k), h = holders(k)
            Dim sign As Double
            Dim source As String
            If c.A = 0 Then
                sign = 1 : source = h.SourceA
            ElseIf c.B = 0 Then
                sign = -1 : source = h.SourceB
            Else
                Continue For
            End If
            If forces(k) = 0 AndAlso friction(k) = 0 Then Continue For
            Dim u = solveRows(k).Direction * sign
            If h.Kind = ForceKind.Tension Then
                found.Add(New BodyForce(ForceKind.Tension, source, u * forces(k), body.CentreOfMass))
                Continue For
            End If
            Dim other = If(c.A = 0, h.OtherShape, members(c.A))
            Dim at = ContactPoint(body, other, u)
            If forces(k) <> 0 Then found.Add(New BodyForce(ForceKind.Normal, source, u * forces(k), at))
            If friction(k) <> 0 Then found.Add(New BodyForce(ForceKind.Friction, source, c.Along * (friction(k) * sign), at))
        Next
        Return New FreeBodyDiagram(body, found, result(0))
    End Function

    ''' <summary>
    ''' Adds the touching contacts of the members from slot <paramref name="head"/> on (with the walls, the fixed
    ''' bodies and the other movables), and the movables they touch to the members; returns the slot after the
    ''' last member gathered.
    ''' </summary>
    Private Function GatherContacts(world As World, members As List(Of Shape), holders As List(Of Holder), seenPairs As HashSet(Of Long), head As Integer) As Integer
        Dim movables = world.Movables
        Do While head < members.Count
            Dim m = members(head)
            Dim a = head
            head += 1
            If world.Walls Then
                Dim o = m.Outline
                Dim low = New Vector(o.MinX - o.Centroid.X, o.MinY - o.Centroid.Y), high = New Vector(o.MaxX - o.Centroid.X, o.MaxY - o.Centroid.Y)
                For s = 1 To 4
                    Dim side = CType(s, WallSide)
                    Dim c = ContactFeatures.OnWall(0, side, low, high, world.Width, world.Height)
                    If Not Touching(c, New Shape() {m}) Then Continue For
                    c = c.WithSlots(a, -1)
                    ContactFriction.Give(world, c, m, Nothing)
                    holders.Add(New Holder With {.Row = c, .Kind = ForceKind.Normal, .SourceA = WallName(side)})
                Next
            End If
            For Each f In world.Bodies
                If Not f.IsFixed OrElse Not Near(m, f) Then Continue For
                Dim k = Outline.MinkowskiDifference(f.Outline, m.Outline)
                Dim shift = f.Position + m.Outline.Centroid
                Dim c = ContactFeatures.OnOutline(0, -1, shift, k, m.CentreOfMass - shift, m.Velocity, Vector.Zero, TouchSlop)
                If c Is Nothing OrElse Not Touching(c, New Shape() {m}) Then Continue For
                c = c.WithSlots(a, -1)
                ContactFriction.Give(world, c, m, f)
                holders.Add(New Holder With {.Row = c, .Kind = ForceKind.Normal, .SourceA = f.Id, .OtherShape = f})
            Next
            Dim i = IndexOf(movables, m)
            For j = 0 To movables.Count - 1
                Dim other = movables(j)
                If j = i OrElse Not Near(m, other) Then Continue For
                If Not seenPairs.Add(CLng(Math.Min(i, j)) * movables.Count + Math.Max(i, j)) Then Continue For
                Dim k = Outline.MinkowskiDifference(other.Outline, m.Outline)
                Dim shift = m.Outline.Centroid - other.Outline.Centroid
                Dim c = ContactFeatures.OnOutline(0, 1, shift, k, m.CentreOfMass - other.CentreOfMass - shift, m.Velocity - other.Velocity, Vector.Zero, TouchSlop)
                If c Is Nothing OrElse Not Touching(c, New Shape() {m, other}) Then Continue For
                c = c.WithSlots(a, SlotOf(members, other))
                ContactFriction.Give(world, c, m, other)
                holders.Add(New Holder With {.Row = c, .Kind = ForceKind.Normal, .SourceA = other.Id, .SourceB = m.Id, .OtherShape = other})
            Next
        Loop
        Return head
    End Function

    ''' <summary>Adds the rods and taut strings on the members not yet added, and the bodies they tie in; returns whether any was added.</summary>
    Private Function GatherTies(world As World, members As List(Of Shape), holders As List(Of Holder), tied As HashSet(Of Link)) As Boolean
        Dim any = False
        For Each l In world.Links
            If l.Kind = LinkKind.Spring OrElse tied.Contains(l) Then Continue For
            Dim onB = l.B IsNot Nothing AndAlso Not l.B.IsFixed AndAlso members.Contains(l.B)
            If Not (members.Contains(l.A) OrElse onB) OrElse Not (l.Kind = LinkKind.Rod OrElse LinkedMotions.IsTaut(l, world.Gravity, TouchSlop, TouchSpeed)) Then Continue For
            tied.Add(l)
            Dim a = SlotOf(members, l.A)
            Dim b = If(l.IsAnchored, -1, SlotOf(members, l.B))
            Dim c = Constraint.Tie(a, b, If(l.IsAnchored, l.EndB, Vector.Zero), l.Length, l.Kind = LinkKind.Rod)
            holders.Add(New Holder With {.Row = c, .Kind = ForceKind.Tension, .SourceA = l.Id, .SourceB = l.Id})
            any = True
        Next
        Return any
    End Function

    ''' <summary>The slot of <paramref name="s"/> among the members, added at the end when it is not one yet.</summary>
    Private Function SlotOf(members As List(Of Shape), s As Shape) As Integer
        Dim k = members.IndexOf(s)
        If k >= 0 Then Return k
        members.Add(s)
        Return members.Count - 1
    End Function

    ''' <summary>Where <paramref name="s"/> is in <paramref name="list"/> (by reference), or −1.</summary>
    Private Function IndexOf(list As IReadOnlyList(Of Shape), s As Shape) As Integer
        For k = 0 To list.Count - 1
            If list(k) Is s Then Return k
        Next
        Return -1
    End Function

    ''' <summary>Whether the bounding boxes of two bodies are within <see cref="TouchSlop"/> of each other.</summary>
    Private Function Near(a As Shape, b As Shape) As Boolean
        Dim aMin = a.BoundsMin, aMax = a.BoundsMax, bMin = b.BoundsMin, bMax = b.BoundsMax
        Return aMin.X <= bMax.X + TouchSlop AndAlso bMin.X <= aMax.X + TouchSlop AndAlso aMin.Y <= bMax.Y + TouchSlop AndAlso bMin.Y <= aMax.Y + TouchSlop
    End Function

    ''' <summary>Whether contact <paramref name="c"/> on slots 0 (and 1) of <paramref name="bodies"/> touches and lasts: within the slop, neither parting nor closing.</summary>
    Private Function Touching(c As Constraint, bodies As Shape()) As Boolean
        Dim u As Vector, value As Double, rate As Double, curvature As Double
        c.Measure(Constraint.StateOf(bodies), u, value, rate, curvature)
        Return Math.Abs(value) <= TouchSlop AndAlso Math.Abs(rate) <= TouchSpeed
    End Function

    ''' <summary>How a wall is named in a diagram.</summary>
    Private Function WallName(side As WallSide) As String
        Select Case side
            Case WallSide.Bottom : Return "floor"
            Case WallSide.Top : Return "ceiling"
            Case WallSide.Left : Return "left wall"
            Case Else : Return "right wall"
        End Select
    End Function

    ''' <summary>The liquid a body floats in (the first it is in), by id.</summary>
    Private Function LiquidName(world As World, s As Shape) As String
        For Each l In world.Liquids
            If SubmergedArea.Inside(s.Outline, s.Position, l.Min, l.Max).Area > 0 Then Return If(String.IsNullOrEmpty(l.Id), "liquid", l.Id)
        Next
        Return "liquid"
    End Function

    ''' <summary>
    ''' Where a contact pushes <paramref name="body"/> along <paramref name="u"/> (unit, from the other towards it):
    ''' the middle of the stretch where the two surfaces face each other, on the body's surface. A wall
    ''' (<paramref name="other"/> Nothing) faces all of it.
    ''' </summary>
    Friend Function ContactPoint(body As Shape, other As Shape, u As Vector) As Vector
        Dim t = New Vector(-u.Y, u.X)
        Dim level As Double, lowA As Double, highA As Double
        Extent(body, -u, t, level, lowA, highA)
        Dim low = lowA, high = highA
        If other IsNot Nothing Then
            Dim otherLevel As Double, lowB As Double, highB As Double
            Extent(other, u, t, otherLevel, lowB, highB)
            low = Math.Max(lowA, lowB)
            high = Math.Min(highA, highB)
            ' Faces that do not overlap (a corner at the end of a face): where they come nearest.
            If low > high Then
                Dim nearest = If(lowB > highA, highA, lowA)
                low = nearest : high = nearest
            End If
        End If
        Return t * (0.5 * (low + high)) + u * level
    End Function

    ''' <summary>
    ''' The part of <paramref name="s"/>'s surface furthest along <paramref name="e"/> (unit): how far along −e it is
    ''' (<paramref name="level"/>, m, so that the surface is at −level e) and its extent along <paramref name="t"/> (m),
    ''' in world coordinates.
    ''' </summary>
    Private Sub Extent(s As Shape, e As Vector, t As Vector, ByRef level As Double, ByRef low As Double, ByRef high As Double)
        Dim vs = s.Outline.Vertices
        Dim best = Double.NegativeInfinity
        For Each v In vs
            best = Math.Max(best, Vector.Dot(v + s.Position, e))
        Next
        Dim size = Math.Max(s.Outline.MaxX - s.Outline.MinX, s.Outline.MaxY - s.Outline.MinY)
        low = Double.PositiveInfinity : high = Double.NegativeInfinity
        For Each v In vs
            Dim p = v + s.Position
            If Vector.Dot(p, e) < best - 0.000000001 * Math.Max(size, 1) Then Continue For
            low = Math.Min(low, Vector.Dot(p, t))
            high = Math.Max(high, Vector.Dot(p, t))
        Next
        ' The rounded part (a ball, a rounded box) reaches its radius further.
        level = -(best + s.Outline.Radius)
    End Sub
End Module
