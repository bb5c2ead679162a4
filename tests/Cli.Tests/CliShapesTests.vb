Option Strict On
Imports System.Globalization
Imports System.IO
Imports System.Text.Json
Imports Xunit

''' <summary>
''' run with a scene of every kind: one states row per movable body at the point the scene file uses,
''' the totals (--series) recomputed from the states, and a collision kind for every pair of shapes.
''' </summary>
Public Class CliShapesTests
    Private Const SeriesHeader As String = "t,ke,pe,energy,px,py,com_x,com_y,dissipated"
    Private Const G As Double = 9.81

    ''' <summary>
    ''' A ball over a ramp, a box over a table, a triangle over a fixed wedge, near a peg: movable bodies
    ''' "ball" (1 kg, centre), "box" (2 kg, 0.3 × 0.2, lower-left) and "tri" (0.5 kg, centroid (2.65, 2.1)).
    ''' </summary>
    Private Shared ReadOnly EveryKind As String = Q("{'format':'physics-scene/1','world':{'width':4,'height':3,'gravity':9.81,'restitution':0.8},'bodies':[" &
        "{'id':'ball','type':'circle','x':0.5,'y':1.3,'radius':0.1,'mass':1,'vx':0.2}," &
        "{'id':'peg','type':'circle','x':3.7,'y':2.6,'radius':0.1,'fixed':true}," &
        "{'id':'table','type':'rectangle','x':3.0,'y':0,'width':1,'height':0.5}," &
        "{'id':'box','type':'rectangle','x':3.3,'y':1.0,'width':0.3,'height':0.2,'fixed':false,'mass':2}," &
        "{'id':'ramp','type':'segment','x1':0,'y1':1.0,'x2':1.5,'y2':0.2}," &
        "{'id':'tri','type':'polygon','vertices':[[2.5,2.0],[2.8,2.0],[2.65,2.3]],'mass':0.5}," &
        "{'id':'wedge','type':'polygon','vertices':[[1.8,0],[2.6,0],[2.6,0.4]],'fixed':true}]}")

    Private Shared ReadOnly Movable As String() = {"ball", "box", "tri"}
    ''' <summary>The first two rows: the ball's centre and the box's lower-left corner, as in the file.</summary>
    Private Shared ReadOnly BallAtStart As String() = {"0", "ball", "0.5", "1.3", "0.2", "0"}
    Private Shared ReadOnly BoxAtStart As String() = {"0", "box", "3.3", "1", "0", "0"}
    Private Shared ReadOnly Masses As Double() = {1.0, 2.0, 0.5}
    ''' <summary>From each body's scene-file point to its centre of mass, m.</summary>
    Private Shared ReadOnly ToCentre As Vector() = {Vector.Zero, New Vector(0.15, 0.1), Vector.Zero}

    Private Shared Function D(text As String) As Double
        Return Double.Parse(text, NumberStyles.Float, CultureInfo.InvariantCulture)
    End Function

    Private Shared Function Rows(path As String) As String()()
        Dim text = File.ReadAllText(path)
        Assert.EndsWith(vbLf, text)
        Return text.TrimEnd(ChrW(10)).Split(ChrW(10)).Select(Function(l) l.Split(","c)).ToArray()
    End Function

    <Theory>
    <InlineData("euler")>
    <InlineData("verlet")>
    Public Sub EveryKind_StatesSeriesAndKinds(solver As String)
        Using t As New TempFolder()
            Dim scene = t.Write("every.json", EveryKind)
            Dim states = t.File("states.csv"), events = t.File("events.csv"), series = t.File("series.csv")
            Dim r = RunCli("run", scene, "--time", "1.5", "--sample", "0.1", "--solver", solver, "--json",
                           "--states", states, "--events", events, "--series", series)
            Assert.True(r.ExitCode = 0, r.ToString())

            ' States: the movable bodies in the scene's order, at the scene file's points at t = 0.
            Dim s = Rows(states)
            Assert.Equal("t,id,x,y,vx,vy", String.Join(",", s(0)))
            Dim data = s.Skip(1).ToArray()
            Assert.Equal(0, data.Length Mod 3)
            For k = 0 To data.Length - 1
                Assert.Equal(Movable(k Mod 3), data(k)(1))
            Next
            Assert.Equal(BallAtStart, data(0))
            Assert.Equal(BoxAtStart, data(1))
            Assert.Equal(2.65, D(data(2)(2)), 12)
            Assert.Equal(2.1, D(data(2)(3)), 12)

            ' Totals: one row per sample time, each recomputed from that time's states.
            Dim z = Rows(series)
            Assert.Equal(SeriesHeader, String.Join(",", z(0)))
            Assert.Equal(data.Length \ 3, z.Length - 1)
            For row = 1 To z.Length - 1
                Dim at = data.Skip(3 * (row - 1)).Take(3).ToArray()
                Assert.Equal(at(0)(0), z(row)(0))
                Dim ke = 0.0, pe = 0.0, px = 0.0, py = 0.0, mx = 0.0, my = 0.0
                For b = 0 To 2
                    Dim m = Masses(b)
                    Dim vx = D(at(b)(4)), vy = D(at(b)(5))
                    Dim cx = D(at(b)(2)) + ToCentre(b).X, cy = D(at(b)(3)) + ToCentre(b).Y
                    ke += 0.5 * m * (vx * vx + vy * vy)
                    pe += m * G * cy
                    px += m * vx : py += m * vy
                    mx += m * cx : my += m * cy
                Next
                Dim scale = Math.Abs(pe) + Math.Abs(ke) + 1
                Assert.Equal(ke, D(z(row)(1)), 9)
                Assert.Equal(pe, D(z(row)(2)), 9)
                Assert.Equal(D(z(row)(1)) + D(z(row)(2)), D(z(row)(3)), 12)
                Assert.Equal(px, D(z(row)(4)), 9)
                Assert.Equal(py, D(z(row)(5)), 9)
                Assert.Equal(mx / 3.5, D(z(row)(6)), 9)
                Assert.Equal(my / 3.5, D(z(row)(7)), 9)
                ' Energy taken (e = 0.8): never negative, never falling.
                Assert.True(D(z(row)(8)) >= If(row > 1, D(z(row - 1)(8)), 0))
            Next
            ' The summary's energies are the last row's.
            Using doc = JsonDocument.Parse(r.StdOut)
                Dim summary = doc.RootElement
                Assert.Equal(D(z(z.Length - 1)(1)), summary.GetProperty("kinetic_energy").GetDouble())
                Assert.Equal(D(z(z.Length - 1)(2)), summary.GetProperty("potential_energy").GetDouble())
                Assert.Equal(3, summary.GetProperty("movable").GetInt32())
                Assert.Equal(series, summary.GetProperty("series").GetString())
            End Using

            ' Kinds: A-B from the two bodies' kinds; each movable body lands on its own obstacle.
            Dim kindOf As New Dictionary(Of String, String) From {
                {"ball", "circle"}, {"peg", "fixed"}, {"table", "rectangle"}, {"box", "rectangle"}, {"ramp", "segment"}, {"tri", "polygon"}, {"wedge", "polygon"}}
            Dim e = Rows(events)
            Dim seen As New HashSet(Of String)
            For Each f In e.Skip(1)
                Dim other = If(f(2).StartsWith("wall:", StringComparison.Ordinal), "wall", kindOf(f(2)))
                Assert.Equal(kindOf(f(1)) & "-" & other, f(3))
                seen.Add(f(1) & ">" & f(2) & ":" & f(3))
            Next
            Assert.Contains("ball>ramp:circle-segment", seen)
            Assert.Contains("box>table:rectangle-rectangle", seen)
            Assert.Contains("tri>wedge:polygon-polygon", seen)
        End Using
    End Sub

    <Fact>
    Public Sub Series_IsSampledAtTheStatesTimes_WithTheSameTimeColumn()
        Using t As New TempFolder()
            Dim scene = t.Write("ball.json", BouncingBall)
            Dim states = t.File("s.csv"), series = t.File("z.csv")
            Dim r = RunCli("run", scene, "--time", "0.7", "--solver", "euler", "--states", states, "--series", series)
            Assert.True(r.ExitCode = 0, r.ToString())
            Dim times = Rows(states).Skip(1).Select(Function(f) f(0)).ToArray()
            Assert.Equal(times, Rows(series).Skip(1).Select(Function(f) f(0)).ToArray())
            Assert.Equal("0|0.1|0.2|0.30000000000000004|0.4|0.5|0.6000000000000001|0.7", String.Join("|", times))
            Assert.Contains("totals CSV        " & series, r.StdOut)
        End Using
    End Sub
End Class
