Option Strict On
Imports System.Xml.Linq
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>The SVG work-precision plots, read back as XML.</summary>
Public Class SvgPlotTests
    Private Shared ReadOnly Ns As XNamespace = "http://www.w3.org/2000/svg"

    Private Shared Function Plot() As XDocument
        Dim series As New List(Of PlotSeries) From {
            New PlotSeries("event (exact)", "#d62728", {New PlotPoint(0.0, 0.05)}, 0),
            New PlotSeries("semi-implicit Euler", "#1f77b4", {New PlotPoint(0.1, 0.03, "1/30"), New PlotPoint(0.01, 0.3, "1/250"), New PlotPoint(0.001, 3, "1/1000")}, 1),
            New PlotSeries("a <b> & c", "#2ca02c", {New PlotPoint(Double.NaN, 1.0), New PlotPoint(0.02, 0.5)}, 2)}
        Return XDocument.Parse(SvgPlot.Render("Title", "error (m) — log scale", "cost: ms per simulated s — log scale", series))
    End Function

    Private Shared Function Texts(doc As XDocument) As List(Of String)
        Return doc.Descendants(Ns + "text").Select(Function(t) t.Value).ToList()
    End Function

    <Fact>
    Public Sub Render_IsWellFormedSvg_WithBothAxisLabelsAndTheTitle()
        Dim doc = Plot()
        Assert.Equal(Ns + "svg", doc.Root.Name)
        Dim t = Texts(doc)
        Assert.Contains("Title", t)
        Assert.Contains("error (m) — log scale", t)
        Assert.Contains("cost: ms per simulated s — log scale", t)
    End Sub

    <Fact>
    Public Sub Render_DrawsALineOnlyForSeriesWithMoreThanOnePoint_AndALegendEntryForEach()
        Dim doc = Plot()
        Dim lines = doc.Descendants(Ns + "polyline").ToList()
        Assert.Single(lines)
        Assert.Equal(3, lines(0).Attribute("points").Value.Split(" "c).Length)
        Dim t = Texts(doc)
        Assert.Contains("event (exact)", t)
        Assert.Contains("semi-implicit Euler", t)
        Assert.Contains("a <b> & c", t) ' escaped in the file, read back intact
        Assert.Contains("1/250", t)
    End Sub

    <Fact>
    Public Sub Render_LeavesOutNaN_AndDrawsAZeroErrorAtTheFloorWithAFootnote()
        Dim doc = Plot()
        ' Markers: 1 event + 3 euler + 1 finite verlet point, plus one legend marker per series.
        Assert.Equal(5 + 3, doc.Descendants().Count(Function(e) e.Attribute("class")?.Value = "marker"))
        Assert.Contains("values at or below 1e-16 (exact to rounding) are drawn at 1e-16", Texts(doc))
        Assert.Contains("1e-16", Texts(doc))
    End Sub

    <Fact>
    Public Sub DecadeRange_CoversEveryValue_AtLeastOneDecadeWide()
        Assert.Equal((-3, 0), SvgPlot.DecadeRange(Values(0.001, 0.5)))
        Assert.Equal((1, 2), SvgPlot.DecadeRange(Values(10.0)))
        Assert.Equal((0, 1), SvgPlot.DecadeRange(Array.Empty(Of Double)()))
    End Sub
End Class
