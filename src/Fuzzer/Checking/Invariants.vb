Option Strict On

Namespace Checking
    ''' <summary>
    ''' The names of what must hold in every run, as failure lines and file names give them
    ''' ("overlap-1234.json").
    ''' </summary>
    Friend Module Invariants
        ''' <summary>Every movable body's position and velocity is finite (no NaN, no infinity). All solvers.</summary>
        Friend Const NotFinite As String = "not-finite"
        ''' <summary>With walls on, no movable body is outside the container by more than 1e-9 m. All solvers.</summary>
        Friend Const Outside As String = "outside"
        ''' <summary>No movable circle's centre is inside a fixed body (circle, rectangle). All solvers.</summary>
        Friend Const CentreInside As String = "centre-inside"
        ''' <summary>No two bodies that collide with each other overlap by more than 1e-9 m. Event solver.</summary>
        Friend Const Overlap As String = "overlap"
        ''' <summary>Kinetic plus potential energy never grows (e ≤ 1 always). Event solver.</summary>
        Friend Const Energy As String = "energy"
        ''' <summary>Two sampling intervals give the same collisions and the same final state, to the bit. Event solver.</summary>
        Friend Const Sampling As String = "sampling"
        ''' <summary>A run finishes within the wall-time cap. All solvers.</summary>
        Friend Const WallTime As String = "wall-time"
        ''' <summary>The solver threw (or the process running it died). All solvers.</summary>
        Friend Const Crash As String = "exception"

        ''' <summary>The scene reader refused a generated scene: a fault of the generator (or of the reader, when the scene follows the format).</summary>
        Friend Const Refused As String = "scene-refused"

        ''' <summary>Every name, in the order reports list them.</summary>
        Friend ReadOnly Property All As IReadOnlyList(Of String) = {NotFinite, Outside, CentreInside, Overlap, Energy, Sampling, WallTime, Crash, Refused}
    End Module
End Namespace
