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
''' --frame-benchmark galton|rope|cradle: one lesson scene instead (the benchmark report's 500-ball
''' Galton board, rope of ten balls and Newton's cradle on strings), run through the presenter with
''' the solver the app picks for it, for the span <see cref="SceneFrames"/> gives, each frame as the
''' window does it: the presenter's Tick of 1/60 s (the advance within the frame budget, the tables'
''' snapshot ten times a second) and one paint of the canvas (its time told to the presenter, as the
''' window's paint does). One JSON line with the median, 95th percentile and worst frame, the frames
''' the budget slowed (slow_frames) and the simulated seconds it held back over the run (lag_s).
''' </summary>
Friend Module FrameBenchmark
    Private Const Frames As Integer = 300
    Private Const FrameSeconds As Double = 1.0 / 60
    Private Const CanvasWidth As Integer = 860
    Private Const CanvasHeight As Integer = 496
    Private Const GraphWidth As Integer = 845
    Private Const GraphHeight As Integer = 190

    ''' <summary>The scenes <c>--frame-benchmark NAME</c> knows, in the order its message lists them.</summary>
    Public ReadOnly Property SceneNames As IReadOnlyList(Of String) = {"galton", "rope", "cradle"}

    ''' <summary>The frame time every scene is held to, ms: about one frame of a 60 Hz screen.</summary>
    Public Const TargetMs As Integer = 16

    ''' <summary>Whether <paramref name="text"/> names one of <see cref="SceneNames"/> (exactly, lower case).</summary>
    Public Function IsSceneName(text As String) As Boolean
        Return text IsNot Nothing AndAlso SceneNames.Contains(text)
    End Function

    ''' <summary>
    ''' Frames timed per scene: the Galton board's 15 s (its balls leave the shelves, pass the pegs and
    ''' fill the bins, as the report's galton row runs it), the rope's 5 s (its row's span), and 5 s of
    ''' the cradle (its row stops at half a period, about 1 s: too few frames for a 95th percentile).
    ''' </summary>
    Public Function SceneFrames(name As String) As Integer
        Select Case name
            Case "galton" : Return 900
            Case "rope", "cradle" : Return 300
            Case Else : Throw New ArgumentException("unknown scene '" & name & "'", NameOf(name))
        End Select
    End Function

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
                FramePaint.Paint(painter, g, presenter, CanvasWidth, CanvasHeight)
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

    ''' <summary>
    ''' Times one lesson scene, after an untimed run of the same frames (so no timed frame pays for
    ''' Mono compiling code that the scene reaches late), and prints its JSON line.
    ''' </summary>
    Public Function RunScene(name As String, output As TextWriter) As Integer
        If output Is Nothing Then Throw New ArgumentNullException(NameOf(output))
        MeasureScene(name, TextWriter.Null)
        MeasureScene(name, output)
        Return 0
    End Function

    Private Sub MeasureScene(name As String, output As TextWriter)
        Dim world = BuildScene(name)
        Dim frames = SceneFrames(name)
        ' Taken before the first step: the benchmark compares them with its own scene of that name.
        Dim bodies = world.Bodies.Count, links = world.Links.Count, energy = MovingEnergy(world)
        Dim presenter As New SimulationPresenter(New QuietView(), world:=world)
        presenter.CanvasResized(CanvasWidth, CanvasHeight)
        Dim stepMs(frames - 1) As Double, paintMs(frames - 1) As Double, totalMs(frames - 1) As Double
        Using bitmap As New Bitmap(CanvasWidth, CanvasHeight), g = Graphics.FromImage(bitmap), painter As New ScenePainter()
            FramePaint.Paint(painter, g, presenter, CanvasWidth, CanvasHeight) ' warm-up: fonts, brushes
            Dim sw As New Stopwatch()
            For f = 0 To frames - 1
                ' As the window's frame: the presenter's Tick (the advance within its budget, the tables'
                ' snapshot), then the canvas's paint, whose time the presenter is told for its next budgets.
                sw.Restart()
                presenter.Tick(FrameSeconds)
                Dim afterStep = sw.Elapsed.TotalMilliseconds
                FramePaint.Paint(painter, g, presenter, CanvasWidth, CanvasHeight)
                g.Flush(Drawing2D.FlushIntention.Sync)
                Dim afterPaint = sw.Elapsed.TotalMilliseconds
                stepMs(f) = afterStep
                paintMs(f) = afterPaint - afterStep
                totalMs(f) = afterPaint
            Next
        End Using
        Dim fields As New List(Of (String, String)) From {
            ("scene", """" & name & """"),
            ("bodies", Whole(bodies)), ("links", Whole(links)),
            ("energy_j", energy.ToString("R", CultureInfo.InvariantCulture)),
            ("frames", Whole(frames)),
            ("frame_s", FrameSeconds.ToString("R", CultureInfo.InvariantCulture)),
            ("simulated_s", presenter.World.Time.ToString("F3", CultureInfo.InvariantCulture)),
            ("solver", """" & presenter.World.Solver.Name & """"),
            ("canvas", """" & Whole(CanvasWidth) & "x" & Whole(CanvasHeight) & """")}
        For Each part In {("step", stepMs), ("paint", paintMs), ("total", totalMs)}
            fields.Add((part.Item1 & "_median_ms", Ms(Percentile(part.Item2, 0.5))))
            fields.Add((part.Item1 & "_p95_ms", Ms(Percentile(part.Item2, 0.95))))
            fields.Add((part.Item1 & "_max_ms", Ms(Percentile(part.Item2, 1))))
        Next
        fields.AddRange({("target_ms", Whole(TargetMs)),
                         ("over_target_frames", Whole(totalMs.Count(Function(t) t >= TargetMs))),
                         ("slow_frames", presenter.SlowedFrames.ToString(CultureInfo.InvariantCulture)),
                         ("lag_s", presenter.HeldBackSeconds.ToString("F3", CultureInfo.InvariantCulture))})
        output.WriteLine("{""benchmark"":""frame""," & String.Join(",", fields.Select(Function(f) """" & f.Item1 & """:" & f.Item2)) & "}")
        output.Flush()
    End Sub

    ''' <summary>
    ''' The scene as the benchmark report builds it: Scenarios.GaltonBoard(500, 12, 20, 10), and the
    ''' rope and cradle lessons as its rope and cradle-strings rows build them (with e = 1).
    ''' </summary>
    Private Function BuildScene(name As String) As World
        Select Case name
            Case "galton" : Return Scenarios.GaltonBoard(500, 12, 20, 10)
            Case "rope" : Return Rope()
            Case "cradle" : Return CradleOnStrings()
            Case Else : Throw New ArgumentException("unknown scene '" & name & "'", NameOf(name))
        End Select
    End Function

    ''' <summary>Ten 0.2 kg balls on 0.2 m rods from a fixed point, released level, beside three free 1 kg balls; 5 m box, e = 1.</summary>
    Private Function Rope() As World
        Dim w As New World(5, 5, 9.81, 1.0)
        Dim pivot As New Vector(1.0, 4.0)
        Dim previous As Circle = Nothing
        For k = 1 To 10
            Dim ball As New Circle(pivot + New Vector(k * 0.2, 0), 0.06, 0.2, id:="rope" & Whole(k))
            w.Add(ball)
            If previous Is Nothing Then
                w.Add(Link.CreateTie(LinkKind.Rod, ball, pivot, 0.2, "rod1"))
            Else
                w.Add(Link.CreateTie(LinkKind.Rod, ball, previous, 0.2, "rod" & Whole(k)))
            End If
            previous = ball
        Next
        For k = 1 To 3
            w.Add(New Circle(New Vector(0.6 + 0.35 * (k - 1), 0.15), 0.15, 1.0, id:="free" & Whole(k)))
        Next
        Return w
    End Function

    ''' <summary>Five touching 1 kg balls (r = 0.1 m) on 1 m strings, the first released from 30°; 4 × 3 m box, e = 1.</summary>
    Private Function CradleOnStrings() As World
        Const Angle = Math.PI / 6 ' rad
        Dim w As New World(4, 3, 9.81, 1.0)
        For k = 1 To 5
            Dim pivot As New Vector(1.6 + 0.2 * (k - 1), 2.5)
            Dim theta = If(k = 1, -Angle, 0)
            Dim ball As New Circle(pivot + New Vector(Math.Sin(theta), -Math.Cos(theta)), 0.1, 1.0, id:="b" & Whole(k))
            w.Add(ball)
            w.Add(Link.CreateTie(LinkKind.String, ball, pivot, 1.0, "s" & Whole(k)))
        Next
        Return w
    End Function

    ''' <summary>½mv² + mgy of the bodies that move, J (y up from the floor).</summary>
    Private Function MovingEnergy(world As World) As Double
        Return world.Circles.Where(Function(c) Not c.IsFixed).Sum(Function(c) 0.5 * c.Mass * c.Velocity.LengthSquared + c.Mass * world.Gravity * c.Position.Y)
    End Function

    Private Function Whole(value As Integer) As String
        Return value.ToString(CultureInfo.InvariantCulture)
    End Function

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
