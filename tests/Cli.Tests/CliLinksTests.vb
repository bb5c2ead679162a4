Option Strict On
Imports System.Globalization
Imports System.IO
Imports Xunit

''' <summary>
''' run with links, with every solver: a pendulum on a string ends where the elliptic closed form puts it
''' (to the step's order for the stepping solvers), the lesson scenes with chains of rods run with the event
''' solver, a box pulled along a table by a spring slides as the spring says, and a string snapping taut has
''' its row in the collisions CSV.
''' </summary>
Public Class CliLinksTests
    Private Const G As Double = 9.81

    ''' <summary>A 0.5 kg bob on a 1 m string from (5, 6), released at rest 60° out.</summary>
    Private Shared ReadOnly PendulumScene As String = Q("{'format':'physics-scene/1','world':{'width':10,'height':10,'gravity':9.81,'restitution':1},'bodies':[" &
        "{'id':'bob','type':'circle','x':" & (5 + Math.Sin(Math.PI / 3)).ToString("R", CultureInfo.InvariantCulture) &
        ",'y':5.5,'radius':0.05,'mass':0.5}],'links':[{'type':'string','a':'bob','at':[5,6],'length':1}]}")

    ''' <summary>A box (0.5 kg) on a vertical spring (40 N/m) from a point 1 m above its centre, released at rest.</summary>
    Private Shared ReadOnly SpringBoxScene As String = Q("{'format':'physics-scene/1','world':{'width':10,'height':10,'gravity':9.81,'restitution':1},'bodies':[" &
        "{'id':'box','type':'rectangle','x':4.75,'y':4.25,'width':0.5,'height':0.5,'fixed':false,'mass':0.5}]," &
        "'links':[{'type':'spring','a':'box','at':[5,5.5],'stiffness':40}]}")

    ''' <summary>A bob on a rod, and a box on a table pulled along it by a spring: the event solver does not yet let a body on a spring off the vertical rest on anything.</summary>
    Private Shared ReadOnly BoxOnTableScene As String = Q("{'format':'physics-scene/1','world':{'width':10,'height':10,'gravity':9.81,'restitution':1},'bodies':[" &
        "{'id':'bob','type':'circle','x':5,'y':5,'radius':0.05,'mass':0.5,'vx':1},{'id':'table','type':'rectangle','x':1,'y':0,'width':2,'height':1}," &
        "{'id':'box','type':'rectangle','x':1.5,'y':1,'width':0.3,'height':0.2,'fixed':false,'mass':2}]," &
        "'links':[{'type':'rod','a':'bob','at':[5,6]},{'type':'spring','a':'box','at':[2.65,1.1],'stiffness':10,'rest_length':0.5}]}")

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
    Public Sub ABoxOnASpring_WithTheEventSolver_IsTheSimpleHarmonicClosedForm()
        Using t As New TempFolder()
            Dim scene = t.Write("spring-box.json", SpringBoxScene)
            Dim states = t.File("states.csv")
            Dim r = RunCli("run", scene, "--time", "2", "--sample", "0.5", "--solver", "event", "--states", states)
            Assert.True(r.ExitCode = 0, r.ToString())
            Assert.DoesNotContain("verlet", r.StdErr, StringComparison.OrdinalIgnoreCase)
            Dim last = File.ReadAllLines(states).Last().Split(","c)
            Assert.Equal("2", last(0))
            Assert.Equal("box", last(1))
            ' The states table gives the lower-left corner: it follows the centre, y_eq + (mg/k) cos(√(k/m) t).
            Dim stretch = 0.5 * G / 40
            Dim exact = 4.25 - stretch + stretch * Math.Cos(Math.Sqrt(40 / 0.5) * 2)
            Assert.Equal(4.75, D(last(2)), 9)
            Assert.Equal(exact, D(last(3)), 9)
        End Using
    End Sub

    <Fact>
    Public Sub ABoxOnATablePulledAlongItByASpring_InASceneWithLinks_RunsWithTheEventSolver_AsTheSpringSays()
        ' The spring lies level with the box's centre: simple harmonic motion along the table top about the
        ' spring's rest, x = 2.15 − 0.5 cos(√(k/m) t) for the centre, the box held on the table.
        Using t As New TempFolder()
            Dim scene = t.Write("box.json", BoxOnTableScene)
            Dim states = t.File("states.csv")
            Dim r = RunCli("run", scene, "--time", "1", "--solver", "event", "--states", states)
            Assert.True(r.ExitCode = 0, r.ToString())
            Assert.DoesNotContain("verlet", r.StdErr, StringComparison.OrdinalIgnoreCase)
            Dim last = IO.File.ReadAllLines(states).Skip(1).Select(Function(l) l.Split(","c)).Last(Function(c) c(1) = "box")
            Assert.Equal("1", last(0))
            Assert.Equal(2.15 - 0.5 * Math.Cos(Math.Sqrt(5.0)) - 0.15, D(last(2)), 9)
            Assert.Equal(1.0, D(last(3)), 12)
        End Using
    End Sub
    <Fact>
    Public Sub AStringSnappingTaut_IsARowOfItsOwnInTheCollisionsCsv()
        ' The collisions CSV names a string snapping taut: kind string-taut, b the string's id (docs/cli.md).
        Using t As New TempFolder()
            Dim events = t.File("events.csv")
            Dim scene = Path.Combine(RepoRoot, "tests", "cases", "string-taut-not-in-events.json")
            Dim r = RunCli("run", scene, "--time", "1", "--solver", "event", "--events", events)
            Assert.True(r.ExitCode = 0, r.ToString())
            Dim rows = IO.File.ReadAllLines(events).Skip(1).Select(Function(l) l.Split(","c)).ToList()
            Dim snap = rows.First(Function(c) c(3) = "string-taut")
            Assert.Equal("bob", snap(1))
            Assert.Equal("s", snap(2))
            Assert.InRange(D(snap(0)), 0.4, 0.45)
        End Using
    End Sub
    <Fact>
    Public Sub ARodWhoseEndsTheFileSetsMovingApart_KeepsItsLength_AndTheRunSaysSo()
        ' The file gives the bob a speed along its rod: the run makes the rod keep its length from the start (the
        ' least change of kinetic energy) and says what it did, on standard error, before it starts.
        Using t As New TempFolder()
            Dim scene = t.Write("rod.json", Q("{'format':'physics-scene/1','world':{'width':10,'height':10,'gravity':9.81,'restitution':1}," &
                "'bodies':[{'id':'bob','type':'circle','x':5,'y':4,'radius':0.1,'mass':2,'vx':1,'vy':-0.5}]," &
                "'links':[{'id':'arm','type':'rod','a':'bob','at':[5,5]}]}"))
            Dim r = RunCli("run", scene, "--time", "1", "--solver", "event")
            Assert.True(r.ExitCode = 0, r.ToString())
            Assert.Contains("note: links[0] ('arm', a rod): its ends moved apart along it; they now keep its length (kinetic energy 1.25 J before, 1 J after)", r.StdErr)
        End Using
    End Sub

    <Theory>
    <InlineData("double-pendulum.json")>
    <InlineData("rope.json")>
    Public Sub ChainLessonScenes_RunWithTheEventSolver_AndKeepTheirRodLengths(file As String)
        Using t As New TempFolder()
            Dim scene = Path.Combine(RepoRoot, "scenes", file)
            Dim states = t.File("states.csv")
            Dim r = RunCli("run", scene, "--time", "2", "--sample", "0.5", "--solver", "event", "--states", states)
            Assert.True(r.ExitCode = 0, r.ToString())
            Assert.DoesNotContain("verlet", r.StdErr, StringComparison.OrdinalIgnoreCase)
            ' Each rod's length from the last sample's positions, against its ends' distance at the start.
            Dim rows = IO.File.ReadAllLines(states).Skip(1).Select(Function(l) l.Split(","c)).ToList()
            Dim first = rows.Where(Function(c) c(0) = "0").ToDictionary(Function(c) c(1), Function(c) New Vector(D(c(2)), D(c(3))))
            Dim last = rows.Where(Function(c) c(0) = "2").ToDictionary(Function(c) c(1), Function(c) New Vector(D(c(2)), D(c(3))))
            Assert.Equal(first.Count, last.Count)
            Dim names = first.Keys.Where(Function(k) Not k.StartsWith("free", StringComparison.Ordinal)).ToList()
            For i = 1 To names.Count - 1
                Dim before = (first(names(i)) - first(names(i - 1))).Length
                Dim after = (last(names(i)) - last(names(i - 1))).Length
                Assert.True(Math.Abs(after - before) < 0.000000001, $"{file}: {names(i - 1)}–{names(i)} was {before} m apart and is {after} m")
            Next
            ' And it moved.
            Assert.NotEqual(first(names.Last()), last(names.Last()))
        End Using
    End Sub

    Private Shared Function D(text As String) As Double
        Return Double.Parse(text, CultureInfo.InvariantCulture)
    End Function
End Class
