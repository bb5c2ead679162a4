Option Strict On
Imports System.Diagnostics
Imports System.Globalization

''' <summary>
''' Measures one case (scene × solver × time step): one run for the error, one warm-up run, then
''' several timed runs of which the median is reported. Every run starts from a freshly built scene.
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
        result.BodyCount = world.Circles.Count
        Dim measured = scene.Measure(world, If(world.Solver.TimeStep, EventSampleStep), New RunBudget(budgetSeconds))
        result.Error = measured.Error
        result.Note = measured.Note
        ' A run the budget stopped has no error to report, and timing it again would only repeat that.
        If Not measured.Completed Then Return result

        ' Warm-up, then the timed runs; fewer of them when one run is slow, so the case fits its budget.
        Dim warm = TimedRun(scene, solverName, timeStep, budgetSeconds - clock.Elapsed.TotalSeconds)
        Dim times As New List(Of Double)
        Dim collisions = warm.Collisions
        Dim simulated = warm.Simulated
        Dim runs = If(warm.Simulated < scene.SimulatedSeconds - 1.0E-9, 0, repeats)
        ' A run of a second or more is steady enough that three make a good median.
        If warm.WallSeconds >= 1 Then runs = Math.Min(runs, 3)
        For k = 1 To runs
            Dim left = budgetSeconds - clock.Elapsed.TotalSeconds
            If k > 1 AndAlso left < warm.WallSeconds * 1.5 Then Exit For
            Dim r = TimedRun(scene, solverName, timeStep, left)
            times.Add(r.WallSeconds * 1000 / r.Simulated)
            collisions = r.Collisions
            simulated = r.Simulated
            If r.Simulated < scene.SimulatedSeconds - 1.0E-9 Then Exit For
        Next
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
    End Structure

    Private Function TimedRun(scene As IBenchScene, solverName As String, timeStep As Double?, budgetSeconds As Double) As RunTiming
        Dim world = scene.Build()
        world.Solver = SolverFactory.Create(solverName, timeStep)
        GC.Collect()
        GC.WaitForPendingFinalizers()
        GC.Collect()
        Dim budget As New RunBudget(budgetSeconds)
        Dim slice = Sampling.SliceOf(If(timeStep, EventSampleStep), Chunk)
        Dim clock = Stopwatch.StartNew()
        Sampling.Run(world, scene.SimulatedSeconds, slice, Function(t) True, budget)
        clock.Stop()
        Return New RunTiming With {.WallSeconds = clock.Elapsed.TotalSeconds, .Simulated = world.Time, .Collisions = world.CollisionCount}
    End Function
End Module
