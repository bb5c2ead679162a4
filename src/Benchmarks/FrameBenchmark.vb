Option Strict On
Imports System.Diagnostics
Imports System.Globalization
Imports System.IO
Imports System.Text.Json

''' <summary>
''' Runs the app's own frame benchmark (mono SimulatorApp.exe --frame-benchmark N, one JSON line out;
''' and --frame-benchmark galton|rope|cradle, the lesson scenes) on an Xvfb display started here, and
''' reads step and paint times from it. Anything missing (mono, Xvfb, the built app, the option)
''' gives a note instead of a failure.
''' </summary>
Friend Module FrameBenchmark
    ''' <summary>
    ''' The lesson scenes the app can time, by its name for each, with the name of the report's scene it
    ''' builds (the app builds the same world; <see cref="CheckSameScene"/> compares them).
    ''' </summary>
    Public ReadOnly Property SceneRows As IReadOnlyList(Of (AppName As String, ReportScene As String)) =
        {("galton", "galton"), ("rope", "rope"), ("cradle", "cradle-strings")}

    ''' <summary>How long one scene's run may take (it times each frame twice: once untimed, as a warm-up).</summary>
    Private ReadOnly SceneTimeout As TimeSpan = TimeSpan.FromMinutes(5)

    ''' <summary>Runs it with <paramref name="circles"/> circles, or says why it cannot.</summary>
    Public Function TryRun(appPath As String, circles As Integer) As FrameResult
        Dim result As New FrameResult With {.Circles = circles}
        Dim missing = MissingPiece(appPath, "--frame-benchmark", "this build of the app has no --frame-benchmark option.")
        If missing IsNot Nothing Then result.Note = missing : Return result
        Dim run = RunOnDisplay(appPath, circles.ToString(CultureInfo.InvariantCulture), TimeSpan.FromMinutes(2))
        If run.Note IsNot Nothing Then result.Note = run.Note : Return result
        If run.TimedOut Then
            result.Note = "the app did not finish within 2 minutes (does this build know --frame-benchmark?)."
            Return result
        End If
        ' The plain row is the last JSON line; an app with the momentum views prints their row before it.
        Dim jsonLines = JsonLinesOf(run.StdOut)
        Dim line = jsonLines.LastOrDefault()
        Dim viewsLine = jsonLines.FirstOrDefault(Function(l) l.Contains(ViewsMarker, StringComparison.Ordinal))
        If line Is Nothing Then
            result.Note = "the app printed no JSON line (exit " & run.ExitCode.ToString(CultureInfo.InvariantCulture) & "): " &
                          FirstLine(run.StdErr & " " & run.StdOut)
            Return result
        End If
        If viewsLine IsNot Nothing AndAlso viewsLine IsNot line Then result.Views = Interpret(viewsLine, New FrameResult With {.Circles = circles})
        Return Interpret(line, result)
    End Function

    ''' <summary>
    ''' Times every scene of <see cref="SceneRows"/> in the app, one after the other, each checked against
    ''' the report's scene of that name; a scene that cannot run says why.
    ''' </summary>
    Public Function TryRunScenes(appPath As String, reportScene As Func(Of String, IBenchScene)) As List(Of SceneFrameResult)
        If reportScene Is Nothing Then Throw New ArgumentNullException(NameOf(reportScene))
        Dim results As New List(Of SceneFrameResult)
        Dim missing = MissingPiece(appPath, SceneRows(0).AppName, "this build of the app cannot time the lesson scenes (--frame-benchmark galton).")
        For Each row In SceneRows
            Dim result As New SceneFrameResult With {.Scene = row.AppName, .ReportScene = row.ReportScene}
            results.Add(result)
            If missing IsNot Nothing Then result.Note = missing : Continue For
            Dim run = RunOnDisplay(appPath, row.AppName, SceneTimeout)
            If run.Note IsNot Nothing Then
                result.Note = run.Note
            ElseIf run.TimedOut Then
                result.Note = "the app did not finish within " & SceneTimeout.TotalMinutes.ToString("0", CultureInfo.InvariantCulture) & " minutes."
            Else
                Dim line = JsonLinesOf(run.StdOut).LastOrDefault()
                If line Is Nothing Then
                    result.Note = "the app printed no JSON line (exit " & run.ExitCode.ToString(CultureInfo.InvariantCulture) & "): " &
                                  FirstLine(run.StdErr & " " & run.StdOut)
                Else
                    InterpretScene(line, result)
                    If result.Ran Then CheckSameScene(result, reportScene(row.ReportScene))
                End If
            End If
        Next
        Return results
    End Function

    ''' <summary>Why the app's frame benchmark cannot run here (mono, Xvfb, the app or its option missing), or Nothing.</summary>
    Private Function MissingPiece(appPath As String, optionText As String, noOption As String) As String
        If FindOnPath("mono") Is Nothing Then Return "mono is not installed."
        If FindOnPath("Xvfb") Is Nothing Then Return "Xvfb is not installed."
        If Not File.Exists(appPath) Then Return "the app is not built at " & appPath & "."
        ' An app that does not know the option is not started: it would open its window and never exit.
        If Not KnowsOption(appPath, optionText) Then Return noOption
        Return Nothing
    End Function

    ''' <summary>What one run of the app left: its output, or why it did not start (Note), or that it was stopped.</summary>
    Private Structure AppRun
        Public Note As String
        Public TimedOut As Boolean
        Public ExitCode As Integer
        Public StdOut As String
        Public StdErr As String
    End Structure

    ''' <summary>Runs mono SimulatorApp.exe --frame-benchmark <paramref name="argument"/> on an Xvfb display started for it.</summary>
    Private Function RunOnDisplay(appPath As String, argument As String, timeout As TimeSpan) As AppRun
        ' Ready once its socket is there, as before: the benchmark needs no X client tool of its own.
        Dim display As Integer
        Dim started = XDisplays.StartServer(FindOnPath("Xvfb"), 91, 160, "1280x1024x24", TimeSpan.FromSeconds(10), Function(n) True, display)
        If started Is Nothing Then
            Return New AppRun With {.Note = If(XDisplays.FreeDisplay(91, 160) < 0, "no free X display number.", "Xvfb did not start on any free display from :91 to :160.")}
        End If
        Using server = started
            Try
                Return RunApp(FindOnPath("mono"), appPath, argument, display, timeout)
            Finally
                XDisplays.StopServer(server)
                server.WaitForExit()
            End Try
        End Using
    End Function

    Private Function RunApp(mono As String, appPath As String, argument As String, display As Integer, timeout As TimeSpan) As AppRun
        Dim psi As New ProcessStartInfo(mono) With {.UseShellExecute = False, .RedirectStandardOutput = True, .RedirectStandardError = True}
        psi.ArgumentList.Add(appPath)
        psi.ArgumentList.Add("--frame-benchmark")
        psi.ArgumentList.Add(argument)
        psi.Environment("DISPLAY") = ":" & display.ToString(CultureInfo.InvariantCulture)
        Using app = Process.Start(psi)
            Dim outTask = app.StandardOutput.ReadToEndAsync()
            Dim errTask = app.StandardError.ReadToEndAsync()
            If Not app.WaitForExit(CInt(timeout.TotalMilliseconds)) Then
                app.Kill(True)
                app.WaitForExit()
                Return New AppRun With {.TimedOut = True}
            End If
            app.WaitForExit()
            Return New AppRun With {.ExitCode = app.ExitCode, .StdOut = outTask.Result, .StdErr = errTask.Result}
        End Using
    End Function

    Private Function JsonLinesOf(output As String) As List(Of String)
        Return output.Split({vbLf}, StringSplitOptions.RemoveEmptyEntries).Select(Function(l) l.Trim()).
                      Where(Function(l) l.StartsWith("{"c)).ToList()
    End Function

    ''' <summary>
    ''' Reads a lesson scene's line (--frame-benchmark galton|rope|cradle): every field by its exact name.
    ''' A line that is not JSON, or lacks a time, leaves <see cref="SceneFrameResult.Ran"/> False with a note.
    ''' </summary>
    Friend Function InterpretScene(line As String, result As SceneFrameResult) As SceneFrameResult
        If result Is Nothing Then Throw New ArgumentNullException(NameOf(result))
        result.RawJson = line
        Try
            Using doc = JsonDocument.Parse(line)
                Dim root = doc.RootElement
                If root.ValueKind <> JsonValueKind.Object Then Throw New JsonException("not an object")
                Dim text = Function(name As String) As String
                               Dim p As JsonElement
                               Return If(root.TryGetProperty(name, p) AndAlso p.ValueKind = JsonValueKind.String, p.GetString(), "")
                           End Function
                Dim number = Function(name As String) As Double
                                 Dim p As JsonElement
                                 Return If(root.TryGetProperty(name, p) AndAlso p.ValueKind = JsonValueKind.Number, p.GetDouble(), Double.NaN)
                             End Function
                Dim times = Function(part As String) New FrameTimes With {.Median = number(part & "_median_ms"), .P95 = number(part & "_p95_ms"), .Worst = number(part & "_max_ms")}
                Dim scene = text("scene")
                If scene.Length > 0 AndAlso result.Scene.Length > 0 AndAlso scene <> result.Scene Then
                    result.Note = "the app timed the scene '" & scene & "', not '" & result.Scene & "'."
                    Return result
                End If
                If result.Scene.Length = 0 Then result.Scene = scene
                result.Solver = text("solver")
                result.Frames = WholeOr0(number("frames"))
                result.SimulatedSeconds = number("simulated_s")
                result.StepMs = times("step")
                result.PaintMs = times("paint")
                result.TotalMs = times("total")
                result.TargetMs = number("target_ms")
                result.OverTargetFrames = WholeOr0(number("over_target_frames"))
                result.SlowFrames = WholeOr0(number("slow_frames"))
                result.LagSeconds = number("lag_s")
                result.Bodies = WholeOr0(number("bodies"))
                result.Links = WholeOr0(number("links"))
                result.EnergyJoules = number("energy_j")
            End Using
        Catch ex As JsonException
            result.Note = "the app's line is not JSON: " & ex.Message
            Return result
        End Try
        result.Ran = result.Frames > 0 AndAlso result.StepMs.Complete AndAlso result.PaintMs.Complete AndAlso result.TotalMs.Complete AndAlso
                     Not Double.IsNaN(result.TargetMs)
        If Not result.Ran Then result.Note = "no frame count, target and median, 95th-percentile and worst step, paint and frame times (ms) in the app's line: " & line
        Return result
    End Function

    ''' <summary>
    ''' Whether the app timed the report's scene: the same number of bodies and links and the same energy
    ''' at the start (to 1 part in 10⁹). A difference is added to the note: the row is then not the report's scene.
    ''' </summary>
    Friend Function CheckSameScene(result As SceneFrameResult, scene As IBenchScene) As Boolean
        If result Is Nothing Then Throw New ArgumentNullException(NameOf(result))
        If scene Is Nothing Then Throw New ArgumentNullException(NameOf(scene))
        Dim world = scene.Build()
        Dim energy = world.Circles.Where(Function(c) Not c.IsFixed).Sum(Function(c) 0.5 * c.Mass * c.Velocity.LengthSquared + c.Mass * world.Gravity * c.Position.Y)
        Dim same = result.Bodies = world.Bodies.Count AndAlso result.Links = world.Links.Count AndAlso
                   Math.Abs(result.EnergyJoules - energy) <= 0.000000001 * Math.Max(1, Math.Abs(energy))
        If Not same Then
            Dim says = "the app's scene is not the report's " & scene.Name & " scene (" &
                       Whole(result.Bodies) & " bodies, " & Whole(result.Links) & " links, " & Joules(result.EnergyJoules) & " J at the start against " &
                       Whole(world.Bodies.Count) & ", " & Whole(world.Links.Count) & ", " & Joules(energy) & " J)."
            result.Note = If(result.Note.Length > 0, result.Note & " " & says, says)
        End If
        Return same
    End Function

    Private Function WholeOr0(value As Double) As Integer
        Return If(Double.IsNaN(value) OrElse value < 0 OrElse value > Integer.MaxValue, 0, CInt(value))
    End Function

    Private Function Joules(value As Double) As String
        Return value.ToString("0.######", CultureInfo.InvariantCulture)
    End Function

    ''' <summary>How the app marks the row measured with the path traces, the centre of mass and the Σp arrow on.</summary>
    Friend Const ViewsMarker As String = """views"":""traces+com"""

    ''' <summary>
    ''' Reads step and paint times (ms) from the app's JSON line. Prefers fields whose names say median,
    ''' then mean/average, then any number named after step or paint.
    ''' </summary>
    Friend Function Interpret(line As String, result As FrameResult) As FrameResult
        If result Is Nothing Then Throw New ArgumentNullException(NameOf(result))
        result.RawJson = line
        Dim numbers As New List(Of KeyValuePair(Of String, Double))
        Try
            Using doc = JsonDocument.Parse(line)
                Flatten(doc.RootElement, "", numbers)
            End Using
        Catch ex As JsonException
            result.Note = "the app's line is not JSON: " & ex.Message
            Return result
        End Try
        result.StepMs = Pick(numbers, "step")
        result.PaintMs = Pick(numbers, "paint")
        Dim count = numbers.FirstOrDefault(Function(kv) kv.Key.Contains("circles", StringComparison.OrdinalIgnoreCase) OrElse
                                                        kv.Key.Equals("n", StringComparison.OrdinalIgnoreCase))
        If count.Key IsNot Nothing AndAlso count.Value >= 1 Then result.Circles = CInt(count.Value)
        result.Ran = Not Double.IsNaN(result.StepMs) AndAlso Not Double.IsNaN(result.PaintMs)
        If Not result.Ran Then result.Note = "no step and paint times (ms) found in the app's line: " & line
        Return result
    End Function

    Private Function Pick(numbers As List(Of KeyValuePair(Of String, Double)), word As String) As Double
        Dim named = numbers.Where(Function(kv) kv.Key.Contains(word, StringComparison.OrdinalIgnoreCase)).ToList()
        For Each preference In {"median", "mean", "avg", "average", "ms"}
            Dim hit = named.FirstOrDefault(Function(kv) kv.Key.Contains(preference, StringComparison.OrdinalIgnoreCase))
            If hit.Key IsNot Nothing Then Return hit.Value
        Next
        Return If(named.Count > 0, named(0).Value, Double.NaN)
    End Function

    Private Sub Flatten(e As JsonElement, prefix As String, into As List(Of KeyValuePair(Of String, Double)))
        Select Case e.ValueKind
            Case JsonValueKind.Object
                For Each p In e.EnumerateObject()
                    Flatten(p.Value, If(prefix.Length = 0, p.Name, prefix & "." & p.Name), into)
                Next
            Case JsonValueKind.Number
                into.Add(New KeyValuePair(Of String, Double)(prefix, e.GetDouble()))
        End Select
    End Sub

    Private Function FirstLine(text As String) As String
        Dim t = text.Trim()
        Dim nl = t.IndexOf(vbLf, StringComparison.Ordinal)
        Return If(nl >= 0, t.Substring(0, nl), t)
    End Function

    ''' <summary>
    ''' Whether the assembly holds the option as a string literal (.NET stores them UTF-16), so an app
    ''' that does not know it is not started: it would open its window and never exit.
    ''' </summary>
    Friend Function KnowsOption(assemblyPath As String, name As String) As Boolean
        Dim bytes = File.ReadAllBytes(assemblyPath)
        Dim pattern = Text.Encoding.Unicode.GetBytes(name)
        Return bytes.AsSpan().IndexOf(pattern) >= 0
    End Function

    Private Function FindOnPath(program As String) As String
        Dim pathVar = Environment.GetEnvironmentVariable("PATH")
        If pathVar Is Nothing Then Return Nothing
        For Each folder In pathVar.Split(Path.PathSeparator)
            If folder.Length = 0 Then Continue For
            Dim candidate = Path.Combine(folder, program)
            If File.Exists(candidate) Then Return candidate
        Next
        Return Nothing
    End Function
End Module
