Option Strict On
Imports System.Diagnostics
Imports System.Globalization
Imports System.IO
Imports System.Threading.Tasks
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Fuzzing.Generation
Imports PhysicsEngine.Fuzzing.Shrinking
Imports PhysicsEngine.Fuzzing.Workers

''' <summary>
''' A fuzzing campaign: generate scenes from consecutive seeds (or take one scene file), check each with
''' every solver in worker processes, print one line per failure as it is found, shrink each failure and
''' write it out with the command that shows it, and sum up.
''' </summary>
Friend Module Campaign
    ''' <summary>Runs the campaign; progress and failure lines go to <paramref name="log"/>.</summary>
    Friend Function Run(options As FuzzOptions, log As TextWriter) As CampaignResult
        If options Is Nothing Then Throw New ArgumentNullException(NameOf(options))
        If log Is Nothing Then Throw New ArgumentNullException(NameOf(log))
        Dim clock = Stopwatch.StartNew()
        Dim result As New CampaignResult()
        Dim scenes = Prepare(options)
        Dim outcomes(scenes.Count - 1) As SceneOutcome
        Using pool As New WorkerPool(options.Jobs, options.InProcess)
            Parallel.For(0, scenes.Count, New ParallelOptions With {.MaxDegreeOfParallelism = pool.Size},
                Sub(index)
                    Dim outcome = scenes(index)
                    CheckScene(pool, outcome, options.Solvers)
                    outcomes(index) = outcome
                    SyncLock log
                        For Each v In outcome.Violations
                            log.WriteLine(LinePrefix(v.Invariant) & outcome.Label & " " & v.ToString())
                        Next
                    End SyncLock
                End Sub)
            result.Outcomes.AddRange(outcomes)
            If options.Shrink Then
                Dim failures = result.Failures()
                Dim shrunk(failures.Count - 1) As ShrunkFailure
                Parallel.For(0, failures.Count, New ParallelOptions With {.MaxDegreeOfParallelism = pool.Size},
                    Sub(index)
                        Dim f = failures(index)
                        shrunk(index) = ShrinkAndWrite(pool, options, f.Outcome, f.Violation)
                        SyncLock log
                            Dim s = shrunk(index)
                            log.WriteLine("  " & f.Violation.Invariant & " " & f.Outcome.Label & ": " & s.Result.Doc.Bodies.Count.ToString(CultureInfo.InvariantCulture) & " of " &
                                f.Outcome.Doc.Bodies.Count.ToString(CultureInfo.InvariantCulture) & " bodies, T = " & s.Result.Plan.Time.ToString("R", CultureInfo.InvariantCulture) &
                                " s, " & s.Result.Probes.ToString(CultureInfo.InvariantCulture) & " runs -> " & s.Path)
                        End SyncLock
                    End Sub)
                result.Shrunk.AddRange(shrunk)
            End If
        End Using
        result.ElapsedSeconds = clock.Elapsed.TotalSeconds
        Summarize(options, result, log)
        Return result
    End Function

    ''' <summary>The scenes to check: one per seed, or the given file.</summary>
    Private Function Prepare(options As FuzzOptions) As List(Of SceneOutcome)
        Dim list As New List(Of SceneOutcome)
        If options.SceneFile IsNot Nothing Then
            Dim doc = SceneDoc.Parse(File.ReadAllText(options.SceneFile, Text.Encoding.UTF8))
            Dim plan As New RunPlan(options.Time, options.Sample, options.SecondSample, options.Cap)
            list.Add(New SceneOutcome(Path.GetFileNameWithoutExtension(options.SceneFile), Nothing, doc, plan))
            Return list
        End If
        For k = 0 To options.Scenes - 1
            Dim seed = options.Seed + k
            Dim draft = SceneGenerator.Generate(seed, options.Kinds, options.MaxBodies, options.Rough)
            list.Add(New SceneOutcome(seed.ToString(CultureInfo.InvariantCulture), seed, draft.ToDoc(), PlanFor(draft, options)))
        Next
        Return list
    End Function

    ''' <summary>Times a run may be cut to, s: round numbers, so that commands stay readable.</summary>
    Private ReadOnly RoundTimes As Double() = {1000, 500, 200, 100, 50, 20, 10, 5, 2, 1, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01}

    ''' <summary>
    ''' The run for a generated scene: T as asked, but cut (to a round number, not below 0.01 s) so that the
    ''' fastest ball crosses the container at most 1 000 times: a ball at 10⁴ m/s in a 2 cm box would
    ''' otherwise spend the whole wall-time cap bouncing between the walls. The sampling interval shrinks
    ''' with T to give at least ten samples, and the second interval keeps its ratio to the first.
    ''' </summary>
    Friend Function PlanFor(draft As SceneDraft, options As FuzzOptions) As RunPlan
        Dim total = options.Time
        Dim speed = draft.TopSpeed()
        Dim size = Math.Min(draft.World.Width, draft.World.Height)
        If speed > 0 AndAlso 1000 * size / speed < total Then
            Dim fast = 1000 * size / speed
            total = RoundTimes.FirstOrDefault(Function(t) t <= fast)
            If total = 0 Then total = RoundTimes(RoundTimes.Length - 1)
        End If
        Dim sample = Math.Min(options.Sample, RoundTimes.FirstOrDefault(Function(t) t <= total / 10, RoundTimes(RoundTimes.Length - 1) / 10))
        Dim second = options.SecondSample * (sample / options.Sample)
        Return New RunPlan(total, sample, second, options.Cap)
    End Function

    ''' <summary>Checks the scene with each solver, each in a free worker.</summary>
    Friend Sub CheckScene(pool As WorkerPool, outcome As SceneOutcome, solvers As IEnumerable(Of String))
        Dim text = outcome.Doc.ToText()
        For Each solver In solvers
            Dim r = pool.With(Function(c) c.Check(text, solver, outcome.Plan, Nothing))
            outcome.Violations.AddRange(r.Violations)
            outcome.Collisions(solver) = r.Collisions
            outcome.WallSeconds += r.WallSeconds
        Next
    End Sub

    ''' <summary>Shrinks one failure (within the shrink budget) and writes it out.</summary>
    Private Function ShrinkAndWrite(pool As WorkerPool, options As FuzzOptions, outcome As SceneOutcome, v As Violation) As ShrunkFailure
        Dim plan = ProbePlan(outcome.Plan, v)
        Dim probe = Function(doc As SceneDoc, p As RunPlan) As Violation
                        Dim r = pool.With(Function(c) c.Check(doc.ToText(), v.Solver, p, v.Invariant))
                        Return r.Violations.FirstOrDefault(Function(x) x.Invariant = v.Invariant)
                    End Function
        Dim result = SceneShrinker.Shrink(outcome.Doc, plan, v, probe, DateTime.UtcNow.AddSeconds(options.ShrinkBudget))
        Dim also = outcome.Violations.Where(Function(x) x.Invariant = v.Invariant).Select(Function(x) x.Solver).Distinct()
        Dim path = FailureReport.Write(options.Out, outcome, v, result, also)
        Return New ShrunkFailure(outcome, v, result, path)
    End Function

    ''' <summary>The run that shows a violation again: its own sampling interval, and both intervals for the sampling invariant.</summary>
    Friend Function ProbePlan(plan As RunPlan, v As Violation) As RunPlan
        If v.Invariant = Invariants.Sampling Then Return plan
        Return New RunPlan(plan.Time, v.Sample, 0, plan.Cap)
    End Function

    ''' <summary>Heavy and unstable runs are noted, not failures (see <see cref="Invariants"/>).</summary>
    Friend Function IsNoted(invariant As String) As Boolean
        Return invariant = Invariants.Heavy OrElse invariant = Invariants.Unstable
    End Function

    ''' <summary>How a line starts: FAIL, or HEAVY or UNSTABLE for a run that is noted.</summary>
    Friend Function LinePrefix(invariant As String) As String
        If IsNoted(invariant) Then Return invariant.ToUpperInvariant() & " "
        Return "FAIL "
    End Function

    Private Sub Summarize(options As FuzzOptions, result As CampaignResult, log As TextWriter)
        Dim inv = CultureInfo.InvariantCulture
        Dim failures = result.Failures()
        Dim runs = result.Outcomes.Count * options.Solvers.Count
        Dim what = If(options.SceneFile IsNot Nothing, options.SceneFile,
            result.Outcomes.Count.ToString(inv) & " scenes (seeds " & options.Seed.ToString(inv) & " to " & (options.Seed + options.Scenes - 1).ToString(inv) & ")")
        log.WriteLine("fuzz: " & what & ", solvers " & String.Join(",", options.Solvers) & ", kinds " & BodyKindNames.Format(options.Kinds) &
            If(options.Rough > 0, ", rough " & options.Rough.ToString("R", inv), "") & ": " &
            runs.ToString(inv) & " scene runs in " & result.ElapsedSeconds.ToString("0.0", inv) & " s")
        For Each o In result.Outcomes
            For Each v In o.Violations.Where(Function(x) IsNoted(x.Invariant))
                log.WriteLine("fuzz: " & v.Invariant & ", not a failure: " & o.Label & " (" & v.Solver & ", sample " & v.Sample.ToString("R", inv) & " s): " & v.Message)
            Next
        Next
        If failures.Count = 0 Then
            log.WriteLine("fuzz: no failures")
            Return
        End If
        Dim counts As New List(Of String)
        For Each name In Invariants.All
            Dim n = failures.Where(Function(f) f.Violation.Invariant = name).Count()
            If n > 0 Then counts.Add(name & " " & n.ToString(inv))
        Next
        log.WriteLine("fuzz: " & failures.Count.ToString(inv) & " failures in " & failures.Select(Function(f) f.Outcome.Label).Distinct().Count().ToString(inv) & " scenes: " &
            String.Join(", ", counts))
        If result.Shrunk.Count > 0 Then log.WriteLine("fuzz: shrunk scenes and the commands that show them: " & Path.Combine(options.Out, "README.md"))
    End Sub
End Module
