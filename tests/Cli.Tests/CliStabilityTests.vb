Option Strict On
Imports System.IO
Imports System.Text.Json
Imports Xunit

''' <summary>
''' run with a stepping solver on a spring too stiff for its step (ω h ≥ 2, where the step's swing grows without
''' bound): the run still succeeds (exit 0), and the summary says which spring and why, as a last text line
''' "warning" or the JSON field "warning"; with the event solver, or a spring the step can follow, there is
''' no such line and the field is null. A run that blows up past the speeds a double can hold fails as before,
''' with the same sentence in its message.
''' </summary>
Public Class CliStabilityTests
    ''' <summary>
    ''' g = 0, no walls: a 1 kg ball 0.05 m from its rest on a spring from the point (5, 5), of stiffness
    ''' <paramref name="stiffness"/> N/m: ω = √k rad/s, so 9 × 10⁶ N/m is ω h = 3 at a step of 1 ms.
    ''' </summary>
    Private Shared Function SpringScene(stiffness As String) As String
        Return Q("{'format':'physics-scene/1','world':{'width':10,'height':10,'gravity':0,'restitution':1,'walls':false},'bodies':[" &
            "{'id':'ball','type':'circle','x':5.1,'y':5,'radius':0.01,'mass':1}]," &
            "'links':[{'id':'s','type':'spring','a':'ball','at':[5,5],'stiffness':" & stiffness & ",'rest_length':0.05}]}")
    End Function

    ''' <summary>
    ''' Writes <see cref="SpringScene"/> of <paramref name="stiffness"/> to a fresh folder, runs "run" on it with
    ''' <paramref name="args"/> after the scene's name, and checks that it exited with <paramref name="exitCode"/>.
    ''' </summary>
    Private Shared Function RunSpring(stiffness As String, exitCode As Integer, ParamArray args As String()) As ProcessResult
        Using t As New TempFolder()
            Dim scene = t.Write("spring.json", SpringScene(stiffness))
            Dim r = RunCli({"run", scene}.Concat(args).ToArray())
            Assert.True(r.ExitCode = exitCode, r.ToString())
            Return r
        End Using
    End Function

    Private Const Stiff As String = "9000000"
    Private Const Soft As String = "40"

    <Theory>
    <InlineData("verlet")>
    <InlineData("euler")>
    Public Sub AStiffSpring_WithAStepSolver_EndsTheTextSummaryWithAWarning_AndExits0(solver As String)
        Dim r = RunSpring(Stiff, 0, "--time", "0.02", "--solver", solver, "--dt", "0.001")
        Dim last = r.StdOut.TrimEnd().Split(ChrW(10)).Last()
        Assert.StartsWith("warning           spring s has ω h = 3 (k = 9E+06 N/m, ω = 3000 rad/s, h = 0.001 s), beyond the stability limit ω h < 2", last, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub AStiffSpring_WithAStepSolver_HasTheWarningInTheJsonSummary()
        Dim r = RunSpring(Stiff, 0, "--time", "0.02", "--solver", "verlet", "--dt", "0.001", "--json")
        Using doc = JsonDocument.Parse(r.StdOut)
            Dim warning = doc.RootElement.GetProperty("warning")
            Assert.Equal(JsonValueKind.String, warning.ValueKind)
            Assert.StartsWith("spring s has ω h = 3 ", warning.GetString(), StringComparison.Ordinal)
            ' The fields of the contract keep their meaning: the run is reported as it went.
            Assert.Equal("verlet", doc.RootElement.GetProperty("solver").GetString())
            Assert.Equal(0.001, doc.RootElement.GetProperty("dt").GetDouble())
        End Using
    End Sub

    <Fact>
    Public Sub AStiffSpring_RunUntilItsSpeedOverflows_FailsWithTheWarningInItsMessage()
        Dim r = RunSpring(Stiff, 1, "--time", "1", "--solver", "verlet", "--dt", "0.001", "--json")
        Assert.Contains("faster than", r.StdErr, StringComparison.Ordinal)
        Assert.Contains("; spring s has ω h = 3 ", r.StdErr, StringComparison.Ordinal)
    End Sub

    <Theory>
    <InlineData(Stiff, "event")>
    <InlineData(Soft, "verlet")>
    <InlineData(Soft, "euler")>
    Public Sub TheEventSolver_OrASpringTheStepFollows_HasNoWarning(stiffness As String, solver As String)
        Dim text = RunSpring(stiffness, 0, "--time", "0.02", "--solver", solver)
        Assert.DoesNotContain("warning", text.StdOut, StringComparison.Ordinal)
        Dim json = RunSpring(stiffness, 0, "--time", "0.02", "--solver", solver, "--json")
        Using doc = JsonDocument.Parse(json.StdOut)
            Assert.Equal(JsonValueKind.Null, doc.RootElement.GetProperty("warning").ValueKind)
        End Using
    End Sub
End Class
