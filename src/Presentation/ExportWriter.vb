Option Strict On
Imports System.IO

''' <summary>
''' The Export menu: the Bodies table, the collision log and the graph's series as CSV a spreadsheet
''' opens as it is (see Csv), and pictures the window draws (graph, canvas) as PNG. Every file is
''' written whole or not at all (WholeFile); a failure is a message naming the file and the reason.
''' </summary>
Friend NotInheritable Class ExportWriter
    Private ReadOnly _stage As Stage
    Private ReadOnly _graphs As GraphRecorder

    Public Sub New(stage As Stage, graphs As GraphRecorder)
        _stage = stage
        _graphs = graphs
    End Sub

    ''' <summary>The Export button's caption.</summary>
    Public Const ExportCaption As String = "Export ▾"

    ''' <summary>The Export menu's items, in <see cref="ExportKind"/> order.</summary>
    Public Shared ReadOnly Property Names As IReadOnlyList(Of String) = {
        "Bodies table (CSV)…", "Collision log (CSV)…", "Graph series (CSV)…", "Graph picture (PNG)…", "Canvas picture (PNG)…"}

    ''' <summary>The file name the Save dialog suggests for an export.</summary>
    Public Function ExportFileName(kind As ExportKind) As String
        Select Case kind
            Case ExportKind.BodiesCsv : Return "bodies.csv"
            Case ExportKind.LogCsv : Return "collisions.csv"
            Case ExportKind.SeriesCsv : Return "graph-" & GraphSlug() & ".csv"
            Case ExportKind.GraphPng : Return "graph-" & GraphSlug() & ".png"
            Case Else : Return "canvas.png"
        End Select
    End Function

    Private Function GraphSlug() As String
        Select Case _graphs.Graph
            Case GraphKind.Momentum : Return "momentum"
            Case GraphKind.SpeedHistogram : Return "speeds"
            Case GraphKind.Pressure : Return "pressure"
            Case Else : Return "energy"
        End Select
    End Function

    ''' <summary>The Bodies table as CSV: every body, numbers in SI units at full precision.</summary>
    Public Function BodiesCsv() As String
        Dim header = {"id", "kind", "colour", "x (m)", "y (m)", "vx (m/s)", "vy (m/s)", "speed (m/s)", "mass (kg)",
                      "radius (m)", "width (m)", "height (m)", "area (m²)"}
        Dim rows As New List(Of IEnumerable(Of String))
        For Each b In _stage.World.Bodies
            Dim r = BodyRow.Capture(b)
            Dim size = Function(name As String) As String
                           Dim f = r.SizeFields.Where(Function(s) s.Name = name).ToList()
                           Return If(f.Count = 0, "", Csv.Number(f(0).Metres))
                       End Function
            rows.Add({r.Id, r.KindLabel, r.Colour, Csv.Number(r.Centre.X), Csv.Number(r.Centre.Y), Csv.Number(r.Velocity.X), Csv.Number(r.Velocity.Y),
                      Csv.Number(r.Velocity.Length), If(r.IsFixed, "", Csv.Number(r.Mass)), size("radius"), size("width"), size("height"), Csv.Number(r.Area)})
        Next
        Return Csv.Document(header, rows)
    End Function

    ''' <summary>The collision log as CSV, oldest row first, numbers in SI units at full precision.</summary>
    Public Function LogCsv() As String
        Dim header = {"t (s)", "first t (s)", "a", "b", "collisions", "a speed before (m/s)", "a speed after (m/s)",
                      "b speed before (m/s)", "b speed after (m/s)", "px before (kg·m/s)", "py before (kg·m/s)",
                      "px after (kg·m/s)", "py after (kg·m/s)", "KE before (J)", "KE after (J)", "note"}
        Dim rows As New List(Of IEnumerable(Of String))
        For i = _stage.Log.Count - 1 To 0 Step -1
            Dim e = _stage.Log(i)
            If e.SkippedCount > 0 Then
                rows.Add({Csv.Number(e.Time), "", "", "", e.SkippedCount.ToString(Globalization.CultureInfo.InvariantCulture), "", "", "", "", "", "", "", "", "", "",
                          "more collisions, counted but not listed"})
                Continue For
            End If
            Dim note = If(e.WasCarried, "a carried body", If(e.IsPair, "pair: momentum conserved", "against a wall or fixed body: the wall takes the impulse"))
            rows.Add({Csv.Number(e.Time), Csv.Number(e.FirstTime), e.AName, e.BName, e.Repeats.ToString(Globalization.CultureInfo.InvariantCulture),
                      Csv.Number(e.ASpeedBefore), Csv.Number(e.ASpeedAfter),
                      If(e.IsPair, Csv.Number(e.BSpeedBefore), ""), If(e.IsPair, Csv.Number(e.BSpeedAfter), ""),
                      Csv.Number(e.MomentumBefore.X), Csv.Number(e.MomentumBefore.Y), Csv.Number(e.MomentumAfter.X), Csv.Number(e.MomentumAfter.Y),
                      Csv.Number(e.EnergyBefore), Csv.Number(e.EnergyAfter), note})
        Next
        Return Csv.Document(header, rows)
    End Function

    ''' <summary>
    ''' The graph on show as CSV. Against time: the recorded totals, with the command line's
    ''' --series columns (t, ke, pe, energy, px, py, com_x, com_y) and their units. The histogram: its
    ''' bins with the counts and the Maxwell–Boltzmann expectation. The pressure: its readings.
    ''' </summary>
    Public Function SeriesCsv() As String
        Select Case _graphs.Graph
            Case GraphKind.SpeedHistogram
                Dim gas = GasState.Read(_stage.World)
                Dim plot = GraphRecorder.HistogramGraph(gas)
                Dim rows As New List(Of IEnumerable(Of String))
                If plot.Bars IsNot Nothing Then
                    Dim expected = If(gas.KT > 0, MaxwellBoltzmann2D.ExpectedCounts(plot.Bars.Edges, gas.Masses, gas.KT), Nothing)
                    For i = 0 To plot.Bars.Counts.Count - 1
                        rows.Add({Csv.Number(plot.Bars.Edges(i)), Csv.Number(plot.Bars.Edges(i + 1)), plot.Bars.Counts(i).ToString(Globalization.CultureInfo.InvariantCulture),
                                  If(expected Is Nothing, "", Csv.Number(expected(i)))})
                    Next
                End If
                Return Csv.Document(HistogramHeader, rows)
            Case GraphKind.Pressure
                Dim readings = If(_graphs.Pressure?.Readings, New List(Of PressureReading)())
                Return Csv.Document(PressureHeader,
                                    readings.Select(Function(r) CType({Csv.Number(r.Time), Csv.Number(r.Measured), Csv.Number(r.Ideal)}, IEnumerable(Of String))))
            Case Else
                Return Csv.Document(SeriesHeader, _graphs.Series.Samples.Select(Function(s) CType({Csv.Number(s.Time), Csv.Number(s.Kinetic), Csv.Number(s.Potential), Csv.Number(s.Total),
                                    Csv.Number(s.Momentum.X), Csv.Number(s.Momentum.Y), Csv.Number(s.CentreOfMass.X), Csv.Number(s.CentreOfMass.Y)}, IEnumerable(Of String))))
        End Select
    End Function

    ''' <summary>The histogram CSV's header.</summary>
    Private Shared ReadOnly HistogramHeader As String() = {"v from (m/s)", "v to (m/s)", "bodies", "Maxwell–Boltzmann expected"}
    ''' <summary>The pressure CSV's header.</summary>
    Private Shared ReadOnly PressureHeader As String() = {"t (s)", "measured pressure (N/m)", "N·k·T/A (N/m)"}

    ''' <summary>The series CSV's header: the command line's --series columns, each with its unit.</summary>
    Public Shared ReadOnly Property SeriesHeader As IReadOnlyList(Of String) = {
        "t (s)", "ke (J)", "pe (J)", "energy (J)", "px (kg·m/s)", "py (kg·m/s)", "com_x (m)", "com_y (m)"}

    ''' <summary>Writes a CSV export to <paramref name="path"/>; says what was written, or why not.</summary>
    Public Sub ExportCsv(kind As ExportKind, path As String)
        Dim text As String
        Select Case kind
            Case ExportKind.BodiesCsv : text = BodiesCsv()
            Case ExportKind.LogCsv : text = LogCsv()
            Case ExportKind.SeriesCsv : text = SeriesCsv()
            Case Else : Throw New ArgumentOutOfRangeException(NameOf(kind))
        End Select
        Dim bytes = Csv.Bytes(text)
        Dim rows = Csv.Parse(text).Count - 1
        Export(kind, path, Sub(s) s.Write(bytes, 0, bytes.Length), rows & " rows")
    End Sub

    ''' <summary>Writes a picture the window drew (PNG) to <paramref name="path"/> through <paramref name="write"/>; says what was written, or why not.</summary>
    Public Sub ExportPicture(kind As ExportKind, path As String, write As Action(Of Stream), width As Integer, height As Integer)
        Export(kind, path, write, width & "x" & height & " px")
    End Sub

    Private Sub Export(kind As ExportKind, path As String, write As Action(Of Stream), what As String)
        If String.IsNullOrEmpty(path) Then Return
        Dim name = IO.Path.GetFileName(path)
        Dim missing = FolderCheck.MissingFolder(path)
        If missing IsNot Nothing Then
            _stage.Emit("export failed " & kind.ToString() & " " & path)
            _stage.ShowMessage("Could not export " & name & ": " & missing & ".")
            Return
        End If
        Try
            WholeFile.Write(path, write)
            _stage.Emit("exported " & kind.ToString() & " " & path & " " & what)
            _stage.ShowMessage("Exported " & Names(kind).TrimEnd("…"c) & " to " & name & " (" & what & ").")
        Catch ex As IOException
            _stage.Emit("export failed " & kind.ToString() & " " & path)
            _stage.ShowMessage("Could not export " & name & ": " & Stage.OneLine(ex.Message))
        Catch ex As ArgumentException
            _stage.ShowMessage("Could not export " & name & ": " & Stage.OneLine(ex.Message))
        Catch ex As Runtime.InteropServices.ExternalException
            ' GDI+ failing to encode a picture.
            _stage.ShowMessage("Could not export " & name & ": the picture could not be made (" & Stage.OneLine(ex.Message) & "); nothing was written")
        End Try
    End Sub
End Class
