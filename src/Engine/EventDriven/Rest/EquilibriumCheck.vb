Option Strict On

''' <summary>
''' Whether a body may go to sleep where it is (docs/event-driven.md §6): only where the frictionless contact
''' forces can hold it at rest. The body and the still bodies it touches (resting or free with no speed at this
''' instant), and the still bodies those touch, and so on, form its cluster; walls, fixed bodies and sleeping
''' bodies hold without moving, as they do in the solver until something wakes them.
''' Each body of the cluster is pulled down by gravity, (0, −g), and each contact can only push, along its
''' normal. The complementarity solve of those forces (<see cref="ContactSolve"/>: every contact pushes and
''' never pulls, and one that pushes does not open) gives each body's acceleration; the cluster is held when
''' every acceleration is zero, to within what the solver counts as level. A ball off the centre of a peg's
''' top, or across a gap on two balls that would be pushed apart, is not held: it slides, and so do they.
''' Bodies that move (free, sliding round a corner, carried by hand) hold nothing.
''' </summary>
Friend NotInheritable Class EquilibriumCheck
    Private ReadOnly _s As SolverState
    Private ReadOnly _solve As New ContactSolve()

    ''' <summary>At most this many bodies form a cluster; still bodies beyond them hold as fixed bodies do.</summary>
    Friend Const MaxBodies As Integer = 32

    ' The cluster: its bodies (solver numbers; slot 0 is the body asked about) and the contact rows between them.
    Private ReadOnly _members As New List(Of Integer)
    Private ReadOnly _inverseMass As New List(Of Double)
    Private ReadOnly _free As New List(Of Vector)
    Private ReadOnly _rows As New List(Of ContactRow)
    Private _slotOf As Integer() = Array.Empty(Of Integer)()
    Private _neighbours As Integer() = Array.Empty(Of Integer)()
    Private _result As Vector() = Array.Empty(Of Vector)()
    Private _forces As Double() = Array.Empty(Of Double)()
    ' Whether the sleeping bodies the asked body touches join the cluster as movable bodies (Holds' sleepersMove).
    Private _sleepersMove As Boolean
    ' Normals of the asked body's own contacts (the quick first test).
    Private ReadOnly _ownNormals As New List(Of Vector)

    Friend Sub New(state As SolverState)
        _s = state
    End Sub

    ''' <summary>
    ''' The largest acceleration (m/s²) that counts as none: what gravity pulls along a face the solver counts
    ''' as level (its normal within <see cref="RestingFaces.LevelCosine"/> of vertical), g √(2 (1 − cos θ)) ≈ 1.4·10⁻⁶ g.
    ''' </summary>
    Friend Function RestingAcceleration() As Double
        Return _s.G * Math.Sqrt(2 * (1 - RestingFaces.LevelCosine))
    End Function

    ''' <summary>
    ''' Whether body k is at rest now, so that it holds what rests on it as much as it is held itself: asleep,
    ''' or resting or free with no velocity at this instant (a body just stopped). Bodies sliding round a
    ''' corner or carried by hand never are.
    ''' </summary>
    Friend Function IsAtRest(k As Integer) As Boolean
        Dim b = _s.Bodies
        Select Case b.Mode(k)
            Case BodyMode.Sleeping
                Return True
            Case BodyMode.Free, BodyMode.Supported
                Dim x, y, vx, vy As Double
                b.Motion(k).StateAt(_s.Now, x, y, vx, vy)
                Return vx = 0 AndAlso vy = 0
            Case Else
                Return False
        End Select
    End Function

    ''' <summary>
    ''' Whether body i, brought to rest where it is now, would be held there with its cluster of bodies at rest.
    ''' With <paramref name="sleepersMove"/>, the sleeping bodies body i touches join the cluster as movable bodies
    ''' too (those they touch in turn still hold as fixed ones): a ball asleep on a frictionless floor holds up what
    ''' leans on it only if something holds it from the side.
    ''' </summary>
    Friend Function Holds(i As Integer, Optional quick As Boolean = True, Optional sleepersMove As Boolean = False) As Boolean
        If _s.G = 0 Then Return True
        _sleepersMove = sleepersMove
        If quick AndAlso Not HeldByItsOwnContacts(i) Then Return False
        Gather(i)
        For Each k In _members
            _slotOf(k) = -1
        Next
        Dim n = _members.Count
        If _result.Length < n Then _result = New Vector(Math.Max(n, 2 * _result.Length) - 1) {}
        If _forces.Length < _rows.Count Then _forces = New Double(Math.Max(_rows.Count, 2 * _forces.Length) - 1) {}
        _solve.Solve(_inverseMass, _free, _rows, ContactSolve.ApproachTolerance * _s.G, _result, _forces)
        Dim limit = RestingAcceleration()
        For k = 0 To n - 1
            If Not (_result(k).Length <= limit) Then Return False
        Next
        Return True
    End Function

    ''' <summary>
    ''' A quick necessary test: body i alone, with everything it touches held still, can be held only if the
    ''' upward vertical lies among its contact normals (one level, or two either side of the vertical).
    ''' </summary>
    Private Function HeldByItsOwnContacts(i As Integer) As Boolean
        _ownNormals.Clear()
        CollectContacts(i, Nothing)
        Dim count = _ownNormals.Count
        For a = 0 To count - 1
            If _ownNormals(a).Y >= RestingFaces.LevelCosine Then Return True
            For k = a + 1 To count - 1
                If RestingFaces.HoldsUp(_ownNormals(a), _ownNormals(k)) Then Return True
            Next
        Next
        Return False
    End Function

    ''' <summary>The cluster: body i and, breadth first, every still body touching one already in it (up to <see cref="MaxBodies"/>).</summary>
    Private Sub Gather(i As Integer)
        Dim total = _s.Bodies.Count
        If _slotOf.Length < total Then
            _slotOf = Enumerable.Repeat(-1, total).ToArray()
            _neighbours = New Integer(total - 1) {}
        End If
        _members.Clear()
        _inverseMass.Clear()
        _free.Clear()
        _rows.Clear()
        Join(i)
        Dim head = 0
        While head < _members.Count
            CollectContacts(_members(head), head)
            head += 1
        End While
    End Sub

    Private Sub Join(k As Integer)
        _slotOf(k) = _members.Count
        _members.Add(k)
        _inverseMass.Add(_s.Bodies.Info(k).InverseMass)
        _free.Add(New Vector(0, -_s.G))
    End Sub

    ''' <summary>
    ''' Body k's contacts (within 10⁻³ of its size: a settled pile is held a little loosely): with
    ''' <paramref name="slot"/> Nothing, their normals go to the quick test (still bodies as fixed); otherwise
    ''' they become rows of the cluster's solve, still bodies not yet in it joining it.
    ''' </summary>
    Private Sub CollectContacts(k As Integer, slot As Integer?)
        Dim b = _s.Bodies
        Dim p = b.PositionAt(k, _s.Now)
        Dim o = b.Outlines(k)
        Dim gap = 1.0E-3 * b.Size(k).Scale + SolverState.SlopAt(p.X, p.Y)
        If _s.Walls Then
            If p.X + o.MinX <= gap Then AddFixed(slot, New Vector(1, 0))
            If _s.Width - o.MaxX - p.X <= gap Then AddFixed(slot, New Vector(-1, 0))
            If p.Y + o.MinY <= gap Then AddFixed(slot, New Vector(0, 1))
            If _s.Height - o.MaxY - p.Y <= gap Then AddFixed(slot, New Vector(0, -1))
        End If
        Dim firstNear, lastNear As Integer
        Dim near = _s.ObstaclesNear(k, firstNear, lastNear)
        For q = firstNear To lastNear
            Dim c = ContactRules.OverlapWithObstacle(_s, k, near(q), p)
            If c.Depth >= -gap Then AddFixed(slot, c.Normal)
        Next
        If _neighbours.Length < b.Count Then _neighbours = New Integer(b.Count - 1) {}
        Dim count = GridNeighbours.Collect(_s, k, _neighbours)
        For q = 0 To count - 1
            Dim j = _neighbours(q)
            If Not IsAtRest(j) Then Continue For
            Dim pj = b.PositionAt(j, _s.Now)
            ' The same for the pair seen from either side, so that a row is found from both or from neither.
            Dim pairGap = 1.0E-3 * Math.Max(b.Size(k).Scale, b.Size(j).Scale) + Math.Max(SolverState.SlopAt(p.X, p.Y), SolverState.SlopAt(pj.X, pj.Y))
            Dim c = ContactRules.OverlapWithBody(_s, k, j, p, pj)
            If c.Depth < -pairGap Then Continue For
            If b.Mode(j) = BodyMode.Sleeping AndAlso Not (_sleepersMove AndAlso slot.HasValue AndAlso slot.Value = 0) Then
                AddFixed(slot, c.Normal)
                Continue For
            End If
            If Not slot.HasValue Then
                _ownNormals.Add(c.Normal)
                Continue For
            End If
            Dim other = _slotOf(j)
            If other >= 0 AndAlso other < slot.Value Then Continue For ' its row was added when j was expanded
            If other < 0 AndAlso _members.Count < MaxBodies Then
                Join(j)
                other = _slotOf(j)
            End If
            _rows.Add(New ContactRow(slot.Value, If(other >= 0, other, ContactRow.None), c.Normal, 0, False))
        Next
    End Sub

    Private Sub AddFixed(slot As Integer?, normal As Vector)
        If slot.HasValue Then
            _rows.Add(New ContactRow(slot.Value, ContactRow.None, normal, 0, False))
        Else
            _ownNormals.Add(normal)
        End If
    End Sub
End Class
