Option Strict On
Imports System.Diagnostics
Imports System.Globalization

''' <summary>
''' Measures one case (scene × solver × time step): one run for the error, one warm-up run, then
''' several timed runs of which the median is reported. Every run starts from a freshly built scene.
''' A settling scene's timed runs stop when its pile is at rest (see <see cref="ISettlingScene"/>).
''' </summary>
Friend Module SceneRunner
    ''' <summary>Simulated seconds between two looks at the wall clock during a timed run.</summary>
    Private Const Chunk As Double = 0.1

    ''' <summary>How often the event solver's state is sampled by scenes that sample, s.</summary>
    Public Const EventSampleStep As Double = 0.001

    ''' <summary>
    ''' Makes the named solver, or returns Nothing when SolverFactory does not know it (a solver that is
    ''' not in this build is reported, not fatal).
    ''' </summary>
    Public Function TryCreateSolver(name As String, timeStep As Double?) As ISolver
        Try
            Return SolverFactory.Create(name, timeStep)
        Catch ex As ArgumentException
            Return Nothing
        End Try
    End Function

    ''' <summary>A result row for a solver that this build does not have.</summary>
    Public Function NotAvailable(scene As String, solver As String, timeStep As Double?, note As String) As BenchResult
        Return New BenchResult With {.Scene = scene, .Solver = solver, .TimeStep = timeStep, .Available = False, .Note = note}
    End Function

    ''' <summary>
    ''' Runs the case. <paramref name="budgetSeconds"/> bounds the wall-clock time of the whole case:
    ''' a run that would exceed it is cut short and the cost reported from what was simulated.
    ''' </summary>
    Public Function Run(scene As IBenchScene, solverName As String, timeStep As Double?, repeats As Integer, budgetSeconds As Double) As BenchResult
        If scene Is Nothing Then Throw New ArgumentNullException(NameOf(scene))
        Dim probe = TryCreateSolver(solverName, timeStep)
        If probe Is Nothing Then Return NotAvailable(scene.Name, solverName, timeStep, "not available in this build")
        Dim result As New BenchResult With {
            .Scene = scene.Name, .Solver = solverName, .TimeStep = timeStep, .ErrorMetric = scene.ErrorMetric,
            .SimulatedSeconds = scene.SimulatedSeconds}
        Dim clock = Stopwatch.StartNew()

        ' The error run: scenes may look at the state as often as the solver has one.
        Dim world = scene.Build()
        world.Solver = SolverFactory.Create(solverName, timeStep)
        result.BodyCount = If(TypeOf scene Is ISettlingScene, world.Movables.Count, world.Circles.Count)
        Dim measured = scene.Measure(world, If(world.Solver.TimeStep, EventSampleStep), New RunBudget(budgetSeconds))
        result.Error = measured.Error
        result.Note = measured.Note
        ' A run the budget stopped has no error to report, and timing it again would only repeat that.
        If Not measured.Completed Then Return result

        ' Warm-up, then the timed runs; fewer of them when one run is slow, so the case fits its budget.
        Dim warm = TimedRun(scene, solverName, timeStep, budgetSeconds - clock.Elapsed.TotalSeconds)
        Dim times As New List(Of Double)
        Dim restWalls As New List(Of Double)
        Dim collisions = warm.Collisions
        Dim simulated = warm.Simulated
        Dim settling = TryCast(scene, ISettlingScene)
        Dim runs = If(warm.Complete, repeats, 0)
        ' A run of a second or more is steady enough that three make a good median.
        If warm.WallSeconds >= 1 Then runs = Math.Min(runs, 3)
        For k = 1 To runs
            Dim left = budgetSeconds - clock.Elapsed.TotalSeconds
            If k > 1 AndAlso left < warm.WallSeconds * 1.5 Then Exit For
            Dim r = TimedRun(scene, solverName, timeStep, left)
            times.Add(r.WallSeconds * 1000 / r.Simulated)
            If Not Double.IsNaN(r.RestTime) Then restWalls.Add(r.WallSeconds * 1000)
            collisions = r.Collisions
            simulated = r.Simulated
            If Not r.Complete Then Exit For
        Next
        If settling IsNot Nothing Then
            ' Every run of a settling scene comes to rest at the same simulated time (the runs are the same
            ' computation); the warm-up run's says whether it did.
            result.RestSeconds = warm.RestTime
            If restWalls.Count > 0 Then result.RestWallMs = Statistics.Median(restWalls)
        End If
        If times.Count = 0 Then
            ' Even one run did not fit: report the warm-up run's rate, and say so.
            times.Add(warm.WallSeconds * 1000 / Math.Max(warm.Simulated, 1.0E-12))
            result.Note = Join(result.Note, "cut short: " & warm.Simulated.ToString("0.###", CultureInfo.InvariantCulture) &
                               " s simulated in " & warm.WallSeconds.ToString("0.#", CultureInfo.InvariantCulture) & " s (budget)")
        End If
        result.Runs = times.Count
        result.MsPerSimulatedSecond = Statistics.Median(times)
        If TypeOf scene Is IRealTimeScene AndAlso result.MsPerSimulatedSecond > 0 Then
            result.Note = Join(result.Note, (1000 / result.MsPerSimulatedSecond).ToString("0.#", CultureInfo.InvariantCulture) & "× real time")
        End If
        Dim wallPerRun = result.MsPerSimulatedSecond * simulated / 1000
        If wallPerRun > 0 Then result.CollisionsPerSecond = collisions / wallPerRun
        If collisions > 0 Then result.MicrosecondsPerCollision = wallPerRun * 1000000.0 / collisions
        Return result
    End Function

    Private Function Join(a As String, b As String) As String
        If String.IsNullOrEmpty(a) Then Return b
        Return a & "; " & b
    End Function

    Private Structure RunTiming
        Public WallSeconds As Double
        Public Simulated As Double
        Public Collisions As Long
        ''' <summary>A settling scene's simulated time at rest (s), where the run stopped; NaN otherwise.</summary>
        Public RestTime As Double
        ''' <summary>True when the run reached its end: the scene's simulated seconds, or rest.</summary>
        Public Complete As Boolean
    End Structure

    Private Function TimedRun(scene As IBenchScene, solverName As String, timeStep As Double?, budgetSeconds As Double) As RunTiming
        Dim world = scene.Build()
        world.Solver = SolverFactory.Create(solverName, timeStep)
        GC.Collect()
        GC.WaitForPendingFinalizers()
        GC.Collect()
        Dim budget As New RunBudget(budgetSeconds)
        Dim slice = Sampling.SliceOf(If(timeStep, EventSampleStep), Chunk)
        Dim settling = TryCast(scene, ISettlingScene)
        Dim restTime = Double.NaN
        Dim clock = Stopwatch.StartNew()
        If settling IsNot Nothing Then
            ' A settling scene's run ends when the pile is at rest: the time that takes is what it measures.
            restTime = settling.RunToRest(world, budget)
        Else
            Sampling.Run(world, scene.SimulatedSeconds, slice, Function(t) True, budget)
        End If
        clock.Stop()
        Return New RunTiming With {.WallSeconds = clock.Elapsed.TotalSeconds, .Simulated = world.Time, .Collisions = world.CollisionCount,
                                   .RestTime = restTime, .Complete = Not Double.IsNaN(restTime) OrElse world.Time >= scene.SimulatedSeconds - 1.0E-9}
    End Function
End Module
