Option Strict On
Imports System.Diagnostics
Imports System.Globalization
Imports System.IO
Imports System.Text

''' <summary>
''' Entry point. The parent run reads like its pipeline: scenes → gas scaling → frame budget → write
''' the report. Hidden --child-* options run one piece of that in a child process of this program.
''' Exit 0 on success, 2 on bad input, 1 on any other failure.
''' </summary>
Public NotInheritable Class Program
    Private Sub New()
    End Sub

    Public Shared Function Main(args As String()) As Integer
        Dim options As BenchmarkOptions
        Try
            options = BenchmarkOptions.Parse(args)
        Catch ex As OptionsException
            Console.Error.WriteLine("benchmarks: " & ex.Message)
            Return 2
        End Try
        If options.Help Then
            Console.Out.WriteLine(BenchmarkOptions.Usage)
            Return 0
        End If
        Try
            If options.ReadmeOnly Then Return CopyFiguresToReadme(options)
            If options.ChildScene IsNot Nothing Then Return RunChildScene(options)
            If options.ChildGas > 0 Then Return RunChildGas(options)
            Return RunAll(options)
        Catch ex As Exception When Not TypeOf ex Is OutOfMemoryException
            Console.Error.WriteLine("benchmarks: internal error: " & ex.Message)
            Return 1
        End Try
    End Function

    Private Shared Function RunAll(options As BenchmarkOptions) As Integer
        Dim clock = Diagnostics.Stopwatch.StartNew()
        Dim machine = MachineInfo.Current()
        Console.Out.WriteLine("benchmarks: " & If(options.Quick, "quick", "full") & " run on " & machine.ToString())
        Dim scenes = options.Scenes.Where(Function(s) s <> GasScaling.SceneName).Select(Function(s) SceneCatalog.Create(s, options)).ToList()
        Dim results As New List(Of BenchResult)

        For Each scene In scenes
            For Each solver In options.Solvers
                results.AddRange(RunSceneInChild(scene, solver, options))
            Next
            Dim pile = TryCast(scene, BoxPileScene)
            If pile IsNot Nothing Then
                Dim reference = RunBox2d(pile, options)
                Print(reference)
                results.Add(reference)
            End If
        Next
        If options.Scenes.Contains(GasScaling.SceneName) Then results.AddRange(RunScaling(options))
        Dim baseline = RunBaseline(options)

        Dim frame As FrameResult
        Dim sceneFrames As List(Of SceneFrameResult)
        If options.Quick OrElse options.NoFrame Then
            Dim why = If(options.Quick, "the quick run skips it.", "skipped (--no-frame).")
            frame = New FrameResult With {.Note = why}
            sceneFrames = FrameBenchmark.SceneRows.Select(Function(row) New SceneFrameResult With {.Scene = row.AppName, .ReportScene = row.ReportScene, .Note = why}).ToList()
        Else
            Console.Out.WriteLine("frame benchmark: " & options.AppPath)
            frame = FrameBenchmark.TryRun(options.AppPath, 1000)
            Console.Out.WriteLine("  " & If(frame.Ran, "step " & NumberText.Fixed2(frame.StepMs) & " ms + paint " & NumberText.Fixed2(frame.PaintMs) & " ms", "skipped: " & frame.Note))
            sceneFrames = FrameBenchmark.TryRunScenes(options.AppPath, Function(name) SceneCatalog.Create(name, options))
            For Each s In sceneFrames
                Console.Out.WriteLine("  " & s.Scene & ": " &
                                      If(s.Ran, "frame median " & NumberText.Fixed2(s.TotalMs.Median) & " ms, p95 " & NumberText.Fixed2(s.TotalMs.P95) &
                                                " ms, worst " & NumberText.Fixed2(s.TotalMs.Worst) & " ms over " & s.Frames.ToString(CultureInfo.InvariantCulture) & " frames", "skipped") &
                                      If(s.Note.Length > 0, "; " & s.Note, ""))
            Next
        End If

        Console.Out.WriteLine("recording for rewind: the 1000-ball gas with and without it")
        Dim recording = RecordingOverhead.Measure(seconds:=If(options.Quick, 30, 60), repeats:=If(options.Quick, 3, 5))
        Console.Out.WriteLine("  overhead " & (100 * recording.Overhead).ToString("0.0", CultureInfo.InvariantCulture) & " % (from its parts " & (100 * recording.OverheadFromParts).ToString("0.0", CultureInfo.InvariantCulture) & " %), " & recording.Checkpoints & " checkpoints")
        WriteOutputs(options, machine, scenes, results, frame, recording, sceneFrames, baseline)
        Console.Out.WriteLine("benchmarks: done in " & clock.Elapsed.TotalSeconds.ToString("0", CultureInfo.InvariantCulture) & " s; wrote " &
                              Path.Combine(options.OutDir, "benchmarks.md") & If(options.JsonPath Is Nothing, "", " and " & options.JsonPath))
        Return 0
    End Function

    ''' <summary>One scene, one solver, every time step, in a child process; a hang or a crash becomes a note.</summary>
    Private Shared Function RunSceneInChild(scene As IBenchScene, solver As String, options As BenchmarkOptions) As List(Of BenchResult)
        Dim probe = SceneRunner.TryCreateSolver(solver, options.TimeSteps(0))
        If probe Is Nothing Then
            Dim missing = SceneRunner.NotAvailable(scene.Name, solver, Nothing, "not available in this build (SolverFactory does not know '" & solver & "')")
            missing.ErrorMetric = scene.ErrorMetric
            Print(missing)
            Return New List(Of BenchResult) From {missing}
        End If
        Dim expected As IEnumerable(Of Double?) = If(probe.TimeStep.HasValue, options.TimeSteps.Select(Function(t) CType(t, Double?)), {CType(Nothing, Double?)})
        Dim args = options.ChildArguments()
        args.AddRange({"--child-scene", scene.Name, "--child-solver", solver})
        Dim timeout = options.ChildTimeout(expected.Count())
        Dim outcome = ChildProcess.Run(args, timeout)
        Dim results As New List(Of BenchResult)
        For Each dt In expected
            Dim r = outcome.Results.FirstOrDefault(Function(x) Nullable.Equals(x.TimeStep, dt))
            If r Is Nothing Then
                Dim why = If(outcome.TimedOut, "timed out: the child was stopped after " & timeout.TotalSeconds.ToString("0", CultureInfo.InvariantCulture) & " s",
                             "failed (exit " & outcome.ExitCode.ToString(CultureInfo.InvariantCulture) & "): " & FirstLine(outcome.ErrorText))
                r = SceneRunner.NotAvailable(scene.Name, solver, dt, why)
                r.ErrorMetric = scene.ErrorMetric
            End If
            Print(r)
            results.Add(r)
        Next
        Return results
    End Function

    ''' <summary>The same box pile in Box2D 2.4.1 (the reference program the script built), or a row saying why not.</summary>
    Private Shared Function RunBox2d(scene As BoxPileScene, options As BenchmarkOptions) As BenchResult
        If options.Box2dProgram Is Nothing Then
            Return Box2dReference.NotRun(scene.Name, scene.ErrorMetric,
                                         If(options.Box2dNote.Length > 0, options.Box2dNote,
                                            "not run: no Box2D reference program was given (scripts/bench.sh builds one with scripts/box2d-reference.sh)."))
        End If
        Return Box2dReference.Run(options.Box2dProgram, scene, options.Repeats, options.ChildTimeout(1))
    End Function

    ''' <summary>
    ''' The gas at every size, each in a child process, <see cref="BenchmarkOptions.GasRounds"/> times:
    ''' the first round decides which sizes each solver is given; the later rounds run the sizes the
    ''' first one measured again, in the same order; each row is the median round.
    ''' </summary>
    Private Shared Function RunScaling(options As BenchmarkOptions) As List(Of BenchResult)
        Dim rounds As New List(Of IReadOnlyList(Of BenchResult))
        For round = 1 To options.GasRounds
            If options.GasRounds > 1 Then
                Console.Out.WriteLine("gas scaling, round " & round.ToString(CultureInfo.InvariantCulture) & " of " & options.GasRounds.ToString(CultureInfo.InvariantCulture))
            End If
            rounds.Add(If(round = 1, RunFirstScalingRound(options), RunScalingAgain(options, rounds(0))))
        Next
        Dim combined = GasScaling.CombineRounds(rounds)
        If options.GasRounds > 1 Then
            Console.Out.WriteLine("gas scaling, the median of the rounds:")
            For Each r In combined
                Print(r)
            Next
        End If
        Return combined
    End Function

    ''' <summary>
    ''' Every size in turn, smallest first, and at each size every solver one after the other, so
    ''' that rows of one size (the event solver and the textbook baseline beside it) are measured
    ''' close together, in the same spell of a shared machine. A stepping solver skips a size when
    ''' its last measured size predicts too long a step.
    ''' </summary>
    Private Shared Function RunFirstScalingRound(options As BenchmarkOptions) As List(Of BenchResult)
        Dim results As New List(Of BenchResult)
        Dim runnable As New List(Of String)
        Dim timeSteps As New Dictionary(Of String, Double?)
        For Each solver In GasScaling.SolversFor(options.Solvers)
            Dim plan = GasScaling.TimeStepFor(solver)
            If Not plan.Available Then
                Dim missing = SceneRunner.NotAvailable(GasScaling.SceneName, solver, Nothing, "not available in this build")
                Print(missing)
                results.Add(missing)
                Continue For
            End If
            timeSteps(solver) = plan.TimeStep
            runnable.Add(solver)
        Next
        Dim lastMeasured As New Dictionary(Of String, BenchResult)
        For Each n In options.GasSizes.OrderBy(Function(x) x)
            For Each solver In runnable
                Dim dt = timeSteps(solver)
                Dim previous As BenchResult = Nothing
                lastMeasured.TryGetValue(solver, previous)
                Dim r As BenchResult
                Dim predicted = PredictedStepSeconds(previous, n, dt)
                If predicted > options.StepBudgetSeconds Then
                    r = SceneRunner.NotAvailable(GasScaling.SceneName, solver, dt,
                        "skipped: one step could take " & predicted.ToString("0", CultureInfo.InvariantCulture) & " s if the cost grows as N² (from N = " &
                        previous.BodyCount.ToString(CultureInfo.InvariantCulture) & ")")
                    r.BodyCount = n
                Else
                    r = RunGasChild(options, solver, dt, n)
                End If
                Print(r)
                results.Add(r)
                If r.Available Then lastMeasured(solver) = r
            Next
        Next
        Return results
    End Function

    ''' <summary>The cases the first round measured, run again in the same order; the others are kept as they were.</summary>
    Private Shared Function RunScalingAgain(options As BenchmarkOptions, first As IReadOnlyList(Of BenchResult)) As List(Of BenchResult)
        Dim results As New List(Of BenchResult)
        For Each previous In first
            Dim r = If(previous.Available, RunGasChild(options, previous.Solver, previous.TimeStep, previous.BodyCount), previous)
            If previous.Available Then Print(r)
            results.Add(r)
        Next
        Return results
    End Function

    ''' <summary>
    ''' The gas at the compared sizes with the engine at the baseline commit (its own Benchmarks.dll,
    ''' built by scripts/bench.sh) and with this one, <see cref="BenchmarkOptions.BaselineRounds"/> times;
    ''' or why not. Both run the same measurement (GasScaling.Measure is the same at that commit) in
    ''' child processes with the same settings.
    ''' </summary>
    Private Shared Function RunBaseline(options As BenchmarkOptions) As BaselineComparison
        Dim commit = options.BaselineCommit
        If options.Quick Then Return BaselineComparison.NotRun(commit, "the quick run skips it.")
        If Not options.Scenes.Contains(GasScaling.SceneName) Then Return BaselineComparison.NotRun(commit, "not run: this run left out the gas scaling.")
        If options.BaselineDll Is Nothing Then
            Return BaselineComparison.NotRun(commit, If(options.BaselineNote.Length > 0, options.BaselineNote,
                                                        "not run: no baseline build was given (scripts/bench.sh builds one in a full run)."))
        End If
        If Not File.Exists(options.BaselineDll) Then Return BaselineComparison.NotRun(commit, "not run: the baseline build is missing (" & options.BaselineDll & ").")
        Dim sizes = BaselineComparison.SizesIn(options.GasSizes)
        If sizes.Count = 0 Then Return BaselineComparison.NotRun(commit, "not run: this run's gas sizes include neither N = 1 000 nor N = 10 000.")
        Dim label = If(commit.Length > 0, commit.Substring(0, Math.Min(7, commit.Length)), "the baseline")
        Dim nowRounds As New List(Of IReadOnlyList(Of BenchResult))
        Dim beforeRounds As New List(Of IReadOnlyList(Of BenchResult))
        For round = 1 To options.BaselineRounds
            Console.Out.WriteLine("elastic gas, the engine at " & label & " and now, round " & round.ToString(CultureInfo.InvariantCulture) & " of " &
                                  options.BaselineRounds.ToString(CultureInfo.InvariantCulture))
            Dim nowRound As New List(Of BenchResult), beforeRound As New List(Of BenchResult)
            For Each n In sizes
                ' Which engine goes first alternates by round, so a machine speeding up or slowing down
                ' within a pair does not favour the same side every time.
                Dim beforeFirst = round Mod 2 = 0
                Dim before As BenchResult = Nothing
                If beforeFirst Then before = RunBaselineChild(options, n, label)
                Dim now = RunGasChild(options, "event", Nothing, n)
                Console.Out.Write("  now:")
                Print(now)
                If Not beforeFirst Then before = RunBaselineChild(options, n, label)
                nowRound.Add(now)
                beforeRound.Add(before)
            Next
            nowRounds.Add(nowRound)
            beforeRounds.Add(beforeRound)
        Next
        Return BaselineComparison.Combine(commit, nowRounds, beforeRounds)
    End Function

    ''' <summary>The gas at N = <paramref name="n"/> with the baseline build's event solver, in its own child process.</summary>
    Private Shared Function RunBaselineChild(options As BenchmarkOptions, n As Integer, label As String) As BenchResult
        Dim psi As New ProcessStartInfo(DotnetHost())
        psi.ArgumentList.Add(options.BaselineDll)
        Dim args = options.ChildArguments()
        args.AddRange({"--child-gas", n.ToString(CultureInfo.InvariantCulture), "--child-solver", "event"})
        Dim outcome = ChildProcess.RunProgram(psi, args, options.GasChildTimeout, GasScaling.ChildEnvironment)
        Dim r = outcome.Results.FirstOrDefault()
        If r Is Nothing Then
            r = SceneRunner.NotAvailable(GasScaling.SceneName, "event", Nothing,
                If(outcome.TimedOut, "timed out after " & options.GasChildTimeout.TotalSeconds.ToString("0", CultureInfo.InvariantCulture) & " s",
                   "failed (exit " & outcome.ExitCode.ToString(CultureInfo.InvariantCulture) & "): " & FirstLine(outcome.ErrorText)))
            r.BodyCount = n
        End If
        Console.Out.Write("  " & label & ":")
        Print(r)
        Return r
    End Function

    ''' <summary>The dotnet host running this program, or "dotnet" from the PATH.</summary>
    Private Shared Function DotnetHost() As String
        Dim host = Environment.ProcessPath
        Return If(host IsNot Nothing AndAlso String.Equals(Path.GetFileNameWithoutExtension(host), "dotnet", StringComparison.OrdinalIgnoreCase), host, "dotnet")
    End Function

    ''' <summary>The gas at N = <paramref name="n"/> with one solver, in a child process; a failure or time-out becomes a row saying so.</summary>
    Private Shared Function RunGasChild(options As BenchmarkOptions, solver As String, dt As Double?, n As Integer) As BenchResult
        Dim args = options.ChildArguments()
        args.AddRange({"--child-gas", n.ToString(CultureInfo.InvariantCulture), "--child-solver", solver})
        Dim outcome = ChildProcess.Run(args, options.GasChildTimeout, GasScaling.ChildEnvironment)
        Dim r = outcome.Results.FirstOrDefault()
        If r Is Nothing Then
            r = SceneRunner.NotAvailable(GasScaling.SceneName, solver, dt,
                If(outcome.TimedOut, "timed out after " & options.GasChildTimeout.TotalSeconds.ToString("0", CultureInfo.InvariantCulture) & " s",
                   "failed (exit " & outcome.ExitCode.ToString(CultureInfo.InvariantCulture) & "): " & FirstLine(outcome.ErrorText)))
            r.BodyCount = n
        End If
        Return r
    End Function

    ''' <summary>
    ''' Worst-case wall-clock seconds of one step at N = <paramref name="n"/>, from the last measured
    ''' size, assuming the cost grows as N²; 0 for the event solver or when nothing was measured yet.
    ''' </summary>
    Friend Shared Function PredictedStepSeconds(previous As BenchResult, n As Integer, timeStep As Double?) As Double
        If previous Is Nothing OrElse Not timeStep.HasValue OrElse Double.IsNaN(previous.MsPerSimulatedSecond) Then Return 0
        Dim stepSeconds = previous.MsPerSimulatedSecond / 1000 * timeStep.Value
        Dim ratio = n / CDbl(previous.BodyCount)
        Return stepSeconds * ratio * ratio
    End Function

    Private Shared Function RunChildScene(options As BenchmarkOptions) As Integer
        Dim scene = SceneCatalog.Create(options.ChildScene, options)
        Dim solver = options.ChildSolver
        Dim probe = SceneRunner.TryCreateSolver(solver, options.TimeSteps(0))
        If probe Is Nothing Then
            ChildProcess.Report(SceneRunner.NotAvailable(scene.Name, solver, Nothing, "not available in this build"))
            Return 0
        End If
        Dim steps As IEnumerable(Of Double?) = If(probe.TimeStep.HasValue, options.TimeSteps.Select(Function(t) CType(t, Double?)), {CType(Nothing, Double?)})
        For Each dt In steps
            Dim r As BenchResult
            Try
                r = SceneRunner.Run(scene, solver, dt, options.Repeats, options.CaseBudgetSeconds)
            Catch ex As Exception When Not TypeOf ex Is OutOfMemoryException
                ' A solver that throws on a hard case is a finding, not the end of the benchmark.
                r = SceneRunner.NotAvailable(scene.Name, solver, dt, "failed: " & ex.GetType().Name & ": " & ex.Message)
            End Try
            ChildProcess.Report(r)
        Next
        Return 0
    End Function

    Private Shared Function RunChildGas(options As BenchmarkOptions) As Integer
        Dim solver = options.ChildSolver
        Dim dt = GasScaling.TimeStepFor(solver).TimeStep
        Dim r As BenchResult
        Try
            r = GasScaling.Measure(options.ChildGas, solver, dt, options.Repeats, options.GasSliceSeconds, options.GasWarmUpSeconds)
        Catch ex As Exception When Not TypeOf ex Is OutOfMemoryException
            r = SceneRunner.NotAvailable(GasScaling.SceneName, solver, dt, "failed: " & ex.GetType().Name & ": " & ex.Message)
            r.BodyCount = options.ChildGas
        End Try
        ChildProcess.Report(r)
        Return 0
    End Function

    Private Shared Sub WriteOutputs(options As BenchmarkOptions, machine As MachineInfo, scenes As List(Of IBenchScene), results As List(Of BenchResult), frame As FrameResult,
                                    recording As RecordingResult, sceneFrames As List(Of SceneFrameResult), baseline As BaselineComparison)
        Directory.CreateDirectory(options.OutDir)
        Dim mode = If(options.Quick, "quick", "full")
        For Each kv In MarkdownReport.Plots(scenes, results)
            WriteAtomically(Path.Combine(options.OutDir, kv.Key), kv.Value)
        Next
        WriteAtomically(Path.Combine(options.OutDir, "benchmarks.md"), MarkdownReport.Render(machine, mode, options.Repeats, scenes, results, frame, sceneFrames, baseline) & ControlChars.Lf & RecordingOverhead.Section(recording))
        If options.ReadmePath IsNot Nothing Then CopyFiguresToReadme(options)
        If options.JsonPath IsNot Nothing Then
            Dim dir = Path.GetDirectoryName(Path.GetFullPath(options.JsonPath))
            Directory.CreateDirectory(dir)
            WriteAtomically(options.JsonPath, JsonReport.ToJson(machine, mode, results))
        End If
    End Sub

    ''' <summary>Copies the headline figures of the report in the output folder into the README (see <see cref="ReadmeFigures"/>).</summary>
    Private Shared Function CopyFiguresToReadme(options As BenchmarkOptions) As Integer
        If options.ReadmePath Is Nothing Then
            Console.Error.WriteLine("benchmarks: --readme-only needs --readme FILE")
            Return 2
        End If
        Dim report = File.ReadAllText(Path.Combine(options.OutDir, "benchmarks.md"))
        Dim readme = File.ReadAllText(options.ReadmePath)
        WriteAtomically(options.ReadmePath, ReadmeFigures.Splice(readme, ReadmeFigures.FromReport(report)))
        Console.Out.WriteLine("benchmarks: copied the headline figures into " & options.ReadmePath)
        Return 0
    End Function

    ''' <summary>Writes to a temporary file beside the target, then moves it into place: never half a file.</summary>
    Private Shared Sub WriteAtomically(target As String, text As String)
        Dim temp = target & ".tmp"
        File.WriteAllText(temp, text, New UTF8Encoding(False))
        File.Move(temp, target, True)
    End Sub

    Private Shared Sub Print(r As BenchResult)
        Dim text = "  " & r.Scene & " " & r.Solver & " dt=" & TimeStepText.Format(r.TimeStep) &
                   If(r.BodyCount > 0 AndAlso r.Scene = GasScaling.SceneName, " N=" & r.BodyCount.ToString(CultureInfo.InvariantCulture), "") & ": "
        If r.Available Then
            text &= If(Double.IsNaN(r.Error), "", "error " & NumberText.Sci(r.Error) & ", ") & NumberText.Ms(r.MsPerSimulatedSecond) & " ms/sim s, " &
                    NumberText.Whole(r.CollisionsPerSecond) & " collisions/s" &
                    If(Double.IsNaN(r.PeakMegabytes), "", ", peak " & NumberText.Fixed2(r.PeakMegabytes) & " MB")
        End If
        If r.Note.Length > 0 Then text &= If(r.Available, "; ", "") & r.Note
        Console.Out.WriteLine(text)
    End Sub

    Private Shared Function FirstLine(text As String) As String
        Dim t = If(text, "").Trim()
        Dim nl = t.IndexOf(vbLf, StringComparison.Ordinal)
        Return If(nl >= 0, t.Substring(0, nl), t)
    End Function
End Class
