Option Strict On
Imports System.Diagnostics
Imports System.Drawing
Imports System.Globalization
Imports System.IO
Imports PhysicsEngine.Presentation

''' <summary>
''' --frame-benchmark N: an elastic gas of N circles with gravity, 300 frames of one engine step
''' (1/60 s, through the presenter as the window does) and one full paint into an offscreen bitmap
''' with the window's own painter. Prints one JSON line of median and 95th-percentile times, ms;
''' first the same with the path traces, the centre of mass and the total-momentum arrow on and one
''' paint of the speed histogram per frame (the graph that costs most: every body's speed binned, and
''' the Maxwell–Boltzmann curve), marked "views":"traces+com". The window redraws the graph ten times
''' a second, not every frame: timing it every frame is the worst case.
''' </summary>
Friend Module FrameBenchmark
    Private Const Frames As Integer = 300
    Private Const FrameSeconds As Double = 1.0 / 60
    Private Const CanvasWidth As Integer = 860
    Private Const CanvasHeight As Integer = 496
    Private Const GraphWidth As Integer = 845
    Private Const GraphHeight As Integer = 190

    Public Function Run(count As Integer, output As TextWriter) As Integer
        ' An untimed run first, so neither row pays for compiling the solver's code (JIT) in its frames.
        Measure(count, False, TextWriter.Null)
        ' The row with the views first: the plain row stays the last line, as readers of one line expect.
        Measure(count, True, output)
        Measure(count, False, output)
        Return 0
    End Function

    Private Sub Measure(count As Integer, views As Boolean, output As TextWriter)
        Dim world = Scenarios.ElasticGas(count)
        world.Gravity = 9.81
        Dim presenter As New SimulationPresenter(New QuietView(), world:=world)
        presenter.CanvasResized(CanvasWidth, CanvasHeight)
        If views Then
            presenter.SetShowTraces(True)
            presenter.SetShowCentreOfMass(True)
            presenter.SetShowTotalMomentum(True)
            presenter.ChooseGraph(GraphKind.SpeedHistogram)
        End If
        Dim stepMs(Frames - 1) As Double, paintMs(Frames - 1) As Double, graphMs(Frames - 1) As Double, totalMs(Frames - 1) As Double
        Using bitmap As New Bitmap(CanvasWidth, CanvasHeight), g = Graphics.FromImage(bitmap), painter As New ScenePainter(),
              graphBitmap As New Bitmap(GraphWidth, GraphHeight), graphG = Graphics.FromImage(graphBitmap), font As New Font(FontFamily.GenericSansSerif, 10)
            painter.Paint(g, presenter, CanvasWidth, CanvasHeight) ' warm-up: JIT, fonts, brushes
            Dim sw As New Stopwatch()
            For f = 0 To Frames - 1
                sw.Restart()
                presenter.Tick(FrameSeconds)
                Dim afterStep = sw.Elapsed.TotalMilliseconds
                painter.Paint(g, presenter, CanvasWidth, CanvasHeight)
                g.Flush(Drawing2D.FlushIntention.Sync)
                Dim afterPaint = sw.Elapsed.TotalMilliseconds
                If views Then
                    GraphPainter.Paint(graphG, presenter.CurrentGraph(), presenter.Theme, font, GraphWidth, GraphHeight, 1.0)
                    graphG.Flush(Drawing2D.FlushIntention.Sync)
                End If
                Dim afterGraph = sw.Elapsed.TotalMilliseconds
                stepMs(f) = afterStep
                paintMs(f) = afterPaint - afterStep
                graphMs(f) = afterGraph - afterPaint
                totalMs(f) = afterGraph
            Next
        End Using
        Dim fields As New List(Of (String, String)) From {
            ("circles", count.ToString(CultureInfo.InvariantCulture)),
            ("frames", Frames.ToString(CultureInfo.InvariantCulture)),
            ("frame_s", FrameSeconds.ToString("R", CultureInfo.InvariantCulture)),
            ("solver", """" & world.Solver.Name & """"),
            ("canvas", """" & CanvasWidth.ToString(CultureInfo.InvariantCulture) & "x" & CanvasHeight.ToString(CultureInfo.InvariantCulture) & """"),
            ("step_median_ms", Ms(Percentile(stepMs, 0.5))), ("step_p95_ms", Ms(Percentile(stepMs, 0.95))),
            ("paint_median_ms", Ms(Percentile(paintMs, 0.5))), ("paint_p95_ms", Ms(Percentile(paintMs, 0.95)))}
        If views Then fields.AddRange({("graph_median_ms", Ms(Percentile(graphMs, 0.5))), ("graph_p95_ms", Ms(Percentile(graphMs, 0.95)))})
        fields.AddRange({("total_median_ms", Ms(Percentile(totalMs, 0.5))), ("total_p95_ms", Ms(Percentile(totalMs, 0.95))),
                         ("views", If(views, """traces+com""", """none"""))})
        output.WriteLine("{""benchmark"":""frame""," & String.Join(",", fields.Select(Function(f) """" & f.Item1 & """:" & f.Item2)) & "}")
        output.Flush()
    End Sub

    Private Function Ms(value As Double) As String
        Return value.ToString("F3", CultureInfo.InvariantCulture)
    End Function

    ''' <summary>The q-quantile (0 to 1) by nearest rank.</summary>
    Private Function Percentile(values As Double(), q As Double) As Double
        Dim sorted = CType(values.Clone(), Double())
        Array.Sort(sorted)
        Dim rank = CInt(Math.Ceiling(q * sorted.Length)) - 1
        Return sorted(Math.Max(0, Math.Min(sorted.Length - 1, rank)))
    End Function
End Module
