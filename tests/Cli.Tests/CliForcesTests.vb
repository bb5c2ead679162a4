Option Strict On
Imports System.Globalization
Imports System.IO
Imports Xunit

''' <summary>
''' Friction, drag and liquids on the command line: the totals CSV's dissipated column (≥ 0, never falling, and
''' energy + dissipated constant: to rounding with the event solver, within the stepping error otherwise), and a
''' bad coefficient refused by validate with one located line.
''' </summary>
Public Class CliForcesTests
    ''' <summary>A ball with linear drag thrown over water, a box with drag falling into it, e = 0.6.</summary>
    Private Shared ReadOnly Scene As String = Q("{'format':'physics-scene/1','world':{'width':6,'height':4,'restitution':0.6,'air_density':1.2},'bodies':[" &
        "{'id':'water','type':'liquid','x':0,'y':0,'width':6,'height':1,'density':1000,'linear_drag':200}," &
        "{'id':'ball','type':'circle','x':0.5,'y':2,'radius':0.1,'mass':1,'vx':3,'vy':2,'linear_drag':0.2}," &
        "{'id':'box','type':'rectangle','x':3,'y':2.5,'width':0.4,'height':0.3,'fixed':false,'mass':30,'drag_coefficient':1.05}]}")

    Private Shared Function D(text As String) As Double
        Return Double.Parse(text, NumberStyles.Float, CultureInfo.InvariantCulture)
    End Function

    <Theory>
    <InlineData("event", 0.000000001)>
    <InlineData("verlet", 0.02)>
    <InlineData("euler", 0.05)>
    Public Sub Series_EnergyPlusDissipated_StaysWhatItWas(solver As String, tolerance As Double)
        Using t As New TempFolder()
            Dim path = t.Write("forces.json", Scene)
            Dim series = t.File("series.csv")
            Dim r = RunCli("run", path, "--time", "3", "--sample", "0.1", "--solver", solver, "--series", series)
            Assert.True(r.ExitCode = 0, r.ToString())
            Dim rows = File.ReadAllLines(series)
            Assert.Equal("t,ke,pe,energy,px,py,com_x,com_y,dissipated", rows(0))
            Dim first = rows(1).Split(","c)
            Assert.Equal(0.0, D(first(8)))
            Dim e0 = D(first(3))
            Dim previous = 0.0
            For Each line In rows.Skip(1)
                Dim f = line.Split(","c)
                Dim dissipated = D(f(8))
                Assert.True(dissipated >= previous, line)
                previous = dissipated
                Assert.True(Math.Abs(D(f(3)) + dissipated - e0) <= tolerance * Math.Abs(e0), $"{solver}: {line} against {e0}")
            Next
            ' Drag and the water took something.
            Assert.True(previous > 1)
        End Using
    End Sub

    <Fact>
    Public Sub ABlockOnARoughRamp_Stays_WithTheEventSolver_ToTheLastBit_AndWithVerlet()
        ' A ramp at 20° (tan 20° = 0.36 < μs = 0.5) with a block resting on it, its lower-left corner on the slope.
        Dim angle = 20 * Math.PI / 180
        Dim x1 = 0.5, y1 = 2.0, x2 = x1 + 3 * Math.Cos(angle), y2 = y1 - 3 * Math.Sin(angle)
        Dim bx = x1 + Math.Cos(angle), by = y1 - Math.Sin(angle)
        Dim inv = CultureInfo.InvariantCulture
        Dim json = Q("{'format':'physics-scene/1','world':{'width':5,'height':3,'friction':0.4,'static_friction':0.5},'bodies':[" &
            "{'id':'ramp','type':'segment','x1':" & x1.ToString("R", inv) & ",'y1':" & y1.ToString("R", inv) & ",'x2':" & x2.ToString("R", inv) & ",'y2':" & y2.ToString("R", inv) & "}," &
            "{'id':'block','type':'rectangle','x':" & bx.ToString("R", inv) & ",'y':" & by.ToString("R", inv) & ",'width':0.2,'height':0.1,'fixed':false,'mass':1}]}")
        Using t As New TempFolder()
            Dim path = t.Write("ramp.json", json)
            Dim states = t.File("states.csv")
            Dim r = RunCli("run", path, "--time", "2", "--states", states, "--json")
            Assert.True(r.ExitCode = 0, r.ToString())
            Assert.Contains("""solver"":""event""", r.StdOut)
            Dim rows = File.ReadAllLines(states).Select(Function(line) line.Split(","c)).Where(Function(f) f(1) = "block").ToList()
            Assert.True(rows.Count > 2, $"{rows.Count} rows for the block")
            Dim first = rows.First(), last = rows.Last()
            Assert.Equal(first(2), last(2))
            Assert.Equal(first(3), last(3))
            ' The stepping solver holds it too, to its own tolerance.
            Dim verlet = RunCli("run", path, "--time", "2", "--states", states, "--solver", "verlet")
            Assert.True(verlet.ExitCode = 0, verlet.ToString())
            last = File.ReadAllLines(states).Last().Split(","c)
            Assert.True(Math.Abs(D(last(2)) - bx) < 0.000001 AndAlso Math.Abs(D(last(3)) - by) < 0.000001, String.Join(",", last))
        End Using
    End Sub

    <Theory>
    <InlineData("{'world':{'width':6,'height':4,'friction':0.5,'static_friction':0.2},'bodies':[]}", "world.static_friction: must be at least friction (0.5), not 0.2")>
    <InlineData("{'world':{'width':6,'height':4},'bodies':[{'type':'liquid','x':0,'y':0,'width':6,'height':1,'density':0}]}", "bodies[0].density: must be greater than 0")>
    <InlineData("{'world':{'width':6,'height':4},'bodies':[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1,'linear_drag':-1}]}", "bodies[0].linear_drag: must be 0 or greater")>
    Public Sub Validate_RefusesABadCoefficientWithOneLocatedLine(json As String, expected As String)
        Using t As New TempFolder()
            Dim path = t.Write("bad.json", Q("{'format':'physics-scene/1'," & json.TrimStart("{"c)))
            Dim r = RunCli("validate", path)
            Assert.Equal(2, r.ExitCode)
            Assert.EndsWith(": " & expected, r.StdErr.Trim())
        End Using
    End Sub
End Class
