Option Strict On
Imports System.Globalization
Imports System.IO
Imports System.Windows.Forms

''' <summary>
''' Entry point of the classroom simulator.
''' <code>
''' SimulatorApp.exe                      the window, with the demo scene
''' SimulatorApp.exe --trace              the same, printing one line per action to stdout (for GUI tests)
''' SimulatorApp.exe --frame-benchmark N  no window: time 300 frames of N circles (step + paint), print one JSON line
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
        Dim i = 0
        Do While i < args.Length
            Select Case args(i)
                Case "--trace"
                    Dim out As New StreamWriter(Console.OpenStandardOutput()) With {.AutoFlush = True}
                    trace = Sub(line) out.WriteLine(line)
                Case "--frame-benchmark"
                    Dim n As Integer
                    If i + 1 >= args.Length OrElse Not Integer.TryParse(args(i + 1), NumberStyles.None, CultureInfo.InvariantCulture, n) OrElse n < 1 OrElse n > 100000 Then
                        Console.Error.WriteLine("SimulatorApp: --frame-benchmark needs a number of circles from 1 to 100000")
                        Return 2
                    End If
                    benchmark = n
                    i += 1
                Case Else
                    Console.Error.WriteLine("SimulatorApp: unknown argument '" & args(i) & "' (expected --trace or --frame-benchmark N)")
                    Return 2
            End Select
            i += 1
        Loop
        If benchmark.HasValue Then Return FrameBenchmark.Run(benchmark.Value, Console.Out)

        trace?.Invoke("keyboard " & X11KeyboardSafety.Summary)
        Application.EnableVisualStyles()
        Application.SetCompatibleTextRenderingDefault(False)
        AddHandler Application.ThreadException, Sub(s, e) ShowError(e.Exception)
        Using form As New MainForm(trace, SceneStores.Create())
            Application.Run(form)
        End Using
        Return 0
    End Function

    ''' <summary>The last line of defence: a message, never a crash.</summary>
    Private Shared Sub ShowError(ex As Exception)
        Console.Error.WriteLine(ex.ToString())
        MessageBox.Show(ex.Message, MainForm.Title, MessageBoxButtons.OK, MessageBoxIcon.Warning)
    End Sub
End Class
