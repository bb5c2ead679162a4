Option Strict On
Imports System.Diagnostics
Imports System.IO
Imports System.Runtime.InteropServices
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Fuzzing.Generation
Imports PhysicsEngine.Fuzzing.Workers
Imports Xunit

''' <summary>Worker processes: the same results as checking in this process; a silent worker is killed, a dead one reported.</summary>
Public Class WorkerTests
    Private Shared Function Scratch() As String
        Return Path.Combine(Path.GetTempPath(), "fuzz-worker-test-" & Guid.NewGuid().ToString("N") & ".json")
    End Function

    <Fact>
    Public Sub AWorker_FindsWhatThisProcessFinds()
        Dim plan As New RunPlan(0.5, 0.05, 0.013, 60)
        Using worker As New WorkerProcess(Scratch())
            Dim here As New InProcessChecker()
            For Each seed In {1, 7, 12, 14}
                Dim text = SceneGenerator.Generate(seed, BodyKinds.Default, 40).ToText()
                For Each solver In {"event", "euler", "verlet"}
                    Dim there = worker.Check(text, solver, plan, Nothing)
                    Dim local = here.Check(text, solver, plan, Nothing)
                    Assert.Equal(local.Collisions, there.Collisions)
                    Assert.Equal(String.Join(vbLf, local.Violations.Select(Function(v) v.ToString())), String.Join(vbLf, there.Violations.Select(Function(v) v.ToString())))
                Next
            Next
        End Using
    End Sub

    <Fact>
    Public Sub ASceneTheReaderRefuses_IsReportedAsSuch()
        Dim text = "{""format"": ""physics-scene/1"", ""world"": {""width"": 1, ""height"": 1}, ""bodies"": [{""type"": ""circle"", ""x"": 0.5, ""y"": 0.5, ""radius"": 2, ""mass"": 1}]}"
        Using worker As New WorkerProcess(Scratch())
            Dim r = worker.Check(text, "event", New RunPlan(1, 0.05, 0, 10), Nothing)
            Assert.Equal(Invariants.Refused, Assert.Single(r.Violations).Invariant)
            ' and the worker goes on with the next scene
            Dim ok = worker.Check(SceneGenerator.Generate(2, BodyKinds.Default, 40).ToText(), "euler", New RunPlan(0.1, 0.05, 0, 10), Nothing)
            Assert.DoesNotContain(ok.Violations, Function(v) v.Invariant = Invariants.Refused OrElse v.Invariant = Invariants.Crash)
        End Using
    End Sub

    <Fact>
    Public Sub AWorkerThatGoesSilent_IsKilled_AndTheRunFailsTheCap()
        If Not RuntimeInformation.IsOSPlatform(OSPlatform.Linux) AndAlso Not RuntimeInformation.IsOSPlatform(OSPlatform.OSX) Then Return ' the stand-in worker is the Unix shell
        Dim started As Process = Nothing
        Dim silent = Function()
                         Dim psi As New ProcessStartInfo("/bin/sh") With {.RedirectStandardInput = True, .RedirectStandardOutput = True, .RedirectStandardError = True, .UseShellExecute = False}
                         psi.ArgumentList.Add("-c")
                         psi.ArgumentList.Add("sleep 600")
                         Return psi
                     End Function
        Dim clock = Stopwatch.StartNew()
        Using worker As New WorkerProcess(Scratch(), silent)
            ' cap 0.1 s: the worker may be silent for 2 × 0.1 + 5 s
            Dim r = worker.Check(SceneGenerator.Generate(2, BodyKinds.Default, 40).ToText(), "event", New RunPlan(1, 0.05, 0, 0.1), Nothing)
            Dim v = Assert.Single(r.Violations)
            Assert.Equal(Invariants.WallTime, v.Invariant)
            Assert.Contains("killed", v.Message, StringComparison.Ordinal)
        End Using
        Assert.InRange(clock.Elapsed.TotalSeconds, 5.2, 60)
    End Sub

    <Fact>
    Public Sub AWorkerThatDies_IsReported_WithItsExitCode()
        If Not RuntimeInformation.IsOSPlatform(OSPlatform.Linux) AndAlso Not RuntimeInformation.IsOSPlatform(OSPlatform.OSX) Then Return
        Dim dying = Function()
                        Dim psi As New ProcessStartInfo("/bin/sh") With {.RedirectStandardInput = True, .RedirectStandardOutput = True, .RedirectStandardError = True, .UseShellExecute = False}
                        psi.ArgumentList.Add("-c")
                        psi.ArgumentList.Add("read line; echo 'out of stack' >&2; exit 134")
                        Return psi
                    End Function
        Using worker As New WorkerProcess(Scratch(), dying)
            Dim r = worker.Check(SceneGenerator.Generate(2, BodyKinds.Default, 40).ToText(), "event", New RunPlan(1, 0.05, 0, 10), Nothing)
            Dim v = Assert.Single(r.Violations)
            Assert.Equal(Invariants.Crash, v.Invariant)
            Assert.Contains("exit code 134", v.Message, StringComparison.Ordinal)
            Assert.Contains("out of stack", v.Message, StringComparison.Ordinal)
        End Using
    End Sub
End Class
