Option Strict On

''' <summary>
''' Moves a <see cref="World"/> forward in time. The event-driven solver and the stepping solvers
''' (semi-implicit Euler, position Verlet) all drive the same model through this interface.
''' </summary>
Public Interface ISolver
    ''' <summary>The name the command line uses: event, euler or verlet.</summary>
    ReadOnly Property Name As String

    ''' <summary>Time step of a stepping solver, s; Nothing for the event-driven solver.</summary>
    ReadOnly Property TimeStep As Double?

    ''' <summary>Called once when the solver is given to a world.</summary>
    Sub Attach(world As World)

    ''' <summary>
    ''' Advances the world by exactly <paramref name="duration"/> seconds, leaving every body's state at that
    ''' exact time, and reports each collision through <see cref="World.ReportCollision"/>.
    ''' </summary>
    Sub Advance(duration As Double)

    ''' <summary>
    ''' Like <see cref="Advance"/>, but stops early, between two events or steps, once the wall clock
    ''' (<see cref="Diagnostics.Stopwatch.GetTimestamp"/>) passes <paramref name="deadline"/>: for a
    ''' window that must stay responsive. Returns the simulated time (s, absolute like
    ''' <see cref="World.Time"/>) the world has reached, with every body's state exact at that time.
    ''' Stopping early never changes the run: what follows is what an uninterrupted advance would do.
    ''' </summary>
    Function AdvanceWithin(duration As Double, deadline As Long) As Double

    ''' <summary>
    ''' Something changed outside the solver: <paramref name="body"/> was added, removed, moved, pushed,
    ''' dragged or released; Nothing means the world itself changed (g, e, walls, size), so every
    ''' prediction must be rebuilt.
    ''' </summary>
    Sub Invalidate(body As Shape)
End Interface
