Option Strict On
Imports System.Diagnostics
Imports System.Globalization
Imports System.IO
Imports System.Text.Json

''' <summary>
''' Runs the app's own frame benchmark (mono SimulatorApp.exe --frame-benchmark N, one JSON line out)
''' on an Xvfb display started here, and reads step and paint times from it. Anything missing (mono,
''' Xvfb, the built app, the option) gives a note instead of a failure.
''' </summary>
Friend Module FrameBenchmark
    ''' <summary>Runs it with <paramref name="circles"/> circles, or says why it cannot.</summary>
    Public Function TryRun(appPath As String, circles As Integer) As FrameResult
        Dim result As New FrameResult With {.Circles = circles}
        Dim mono = FindOnPath("mono")
        Dim xvfb = FindOnPath("Xvfb")
        If mono Is Nothing Then result.Note = "mono is not installed." : Return result
        If xvfb Is Nothing Then result.Note = "Xvfb is not installed." : Return result
        If Not File.Exists(appPath) Then result.Note = "the app is not built at " & appPath & "." : Return result
        If Not KnowsOption(appPath, "--frame-benchmark") Then
            result.Note = "this build of the app has no --frame-benchmark option."
            Return result
        End If

        ' Ready once its socket is there, as before: the benchmark needs no X client tool of its own.
        Dim display As Integer
        Dim started = XDisplays.StartServer(xvfb, 91, 160, "1280x1024x24", TimeSpan.FromSeconds(10), Function(n) True, display)
        If started Is Nothing Then
            result.Note = If(XDisplays.FreeDisplay(91, 160) < 0, "no free X display number.", "Xvfb did not start on any free display from :91 to :160.")
            Return result
        End If
        Using server = started
            Try
                Return RunApp(mono, appPath, circles, display, result)
            Finally
                XDisplays.StopServer(server)
                server.WaitForExit()
            End Try
        End Using
    End Function

    Private Function RunApp(mono As String, appPath As String, circles As Integer, display As Integer, result As FrameResult) As FrameResult
        Dim psi As New ProcessStartInfo(mono) With {.UseShellExecute = False, .RedirectStandardOutput = True, .RedirectStandardError = True}
        psi.ArgumentList.Add(appPath)
        psi.ArgumentList.Add("--frame-benchmark")
        psi.ArgumentList.Add(circles.ToString(CultureInfo.InvariantCulture))
        psi.Environment("DISPLAY") = ":" & display.ToString(CultureInfo.InvariantCulture)
        Using app = Process.Start(psi)
            Dim outTask = app.StandardOutput.ReadToEndAsync()
            Dim errTask = app.StandardError.ReadToEndAsync()
            If Not app.WaitForExit(120000) Then
                app.Kill(True)
                app.WaitForExit()
                result.Note = "the app did not finish within 2 minutes (does this build know --frame-benchmark?)."
                Return result
            End If
            app.WaitForExit()
            ' The plain row is the last JSON line; an app with the momentum views prints their row before it.
            Dim jsonLines = outTask.Result.Split({vbLf}, StringSplitOptions.RemoveEmptyEntries).Select(Function(l) l.Trim()).
                            Where(Function(l) l.StartsWith("{"c)).ToList()
            Dim line = jsonLines.LastOrDefault()
            Dim viewsLine = jsonLines.FirstOrDefault(Function(l) l.Contains(ViewsMarker, StringComparison.Ordinal))
            If line Is Nothing Then
                result.Note = "the app printed no JSON line (exit " & app.ExitCode.ToString(CultureInfo.InvariantCulture) & "): " &
                              FirstLine(errTask.Result & " " & outTask.Result)
                Return result
            End If
            If viewsLine IsNot Nothing AndAlso viewsLine IsNot line Then result.Views = Interpret(viewsLine, New FrameResult With {.Circles = circles})
            Return Interpret(line, result)
        End Using
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
