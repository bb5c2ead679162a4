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
        ''' <summary>
        ''' A run finishes within the wall-time cap, or (event solver) is still doing physics at the engine's
        ''' rate when it reaches it (see <see cref="Heavy"/>). All solvers.
        ''' </summary>
        Friend Const WallTime As String = "wall-time"
        ''' <summary>The solver threw (or the process running it died). All solvers.</summary>
        Friend Const Crash As String = "exception"

        ''' <summary>The scene reader refused a generated scene: a fault of the generator (or of the reader, when the scene follows the format).</summary>
        Friend Const Refused As String = "scene-refused"

        ''' <summary>
        ''' Not a failure: an event-solver run that reached the wall-time cap while still doing physics at the
        ''' engine's rate (at least <see cref="HeavyCollisionRate"/> collisions per wall-clock second, at most
        ''' <see cref="HeavyEventsPerCollision"/> events per collision, and at most <see cref="HeavyRepeatFraction"/>
        ''' of its collisions at the instant of the one before). A scene can need millions of collisions per
        ''' simulated second (a microgram ball heated by heavy ones to 10⁴ m/s crosses its box 10⁵ times a
        ''' second); a runaway spins on events that are not collisions, or on collisions at one instant. The run
        ''' stops there and is reported as heavy, with its figures.
        ''' </summary>
        Friend Const Heavy As String = "heavy"
        ''' <summary>
        ''' The solver refused the scene (<see cref="UnsupportedSceneException"/>): every solver takes every scene the
        ''' reader takes, so a refusal is a failure. The run stops there.
        ''' </summary>
        Friend Const SolverRefused As String = "solver-refused"

        ''' <summary>
        ''' Not a failure: a stepping-solver run that blew up (a thrown exception, or positions or velocities no
        ''' longer finite) in a scene with a spring beyond the method's stability limit, ω h ≥ 2 (see
        ''' <see cref="StepStability"/>). No explicit step of that size can follow the spring. The run stops there and
        ''' is reported as unstable, with the spring's figures; the same outcome with every spring within the limit
        ''' is still a failure.
        ''' </summary>
        Friend Const Unstable As String = "unstable"

        ''' <summary>Collisions per wall-clock second a heavy run keeps up at least: a tenth of the gas's rate.</summary>
        Friend Const HeavyCollisionRate As Double = 100000.0
        ''' <summary>Solver events per collision a heavy run makes at most (the gas makes about 1.3).</summary>
        Friend Const HeavyEventsPerCollision As Double = 3.0
        ''' <summary>Fraction of a heavy run's collisions at the same instant as the collision before, at most.</summary>
        Friend Const HeavyRepeatFraction As Double = 0.01

        ''' <summary>Every name, in the order reports list them.</summary>
        Friend ReadOnly Property All As IReadOnlyList(Of String) = {NotFinite, Outside, CentreInside, Overlap, Energy, Sampling, WallTime, Crash, Refused, SolverRefused}
    End Module
End Namespace
