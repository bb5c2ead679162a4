Option Strict On
Imports System.Diagnostics
Imports System.Globalization
Imports System.IO
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Fuzzing.Generation
Imports Xunit

''' <summary>A fuzzer run is the command line's run: the same sample times, the same advances, the same end state.</summary>
Public Class SceneRunnerTests
    <Fact>
    Public Sub SampleTimes_AreProductsOfTheInterval_ThenTheEnd()
        Assert.Equal(New List(Of Double) From {0.0, 0.3, 2 * 0.3, 3 * 0.3, 1.0}, SampleClock.Times(1.0, 0.3).ToList())
        Assert.Equal(New List(Of Double) From {0.0, 0.25, 0.5, 0.75, 1.0}, SampleClock.Times(1.0, 0.25).ToList())
        Assert.Equal(New List(Of Double) From {0.0, 0.05}, SampleClock.Times(0.05, 0.05).ToList())
        Assert.Equal(New List(Of Double) From {0.0, 0.02}, SampleClock.Times(0.02, 0.05).ToList())
        ' 7 × 0.05 is 0.35000000000000003: a run to that time ends there, with no extra sample just before it
        Assert.Equal(New List(Of Double) From {0.0, 0.05, 2 * 0.05, 3 * 0.05, 4 * 0.05, 5 * 0.05, 6 * 0.05, 7 * 0.05}, SampleClock.Times(7 * 0.05, 0.05).ToList())
    End Sub

    <Fact>
    Public Sub ARunOverTheCap_StopsWithAWallTimeFailure()
        Dim text = SceneGenerator.Generate(3, BodyKinds.Default, 40).ToText()
        Dim outcome = SceneRunner.Run(text, "verlet", 1.0, 0.05, cap:=0.000000001)
        Dim v = Assert.Single(outcome.Violations)
        Assert.Equal(Invariants.WallTime, v.Invariant)
        Assert.False(outcome.Completed)
    End Sub

    <Fact>
    Public Sub AnEventRunDoingPhysics_IsHeavy_ButOneSpinningOrStalledIsNot()
        Dim world = Scenarios.ElasticGas(200)
        world.Solver = New EventDrivenSolver()
        world.Advance(2.0)
        Dim collisions = world.CollisionCount
        Assert.True(collisions > 100, collisions & " collisions")
        ' The same run seen as having taken a thousandth of a second per thousand collisions: the engine's rate.
        Dim fast = collisions / (10 * Invariants.HeavyCollisionRate)
        Dim heavy = SceneRunner.HeavyWork(world, 0, fast)
        Assert.NotNull(heavy)
        Assert.Contains("events per collision", heavy, StringComparison.Ordinal)
        ' Too slow per collision, or its collisions all at the instant before (a runaway at one instant): not heavy.
        Assert.Null(SceneRunner.HeavyWork(world, 0, collisions / (0.5 * Invariants.HeavyCollisionRate)))
        Assert.Null(SceneRunner.HeavyWork(world, collisions \ 2, fast))
        ' No collisions at all (a solver spinning on other events): not heavy.
        Dim still = Scenarios.ElasticGas(1, 0.01)
        still.Solver = New EventDrivenSolver()
        still.Advance(0.001)
        Assert.Equal(0L, still.CollisionCount)
        Assert.Null(SceneRunner.HeavyWork(still, 0, 0.001))
    End Sub

    <Theory>
    <InlineData("event")>
    <InlineData("euler")>
    Public Sub ASolverThatThrows_IsAnExceptionFailure(solver As String)
        ' faster than World.MaxSpeed: the world refuses to advance it
        Dim text = "{""format"": ""physics-scene/1"", ""world"": {""width"": 2, ""height"": 2}, ""bodies"": [" &
            "{""id"": ""a"", ""type"": ""circle"", ""x"": 1, ""y"": 1, ""radius"": 0.1, ""mass"": 1, ""vx"": 1e151}]}"
        Dim outcome = SceneRunner.Run(text, solver, 1.0, 0.05, 10)
        Dim v = Assert.Single(outcome.Violations)
        Assert.Equal(Invariants.Crash, v.Invariant)
        Assert.Contains("SpeedLimitException between t = 0 s and t = 0.05 s", v.Message, StringComparison.Ordinal)
        Assert.False(outcome.Completed)
    End Sub

    <Theory>
    <InlineData("event")>
    <InlineData("euler")>
    <InlineData("verlet")>
    Public Sub TheEndState_IsTheCommandLinesToTheBit(solver As String)
        Dim folder = Path.Combine(Path.GetTempPath(), "fuzz-cli-" & Guid.NewGuid().ToString("N"))
        Directory.CreateDirectory(folder)
        Try
            For Each seed In {4, 8, 21}
                Dim text = SceneGenerator.Generate(seed, BodyKinds.Default, 40).ToText()
                Dim scene = Path.Combine(folder, "scene.json")
                Dim states = Path.Combine(folder, "s.csv")
                File.WriteAllText(scene, text)
                Const total = 0.5, sample = 0.05
                Dim outcome = SceneRunner.Run(text, solver, total, sample, 60)
                Assert.True(outcome.Completed)
                Dim cli = RunCli(scene, "--time", "0.5", "--solver", solver, "--sample", "0.05", "--states", states)
                Assert.True(cli = 0, $"the command line exited {cli}")
                Dim world = Scenes.SceneFile.Load(text)
                Dim last = File.ReadAllLines(states).Skip(1).Select(Function(l) l.Split(","c)).Where(Function(f) f(0) = "0.5").ToList()
                Dim movable = world.Circles.Where(Function(c) Not c.IsFixed).ToList()
                Assert.Equal(movable.Count, last.Count)
                ' run again in this process to read the end state; the fuzzer's FinalState compares it field by field
                world.Solver = SolverFactory.Create(solver)
                For Each t In SampleClock.Times(total, sample)
                    world.Advance(t - world.Time)
                Next
                Assert.Null(FinalState.FirstDifference(outcome.Final, New FinalState(world), "fuzzer", "again"))
                For i = 0 To movable.Count - 1
                    Dim f = last(i)
                    Assert.Equal(movable(i).Id, f(1))
                    Dim numbers = {movable(i).Position.X, movable(i).Position.Y, movable(i).Velocity.X, movable(i).Velocity.Y}
                    For k = 0 To 3
                        Assert.Equal(BitConverter.DoubleToInt64Bits(numbers(k)), BitConverter.DoubleToInt64Bits(Double.Parse(f(2 + k), CultureInfo.InvariantCulture)))
                    Next
                Next
            Next
        Finally
            Directory.Delete(folder, recursive:=True)
        End Try
    End Sub

    Private Shared Function RunCli(ParamArray args As String()) As Integer
        Dim psi As New ProcessStartInfo("dotnet") With {.UseShellExecute = False, .RedirectStandardOutput = True, .RedirectStandardError = True}
        psi.ArgumentList.Add(TestPaths.CliDll)
        psi.ArgumentList.Add("run")
        For Each a In args
            psi.ArgumentList.Add(a)
        Next
        Using p = Process.Start(psi)
            Dim outText = p.StandardOutput.ReadToEndAsync()
            Dim errText = p.StandardError.ReadToEndAsync()
            If Not p.WaitForExit(120000) Then
                p.Kill(True)
                Throw New TimeoutException("the command line did not finish")
            End If
            p.WaitForExit()
            Return p.ExitCode
        End Using
    End Function
End Class
