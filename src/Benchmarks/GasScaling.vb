Option Strict On
Imports System.Diagnostics
Imports System.Globalization

''' <summary>
''' The elastic gas at growing N and a fixed packing fraction: ms per simulated second, collisions per
''' wall-clock second, µs per collision (flat when the cost per event does not grow with N) and peak
''' memory; for the event solver also the work counts behind them (events per collision, grid cells
''' searched per event), which show whether a growth in time is work or memory. Each N runs in its
''' own child process so the peak working set belongs to that run alone.
''' </summary>
Friend Module GasScaling
    ''' <summary>Scene name of the scaling rows.</summary>
    Public Const SceneName As String = "gas-scaling"

    ''' <summary>Solver name of the textbook baseline's rows (see <see cref="TextbookGas"/>): not an engine solver.</summary>
    Public Const TextbookName As String = "textbook"

    ''' <summary>The time step the stepping solvers run the gas at, s: one everyday step.</summary>
    Public Const SteppingTimeStep As Double = 0.001

    ''' <summary>
    ''' Whether the gas can run with <paramref name="solverName"/> in this build (the textbook baseline
    ''' always can), and at which time step: <see cref="SteppingTimeStep"/> for a stepping solver,
    ''' Nothing for the event solver and the baseline, which have none.
    ''' </summary>
    Public Function TimeStepFor(solverName As String) As (Available As Boolean, TimeStep As Double?)
        If solverName = TextbookName Then Return (True, Nothing)
        Dim probe = SceneRunner.TryCreateSolver(solverName, SteppingTimeStep)
        If probe Is Nothing Then Return (False, Nothing)
        Return (True, If(probe.TimeStep.HasValue, CType(SteppingTimeStep, Double?), Nothing))
    End Function

    ''' <summary>
    ''' The solvers the gas runs with: those asked for, and after the event solver the textbook
    ''' baseline, which shows what this machine gives for the same work done plainly.
    ''' </summary>
    Public Function SolversFor(solvers As IEnumerable(Of String)) As List(Of String)
        Dim list As New List(Of String)
        For Each s In solvers
            list.Add(s)
            If s = "event" Then list.Add(TextbookName)
        Next
        Return list.Distinct().ToList()
    End Function

    ''' <summary>
    ''' The gas children run with .NET's default settings: tiered compilation, which recompiles hot code
    ''' guided by the profile it gathered (dynamic PGO), as the command line and the tests run the
    ''' engine. This program turns tiered compilation off for its short scenes, which would otherwise be
    ''' timed partly in unoptimised code; the gas warms up for seconds first (see Measure), and without
    ''' the profile its event-driven rate is 10–20 % lower at N = 1 000. The variable overrides the
    ''' setting in Benchmarks.runtimeconfig.json.
    ''' </summary>
    Public ReadOnly Property ChildEnvironment As IReadOnlyDictionary(Of String, String) =
        New Dictionary(Of String, String) From {{"DOTNET_TieredCompilation", "1"}}

    ''' <summary>
    ''' In the child: builds the gas, runs it in short advances for <paramref name="warmUpSeconds"/>,
    ''' warms up further while finding a slice of simulated time that takes about
    ''' <paramref name="targetWallSeconds"/>, then times <paramref name="repeats"/> such slices of the same
    ''' gas (it is in equilibrium, so slices are alike) and reports the medians.
    ''' </summary>
    Public Function Measure(count As Integer, solverName As String, timeStep As Double?, repeats As Integer, targetWallSeconds As Double,
                            warmUpSeconds As Double) As BenchResult
        Dim world = Scenarios.ElasticGas(count, GasEnergyScene.PackingFraction)
        Dim result As New BenchResult With {.Scene = SceneName, .Solver = solverName, .TimeStep = timeStep, .BodyCount = count}
        If solverName = TextbookName Then
            Dim gas As New TextbookGas(world)
            result.TimeStep = Nothing
            TimeSlices(result, AddressOf gas.Advance, Function() gas.CollisionCount, Function() gas.EventCount, Nothing, repeats, targetWallSeconds, warmUpSeconds)
            If result.CollisionsPerSecond > 0 Then
                result.Note &= "; the textbook baseline, not the engine (see TextbookGas)"
            End If
            Return result
        End If
        Dim solver = SceneRunner.TryCreateSolver(solverName, timeStep)
        If solver Is Nothing Then Return SceneRunner.NotAvailable(SceneName, solverName, timeStep, "not available in this build")
        world.Solver = solver
        Dim exact = TryCast(solver, EventDrivenSolver)
        If exact Is Nothing Then
            TimeSlices(result, AddressOf world.Advance, Function() world.CollisionCount, Nothing, Nothing, repeats, targetWallSeconds, warmUpSeconds)
        Else
            TimeSlices(result, AddressOf world.Advance, Function() world.CollisionCount, Function() exact.EventCount, Function() exact.CellsSearched,
                       repeats, targetWallSeconds, warmUpSeconds)
        End If
        Return result
    End Function

    ''' <summary>
    ''' Warms the gas up, sizes a slice of simulated time that takes about <paramref name="targetWallSeconds"/>,
    ''' times <paramref name="repeats"/> slices and fills in <paramref name="result"/> (medians, peak
    ''' memory, and the work counts where there are: <paramref name="events"/> processed, grid
    ''' <paramref name="cells"/> searched; Nothing when not counted).
    ''' </summary>
    Private Sub TimeSlices(result As BenchResult, advance As Action(Of Double), collisions As Func(Of Long), events As Func(Of Long),
                           cells As Func(Of Long), repeats As Integer, targetWallSeconds As Double, warmUpSeconds As Double)
        Dim timeStep = result.TimeStep

        ' Warm-up, first part: .NET first compiles a method quickly and recompiles it optimised (guided
        ' by the profile gathered meanwhile) only after it has been called often, in the background.
        ' The timed slices below call Advance only a few times, so without this they ran partly
        ' unoptimised code: on the event-driven gas at N = 1 000 the first second ran at a fifth of
        ' the steady rate, and the rate kept rising until Advance itself had been called about 30
        ' times. The app calls Advance every frame, so it gets there within its first seconds.
        Dim slice = If(timeStep, 0.001)
        Dim clock = Stopwatch.StartNew()
        Dim calls = 0
        Do While clock.Elapsed.TotalSeconds < warmUpSeconds OrElse (calls < 100 AndAlso clock.Elapsed.TotalSeconds < 4 * warmUpSeconds)
            advance(slice)
            calls += 1
        Loop
        ' Second part: double the slice until one slice takes long enough to time well. At least three
        ' slices, because the first one also pays for compiling the code and building the solver's tables.
        Dim warmups = 0
        Do
            clock.Restart()
            advance(slice)
            clock.Stop()
            warmups += 1
            Dim longEnough = clock.Elapsed.TotalSeconds >= targetWallSeconds / 2
            If longEnough AndAlso warmups >= 3 Then Exit Do
            If Not longEnough Then slice *= 2
        Loop
        Dim ms As New List(Of Double)
        Dim perSecond As New List(Of Double)
        ' The work counts (not timed): flat in N when the cost per event is.
        Dim events0 = If(events Is Nothing, 0L, events()), cells0 = If(cells Is Nothing, 0L, cells()), collisions0 = collisions()
        For k = 1 To repeats
            Dim before = collisions()
            GC.Collect()
            clock.Restart()
            advance(slice)
            clock.Stop()
            Dim wall = clock.Elapsed.TotalSeconds
            ms.Add(wall * 1000 / slice)
            perSecond.Add((collisions() - before) / wall)
        Next
        result.Runs = repeats
        result.SimulatedSeconds = slice
        result.MsPerSimulatedSecond = Statistics.Median(ms)
        result.CollisionsPerSecond = Statistics.Median(perSecond)
        If result.CollisionsPerSecond > 0 Then result.MicrosecondsPerCollision = 1000000.0 / result.CollisionsPerSecond
        result.Error = Double.NaN
        result.ErrorMetric = ""
        Using self = Process.GetCurrentProcess()
            self.Refresh()
            result.PeakMegabytes = self.PeakWorkingSet64 / 1048576.0
        End Using
        result.Note = "slice " & slice.ToString("0.####", CultureInfo.InvariantCulture) & " s simulated per timed run"
        ' Started by the parent, the child has .NET's defaults (ChildEnvironment); say so when it has not.
        If Environment.GetEnvironmentVariable("DOTNET_TieredCompilation") <> "1" Then result.Note &= "; tiered compilation off"
        If events IsNot Nothing AndAlso collisions() > collisions0 AndAlso events() > events0 Then
            Dim processed = events() - events0
            result.Note &= "; " & (processed / CDbl(collisions() - collisions0)).ToString("0.00", CultureInfo.InvariantCulture) & " events per collision"
            If cells IsNot Nothing Then
                result.Note &= ", " & ((cells() - cells0) / CDbl(processed)).ToString("0.00", CultureInfo.InvariantCulture) & " cells searched per event"
            End If
        End If
    End Sub

    ''' <summary>
    ''' One row per case from several rounds of the same cases (every round lists them in the same
    ''' order): the round with the median collisions per second (the lower middle one for an even
    ''' count), its note led by how many runs and their range. A case no round could measure keeps
    ''' the first round's reason.
    ''' </summary>
    Public Function CombineRounds(rounds As IReadOnlyList(Of IReadOnlyList(Of BenchResult))) As List(Of BenchResult)
        If rounds Is Nothing OrElse rounds.Count = 0 Then Throw New ArgumentException("at least one round is needed", NameOf(rounds))
        Dim combined As New List(Of BenchResult)
        For k = 0 To rounds(0).Count - 1
            Dim index = k
            Dim runs = rounds.Select(Function(round) round(index)).ToList()
            Dim measured = runs.Where(Function(r) r.Available AndAlso Not Double.IsNaN(r.CollisionsPerSecond)).
                                OrderBy(Function(r) r.CollisionsPerSecond).ToList()
            If measured.Count = 0 OrElse rounds.Count = 1 Then
                combined.Add(runs(0))
                Continue For
            End If
            Dim median = measured((measured.Count - 1) \ 2)
            median.Rounds = measured.Count
            median.SlowestCollisionsPerSecond = measured(0).CollisionsPerSecond
            median.FastestCollisionsPerSecond = measured(measured.Count - 1).CollisionsPerSecond
            Dim summary = "median of " & measured.Count.ToString(CultureInfo.InvariantCulture) & " runs" &
                          If(measured.Count < runs.Count, " (" & (runs.Count - measured.Count).ToString(CultureInfo.InvariantCulture) & " more failed)", "") &
                          ", " & NumberText.Whole(measured(0).CollisionsPerSecond) & " to " &
                          NumberText.Whole(measured(measured.Count - 1).CollisionsPerSecond) & " collisions/s"
            median.Note = If(median.Note.Length > 0, summary & "; " & median.Note, summary)
            combined.Add(median)
        Next
        Return combined
    End Function
End Module
