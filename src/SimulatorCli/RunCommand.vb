Option Strict On
Imports System.Diagnostics
Imports System.Threading

''' <summary>
''' run SCENE --time T: checks every argument and the scene before any output file exists, then
''' runs, sampling states and totals at t = 0, S, 2S, … and T, logging every collision, and prints the summary.
''' </summary>
Friend Module RunCommand
    Friend Const StatesHeader As String = "t,id,x,y,vx,vy"
    Friend Const EventsHeader As String = "t,a,b,kind,a_vx_before,a_vy_before,a_vx_after,a_vy_after,b_vx_before,b_vy_before,b_vx_after,b_vy_after"
    Friend Const SeriesHeader As String = "t,ke,pe,energy,px,py,com_x,com_y,dissipated"

    Friend Function Execute(o As RunOptions) As Integer
        ' Everything that can be bad input is checked here, before any file is created.
        Dim world = SceneInput.Load(o.ScenePath)
        For Each output In o.Outputs
            OutputFile.CheckTarget(output.Name, output.Path)
        Next
        world.Solver = CreateSolver(o, world)
        ' A valid scene too fast to simulate fails (exit 1) before any file is created.
        world.CheckSpeeds()
        ' A rod whose ends the file sets moving apart keeps its length from the start: say what was changed.
        For Each note In world.HoldLinks()
            Console.Error.WriteLine("note: " & note)
        Next

        Dim states As OutputFile = Nothing
        Dim events As OutputFile = Nothing
        Dim series As OutputFile = Nothing
        ' Ctrl+C and SIGTERM: throw the temporary files away, say so, exit 1 (see RunInterruption).
        Using interruption As New RunInterruption(
            Function()
                states?.Dispose()
                events?.Dispose()
                series?.Dispose()
                Return {states, events, series}.Where(Function(f) f IsNot Nothing AndAlso f.IsStream).Select(Function(f) f.Target).ToList()
            End Function)
            Try
                If o.StatesPath IsNot Nothing Then states = OutputFile.Create("--states", o.StatesPath)
                If o.EventsPath IsNot Nothing Then events = OutputFile.Create("--events", o.EventsPath)
                If o.SeriesPath IsNot Nothing Then series = OutputFile.Create("--series", o.SeriesPath)
                Dim summary = Simulate(world, o, states, events, series)
                interruption.Finishing()
                states?.Commit()
                events?.Commit()
                series?.Commit()
                Console.Out.WriteLine(If(o.Json, summary.ToJson(), summary.ToText()))
                Return ExitCodes.Ok
            Catch ex As Exception When interruption.Interrupted
                ' A signal closed the files under this thread, and the process is exiting with the
                ' signal's message: nothing more to say.
                Thread.Sleep(Timeout.Infinite)
                Throw
            Finally
                states?.Dispose()
                events?.Dispose()
                series?.Dispose()
            End Try
        End Using
    End Function

    Private Function CreateSolver(o As RunOptions, world As World) As ISolver
        Try
            Return SolverFactory.Create(o.SolverName, o.TimeStep, world)
        Catch ex As ArgumentException
            If SolverFactory.Names.Contains(o.SolverName) Then
                Throw New BadInputException("--solver: '" & o.SolverName & "' is not available in this build", ex)
            End If
            Throw New BadInputException("--solver: unknown solver '" & o.SolverName & "' (expected one of: " & String.Join(", ", SolverFactory.Names) & ")", ex)
        End Try
    End Function

    Private Function Simulate(world As World, o As RunOptions, states As OutputFile, events As OutputFile, series As OutputFile) As RunSummary
        ' Every movable body, in the scene's order: circles, boxes and polygons alike.
        Dim movable = world.Movables.ToList()
        If events IsNot Nothing Then
            events.Writer.WriteLine(EventsHeader)
            world.CollisionListener = Sub(r) WriteCollision(events.Writer, r)
        End If
        states?.Writer.WriteLine(StatesHeader)
        series?.Writer.WriteLine(SeriesHeader)
        Dim warning = StabilityWarning(world)
        Dim clock = Stopwatch.StartNew()
        For Each t In SampleTimes(o.Time, o.Sample)
            Try
                world.Advance(t - world.Time)
            Catch ex As SpeedLimitException When warning IsNot Nothing
                ' The run blew up, as a step beyond the limit does: say why.
                Throw New SpeedLimitException(ex.Message & "; " & warning, ex)
            Catch ex As Exception When Not TypeOf ex Is OutOfMemoryException AndAlso Not TypeOf ex Is SpeedLimitException AndAlso Not TypeOf ex Is UnsupportedSceneException
                Throw New InvalidOperationException("the " & world.Solver.Name & " solver failed between t = " & CsvText.Number(world.Time) & " s and t = " & CsvText.Number(t) & " s: " & ex.Message &
                    If(warning Is Nothing, "", "; " & warning), ex)
            End Try
            If states IsNot Nothing Then WriteStates(states.Writer, t, movable)
            If series IsNot Nothing Then WriteTotals(series.Writer, t, world)
        Next
        clock.Stop()
        Return New RunSummary(o, world, movable.Count, clock.Elapsed.TotalSeconds, warning)
    End Function

    ''' <summary>
    ''' Nothing, or (with a stepping solver) the sentence naming the spring too stiff for its step, ω h ≥ 2: the step
    ''' cannot follow it, its swing grows without bound, and the run's energies say nothing (see <see cref="StepStability"/>).
    ''' The run goes on, and the summary ends with the sentence.
    ''' </summary>
    Friend Function StabilityWarning(world As World) As String
        If world.Solver.TimeStep.HasValue Then Return StepStability.BeyondLimit(world, world.Solver.TimeStep.Value)
        Return Nothing
    End Function

    ''' <summary>
    ''' t = 0, S, 2S, … (each k·S, not a running sum, so no drift) and T last; a k·S within 1e-9·S of T
    ''' is T itself, so there is no near-duplicate row when T is a multiple of S.
    ''' </summary>
    Friend Iterator Function SampleTimes(total As Double, sample As Double) As IEnumerable(Of Double)
        Dim k = 0L
        Do
            Dim t = k * sample
            If t >= total - sample * 0.000000001 Then Exit Do
            Yield t
            k += 1
        Loop
        Yield total
    End Function

    ''' <summary>One row per movable body: its reference point, the point the scene file gives (a circle's centre, a rectangle's lower-left corner, a polygon's centroid).</summary>
    Private Sub WriteStates(w As IO.TextWriter, t As Double, movable As List(Of Shape))
        Dim time = CsvText.Number(t)
        For Each c In movable
            w.Write(time)
            w.Write(","c)
            w.Write(CsvText.Field(c.Id))
            w.Write(","c)
            w.Write(CsvText.Number(c.Position.X))
            w.Write(","c)
            w.Write(CsvText.Number(c.Position.Y))
            w.Write(","c)
            w.Write(CsvText.Number(c.Velocity.X))
            w.Write(","c)
            w.WriteLine(CsvText.Number(c.Velocity.Y))
        Next
    End Sub

    ''' <summary>
    ''' One row of the totals: kinetic and potential energy and their sum (J), momentum (kg·m/s), centre of mass (m),
    ''' and the energy taken since the start by inelastic collisions, friction, drag and spring damping (J).
    ''' </summary>
    Private Sub WriteTotals(w As IO.TextWriter, t As Double, world As World)
        Dim ke = world.KineticEnergy()
        Dim pe = Totals.PotentialEnergy(world)
        Dim p = world.Momentum()
        Dim com = world.CentreOfMass()
        w.WriteLine(String.Join(",",
            CsvText.Number(t), CsvText.Number(ke), CsvText.Number(pe), CsvText.Number(ke + pe),
            CsvText.Number(p.X), CsvText.Number(p.Y), CsvText.Number(com.X), CsvText.Number(com.Y), CsvText.Number(world.Dissipated)))
    End Sub

    Private Sub WriteCollision(w As IO.TextWriter, r As CollisionRecord)
        w.WriteLine(String.Join(",",
            CsvText.Number(r.Time), CsvText.Field(r.A.Id), CsvText.Field(r.BName), r.KindName,
            CsvText.Number(r.AVelocityBefore.X), CsvText.Number(r.AVelocityBefore.Y),
            CsvText.Number(r.AVelocityAfter.X), CsvText.Number(r.AVelocityAfter.Y),
            CsvText.Number(r.BVelocityBefore.X), CsvText.Number(r.BVelocityBefore.Y),
            CsvText.Number(r.BVelocityAfter.X), CsvText.Number(r.BVelocityAfter.Y)))
    End Sub
End Module
