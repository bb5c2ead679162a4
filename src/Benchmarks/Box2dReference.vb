Option Strict On
Imports System.Diagnostics
Imports System.Globalization
Imports System.IO
Imports System.Text

''' <summary>
''' Box2D 2.4.1 on the same box pile, for comparison: the pile written as a small text file
''' (<see cref="SceneText"/>), run by src/Benchmarks/box2d/box_pile.cpp (built by
''' scripts/box2d-reference.sh) several times in one process, its lines read back into a result row.
''' </summary>
Friend Module Box2dReference
    ''' <summary>The row's solver name.</summary>
    Public Const SolverName As String = "box2d"

    ''' <summary>Box2D's step: 60 Hz, as a game runs it, s.</summary>
    Public Const TimeStep As Double = 1 / 60.0

    ''' <summary>Simulated seconds after which a Box2D run stops even if bodies are still awake.</summary>
    Public Const CapSeconds As Double = 60.0

    ''' <summary>
    ''' The world's walls and movable rectangles as the reference program reads them: "world W H g e",
    ''' then "box x y w h m" per box (lower-left corner, size, mass; SI units, round-trip precision).
    ''' </summary>
    Public Function SceneText(world As World) As String
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If world.Circles.Count > 0 OrElse world.Polygons.Count > 0 OrElse world.Segments.Count > 0 OrElse world.Links.Count > 0 OrElse
           world.Rectangles.Any(Function(r) r.IsFixed) OrElse Not world.Walls Then
            Throw New ArgumentException("the Box2D reference takes a walled world of movable rectangles only", NameOf(world))
        End If
        Dim sb As New StringBuilder
        sb.Append("# box pile: world <width m> <height m> <g m/s²> <restitution>; box <x m> <y m> <width m> <height m> <mass kg>").Append(ControlChars.Lf)
        sb.Append("world ").Append(R(world.Width)).Append(" "c).Append(R(world.Height)).Append(" "c).Append(R(world.Gravity)).Append(" "c).
           Append(R(world.Restitution)).Append(ControlChars.Lf)
        For Each b In world.Rectangles
            sb.Append("box ").Append(R(b.Min.X)).Append(" "c).Append(R(b.Min.Y)).Append(" "c).Append(R(b.Width)).Append(" "c).Append(R(b.Height)).
               Append(" "c).Append(R(b.Mass)).Append(ControlChars.Lf)
        Next
        Return sb.ToString()
    End Function

    Private Function R(x As Double) As String
        Return x.ToString("R", CultureInfo.InvariantCulture)
    End Function

    ''' <summary>One run's line from the reference program.</summary>
    Friend Structure RunLine
        Public Steps As Integer
        Public SimulatedSeconds As Double
        Public WallMs As Double
        Public MaxOverlap As Double
        Public Asleep As Integer
        Public Bodies As Integer
    End Structure

    ''' <summary>
    ''' Reads "run k steps=… simulated_s=… wall_ms=… max_overlap_m=… asleep=… bodies=…"; Nothing for any
    ''' other line or a line with a field missing or unreadable.
    ''' </summary>
    Public Function ParseRunLine(line As String) As RunLine?
        If line Is Nothing OrElse Not line.StartsWith("run ", StringComparison.Ordinal) Then Return Nothing
        Dim fields As New Dictionary(Of String, String)(StringComparer.Ordinal)
        For Each word In line.Split(" "c, StringSplitOptions.RemoveEmptyEntries)
            Dim eq = word.IndexOf("="c)
            If eq > 0 Then fields(word.Substring(0, eq)) = word.Substring(eq + 1)
        Next
        Dim r As New RunLine
        Dim ok = Int("steps", fields, r.Steps) And Num("simulated_s", fields, r.SimulatedSeconds) And Num("wall_ms", fields, r.WallMs) And
                 Num("max_overlap_m", fields, r.MaxOverlap) And Int("asleep", fields, r.Asleep) And Int("bodies", fields, r.Bodies)
        If Not ok Then Return Nothing
        Return r
    End Function

    Private Function Num(name As String, fields As Dictionary(Of String, String), ByRef value As Double) As Boolean
        Dim text As String = Nothing
        Return fields.TryGetValue(name, text) AndAlso Double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, value) AndAlso
               Not Double.IsNaN(value) AndAlso Not Double.IsInfinity(value)
    End Function

    Private Function Int(name As String, fields As Dictionary(Of String, String), ByRef value As Integer) As Boolean
        Dim text As String = Nothing
        Return fields.TryGetValue(name, text) AndAlso Integer.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, value)
    End Function

    ''' <summary>
    ''' The result row from the runs' lines: the median wall-clock time to rest (when every run ended with
    ''' every body asleep), the simulated time and the overlap of the first run (the runs are the same
    ''' computation), and a note with the range and the sleep count.
    ''' </summary>
    Public Function Summarise(sceneName As String, metric As String, runs As IReadOnlyList(Of RunLine)) As BenchResult
        If runs Is Nothing Then Throw New ArgumentNullException(NameOf(runs))
        If runs.Count = 0 Then Return NotRun(sceneName, metric, "the reference program printed no run")
        Dim first = runs(0)
        Dim walls = runs.Select(Function(x) x.WallMs).ToList()
        Dim allAsleep = runs.All(Function(x) x.Asleep = x.Bodies)
        Dim median = Statistics.Median(walls)
        Dim r As New BenchResult With {
            .Scene = sceneName, .Solver = SolverName, .TimeStep = TimeStep, .ErrorMetric = If(metric, ""),
            .Error = Math.Max(0, first.MaxOverlap), .BodyCount = first.Bodies, .Runs = runs.Count,
            .SimulatedSeconds = first.SimulatedSeconds,
            .MsPerSimulatedSecond = median / first.SimulatedSeconds}
        If allAsleep Then
            r.RestSeconds = first.SimulatedSeconds
            r.RestWallMs = median
        End If
        Dim n = first.Bodies.ToString(CultureInfo.InvariantCulture)
        r.Note = If(allAsleep, "all " & n & " asleep after " & first.Steps.ToString(CultureInfo.InvariantCulture) & " steps",
                    first.Asleep.ToString(CultureInfo.InvariantCulture) & " of " & n & " asleep when stopped at " &
                    first.SimulatedSeconds.ToString("0.##", CultureInfo.InvariantCulture) & " s") &
                 "; wall " & NumberText.Fixed2(walls.Min()) & "–" & NumberText.Fixed2(walls.Max()) & " ms over " & runs.Count.ToString(CultureInfo.InvariantCulture) &
                 " runs; end overlap " & NumberText.Sci(first.MaxOverlap) & " m (negative: a gap)"
        Return r
    End Function

    ''' <summary>A row saying why Box2D's figures are missing.</summary>
    Public Function NotRun(sceneName As String, metric As String, why As String) As BenchResult
        Dim r = SceneRunner.NotAvailable(sceneName, SolverName, TimeStep, why)
        r.ErrorMetric = If(metric, "")
        Return r
    End Function

    ''' <summary>
    ''' Runs the reference program <paramref name="program"/> on the scene's pile <paramref name="runs"/>
    ''' times and returns its row; anything that goes wrong (no program, a crash, a time-out, lines it cannot
    ''' read) becomes a row that says so, never an exception.
    ''' </summary>
    Public Function Run(program As String, scene As BoxPileScene, runs As Integer, timeout As TimeSpan) As BenchResult
        If scene Is Nothing Then Throw New ArgumentNullException(NameOf(scene))
        If program Is Nothing OrElse Not File.Exists(program) Then Return NotRun(scene.Name, scene.ErrorMetric, "not run: the Box2D reference program is missing (" & program & ")")
        Dim sceneFile = Path.Combine(Path.GetTempPath(), "box2d-" & scene.Name & "-" & Environment.ProcessId.ToString(CultureInfo.InvariantCulture) & ".txt")
        Try
            File.WriteAllText(sceneFile, SceneText(scene.Build()), New UTF8Encoding(False))
            Dim psi As New ProcessStartInfo(program) With {.RedirectStandardOutput = True, .RedirectStandardError = True, .UseShellExecute = False}
            psi.ArgumentList.Add(sceneFile)
            psi.ArgumentList.Add("--runs")
            psi.ArgumentList.Add(runs.ToString(CultureInfo.InvariantCulture))
            psi.ArgumentList.Add("--cap")
            psi.ArgumentList.Add(CapSeconds.ToString("R", CultureInfo.InvariantCulture))
            Using p = Process.Start(psi)
                Dim errors = p.StandardError.ReadToEndAsync()
                Dim output = p.StandardOutput.ReadToEndAsync()
                If Not p.WaitForExit(CInt(timeout.TotalMilliseconds)) Then
                    p.Kill(True)
                    Return NotRun(scene.Name, scene.ErrorMetric, "the Box2D reference timed out after " & timeout.TotalSeconds.ToString("0", CultureInfo.InvariantCulture) & " s")
                End If
                p.WaitForExit()
                If p.ExitCode <> 0 Then
                    Return NotRun(scene.Name, scene.ErrorMetric, "the Box2D reference failed (exit " & p.ExitCode.ToString(CultureInfo.InvariantCulture) & "): " & errors.Result.Trim())
                End If
                Dim lines = output.Result.Split(ControlChars.Lf).Select(Function(l) ParseRunLine(l.Trim())).Where(Function(l) l.HasValue).Select(Function(l) l.Value).ToList()
                Return Summarise(scene.Name, scene.ErrorMetric, lines)
            End Using
        Catch ex As Exception When TypeOf ex Is IOException OrElse TypeOf ex Is ComponentModel.Win32Exception OrElse TypeOf ex Is UnauthorizedAccessException
            Return NotRun(scene.Name, scene.ErrorMetric, "the Box2D reference could not run: " & ex.Message)
        Finally
            Try
                File.Delete(sceneFile)
            Catch ex As IOException
            End Try
        End Try
    End Function
End Module
