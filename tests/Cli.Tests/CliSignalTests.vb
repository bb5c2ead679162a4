Option Strict On
Imports System.Diagnostics
Imports Xunit

''' <summary>
''' Stopping a run with Ctrl+C (SIGINT) or SIGTERM: one line on standard error says so, the status is
''' 1 (cli.md: any other failure), nothing goes to standard output, and no output file, finished or
''' temporary, is left behind. Signals are POSIX and are sent with kill, so this runs where CI runs.
''' </summary>
Public Class CliSignalTests
    <Runtime.InteropServices.DllImport("libc", EntryPoint:="kill", SetLastError:=True)>
    Private Shared Function NativeKill(pid As Integer, sig As Integer) As Integer
    End Function

    ''' <summary>Every file in the folder, hidden ones (the temporary outputs start with a dot) included.</summary>
    Private Shared Function AllFiles(folder As String) As String()
        Dim options As New IO.EnumerationOptions With {.AttributesToSkip = 0}
        Return IO.Directory.GetFileSystemEntries(folder, "*", options).Select(Function(f) IO.Path.GetFileName(f)).OrderBy(Function(f) f, StringComparer.Ordinal).ToArray()
    End Function

    ''' <summary>Sends signal <paramref name="number"/> to the run and waits (30 s at most) until it has ended.</summary>
    Private Shared Sub SignalAndWait(p As Process, number As Integer, name As String)
        Assert.True(NativeKill(p.Id, number) = 0, "kill failed")
        If Not p.WaitForExit(30000) Then
            p.Kill(True)
            Assert.Fail(name & " did not stop the run within 30 s")
        End If
        p.WaitForExit()
    End Sub

    <Theory>
    <InlineData("TERM", "SIGTERM")>
    <InlineData("INT", "Ctrl+C (SIGINT)")>
    Public Sub RunStoppedBySignal_SaysSo_Exits1_AndLeavesNoFile(signal As String, name As String)
        If OperatingSystem.IsWindows() Then Return ' no POSIX signals to send
        Using t As New TempFolder()
            Dim scene = t.Write("head-on.json", HeadOn)
            ' Millions of samples: long enough to be stopped while it writes.
            Dim psi As New ProcessStartInfo("dotnet") With {
                .RedirectStandardOutput = True, .RedirectStandardError = True, .UseShellExecute = False}
            For Each a In {CliDll, "run", scene, "--time", "5000", "--sample", "0.001", "--states", t.File("states.csv"), "--events", t.File("events.csv"), "--series", t.File("series.csv")}
                psi.ArgumentList.Add(a)
            Next
            Using p = Process.Start(psi)
                Dim outTask = p.StandardOutput.ReadToEndAsync()
                Dim errTask = p.StandardError.ReadToEndAsync()
                ' Wait until it is writing (its temporary files exist), then send the signal.
                Dim clock = Stopwatch.StartNew()
                While AllFiles(t.Path).Length < 4 AndAlso clock.Elapsed.TotalSeconds < 30 AndAlso Not p.HasExited
                    Threading.Thread.Sleep(50)
                End While
                Threading.Thread.Sleep(300)
                If p.HasExited Then Assert.Fail("the run ended before it could be stopped: " & errTask.Result)
                SignalAndWait(p, If(signal = "TERM", 15, 2), name)
                Assert.Equal(1, p.ExitCode)
                Assert.Equal("run: interrupted by " & name & "; no output file was written" & vbLf, errTask.Result)
                Assert.Equal("", outTask.Result)
            End Using
            Assert.Equal("head-on.json", String.Join(" ", AllFiles(t.Path)))
        End Using
    End Sub

    <Fact>
    Public Sub RunStoppedWhileStreamingIntoAFifo_SaysTheStreamedTableStoppedPartWay()
        If OperatingSystem.IsWindows() Then Return ' no FIFOs or POSIX signals there
        Using t As New TempFolder()
            Dim scene = t.Write("head-on.json", HeadOn)
            Dim fifo = t.File("states.fifo")
            Dim made = ProcessRunner.Run("mkfifo", {fifo}, Nothing, TimeSpan.FromSeconds(30))
            Assert.True(made.ExitCode = 0, made.ToString())
            ' A reader that counts what arrives, until the writer closes the FIFO.
            Dim received As Long = 0
            Dim reader = Threading.Tasks.Task.Run(
                Sub()
                    Using stream = IO.File.OpenRead(fifo)
                        Dim buffer(65535) As Byte
                        Do
                            Dim n = stream.Read(buffer, 0, buffer.Length)
                            If n <= 0 Then Exit Do
                            Threading.Interlocked.Add(received, n)
                        Loop
                    End Using
                End Sub)
            Dim psi As New ProcessStartInfo("dotnet") With {
                .RedirectStandardOutput = True, .RedirectStandardError = True, .UseShellExecute = False}
            Dim args = New String() {CliDll, "run", scene, "--time", "5000", "--sample", "0.001", "--states", fifo, "--events", t.File("events.csv")}
            For Each a In args
                psi.ArgumentList.Add(a)
            Next
            Using p = Process.Start(psi)
                Dim outTask = p.StandardOutput.ReadToEndAsync()
                Dim errTask = p.StandardError.ReadToEndAsync()
                Dim clock = Stopwatch.StartNew()
                While Threading.Interlocked.Read(received) < 100000 AndAlso clock.Elapsed.TotalSeconds < 30 AndAlso Not p.HasExited
                    Threading.Thread.Sleep(50)
                End While
                If p.HasExited Then Assert.Fail("the run ended before it could be stopped: " & errTask.Result)
                SignalAndWait(p, 15, "SIGTERM")
                Assert.Equal(1, p.ExitCode)
                Assert.Equal("run: interrupted by SIGTERM; no output file was written (the table streamed into '" & fifo & "' stopped part-way)" & vbLf, errTask.Result)
                Assert.Equal("", outTask.Result)
            End Using
            Assert.True(reader.Wait(TimeSpan.FromSeconds(30)), "the FIFO was never closed")
            Assert.True(Threading.Interlocked.Read(received) >= 100000)
            Assert.Equal("head-on.json states.fifo", String.Join(" ", AllFiles(t.Path)))
        End Using
    End Sub
End Class
