Option Strict On
Imports System.Globalization
Imports System.IO
Imports Xunit

''' <summary>
''' run with links, with every solver: a pendulum on a string ends where the elliptic closed form puts it
''' (to the step's order for the stepping solvers), and a scene the event solver cannot move yet fails
''' with its plain message, not an internal error.
''' </summary>
Public Class CliLinksTests
    Private Const G As Double = 9.81

    ''' <summary>A 0.5 kg bob on a 1 m string from (5, 6), released at rest 60° out.</summary>
    Private Shared ReadOnly PendulumScene As String = Q("{'format':'physics-scene/1','world':{'width':10,'height':10,'gravity':9.81,'restitution':1},'bodies':[" &
        "{'id':'bob','type':'circle','x':" & (5 + Math.Sin(Math.PI / 3)).ToString("R", CultureInfo.InvariantCulture) &
        ",'y':5.5,'radius':0.05,'mass':0.5}],'links':[{'type':'string','a':'bob','at':[5,6],'length':1}]}")

    ''' <summary>Two bobs, one below the other: a chain of two rods.</summary>
    Private Shared ReadOnly ChainScene As String = Q("{'format':'physics-scene/1','world':{'width':10,'height':10,'gravity':9.81,'restitution':1},'bodies':[" &
        "{'id':'upper','type':'circle','x':5,'y':5,'radius':0.05,'mass':0.5},{'id':'lower','type':'circle','x':5,'y':4,'radius':0.05,'mass':0.5,'vx':1}]," &
        "'links':[{'type':'rod','a':'upper','at':[5,6]},{'type':'rod','a':'lower','b':'upper'}]}")

    <Theory>
    <InlineData("event", 0.000000001)>
    <InlineData("verlet", 0.0001)>
    <InlineData("euler", 0.01)>
    Public Sub PendulumOnAString_EndsOnTheClosedForm(solver As String, tolerance As Double)
        Using t As New TempFolder()
            Dim scene = t.Write("pendulum.json", PendulumScene)
            Dim states = t.File("states.csv")
            Dim r = RunCli("run", scene, "--time", "2", "--sample", "0.5", "--solver", solver, "--states", states)
            Assert.True(r.ExitCode = 0, r.ToString())
            Dim last = File.ReadAllLines(states).Last().Split(","c)
            Assert.Equal("2", last(0))
            Assert.Equal("bob", last(1))
            Dim x = Double.Parse(last(2), CultureInfo.InvariantCulture), y = Double.Parse(last(3), CultureInfo.InvariantCulture)
            Dim exact = New Pendulum(New Vector(5, 6), 1, G, New Vector(5 + Math.Sin(Math.PI / 3), 5.5), Vector.Zero).PositionAt(2)
            Assert.True((New Vector(x, y) - exact).Length < tolerance, $"{solver}: ({x}, {y}) against {exact}")
        End Using
    End Sub

    <Fact>
    Public Sub AChainOfLinks_WithTheEventSolver_FailsInPlainWords_AndRunsWithVerlet()
        Using t As New TempFolder()
            Dim scene = t.Write("chain.json", ChainScene)
            Dim r = RunCli("run", scene, "--time", "1", "--solver", "event")
            Assert.Equal(1, r.ExitCode)
            Assert.Contains("chain of links", r.StdErr)
            Assert.Contains("--solver verlet", r.StdErr)
            Assert.DoesNotContain("internal error", r.StdErr)
            Dim ok = RunCli("run", scene, "--time", "1", "--solver", "verlet")
            Assert.True(ok.ExitCode = 0, ok.ToString())
        End Using
    End Sub
End Class
