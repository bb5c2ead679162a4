Option Strict On

''' <summary>
''' The Graphs tab: the series recorded as time runs (energies, momentum), the wall pressure gauge,
''' and the speed histogram with the 2D Maxwell–Boltzmann curve, each built as a GraphPlot the window
''' draws. Recording starts again when a scene is opened, restarted or reset, or the container changes.
''' </summary>
Friend NotInheritable Class GraphRecorder
    Private ReadOnly _stage As Stage

    Public Sub New(stage As Stage)
        _stage = stage
    End Sub

    ''' <summary>Kinetic energy's colour on the graphs (red).</summary>
    Public Const KineticColour As Integer = &HE53935
    ''' <summary>Potential energy's colour on the graphs (green).</summary>
    Public Const PotentialColour As Integer = &H2E9D4A
    ''' <summary>Total energy's and the measured pressure's colour on the graphs (blue).</summary>
    Public Const TotalColour As Integer = &H1E88E5
    ''' <summary>The theory curves' colour on the graphs (orange).</summary>
    Public Const TheoryColour As Integer = &HFB8C00

    Private _graphWorld As World
    Private _gaugeKey As String = ""
    Private _freeArea As Double

    ''' <summary>The graph the Graphs tab shows.</summary>
    Public ReadOnly Property Graph As GraphKind = GraphKind.Energy

    ''' <summary>The totals recorded as time runs (bounded: see <see cref="SeriesRecorder"/>).</summary>
    Public ReadOnly Property Series As New SeriesRecorder()

    ''' <summary>The wall pressure measured since the gas last changed (Nothing before the first frame).</summary>
    Public ReadOnly Property Pressure As WallPressure

    ''' <summary>The graphs' names in the Graphs tab's chooser, in <see cref="GraphKind"/> order.</summary>
    Public Shared ReadOnly Property Names As IReadOnlyList(Of String) = {
        "Energy: KE, PE and total against time",
        "Momentum: px and py against time",
        "Speed histogram with Maxwell–Boltzmann",
        "Pressure on the walls and N·k·T/A"}

    ''' <summary>Shows another graph.</summary>
    Public Sub ChooseGraph(kind As GraphKind)
        If kind < GraphKind.Energy OrElse kind > GraphKind.Pressure Then Return
        _Graph = kind
        _stage.Emit("graph " & kind.ToString())
    End Sub

    ''' <summary>
    ''' Records the totals and reads the pressure gauge at the world's time; called every frame and
    ''' with every snapshot. A new world, a time earlier than the last sample, or a gas whose count or
    ''' container changed starts the recording again.
    ''' </summary>
    Public Sub SampleGraphs()
        Dim w = _stage.World
        If w IsNot _graphWorld Then
            _graphWorld = w
            Series.Clear()
            _Pressure = Nothing
        End If
        Dim sample = SeriesSample.Take(w)
        Series.Offer(sample)
        Dim key = w.Movables.Count & " " & w.Bodies.Count & " " & w.Width.ToString("R", Globalization.CultureInfo.InvariantCulture) & " " &
                  w.Height.ToString("R", Globalization.CultureInfo.InvariantCulture) & " " & w.Walls.ToString()
        If _Pressure Is Nothing OrElse key <> _gaugeKey OrElse w.Time < _Pressure.MeasuredSeconds + PressureStart Then
            _gaugeKey = key
            _freeArea = GasState.Read(w).FreeArea
            _Pressure = New WallPressure(w.Time, 2 * (w.Width + w.Height))
            _PressureStart = w.Time
        End If
        Dim n = w.Movables.Count
        Dim kT = GasLaw.Temperature(sample.Kinetic, n)
        _Pressure.Advance(w.Time, kT, GasLaw.IdealPressure(n, kT, _freeArea))
    End Sub

    ''' <summary>Simulated time the pressure gauge was last started, s.</summary>
    Public ReadOnly Property PressureStart As Double

    ''' <summary>Takes one collision for the pressure gauge (walls only; not while a body is carried).</summary>
    Public Sub GraphCollision(record As CollisionRecord)
        If _stage.World.DraggedBody IsNot Nothing Then Return
        _Pressure?.Collided(record)
    End Sub

    ''' <summary>The graph on show, built from what has been recorded.</summary>
    Public Function CurrentGraph() As GraphPlot
        Select Case Graph
            Case GraphKind.Momentum : Return MomentumGraph()
            Case GraphKind.SpeedHistogram : Return HistogramGraph(GasState.Read(_stage.World))
            Case GraphKind.Pressure : Return PressureGraph()
            Case Else : Return EnergyGraph()
        End Select
    End Function

    Private Function EnergyGraph() As GraphPlot
        Dim s = Series.Samples
        Dim g As New GraphPlot With {.Title = "Energy against time", .XLabel = "time t (s)", .YLabel = "energy (J)", .YFloor = 0}
        ' The total first, so KE or PE is drawn over it where they coincide (no PE: KE = total).
        g.Lines.Add(New GraphLine("KE + PE", TotalColour, s.Select(Function(p) New Vector(p.Time, p.Total)).ToList()))
        g.Lines.Add(New GraphLine("KE", KineticColour, s.Select(Function(p) New Vector(p.Time, p.Kinetic)).ToList()))
        g.Lines.Add(New GraphLine("PE", PotentialColour, s.Select(Function(p) New Vector(p.Time, p.Potential)).ToList()))
        If s.Count > 0 Then
            Dim last = s(s.Count - 1)
            g.Notes.Add("KE " & Units.Quantity(last.Kinetic, "J") & "   PE " & Units.Quantity(last.Potential, "J") & "   KE + PE " & Units.Quantity(last.Total, "J"))
        End If
        If s.Count = 0 Then g.EmptyText = "Run time to draw the graph."
        Return g
    End Function

    Private Function MomentumGraph() As GraphPlot
        Dim s = Series.Samples
        Dim g As New GraphPlot With {.Title = "Total momentum against time", .XLabel = "time t (s)", .YLabel = "momentum (kg·m/s)"}
        g.Lines.Add(New GraphLine("px", KineticColour, s.Select(Function(p) New Vector(p.Time, p.Momentum.X)).ToList()))
        g.Lines.Add(New GraphLine("py", PotentialColour, s.Select(Function(p) New Vector(p.Time, p.Momentum.Y)).ToList()))
        If s.Count > 0 Then
            Dim last = s(s.Count - 1)
            g.Notes.Add("px " & Units.Quantity(last.Momentum.X, "kg·m/s") & "   py " & Units.Quantity(last.Momentum.Y, "kg·m/s"))
        End If
        If s.Count = 0 Then g.EmptyText = "Run time to draw the graph."
        Return g
    End Function

    ''' <summary>
    ''' The speeds now in bins of a round width (1, 2 or 5 × 10ⁿ m/s, at most
    ''' <see cref="SpeedHistogram.DefaultBins"/> of them up to 4 × the most probable speed of the
    ''' lightest body, rounded up to a tick of the axis; more when a body is faster), with the 2D Maxwell–Boltzmann curve for
    ''' the gas's kT as the expected count per bin: N f(v) Δv for equal masses; for mixed masses
    ''' the average of each body's curve at the common kT.
    ''' </summary>
    Public Shared Function HistogramGraph(gas As GasState) As GraphPlot
        If gas Is Nothing Then Throw New ArgumentNullException(NameOf(gas))
        Dim g As New GraphPlot With {.Title = "Speeds now, with the 2D Maxwell–Boltzmann curve", .XLabel = "speed v (m/s)", .YFloor = 0}
        If gas.Count = 0 Then
            g.YLabel = "bodies per bin"
            g.EmptyText = "No movable bodies."
            Return g
        End If
        Dim lightest = gas.Masses.Min()
        Dim ticks = AxisTicks.Ticks(0, If(gas.KT > 0, 4 * MaxwellBoltzmann2D.PeakSpeed(lightest, gas.KT), gas.Speeds.Max()), 7)
        Dim top = ticks(ticks.Count - 1)
        Dim width = AxisTicks.NiceStep(top, SpeedHistogram.DefaultBins + 1)
        Dim bars = SpeedHistogram.Count(gas.Speeds, top, CInt(Math.Round(top / width)))
        g.Bars = bars
        g.YLabel = "bodies per " & Units.Sig(bars.BinWidth) & " m/s"
        If gas.KT > 0 Then
            Dim curve As New List(Of Vector)
            Dim reach = bars.Edges(bars.Edges.Count - 1)
            Const Steps As Integer = 120
            For i = 0 To Steps
                Dim v = reach * i / Steps
                curve.Add(New Vector(v, gas.Count * bars.BinWidth * MaxwellBoltzmann2D.MixtureDensity(v, gas.Masses, gas.KT)))
            Next
            g.Lines.Add(New GraphLine("Maxwell–Boltzmann, kT = " & Units.Quantity(gas.KT, "J"), TheoryColour, curve))
        End If
        Dim mean = gas.Speeds.Average()
        g.Notes.Add("N = " & bars.Total & " bodies in the bars   kT = mean KE = " & Units.Quantity(gas.KT, "J"))
        If Not (gas.KT > 0) Then
            g.Notes.Add("Every body is at rest: no temperature, no curve.")
        ElseIf gas.Masses.All(Function(m) m = lightest) Then
            g.Notes.Add("mean speed " & Units.Quantity(mean, "m/s") & "   theory √(πkT/2m) = " & Units.Quantity(MaxwellBoltzmann2D.MeanSpeed(lightest, gas.KT), "m/s"))
        Else
            g.Notes.Add("mean speed " & Units.Quantity(mean, "m/s") & "   (mixed masses: the curve averages each body's, all at kT)")
        End If
        Return g
    End Function

    Private Function PressureGraph() As GraphPlot
        Dim g As New GraphPlot With {.Title = "Pressure on the walls", .XLabel = "time t (s)", .YLabel = "pressure (N/m)", .YFloor = 0}
        Dim gauge = Pressure
        Dim readings = If(gauge Is Nothing, New List(Of PressureReading)(), gauge.Readings.ToList())
        g.Lines.Add(New GraphLine("measured Σ|Δp| / (perimeter × Δt)", TotalColour, readings.Select(Function(r) New Vector(r.Time, r.Measured)).ToList()))
        g.Lines.Add(New GraphLine("ideal gas N·k·T/A", TheoryColour, readings.Select(Function(r) New Vector(r.Time, r.Ideal)).ToList(), dashed:=True))
        If gauge Is Nothing OrElse gauge.ReadingCount = 0 Then
            g.EmptyText = "Run time: a reading every " & Units.Quantity(If(gauge?.ReadingSeconds, 1.0), "s") & " of simulated time."
            Return g
        End If
        Dim gas = GasState.Read(_stage.World)
        Dim err = gauge.StandardError
        g.Notes.Add("measured over " & Units.Quantity(gauge.MeasuredSeconds, "s") & ": " & Units.Quantity(gauge.Average, "N/m") &
                    If(Double.IsNaN(err), "", " ± " & Units.Sig(err, 2)) & "   N·k·T/A = " & Units.Quantity(gauge.AverageIdeal, "N/m"))
        g.Notes.Add("N = " & gas.Count & ", A = " & Units.Quantity(gas.FreeArea, "m²") & ", packing η = " & Units.Sig(gas.PackingFraction, 2) &
                    ": hard discs Z(η)·N·k·T/A = " & Units.Quantity(gas.HardDiscPressure, "N/m"))
        Return g
    End Function

    ''' <summary>The tutorial's page on graphs and exports.</summary>
    Public Shared ReadOnly Property GraphsHelp As New HelpTopic("7. Graphs and data out",
        "The Graphs tab (beside the collision log) draws one graph: Energy (KE, PE and their sum against time), Momentum (px and py against time), Speeds (how many bodies have each speed, with the 2D Maxwell–Boltzmann curve for the gas's temperature) and Pressure (the push of the walls, measured from their impulses, beside the ideal gas law N·k·T/A). ⤢ Window shows the graph in a large window of its own for a projector." & vbLf & "" & vbLf &
        "The graphs show the run since the scene was opened, restarted or reset. A long run is kept whole at a coarser spacing, so memory never grows." & vbLf & "" & vbLf &
        "Export ▾ (beside Scenes) saves the Bodies table, the collision log or the graph's data as a CSV file a spreadsheet opens as it is, or the graph or the canvas as a PNG picture for a worksheet or a slide.")

    ''' <summary>The Maths used pages on the gas graphs.</summary>
    Public Shared ReadOnly Property GraphsMaths As IReadOnlyList(Of HelpTopic) = {
        New HelpTopic("Speeds in a gas: the 2D Maxwell–Boltzmann curve",
            "In a gas at temperature T each velocity component is spread like a normal distribution with variance kT/m. The bodies with speeds between v and v + dv lie in a ring of circumference 2πv in the (vₓ, v_y) plane, so the fraction per m/s is" & vbLf & "" & vbLf &
            "  f(v) = (m v / kT) · exp(−m v² / 2kT)" & vbLf & "" & vbLf &
            "Its area is 1, it peaks at v = √(kT/m), and its mean is √(πkT / 2m). A body moving in a plane (and not spinning) has two degrees of freedom, ½kT each, so its mean kinetic energy is kT: the app reads kT = ΣKE / N, in joules. The curve on the histogram is N f(v) Δv, the count a bin of width Δv should hold. With unequal masses it is the average of every body's own curve at the same kT (heavy bodies are slower, with the same mean energy)."),
        New HelpTopic("Pressure and the ideal gas law in 2D",
            "In two dimensions pressure is force per metre of wall (N/m) and volume is area (m²). The app measures it like a gauge: every bounce gives the wall an impulse |Δp| = m |v after − v before|, and" & vbLf & "" & vbLf &
            "  P = Σ|Δp| / (perimeter × time)" & vbLf & "" & vbLf &
            "From the speeds: a body with velocity component vₓ hits the right wall of a box L wide every 2L/vₓ, with impulse 2mvₓ: an average force mvₓ²/L. N bodies on a wall H long give P = N m⟨vₓ²⟩ / (L H), and ⟨vₓ²⟩ = kT/m, so" & vbLf & "" & vbLf &
            "  P A = N k T" & vbLf & "" & vbLf &
            "with A the area the gas has (the box less the fixed bodies). Real balls take up room: at packing fraction η (the balls' area over A) hard discs press harder, by about Z = (1 + η²/8)/(1 − η)² (Henderson). The lesson's gas has η ≈ 0.1 and presses about 23 % harder than N·k·T/A; a gas of small balls follows the ideal law.")}
End Class
