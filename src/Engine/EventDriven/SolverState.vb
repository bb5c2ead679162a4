Option Strict On

''' <summary>
''' What every part of the event-driven solver shares: the world and the settings read from it, the
''' solver's clock, and the owners of its state (the movable bodies, the obstacles, the grid and the
''' queue). The parts (<see cref="Predictor"/>, <see cref="Responder"/>, <see cref="RestRules"/>,
''' <see cref="CornerSlides"/>) hold no state of their own beyond what they say they own.
''' </summary>
Friend NotInheritable Class SolverState
    Friend ReadOnly Bodies As New BodyTable()
    Friend ReadOnly Obstacles As New Obstacles()
    Friend ReadOnly Grid As New UniformGrid()
    Friend ReadOnly Queue As New EventQueue()
    ''' <summary>The pairs' Minkowski differences (see <see cref="ContactRules"/>).</summary>
    Friend ReadOnly Shapes As New ContactShapes()

    Friend World As World
    ''' <summary>The solver's clock, s (absolute, like World.Time).</summary>
    Friend Now As Double
    ''' <summary>g, m/s² (towards −y); e; the walls; the container, m.</summary>
    Friend G As Double
    Friend E As Double
    Friend Walls As Boolean
    Friend Width As Double
    Friend Height As Double
    ''' <summary>Largest reach (m) of a body in the grid from its reference point (a circle's radius).</summary>
    Friend RMax As Double
    ''' <summary>Bodies too big for the grid, checked against every body.</summary>
    Friend Oversized As Integer() = Array.Empty(Of Integer)()
    Friend OversizedCount As Integer

    ''' <summary>Grid cells searched for partners so far (see <see cref="EventDrivenSolver.CellsSearched"/>).</summary>
    Friend CellsSearched As Long

    ''' <summary>
    ''' Set by a rule that meets what the fast path cannot follow exactly (a jam of bodies in motion, see
    ''' Responder): the solver hands the world over to the general path of lasting contact once the event is
    ''' resolved (see <see cref="EventDrivenSolver"/>).
    ''' </summary>
    Friend HandOver As Boolean

    ''' <summary>
    ''' The most movable bodies a world may have for the fast path to hand it over: the general path works on
    ''' every pair of bodies, so a crowd keeps the fast path's own rules (a cluster resolved at once, a pile asleep).
    ''' </summary>
    Friend Const HandOverBodies As Integer = 16

    ''' <summary>
    ''' The most movable bodies a world may have for the fast path to hand it over when it would otherwise put a body
    ''' to sleep where nothing holds it (a ball wedged against a neighbour on a frictionless slope, see ClusterResponse).
    ''' Sleeping there is wrong at any size, but the general path integrates a pressed pile as one group: 60 balls
    ''' through a hopper take it seconds, a pile of 120 balls settling in a box minutes. Beyond this count the fast
    ''' path keeps its own rule, and a ball may sleep where nothing holds it.
    ''' </summary>
    Friend Const HandOverUnheldBodies As Integer = 64

    ''' <summary>
    ''' Whether the world may be handed over when a body would sleep where nothing holds it: it has at most
    ''' <see cref="HandOverUnheldBodies"/> movable bodies. Asked before anything asks whether a wedged body is held.
    ''' Their masses may be any distance apart: among masses 10⁶ and more apart the general path measures its step
    ''' error only in what the contacts leave free (docs/links.md, "Bodies of very different masses").
    ''' </summary>
    Friend Function MayHandOverUnheld() As Boolean
        Return Bodies.Count <= HandOverUnheldBodies
    End Function

    ''' <summary>Asks for the hand-over (<see cref="HandOver"/>); whether it will happen (only in a world of at most <paramref name="most"/> bodies).</summary>
    Friend Function TryHandOver(Optional most As Integer = HandOverBodies) As Boolean
        If Bodies.Count > most Then Return False
        HandOver = True
        Return True
    End Function

    ''' <summary>The bodies an event changed, to be rescheduled once it is resolved (each once, in the order they changed).</summary>
    Friend ReadOnly Touched As New TouchedList()

    ''' <summary>Touching tolerance relative to the coordinates involved: 10⁻¹² of them, and never below 10⁻¹² m.</summary>
    Friend Const SlopFraction As Double = 1.0E-12

    ''' <summary>
    ''' Distance (m) within which bodies at (x, y) count as touching: rounding, never physics. It is
    ''' local, because rounding is: a coordinate of 10⁶ m carries errors a million times those of one
    ''' of 1 m, and a container 10¹² m wide says nothing about a ball bouncing on its floor.
    ''' </summary>
    Friend Shared Function SlopAt(x As Double, y As Double) As Double
        Return SlopFraction * Math.Max(1.0, Math.Max(Math.Abs(x), Math.Abs(y)))
    End Function

    ''' <summary>Like <see cref="SlopAt"/>, for a gap measured along one axis from coordinate v (m).</summary>
    Friend Shared Function SlopAlong(v As Double) As Double
        Return SlopFraction * Math.Max(1.0, Math.Abs(v))
    End Function

    ''' <summary>The touching tolerance (m) for body i where it is now.</summary>
    Friend Function SlopOf(i As Integer) As Double
        Return SlopAt(Bodies.Motion(i).Px, Bodies.Motion(i).Py)
    End Function

    ''' <summary>
    ''' Body i's motion changed: predictions made with its old motion become stale (its counter), its
    ''' lane shows the new motion at once (before anything is predicted against it), and it is
    ''' rescheduled when the event is resolved.
    ''' </summary>
    Friend Sub Changed(i As Integer)
        Bodies.Slot(i).Count += 1
        Publish(i)
        Touched.Add(i)
    End Sub

    ''' <summary>Copies body i's motion and next collision time into its grid lane (see UniformGrid).</summary>
    Friend Sub Publish(i As Integer)
        Grid.Publish(i, Bodies.Motion(i), Bodies.Slot(i).ColTime)
    End Sub

    ''' <summary>Moves body i's reference point to the clock, exactly along its path (not while it slides round a corner).</summary>
    Friend Sub Sync(i As Integer)
        If SyncUnpublished(i) Then Publish(i)
    End Sub

    ''' <summary>
    ''' As <see cref="Sync"/>, without publishing: for a collision that ends in <see cref="Changed"/>
    ''' (which publishes), so that each body's lane is written once. Its lane lags until then, so
    ''' nothing may scan the lanes in between. Whether the body moved.
    ''' </summary>
    Friend Function SyncUnpublished(i As Integer) As Boolean
        If Now = Bodies.Motion(i).T0 OrElse Bodies.Slot(i).Mode = BodyMode.Rounding Then Return False
        Bodies.Motion(i).MoveTo(Now)
        Return True
    End Function

    ''' <summary>Moves gridded body i to the cell at (col, row), if it is not there already, and publishes it there.</summary>
    Friend Sub MoveToCell(i As Integer, col As Integer, row As Integer)
        Dim cell = row * Grid.Nx + col
        If cell = Bodies.Slot(i).Cell Then Return
        Dim pulled = Grid.Remove(i, Bodies.Slot(i).Cell)
        If pulled >= 0 Then Publish(pulled)
        Grid.Insert(i, cell)
        Bodies.Slot(i).Cell = cell
        Bodies.Slot(i).Col = col
        Bodies.Slot(i).Row = row
        Publish(i)
    End Sub

    Private _everyObstacle As Integer() = Array.Empty(Of Integer)()

    ''' <summary>
    ''' The obstacles body i could be touching where it is now: the returned array's items first … last.
    ''' A gridded body's cell lists every obstacle within half a cell of it, which covers every contact;
    ''' a body outside the grid (too large for it, or roaming) is given them all.
    ''' </summary>
    Friend Function ObstaclesNear(i As Integer, ByRef first As Integer, ByRef last As Integer) As Integer()
        Dim c = Bodies.Slot(i).Cell
        If c >= 0 Then
            first = Grid.StaticStart(c)
            last = Grid.StaticStart(c + 1) - 1
            Return Grid.StaticItems
        End If
        If _everyObstacle.Length <> Obstacles.Count Then _everyObstacle = Enumerable.Range(0, Obstacles.Count).ToArray()
        first = 0
        last = Obstacles.Count - 1
        Return _everyObstacle
    End Function

    ''' <summary>
    ''' Body i leaves the grid for a while: it is about to slide along an arc that can take it further
    ''' than the cells around it are searched, so, like a body too large for the grid, it is checked
    ''' against every body and every body against it until <see cref="StopRoaming"/>.
    ''' </summary>
    Friend Sub Roam(i As Integer)
        Dim cell = Bodies.Slot(i).Cell
        If cell < 0 Then Return
        Dim pulled = Grid.Remove(i, cell)
        If pulled >= 0 Then Publish(pulled)
        Bodies.Slot(i).Cell = -1
        Bodies.Roaming(i) = True
        Oversized(OversizedCount) = i
        OversizedCount += 1
    End Sub

    ''' <summary>Body i, roaming (see <see cref="Roam"/>), goes back into the grid at the cell its reference point is in now.</summary>
    Friend Sub StopRoaming(i As Integer)
        If Not Bodies.Roaming(i) Then Return
        Bodies.Roaming(i) = False
        Dim k = Array.IndexOf(Oversized, i, 0, OversizedCount)
        Oversized(k) = Oversized(OversizedCount - 1)
        OversizedCount -= 1
        Dim col = Grid.ColumnOf(Bodies.Motion(i).Px), row = Grid.RowOf(Bodies.Motion(i).Py)
        Dim cell = row * Grid.Nx + col
        Grid.Insert(i, cell)
        Bodies.Slot(i).Cell = cell
        Bodies.Slot(i).Col = col
        Bodies.Slot(i).Row = row
        Publish(i)
    End Sub

    ''' <summary>Moves gridded body i to the cell its reference point is in now.</summary>
    Friend Sub MoveToCellOfPosition(i As Integer)
        If Bodies.Slot(i).Cell < 0 Then Return
        MoveToCell(i, Grid.ColumnOf(Bodies.Motion(i).Px), Grid.RowOf(Bodies.Motion(i).Py))
    End Sub
End Class
