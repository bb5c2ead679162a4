Option Strict On

''' <summary>
''' When pairwise impulses cannot get past an instant (a light ball between the floor and a heavy one
''' is hit back and forth thousands of times at one instant; a ball wedged in a narrow gap loses only
''' a little speed at each hit), the bodies touching the one hit too often are resolved together by
''' <see cref="ContactCluster"/>: exactly, with momentum conserved and no energy gained. This gathers
''' that cluster (movable bodies in contact, and what they touch: walls, obstacles, bodies asleep or
''' dragged, which do not give way), applies the result and reports each contact that pushed.
''' </summary>
Friend NotInheritable Class ClusterResponse
    Private ReadOnly _s As SolverState
    Private ReadOnly _rest As RestRules

    ''' <summary>At most this many bodies are gathered (those beyond are left to pairwise impulses).</summary>
    Private Const MaxBodies As Integer = 64

    ' The cluster: its bodies (solver numbers) with their inverse masses and velocities, and its contacts
    ' with what each is against (a body's shape, or an obstacle's, or a wall).
    Private ReadOnly _members As New List(Of Integer)
    Private ReadOnly _slotOf As New Dictionary(Of Integer, Integer)
    Private ReadOnly _inverseMass As New List(Of Double)
    Private ReadOnly _velocity As New List(Of Vector)
    Private ReadOnly _contacts As New List(Of ClusterContact)
    Private ReadOnly _against As New List(Of Shape)
    Private ReadOnly _side As New List(Of WallSide)
    ''' <summary>What each contact would be as a support for body A (see BodyTable's Support codes), and which face.</summary>
    Private ReadOnly _support As New List(Of Integer)
    Private ReadOnly _supportEdge As New List(Of Integer)
    Private ReadOnly _pairs As New HashSet(Of Long)
    Private ReadOnly _workspace As New ContactClusterWorkspace()
    ''' <summary>Each body's mechanical energy (J) before the cluster is resolved (see <see cref="CollisionLosses.OpenBooks"/>).</summary>
    Private _energies As Double() = Array.Empty(Of Double)()
    Private _neighbours As Integer() = Array.Empty(Of Integer)()
    ''' <summary>Per body: the instant (s) it was last resolved in a cluster.</summary>
    Private _clusteredAt As Double() = Array.Empty(Of Double)()
    ''' <summary>Per body: how many clusters in a row came each within the collapse window of the one before.</summary>
    Private _clusterRun As Integer() = Array.Empty(Of Integer)()
    ''' <summary>Per slot of the cluster being resolved: whether that body is wedged (stopped, and under gravity put to sleep).</summary>
    Private _wedged As Boolean() = Array.Empty(Of Boolean)()

    Friend Sub New(state As SolverState, rest As RestRules)
        _s = state
        _rest = rest
    End Sub

    ''' <summary>Resolves every contact of the cluster of touching bodies around body <paramref name="seed"/> at once.</summary>
    Friend Sub Resolve(seed As Integer)
        Gather(seed)
        Dim result = ContactCluster.Resolve(_inverseMass, _velocity, _contacts, _s.E, _workspace)
        Dim b = _s.Bodies
        Dim movers = 0
        For k = 0 To _members.Count - 1
            If _inverseMass(k) > 0 Then movers += 1
        Next
        Dim alone = movers = 1
        ' Wedged: squeezed between bodies that do not give way (no velocity separates it from them
        ' all), or back in a cluster at once (gravity presses it into a gap its contacts neither
        ' hold it in nor let it through: a ball between a wall and a peg comes back within
        ' nanoseconds, again and again). It stops, and under gravity sleeps where it is, to wake
        ' again when something hits it. "At once" is the same instant, or, for a body alone among
        ' things that do not give way under gravity, the fourth time in a row within 10⁻⁴ √(r/g)
        ' (the collapse guard's window).
        ' Whether a wedged body is held is asked only where the answer can hand the world over.
        Dim askHeld = _s.G > 0 AndAlso _s.MayHandOverUnheld()
        Dim unheld = False
        If _wedged.Length < _members.Count Then _wedged = New Boolean(Math.Max(_members.Count, 2 * _wedged.Length) - 1) {}
        For k = 0 To _members.Count - 1
            If _inverseMass(k) = 0 Then Continue For
            Dim i = _members(k)
            _wedged(k) = Not result.Separated OrElse ClusteredJustNow(i, alone)
            _clusteredAt(i) = _s.Now
            If _wedged(k) AndAlso askHeld AndAlso Not unheld Then unheld = Not _rest.WouldBeHeld(i)
        Next
        ' A body that would sleep where nothing holds it (against a neighbour on a frictionless slope, which
        ' both would slide down pressed together): the fast path cannot move bodies pressed on one another,
        ' so the world goes to the general path, which finds the contact forces, from before this blow.
        If unheld AndAlso _s.TryHandOver(SolverState.HandOverUnheldBodies) Then Return
        ' Every change of energy the cluster makes is counted (see CollisionLosses.OpenBooks): the blow
        ' itself at e < 1, a second projection, a wedged body stopped, the rest rules that follow.
        Dim dissipatedBefore = CollisionLosses.OpenBooks(_s, _energies)
        For k = 0 To _members.Count - 1
            Dim i = _members(k)
            If _inverseMass(k) = 0 Then Continue For
            Dim wedged = _wedged(k)
            Dim after = If(wedged, Vector.Zero, result.Velocities(k))
            _rest.ForgetHits(i)
            If after = _velocity(k) AndAlso Not wedged Then Continue For
            If b.Mode(i) = BodyMode.Supported OrElse b.Mode(i) = BodyMode.Sleeping Then _rest.WakeFrom(i)
            b.Motion(i).Vx = after.X
            b.Motion(i).Vy = after.Y
            If wedged AndAlso _s.G > 0 Then _rest.Sleep(i)
            _rest.NoteHit(i)
            _s.Changed(i)
        Next
        ApplyRestRules()
        Report(result)
        CollisionLosses.NoteChange(_s, _energies, dissipatedBefore)
    End Sub

    ''' <summary>
    ''' Whether body i was last in a cluster at this instant, or (under gravity, <paramref name="alone"/>
    ''' among things that do not give way) is in its fourth such cluster in a row, each within
    ''' 10⁻⁴ √(r/g) of the one before; also counts this cluster.
    ''' </summary>
    Private Function ClusteredJustNow(i As Integer, alone As Boolean) As Boolean
        Dim last = _clusteredAt(i)
        If last = _s.Now Then Return True
        Dim soon = alone AndAlso _s.G > 0 AndAlso _s.Now - last <= 1.0E-4 * Math.Sqrt(_s.Bodies.Size(i).Scale / _s.G) ' False for NaN
        _clusterRun(i) = If(soon, _clusterRun(i) + 1, 0)
        Return _clusterRun(i) >= 3
    End Function

    ''' <summary>The cluster: body <paramref name="seed"/> and, breadth first, every movable body touching one already in it.</summary>
    Private Sub Gather(seed As Integer)
        _members.Clear()
        _slotOf.Clear()
        _inverseMass.Clear()
        _velocity.Clear()
        _contacts.Clear()
        _against.Clear()
        _side.Clear()
        _support.Clear()
        _supportEdge.Clear()
        _pairs.Clear()
        If _neighbours.Length < _s.Bodies.Count Then
            _neighbours = New Integer(_s.Bodies.Count - 1) {}
            _clusteredAt = Enumerable.Repeat(Double.NaN, _s.Bodies.Count).ToArray()
            _clusterRun = New Integer(_s.Bodies.Count - 1) {}
        End If
        Join(seed)
        Dim head = 0
        While head < _members.Count
            Dim k = _members(head)
            If _inverseMass(head) > 0 Then Expand(k, head)
            head += 1
        End While
    End Sub

    ''' <summary>Whether body i gives way in a cluster (bodies asleep, dragged or sliding round a corner do not).</summary>
    Friend Function CanMove(i As Integer) As Boolean
        Dim mode = _s.Bodies.Mode(i)
        Return Not (mode = BodyMode.Sleeping OrElse mode = BodyMode.Dragged OrElse mode = BodyMode.Rounding) AndAlso _s.Bodies.Info(i).InverseMass > 0
    End Function

    ''' <summary>Adds body i to the cluster (at the clock) and returns its slot.</summary>
    Private Function Join(i As Integer) As Integer
        Dim slot As Integer
        If _slotOf.TryGetValue(i, slot) Then Return slot
        _s.Sync(i)
        Dim b = _s.Bodies
        slot = _members.Count
        _members.Add(i)
        _slotOf(i) = slot
        _inverseMass.Add(If(CanMove(i), b.Info(i).InverseMass, 0.0))
        _velocity.Add(New Vector(b.Motion(i).Vx, b.Motion(i).Vy))
        Return slot
    End Function

    ''' <summary>Body i's contacts (within a few touching tolerances): walls, obstacles and movable neighbours.</summary>
    Private Sub Expand(i As Integer, slot As Integer)
        Dim b = _s.Bodies
        Dim p = New Vector(b.Motion(i).Px, b.Motion(i).Py)
        Dim o = b.Outlines(i)
        Dim near = 4 * SolverState.SlopAt(p.X, p.Y)
        If _s.Walls Then
            If p.X + o.MinX <= near Then AddWorld(slot, New Vector(1, 0), Nothing, WallSide.Left, BodyTable.SupportNone, -1)
            If _s.Width - o.MaxX - p.X <= near Then AddWorld(slot, New Vector(-1, 0), Nothing, WallSide.Right, BodyTable.SupportNone, -1)
            If p.Y + o.MinY <= near Then AddWorld(slot, New Vector(0, 1), Nothing, WallSide.Bottom, BodyTable.SupportFloor, -1)
            If _s.Height - o.MaxY - p.Y <= near Then AddWorld(slot, New Vector(0, -1), Nothing, WallSide.Top, BodyTable.SupportNone, -1)
        End If
        Dim obstacles = _s.Obstacles
        For s = 0 To obstacles.Count - 1
            Dim c = ContactRules.OverlapWithObstacle(_s, i, s, p)
            If c.Depth < -near Then Continue For
            ' As a support: the face it lies on, or a rounded corner (holds only from right above).
            Dim shape = _s.Shapes.Difference(obstacles.Outlines(s), o)
            Dim first, second As Integer
            Dim faces = OutlineContact.TouchingEdges(shape, p - New Vector(obstacles.X0(s), obstacles.Y0(s)), near, first, second)
            If faces = 1 Then
                AddWorld(slot, c.Normal, obstacles.Shapes(s), WallSide.None, s, first)
            Else
                AddWorld(slot, c.Normal, obstacles.Shapes(s), WallSide.None, If(shape.Radius > 0, BodyTable.SupportBody, BodyTable.SupportNone), -1)
            End If
        Next
        Dim count = GridNeighbours.Collect(_s, i, _neighbours)
        For q = 0 To count - 1
            Dim j = _neighbours(q)
            If b.Mode(j) = BodyMode.Rounding Then Continue For
            Dim c = ContactRules.OverlapWithBody(_s, i, j, p, b.PositionAt(j, _s.Now))
            If c.Depth < -near Then Continue For
            Dim key = CLng(Math.Min(i, j)) * Integer.MaxValue + Math.Max(i, j)
            If Not _pairs.Add(key) Then Continue For
            If Not _slotOf.ContainsKey(j) AndAlso _members.Count >= MaxBodies Then Continue For
            Dim other = Join(j)
            _contacts.Add(New ClusterContact(slot, other, c.Normal))
            _against.Add(b.Shapes(j))
            _side.Add(WallSide.None)
            _support.Add(BodyTable.SupportBody)
            _supportEdge.Add(-1)
        Next
    End Sub

    Private Sub AddWorld(slot As Integer, normal As Vector, other As Shape, side As WallSide, support As Integer, edge As Integer)
        _contacts.Add(New ClusterContact(slot, ClusterContact.World, normal))
        _against.Add(other)
        _side.Add(side)
        _support.Add(support)
        _supportEdge.Add(edge)
    End Sub

    ''' <summary>
    ''' After the velocities are resolved, the resting rules for each body that now sits on something
    ''' that does not give way (the floor, an obstacle, a body asleep): a body pressed onto its support
    ''' by gravity alone, with no velocity into it, would otherwise be found "approaching" again at once.
    ''' The support that faces most nearly upwards is the one that counts.
    ''' </summary>
    Private Sub ApplyRestRules()
        Dim b = _s.Bodies
        For k = 0 To _members.Count - 1
            If _inverseMass(k) = 0 Then Continue For
            Dim i = _members(k)
            If b.Mode(i) <> BodyMode.Free Then Continue For
            Dim best = -1
            Dim bestUp = 0.0
            Dim immovableContacts = 0
            For c = 0 To _contacts.Count - 1
                Dim other = _contacts(c).BodyB
                Dim n = _contacts(c).Normal
                If _contacts(c).BodyA <> k OrElse Not (other = ClusterContact.World OrElse _inverseMass(other) = 0) Then Continue For
                immovableContacts += 1
                If n.Y > bestUp Then
                    best = c
                    bestUp = n.Y
                End If
            Next
            ' Wedged between several: a hop off one support would only drive it into another.
            If best < 0 OrElse (immovableContacts > 1 AndAlso bestUp < 1 - 1.0E-12) Then Continue For
            Dim s = If(_contacts(best).BodyB = ClusterContact.World, Vector.Zero, _velocity(_contacts(best).BodyB))
            _rest.AfterSupportContact(i, _contacts(best).Normal, _support(best), _supportEdge(best), s.X, s.Y)
            _s.Changed(i)
        Next
    End Sub

    ''' <summary>
    ''' Reports every contact that pushed as a collision. Each record shows what that contact's own
    ''' impulse J did (Δv = J n / m on each side), so every record conserves momentum, and a body's
    ''' records add up to its whole change of velocity in the cluster.
    ''' </summary>
    Private Sub Report(result As ClusterResolution)
        Dim b = _s.Bodies
        For c = 0 To _contacts.Count - 1
            Dim j = result.Impulses(c)
            If Not (j > 0) Then Continue For
            Dim a = _contacts(c).BodyA, other = _contacts(c).BodyB
            Dim n = _contacts(c).Normal
            Dim aBefore = _velocity(a)
            Dim aAfter = aBefore + n * (j * _inverseMass(a))
            Dim bBefore = Vector.Zero, bAfter = Vector.Zero
            If other <> ClusterContact.World Then
                bBefore = _velocity(other)
                bAfter = bBefore - n * (j * _inverseMass(other))
            End If
            Dim body = b.Shapes(_members(a))
            _s.World.ReportCollision(New CollisionRecord(_s.Now, body, _against(c), _side(c), CollisionKinds.Between(body, _against(c)),
                                                         aBefore, aAfter, bBefore, bAfter))
        Next
    End Sub
End Class
