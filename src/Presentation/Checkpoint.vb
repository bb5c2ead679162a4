Option Strict On

''' <summary>
''' One moment of a recorded run from which replay is exact: the run itself restarted its solver
''' here (see <see cref="TimelineSolver"/>), so a fresh solver on the same state does what the
''' first one did. Immutable.
''' </summary>
Public NotInheritable Class Checkpoint
    ''' <param name="time">simulated time, s</param>
    ''' <param name="scene">the world as a scene file (exact: every number round-trips)</param>
    ''' <param name="solverName">the solver that ran from here (event, euler or verlet)</param>
    ''' <param name="draggedId">the body carried by the engine here, or Nothing</param>
    ''' <param name="dragTarget">where that body was heading, m</param>
    ''' <param name="collisions">collisions counted since the run started, up to here</param>
    Public Sub New(time As Double, scene As String, solverName As String, draggedId As String, dragTarget As Vector, collisions As Long)
        Me.Time = time
        Me.Scene = scene
        Me.SolverName = solverName
        Me.DraggedId = draggedId
        Me.DragTarget = dragTarget
        Me.Collisions = collisions
    End Sub

    ''' <summary>Simulated time, s.</summary>
    Public ReadOnly Property Time As Double
    ''' <summary>The world as scene-file text.</summary>
    Public ReadOnly Property Scene As String
    ''' <summary>The solver that ran from here.</summary>
    Public ReadOnly Property SolverName As String
    ''' <summary>The body carried by the engine, or Nothing.</summary>
    Public ReadOnly Property DraggedId As String
    ''' <summary>Where the carried body was heading, m.</summary>
    Public ReadOnly Property DragTarget As Vector
    ''' <summary>Collisions counted since the run started.</summary>
    Public ReadOnly Property Collisions As Long

    ''' <summary>Whether a body was being carried: until the next checkpoint the run follows the mouse, which is not kept, so rewinding stops here.</summary>
    Public ReadOnly Property IsCarrying As Boolean
        Get
            Return DraggedId IsNot Nothing
        End Get
    End Property

    ''' <summary>Memory it holds, bytes: two per character of its scene, plus the object.</summary>
    Public ReadOnly Property Bytes As Long
        Get
            Return 2L * If(Scene, "").Length + 64
        End Get
    End Property
End Class
