Option Strict On
Imports System.Globalization
Imports System.IO
Imports System.Text.Json
Imports Xunit

''' <summary>run SCENE --time T: the states and collisions CSVs and the summary, checked against closed forms.</summary>
Public Class CliRunTests
    Private Const StatesHeader As String = "t,id,x,y,vx,vy"
    Private Const EventsHeader As String = "t,a,b,kind,a_vx_before,a_vy_before,a_vx_after,a_vy_after,b_vx_before,b_vy_before,b_vx_after,b_vy_after"
    ''' <summary>Time of the head-on collision, s.</summary>
    Private Const HeadOnHit As Double = 3.8 / 3

    Private Shared Function D(text As String) As Double
        Return Double.Parse(text, NumberStyles.Float, CultureInfo.InvariantCulture)
    End Function

    Private Shared Function Lines(path As String) As String()
        Dim text = File.ReadAllText(path)
        Assert.DoesNotContain(vbCr, text)
        Assert.EndsWith(vbLf, text)
        Return text.TrimEnd(ChrW(10)).Split(ChrW(10))
    End Function

    <Fact>
    Public Sub States_AreSampledAtKTimesS_AndAtT_ForMovableCirclesInSceneOrder_ExactlyAtThoseTimes()
        Using t As New TempFolder()
            Dim scene = t.Write("head-on.json", HeadOn)
            Dim states = t.File("states.csv")
            Dim r = RunCli("run", scene, "--time", "0.35", "--sample", "0.1", "--solver", "euler", "--states", states)
            Assert.True(r.ExitCode = 0, r.ToString())
            Dim rows = Lines(states)
            Assert.Equal(StatesHeader, rows(0))
            Dim expectedTimes = {0.0, 0.1, 2 * 0.1, 3 * 0.1, 0.35}
            Assert.Equal(1 + 2 * expectedTimes.Length, rows.Length)
            For k = 0 To expectedTimes.Length - 1
                For Each pair In {(1, "light", 3.0, 2.0), (2, "heavy", 7.0, -1.0)}
                    Dim f = rows(1 + 2 * k + pair.Item1 - 1).Split(","c)
                    Assert.Equal(6, f.Length)
                    ' the t column is k·S itself (not a running sum), and T at the end
                    Assert.Equal(expectedTimes(k), D(f(0)))
                    Assert.Equal(pair.Item2, f(1))
                    ' before the collision each ball moves freely: x = x0 + v t at exactly that time
                    Assert.Equal(pair.Item3 + pair.Item4 * expectedTimes(k), D(f(2)), 9)
                    Assert.Equal(1.0, D(f(3)))
                    Assert.Equal(pair.Item4, D(f(4)))
                    Assert.Equal(0.0, D(f(5)))
                Next
            Next
        End Using
    End Sub

    <Theory>
    <InlineData("1", "0.25", "0|0.25|0.5|0.75|1")>
    <InlineData("0.3", "0.1", "0|0.1|0.2|0.3")>
    <InlineData("0.25", Nothing, "0|0.1|0.2|0.25")>
    <InlineData("0.05", "0.1", "0|0.05")>
    <InlineData("0.7", "0.1", "0|0.1|0.2|0.30000000000000004|0.4|0.5|0.6000000000000001|0.7")>
    Public Sub SampleTimes_HaveNoDuplicateRowAtT(time As String, sample As String, expected As String)
        Using t As New TempFolder()
            Dim scene = t.Write("ball.json", BouncingBall)
            Dim states = t.File("states.csv")
            Dim args As New List(Of String) From {"run", scene, "--time", time, "--states", states, "--solver", "euler"}
            If sample IsNot Nothing Then args.AddRange({"--sample", sample})
            Dim r = RunCli(args.ToArray())
            Assert.True(r.ExitCode = 0, r.ToString())
            Dim times = Lines(states).Skip(1).Select(Function(l) l.Split(","c)(0)).ToArray()
            Assert.Equal(expected, String.Join("|", times))
            Assert.All(Lines(states).Skip(1), Sub(l) Assert.Equal("ball", l.Split(","c)(1)))
        End Using
    End Sub

    <Fact>
    Public Sub Collisions_MatchTheClosedForm_OfAHeadOnElasticHit()
        Using t As New TempFolder()
            Dim scene = t.Write("head-on.json", HeadOn)
            Dim events = t.File("events.csv")
            Dim r = RunCli("run", scene, "--time", "2", "--solver", "euler", "--dt", "0.0001", "--events", events)
            Assert.True(r.ExitCode = 0, r.ToString())
            Dim rows = Lines(events)
            Assert.Equal(EventsHeader, rows(0))
            Assert.Equal(2, rows.Length)
            Dim f = rows(1).Split(","c)
            Assert.Equal(12, f.Length)
            Assert.Equal("circle-circle", f(3))
            Assert.Equal(HeadOnHit, D(f(0)), 3)
            ' whichever ball is "a", its before/after velocities follow v1' = ((m1 − e m2) u1 + (1 + e) m2 u2) / (m1 + m2)
            Dim expected As New Dictionary(Of String, (Before As Double, After As Double)) From {{"light", (2.0, -2.5)}, {"heavy", (-1.0, 0.5)}}
            Assert.NotEqual(f(1), f(2))
            Assert.Equal(expected(f(1)).Before, D(f(4)), 9)
            Assert.Equal(expected(f(1)).After, D(f(6)), 9)
            Assert.Equal(expected(f(2)).Before, D(f(8)), 9)
            Assert.Equal(expected(f(2)).After, D(f(10)), 9)
            For Each i In {5, 7, 9, 11}
                Assert.Equal(0.0, D(f(i)), 9)
            Next
        End Using
    End Sub

    <Fact>
    Public Sub WallCollisions_NameTheWall_AndGiveItZeroVelocities()
        Using t As New TempFolder()
            Dim scene = t.Write("ball.json", BouncingBall)
            Dim events = t.File("events.csv")
            Dim r = RunCli("run", scene, "--time", "0.6", "--solver", "euler", "--events", events)
            Assert.True(r.ExitCode = 0, r.ToString())
            Dim rows = Lines(events)
            Assert.Equal(EventsHeader, rows(0))
            Assert.True(rows.Length >= 2, String.Join(vbLf, rows))
            Dim f = rows(1).Split(","c)
            Assert.Equal("ball", f(1))
            Assert.Equal("wall:bottom", f(2))
            Assert.Equal("circle-wall", f(3))
            Assert.Equal(Math.Sqrt(2 / 9.81), D(f(0)), 2)
            Assert.True(D(f(5)) < 0 AndAlso D(f(7)) > 0, rows(1))
            For i = 8 To 11
                Assert.Equal(0.0, D(f(i)))
            Next
        End Using
    End Sub

    <Fact>
    Public Sub JsonSummary_HasEveryField_AndConservesMomentumAndEnergy()
        Using t As New TempFolder()
            Dim scene = t.Write("head-on.json", HeadOn)
            Dim r = RunCli("run", scene, "--time", "2", "--solver", "euler", "--dt", "0.0005", "--json")
            Assert.True(r.ExitCode = 0, r.ToString())
            Assert.Equal("", r.StdErr)
            Using doc = JsonDocument.Parse(r.StdOut)
                Dim s = doc.RootElement
                Assert.Equal("euler", s.GetProperty("solver").GetString())
                Assert.Equal(0.0005, s.GetProperty("dt").GetDouble())
                Assert.Equal(2.0, s.GetProperty("simulated_s").GetDouble(), 12)
                Assert.True(s.GetProperty("wall_s").GetDouble() >= 0)
                Assert.Equal(1, s.GetProperty("collisions").GetInt64())
                Assert.NotEqual(JsonValueKind.Undefined, s.GetProperty("events_per_s").ValueKind)
                ' p = 1·2 + 3·(−1) = −1 kg·m/s before and after; KE = ½·1·4 + ½·3·1 = 3.5 J (e = 1); g = 0 so PE = 0
                Dim p = s.GetProperty("momentum")
                Assert.Equal(2, p.GetArrayLength())
                Assert.Equal(-1.0, p(0).GetDouble(), 9)
                Assert.Equal(0.0, p(1).GetDouble(), 9)
                Assert.Equal(3.5, s.GetProperty("kinetic_energy").GetDouble(), 9)
                Assert.Equal(0.0, s.GetProperty("potential_energy").GetDouble())
                Assert.Equal(3.5, s.GetProperty("energy_total").GetDouble(), 9)
                Assert.Equal(3, s.GetProperty("bodies").GetInt32())
            End Using
        End Using
    End Sub

    <Fact>
    Public Sub JsonSummary_PotentialEnergy_IsMgyOfTheFinalState()
        Using t As New TempFolder()
            Dim scene = t.Write("ball.json", BouncingBall)
            Dim states = t.File("s.csv")
            Dim r = RunCli("run", scene, "--time", "0.2", "--solver", "euler", "--json", "--states", states)
            Assert.True(r.ExitCode = 0, r.ToString())
            Dim last = Lines(states).Last().Split(","c)
            Assert.Equal(0.2, D(last(0)))
            Using doc = JsonDocument.Parse(r.StdOut)
                Dim s = doc.RootElement
                Assert.Equal(1.0 * 9.81 * D(last(3)), s.GetProperty("potential_energy").GetDouble(), 12)
                Assert.Equal(0.5 * D(last(5)) * D(last(5)), s.GetProperty("kinetic_energy").GetDouble(), 12)
                Assert.Equal(D(last(5)), s.GetProperty("momentum")(1).GetDouble(), 12)
                ' free fall for 0.2 s (no bounce yet): y = 1.05 − ½ g t², within the step's error
                Assert.Equal(1.05 - 0.5 * 9.81 * 0.04, D(last(3)), 2)
            End Using
        End Using
    End Sub

    <Fact>
    Public Sub AutoSolver_RunsAndReportsItself()
        Using t As New TempFolder()
            Dim scene = t.Write("head-on.json", HeadOn)
            Dim r = RunCli("run", scene, "--time", "2", "--json")
            Assert.True(r.ExitCode = 0, r.ToString())
            Using doc = JsonDocument.Parse(r.StdOut)
                Dim s = doc.RootElement
                Assert.False(String.IsNullOrEmpty(s.GetProperty("solver").GetString()))
                Dim dt = s.GetProperty("dt")
                Assert.True(dt.ValueKind = JsonValueKind.Null OrElse dt.GetDouble() > 0, r.StdOut)
                Assert.Equal(-1.0, s.GetProperty("momentum")(0).GetDouble(), 9)
                Assert.Equal(1, s.GetProperty("collisions").GetInt64())
            End Using
        End Using
    End Sub

    <Fact>
    Public Sub TextSummary_NamesSolverCollisionsAndEnergy()
        Using t As New TempFolder()
            Dim scene = t.Write("head-on.json", HeadOn)
            Dim r = RunCli("run", scene, "--time", "2", "--solver", "euler")
            Assert.True(r.ExitCode = 0, r.ToString())
            Assert.Contains("solver            euler, dt = 0.001 s", r.StdOut)
            Assert.Contains("collisions        1", r.StdOut)
            Assert.Contains("momentum          (-1, 0) kg m/s", r.StdOut)
            Assert.Contains("kinetic energy", r.StdOut)
            Assert.Equal("", r.StdErr)
        End Using
    End Sub

    <Fact>
    Public Sub OutputFiles_ReplaceOldOnes_AndLeaveNoTemporaryFiles()
        Using t As New TempFolder()
            Dim scene = t.Write("head-on.json", HeadOn)
            t.Write("states.csv", "old")
            Dim r = RunCli("run", scene, "--time", "0.1", "--states", t.File("states.csv"), "--events", t.File("events.csv"), "--solver", "euler")
            Assert.True(r.ExitCode = 0, r.ToString())
            Assert.Equal("events.csv|head-on.json|states.csv", String.Join("|", t.Files()))
            Assert.StartsWith(StatesHeader & vbLf, File.ReadAllText(t.File("states.csv")))
            Assert.Equal(EventsHeader & vbLf, File.ReadAllText(t.File("events.csv")))
        End Using
    End Sub

    <Fact>
    Public Sub IdsThatNeedQuoting_AreQuotedInTheCsv()
        Using t As New TempFolder()
            Dim scene = t.Write("s.json", Q("{'format':'physics-scene/1','world':{'width':4,'height':2,'gravity':0},'bodies':[{'id':'ball, \'red\'','type':'circle','x':1,'y':1,'radius':0.1,'mass':1}]}").Replace("\'", "\"""))
            Dim states = t.File("s.csv")
            Dim r = RunCli("run", scene, "--time", "0.1", "--states", states, "--solver", "euler")
            Assert.True(r.ExitCode = 0, r.ToString())
            Assert.Equal("0,""ball, """"red"""""",1,1,0,0", Lines(states)(1))
        End Using
    End Sub

    <Fact>
    Public Sub ExampleDemo_RunsWithEveryOutput()
        Using t As New TempFolder()
            Dim r = RunCli("run", Path.Combine("scenes", "demo.json"), "--time", "1", "--states", t.File("s.csv"), "--events", t.File("e.csv"), "--json")
            Assert.True(r.ExitCode = 0, r.ToString())
            Using doc = JsonDocument.Parse(r.StdOut)
                Assert.Equal(1.0, doc.RootElement.GetProperty("simulated_s").GetDouble(), 12)
            End Using
            ' three movable circles × 11 sample times
            Assert.Equal(1 + 3 * 11, Lines(t.File("s.csv")).Length)
        End Using
    End Sub
End Class
