Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>The grid under the bodies: off until switched on, a line every metre and every 10 cm inside the container, only what the canvas shows.</summary>
Public Class CanvasGridTests
    <Fact>
    Public Sub TheGrid_IsOffUntilSwitchedOn_ThenHasMetreAnd10cmLinesAcrossTheContainer()
        Dim h As New PresenterHarness(New World(8, 5, 9.81, 1.0))
        Assert.False(h.P.ShowGrid)
        Assert.Empty(h.P.GridLines())
        h.P.SetShowGrid(True)
        Assert.Contains("grid on", h.TraceLines)
        Assert.True(h.P.View.ToPixels(0.1) >= CanvasGrid.MinMinorPixels, "the 8 m box is drawn large enough for 10 cm lines")
        Dim lines = h.P.GridLines()
        Dim vertical = lines.Where(Function(l) l.Start.X = l.End.X).ToList()
        Dim horizontal = lines.Where(Function(l) l.Start.Y = l.End.Y).ToList()
        Assert.Equal(lines.Count, vertical.Count + horizontal.Count)
        ' 0, 0.1, …, 8 m across and 0, 0.1, …, 5 m up.
        Assert.Equal(81, vertical.Count)
        Assert.Equal(51, horizontal.Count)
        Assert.Equal(9, vertical.Where(Function(l) l.Major).Count())
        Assert.Equal(6, horizontal.Where(Function(l) l.Major).Count())
        For Each l In vertical
            Assert.Equal(0.0, l.Start.Y)
            Assert.Equal(5.0, l.End.Y)
            ' A metre line is at a whole metre, every other line is not.
            Assert.Equal(l.Major, Math.Abs(l.Start.X - Math.Round(l.Start.X)) < 0.000000001)
        Next
        Assert.Contains(vertical, Function(l) Math.Abs(l.Start.X - 0.3) < 0.000000001 AndAlso Not l.Major)
        Assert.Equal(Enumerable.Range(0, 81).Select(Function(i) i / 10.0), vertical.Select(Function(l) Math.Round(l.Start.X, 9)).OrderBy(Function(x) x))
        h.P.SetShowGrid(False)
        Assert.Empty(h.P.GridLines())
        Assert.Contains("grid off", h.TraceLines)
    End Sub

    <Fact>
    Public Sub InALargeBox_OnlyTheMetreLinesAreDrawn_AndZoomedIn_OnlyThoseOnTheCanvas()
        Dim h As New PresenterHarness(New World(100, 60, 9.81, 1.0))
        h.P.SetShowGrid(True)
        Assert.True(h.P.View.ToPixels(0.1) < CanvasGrid.MinMinorPixels)
        Dim whole = h.P.GridLines()
        Assert.All(whole, Sub(l) Assert.True(l.Major))
        Assert.Equal(101 + 61, whole.Count)
        ' Zoomed in about the middle: the 10 cm lines come, but only the few on the canvas.
        For k = 1 To 12
            h.P.ZoomAt(1, 400, 250)
        Next
        Assert.True(h.P.View.ToPixels(0.1) >= CanvasGrid.MinMinorPixels, $"{h.P.View.Scale} px/m")
        Dim near = h.P.GridLines()
        Assert.Contains(near, Function(l) Not l.Major)
        Assert.True(near.Count < 400, $"{near.Count} lines")
        Dim left = h.P.View.ToWorld(0, 0).X, right = h.P.View.ToWorld(800, 0).X
        Assert.All(near.Where(Function(l) l.Start.X = l.End.X), Sub(l) Assert.InRange(l.Start.X, left, right))
    End Sub
End Class
