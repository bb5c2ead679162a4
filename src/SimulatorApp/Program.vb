Option Strict On
Imports System.Globalization
Imports System.IO
Imports System.Windows.Forms
Imports PhysicsEngine.Presentation

''' <summary>
''' Entry point of the classroom simulator.
''' <code>
''' SimulatorApp.exe                      the window, with the demo scene
''' SimulatorApp.exe scene.json           the window, with that scene
''' SimulatorApp.exe --gas N              the window, with an elastic gas of N balls
''' SimulatorApp.exe --trace              print one line per action to stdout (for GUI tests)
''' SimulatorApp.exe --stats S            print the frame time and memory every S seconds (for the soak script)
''' SimulatorApp.exe --frame-benchmark N  no window: time 300 frames of N circles (step + paint), print one JSON line
''' SimulatorApp.exe --frame-benchmark galton|rope|cradle   no window: time that lesson scene's frames, print one JSON line
''' </code>
''' </summary>
Public NotInheritable Class Program
    Private Sub New()
    End Sub

    <STAThread>
    Public Shared Function Main(args As String()) As Integer
        ' Before anything touches WinForms: Mono reads these settings when it starts its X11 driver.
        X11KeyboardSafety.Apply()
        Dim trace As Action(Of String) = Nothing
        Dim benchmark As Integer? = Nothing
        Dim benchmarkScene As String = Nothing
        Dim gas As Integer? = Nothing
        Dim stats As Double? = Nothing
        Dim scenePath As String = Nothing
        Dim i = 0
        Do While i < args.Length
            Select Case args(i)
                Case "--trace"
                    Dim out As New StreamWriter(Console.OpenStandardOutput()) With {.AutoFlush = True}
                    trace = Sub(line) out.WriteLine(line)
                Case "--frame-benchmark", "--gas"
                    Dim n As Integer
                    Dim isBenchmark = args(i) = "--frame-benchmark"
                    If isBenchmark AndAlso i + 1 < args.Length AndAlso FrameBenchmark.IsSceneName(args(i + 1)) Then
                        benchmarkScene = args(i + 1)
                        benchmark = Nothing
                    ElseIf i + 1 >= args.Length OrElse Not Integer.TryParse(args(i + 1), NumberStyles.None, CultureInfo.InvariantCulture, n) OrElse n < 1 OrElse n > 100000 Then
                        Console.Error.WriteLine("SimulatorApp: " & args(i) & " needs a number of circles from 1 to 100000" &
                                                If(isBenchmark, " or a scene (" & String.Join(", ", FrameBenchmark.SceneNames) & ")", "") &
                                                If(i + 1 < args.Length, ", not '" & args(i + 1) & "'", ""))
                        Return 2
                    ElseIf isBenchmark Then
                        benchmark = n
                        benchmarkScene = Nothing
                    Else
                        gas = n
                    End If
                    i += 1
                Case "--stats"
                    Dim s As Double
                    If i + 1 >= args.Length OrElse Not Double.TryParse(args(i + 1), NumberStyles.Float, CultureInfo.InvariantCulture, s) OrElse Not (s >= 0.5 AndAlso s <= 3600) Then
                        Console.Error.WriteLine("SimulatorApp: --stats needs a number of seconds from 0.5 to 3600")
                        Return 2
                    End If
                    stats = s
                    i += 1
                Case Else
                    If args(i).StartsWith("-", StringComparison.Ordinal) OrElse scenePath IsNot Nothing Then
                        Console.Error.WriteLine("SimulatorApp: unknown argument '" & args(i) & "' (expected a scene file, --trace, --gas N, --stats S or --frame-benchmark N|galton|rope|cradle)")
                        Return 2
                    End If
                    scenePath = args(i)
            End Select
            i += 1
        Loop
        If benchmarkScene IsNot Nothing Then Return FrameBenchmark.RunScene(benchmarkScene, Console.Out)
        If benchmark.HasValue Then Return FrameBenchmark.Run(benchmark.Value, Console.Out)

        trace?.Invoke("keyboard " & X11KeyboardSafety.Summary)
        Application.EnableVisualStyles()
        Application.SetCompatibleTextRenderingDefault(False)
        AddHandler Application.ThreadException, Sub(s, e) ShowError(e.Exception)
        Dim world As World = Nothing
        If gas.HasValue Then world = Scenarios.ElasticGas(gas.Value)
        Using form As New MainForm(trace, SceneStores.Create(), world, ScenesFolder())
            If stats.HasValue Then form.FrameStats = New FrameStats(stats.Value, Console.Out)
            If scenePath IsNot Nothing Then form.Presenter.OpenAtStart(scenePath)
            Application.Run(form)
        End Using
        Return 0
    End Function

    ''' <summary>The example scenes' folder: "scenes" beside the app or in a folder above it (the repository's), else the current folder.</summary>
    Private Shared Function ScenesFolder() As String
        Dim dir = AppDomain.CurrentDomain.BaseDirectory
        For level = 0 To 6
            If dir Is Nothing Then Exit For
            Dim candidate = Path.Combine(dir, "scenes")
            If Directory.Exists(candidate) Then Return candidate
            dir = Path.GetDirectoryName(dir.TrimEnd(Path.DirectorySeparatorChar))
        Next
        Return Environment.CurrentDirectory
    End Function

    ''' <summary>The last line of defence: a message, never a crash.</summary>
    Private Shared Sub ShowError(ex As Exception)
        Console.Error.WriteLine(ex.ToString())
        MessageBox.Show(ex.Message, MainForm.Title, MessageBoxButtons.OK, MessageBoxIcon.Warning)
    End Sub
End Class
