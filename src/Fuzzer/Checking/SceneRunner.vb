Option Strict On
Imports System.Diagnostics
Imports PhysicsEngine.Scenes

Namespace Checking
    ''' <summary>
    ''' Runs one scene, loaded from its text as the command line loads it, with one solver at its default
    ''' step, advancing to each sample time of <see cref="SampleClock"/> exactly as the command line's run
    ''' does, and checks the state at every sample. So a failure seen here is the failure that
    ''' <c>SimulatorCli run FILE --time T --solver S --sample S</c> shows.
    ''' </summary>
    Friend Module SceneRunner
        ''' <summary>
        ''' One run. Stops at a non-finite state, a thrown exception, the wall-time cap (checked after each
        ''' sample's advance: one advance cannot be interrupted, which is why campaigns run scenes in worker
        ''' processes), or the first violation of <paramref name="stopAt"/> when one is given.
        ''' </summary>
        ''' <param name="text">physics-scene/1 text; a <see cref="SceneFormatException"/> is left to the caller</param>
        Friend Function Run(text As String, solver As String, total As Double, sample As Double, cap As Double,
                            Optional stopAt As String = Nothing, Optional keepLog As Boolean = False) As RunOutcome
            Dim world = SceneFile.Load(text)
            world.Solver = SolverFactory.Create(solver)
            ' As the command line does at load: rods and taut strings set off their lengths are put on them first.
            world.HoldLinks()
            Dim isEvent = TypeOf world.Solver Is EventDrivenSolver
            Dim outcome As New RunOutcome()
            Dim log As CollisionLog = Nothing
            If keepLog Then
                log = New CollisionLog()
                outcome.Log = log
            End If
            ' Collisions at the instant of the one before: a heavy run has few (see Invariants.Heavy).
            Dim repeats = 0L
            Dim lastTime = Double.NaN
            world.CollisionListener =
                Sub(c)
                    If c.Time = lastTime Then repeats += 1
                    lastTime = c.Time
                    log?.Add(c)
                End Sub
            Dim energy = If(isEvent, New EnergyBudget(world), Nothing)
            ' A stepping solver cannot follow a spring beyond its stability limit: blowing up there is the method's, not a fault.
            Dim unstable = If(Not isEvent AndAlso world.Solver.TimeStep.HasValue, StepStability.BeyondLimit(world, world.Solver.TimeStep.Value), Nothing)
            Dim clock = Stopwatch.StartNew()
            Dim seen As New HashSet(Of String)(StringComparer.Ordinal)
            Dim report =
                Function(invariant As String, t As Double, message As String) As Boolean
                    If message Is Nothing OrElse Not seen.Add(invariant) Then Return False
                    outcome.Violations.Add(New Violation(invariant, solver, sample, t, message))
                    Return invariant = stopAt
                End Function
            Dim stopped = False
            For Each t In SampleClock.Times(total, sample)
                Try
                    world.Advance(t - world.Time)
                Catch ex As UnsupportedSceneException
                    ' Every solver takes every scene the reader takes: a refusal is a failure, and the run ends there.
                    report(Invariants.SolverRefused, t, "refused between t = " & world.Time.ToString("R", Globalization.CultureInfo.InvariantCulture) & " s and t = " &
                        t.ToString("R", Globalization.CultureInfo.InvariantCulture) & " s: " & OneLine(ex.Message))
                    stopped = True
                    Exit For
                Catch ex As Exception When Not TypeOf ex Is OutOfMemoryException
                    If unstable IsNot Nothing Then
                        report(Invariants.Unstable, t, "blew up (" & ex.GetType().Name & ") between t = " & world.Time.ToString("R", Globalization.CultureInfo.InvariantCulture) & " s and t = " &
                            t.ToString("R", Globalization.CultureInfo.InvariantCulture) & " s: " & unstable)
                        stopped = True
                        Exit For
                    End If
                    report(Invariants.Crash, t, ex.GetType().Name & " between t = " & world.Time.ToString("R", Globalization.CultureInfo.InvariantCulture) & " s and t = " &
                        t.ToString("R", Globalization.CultureInfo.InvariantCulture) & " s: " & OneLine(ex.Message))
                    stopped = True
                    Exit For
                End Try
                Dim notFinite = StateChecks.NotFinite(world)
                If notFinite IsNot Nothing Then
                    If unstable IsNot Nothing Then
                        report(Invariants.Unstable, t, "blew up (" & notFinite & "): " & unstable)
                    Else
                        report(Invariants.NotFinite, t, notFinite)
                    End If
                    stopped = True
                    Exit For
                End If
                Dim hit = report(Invariants.Outside, t, StateChecks.Outside(world))
                hit = report(Invariants.CentreInside, t, StateChecks.CentreInside(world)) OrElse hit
                If isEvent Then
                    hit = report(Invariants.Overlap, t, StateChecks.Overlap(world)) OrElse hit
                    hit = report(Invariants.Energy, t, energy.Check(world)) OrElse hit
                End If
                If hit Then
                    stopped = True
                    Exit For
                End If
                If clock.Elapsed.TotalSeconds > cap Then
                    Dim inv = Globalization.CultureInfo.InvariantCulture
                    Dim collisions = world.CollisionCount.ToString(inv) & " collisions"
                    Dim heavy = If(isEvent, HeavyWork(world, repeats, clock.Elapsed.TotalSeconds), Nothing)
                    If heavy IsNot Nothing Then
                        ' Physics at the engine's rate, not a runaway: noted, and the run ends here.
                        report(Invariants.Heavy, t, "reached t = " & t.ToString("R", inv) & " s of " & total.ToString("R", inv) & " s in the cap of " &
                            cap.ToString("R", inv) & " s, doing physics: " & heavy)
                        stopped = True
                        Exit For
                    End If
                    If t < total Then
                        report(Invariants.WallTime, t, "reached only t = " & t.ToString("R", inv) & " s of " & total.ToString("R", inv) &
                            " s in the cap of " & cap.ToString("R", inv) & " s (" & collisions & ")")
                        stopped = True
                        Exit For
                    End If
                    report(Invariants.WallTime, t, "took " & clock.Elapsed.TotalSeconds.ToString("0.0", inv) & " s, over the cap of " & cap.ToString("R", inv) & " s (" & collisions & ")")
                End If
            Next
            clock.Stop()
            outcome.WallSeconds = clock.Elapsed.TotalSeconds
            outcome.Collisions = world.CollisionCount
            outcome.Completed = Not stopped
            If Not stopped Then outcome.Final = New FinalState(world)
            Return outcome
        End Function

        ''' <summary>
        ''' The figures of an event-solver run that is still doing physics at the engine's rate (see
        ''' <see cref="Invariants.Heavy"/>), or Nothing when it is not: too few collisions per wall-clock second,
        ''' too many events per collision, or too many collisions at one instant.
        ''' </summary>
        Friend Function HeavyWork(world As World, repeats As Long, wallSeconds As Double) As String
            Dim collisions = world.CollisionCount
            If collisions = 0 OrElse wallSeconds <= 0 OrElse world.Time <= 0 Then Return Nothing
            Dim rate = collisions / wallSeconds
            Dim perCollision = DirectCast(world.Solver, EventDrivenSolver).EventCount / CDbl(collisions)
            Dim repeated = repeats / CDbl(collisions)
            If rate < Invariants.HeavyCollisionRate OrElse perCollision > Invariants.HeavyEventsPerCollision OrElse repeated > Invariants.HeavyRepeatFraction Then Return Nothing
            Dim inv = Globalization.CultureInfo.InvariantCulture
            Return collisions.ToString(inv) & " collisions, " & (collisions / world.Time).ToString("0.00E+0", inv) & " per simulated s, " &
                rate.ToString("0.00E+0", inv) & " per wall-clock s, " & perCollision.ToString("0.00", inv) & " events per collision, " &
                repeated.ToString("0.0000", inv) & " of them at the instant before"
        End Function

        ''' <summary>A message on one line (worker lines and failure lines are one line each).</summary>
        Friend Function OneLine(message As String) As String
            If message Is Nothing Then Return ""
            Return String.Join(" ", message.Split({ChrW(13), ChrW(10), ChrW(9)}, StringSplitOptions.RemoveEmptyEntries)).Trim()
        End Function
    End Module
End Namespace
