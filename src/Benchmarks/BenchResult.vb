Option Strict On

''' <summary>
''' One measured case: a scene run by one solver at one time step. The same shape goes to the JSON
''' file, the markdown tables and the plots, and between a child process and its parent.
''' </summary>
Friend NotInheritable Class BenchResult
    ''' <summary>Scene name, e.g. "bouncing-apex" or "gas-scaling".</summary>
    Public Property Scene As String

    ''' <summary>Solver name as SolverFactory spells it: event, euler, verlet.</summary>
    Public Property Solver As String

    ''' <summary>Time step, s; Nothing for the event-driven solver (and for a solver that is not available).</summary>
    Public Property TimeStep As Double?

    ''' <summary>False when SolverFactory does not know the solver, or the run failed or timed out.</summary>
    Public Property Available As Boolean = True

    ''' <summary>Error against the closed form, in the unit <see cref="ErrorMetric"/> names; NaN when not measured.</summary>
    Public Property [Error] As Double = Double.NaN

    ''' <summary>What <see cref="[Error]"/> measures, with its unit, e.g. "max apex error (m)".</summary>
    Public Property ErrorMetric As String = ""

    ''' <summary>Wall-clock milliseconds per simulated second (median of the timed runs).</summary>
    Public Property MsPerSimulatedSecond As Double = Double.NaN

    ''' <summary>Collisions reported per wall-clock second during the timed runs.</summary>
    Public Property CollisionsPerSecond As Double = Double.NaN

    ''' <summary>Wall-clock microseconds per reported collision.</summary>
    Public Property MicrosecondsPerCollision As Double = Double.NaN

    ''' <summary>Number of bodies in the scene.</summary>
    Public Property BodyCount As Integer

    ''' <summary>Peak working set of the process that ran this case, MB; NaN when not measured per run.</summary>
    Public Property PeakMegabytes As Double = Double.NaN

    ''' <summary>Simulated seconds per timed run.</summary>
    Public Property SimulatedSeconds As Double = Double.NaN

    ''' <summary>How many timed runs the median is over.</summary>
    Public Property Runs As Integer

    ''' <summary>
    ''' How many separate runs of the whole case this row is the median of (the gas scaling runs each
    ''' size in several rounds); 1 for a single run.
    ''' </summary>
    Public Property Rounds As Integer = 1

    ''' <summary>The slowest and fastest of those runs, collisions per wall-clock second; NaN for a single run.</summary>
    Public Property SlowestCollisionsPerSecond As Double = Double.NaN
    Public Property FastestCollisionsPerSecond As Double = Double.NaN

    ''' <summary>A settling scene's simulated time at rest, s; NaN when it did not settle or is not such a scene.</summary>
    Public Property RestSeconds As Double = Double.NaN

    ''' <summary>Wall-clock milliseconds a run took to bring that scene to rest (median of the timed runs); NaN when it did not.</summary>
    Public Property RestWallMs As Double = Double.NaN

    ''' <summary>Anything a reader needs to know: why it is not available, a secondary figure, a warning.</summary>
    Public Property Note As String = ""
End Class
