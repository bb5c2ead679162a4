Option Strict On
Imports System.Globalization
Imports System.IO
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>The Graphs tab and the Export menu through the presenter.</summary>
Public Class GraphsPresenterTests
    ''' <summary>The command line's --series header.</summary>
    Private Shared ReadOnly CliColumns As String() = {"t", "ke", "pe", "energy", "px", "py", "com_x", "com_y"}

    Private Shared Function Num(text As String) As Double
        Return Double.Parse(text, CultureInfo.InvariantCulture)
    End Function

    <Fact>
    Public Sub Series_FollowsTheWorld_AndItsCsvHasTheCommandLineColumns()
        Dim h As New PresenterHarness()
        Dim ball = h.Ball(2.0, 3.0, mass:=2.0)
        For k = 1 To 60
            h.P.Tick(1 / 60.0)
        Next
        Dim s = h.P.Series.Samples
        Assert.True(s.Count > 30, $"{s.Count} samples")
        ' A falling ball: KE + PE stays what it was (e = 1, no collision yet).
        Assert.Equal(2.0 * 9.81 * 3.0, s(0).Total, 6)
        Assert.Equal(s(0).Total, s(s.Count - 1).Total, 6)
        Dim rows = Csv.Parse(h.P.SeriesCsv())
        Assert.Equal(SimulationPresenter.SeriesHeader, rows(0).ToArray())
        Assert.Equal(CliColumns, rows(0).Select(Function(c) c.Split(" "c)(0)).ToArray())
        Assert.Equal(s.Count + 1, rows.Count)
        Dim last = rows(rows.Count - 1)
        Assert.Equal(s(s.Count - 1).Time, Num(last(0)))
        Assert.Equal(ball.Velocity.Y * 2.0, Num(last(5)), 12)
        Assert.Equal(ball.Position.Y, Num(last(7)), 12)
    End Sub

    <Fact>
    Public Sub Histogram_OfAGas_CountsEveryBall()
        Dim h As New PresenterHarness(Scenarios.ElasticGas(200, 0.05, 0.02, seed:=4))
        h.P.Tick(0.05)
        h.P.ChooseGraph(GraphKind.SpeedHistogram)
        Dim plot = h.P.CurrentGraph()
        Assert.Equal(200, plot.Bars.Total)
        Assert.Contains(plot.Notes, Function(n) n.StartsWith("N = 200 ", StringComparison.Ordinal))
        ' The curve is the expected count per bin: its area under the bars' width is N.
        Dim curve = plot.Lines(0).Points
        Dim area = 0.0
        For i = 1 To curve.Count - 1
            area += (curve(i).X - curve(i - 1).X) * (curve(i).Y + curve(i - 1).Y) / 2
        Next
        Assert.Equal(200.0, area / plot.Bars.BinWidth, 0)
        ' The histogram's CSV holds the same counts.
        Dim rows = Csv.Parse(h.P.SeriesCsv())
        Assert.Equal(plot.Bars.Counts.ToArray(), rows.Skip(1).Select(Function(r) CInt(Num(r(2)))).ToArray())
    End Sub

    <Fact>
    Public Sub BodiesAndLog_Csv_HoldEveryBodyAndRow()
        Dim h As New PresenterHarness(New World(4.0, 2.0, 0.0, 1.0))
        h.Ball(1.0, 1.0, id:="a,1")
        h.P.World.Add(New Circle(New Vector(3.0, 1.0), 0.2, 1.0, New Vector(-2.0, 0), "b"))
        For k = 1 To 60
            h.P.Tick(1 / 60.0)
        Next
        Dim bodies = Csv.Parse(h.P.BodiesCsv())
        Assert.Equal(3, bodies.Count)
        Assert.Equal("a,1", bodies(1)(0))
        Assert.Equal("x (m)", bodies(0)(3))
        Dim b = h.P.World.Find("b")
        Assert.Equal(b.Velocity.X, Num(bodies(2)(5)))
        Dim log = Csv.Parse(h.P.LogCsv())
        Assert.Equal(h.P.Log.Count + 1, log.Count)
        Assert.True(h.P.Log.Count > 0)
        Assert.Equal(h.P.Log(0).Time, Num(log(log.Count - 1)(0)))
    End Sub

    <Fact>
    Public Sub Export_WritesTheFile_OrSaysWhyNot()
        Dim h As New PresenterHarness()
        h.Ball(2.0, 3.0)
        Dim folder = Path.Combine(Path.GetTempPath(), "export-" & Guid.NewGuid().ToString("N"))
        Directory.CreateDirectory(folder)
        Try
            Dim target = Path.Combine(folder, "bodies.csv")
            h.P.ExportCsv(ExportKind.BodiesCsv, target)
            Assert.StartsWith("Exported ", h.View.LastMessage, StringComparison.Ordinal)
            Assert.Equal(h.P.BodiesCsv(), File.ReadAllText(target, Text.Encoding.UTF8))
            Dim bad = Path.Combine(folder, "missing", "bodies.csv")
            h.P.ExportCsv(ExportKind.BodiesCsv, bad)
            Assert.StartsWith("Could not export bodies.csv: ", h.View.LastMessage, StringComparison.Ordinal)
            Assert.Contains("does not exist", h.View.LastMessage, StringComparison.Ordinal)
        Finally
            Directory.Delete(folder, True)
        End Try
    End Sub

    <Fact>
    Public Sub Histogram_OfMixedMasses_AveragesEachBodysCurve_AndOfBodiesAtRestDrawsNoCurve()
        Dim w As New World(6.0, 6.0, 0.0, 1.0)
        w.Add(New Circle(New Vector(1, 1), 0.1, 1.0, New Vector(1.0, 0)))
        w.Add(New Circle(New Vector(3, 3), 0.1, 4.0, New Vector(0, 0.5)))
        Dim gas = GasState.Read(w)
        ' kT = mean KE = (0.5 + 0.5) / 2 J.
        Assert.Equal(0.5, gas.KT, 12)
        Dim plot = SimulationPresenter.HistogramGraph(gas)
        Assert.Equal(2, plot.Bars.Total)
        Dim p = plot.Lines(0).Points(30)
        Dim expected = 2 * plot.Bars.BinWidth * (MaxwellBoltzmann2D.Density(p.X, 1.0, 0.5) + MaxwellBoltzmann2D.Density(p.X, 4.0, 0.5)) / 2
        Assert.Equal(expected, p.Y, 12)
        Dim still As New World(6.0, 6.0, 0.0, 1.0)
        still.Add(New Circle(New Vector(1, 1), 0.1, 1.0))
        Dim resting = SimulationPresenter.HistogramGraph(GasState.Read(still))
        Assert.Equal(1, resting.Bars.Total)
        Assert.Empty(resting.Lines)
    End Sub

    <Fact>
    Public Sub HelpPages_ExplainTheGraphs_AndTheirMaths()
        Assert.Contains(HelpTexts.Tutorial, Function(t) t.Text.Contains("Export ▾", StringComparison.Ordinal) AndAlso t.Text.Contains("⤢ Window", StringComparison.Ordinal))
        Dim maths = String.Join(vbLf, HelpTexts.Maths.Select(Function(t) t.Text))
        Assert.Contains("f(v) = (m v / kT) · exp(−m v² / 2kT)", maths, StringComparison.Ordinal)
        Assert.Contains("P A = N k T", maths, StringComparison.Ordinal)
        ' The engine's pages are still there, first.
        Assert.Equal("Motion between collisions", HelpTexts.Maths(0).Title)
    End Sub
End Class
