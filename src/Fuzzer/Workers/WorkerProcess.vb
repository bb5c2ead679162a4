Option Strict On
Imports System.Diagnostics
Imports System.Globalization
Imports System.IO
Imports System.Text
Imports PhysicsEngine.Fuzzing.Checking

Namespace Workers
    ''' <summary>
    ''' One worker process (this program with --worker), started on first use and again after it was
    ''' killed or died. It checks scenes from files; when it goes silent for longer than a run may take
    ''' (twice the cap and five seconds: the worker checks the cap itself after every sample, so only a
    ''' single advance that never returns gets here), it is killed and the run fails the wall-time cap.
    ''' A process is needed for that: .NET cannot stop a thread that is inside a solver's loop.
    ''' </summary>
    Friend NotInheritable Class WorkerProcess
        Implements ISceneChecker, IDisposable

        Private ReadOnly _scratch As String
        Private ReadOnly _start As Func(Of ProcessStartInfo)
        Private _process As Process
        Private _stderr As StringBuilder
        Private _disposed As Boolean

        ''' <param name="scratch">a file this worker may write scenes to</param>
        ''' <param name="start">how to start the process (<see cref="StartInfo"/> when Nothing)</param>
        Friend Sub New(scratch As String, Optional start As Func(Of ProcessStartInfo) = Nothing)
            _scratch = scratch
            _start = If(start, AddressOf StartInfo)
        End Sub

        ''' <summary>How the worker is started: the dotnet host and this program's dll, or this program's own executable.</summary>
        Friend Shared Function StartInfo() As ProcessStartInfo
            Dim dll = GetType(WorkerProcess).Assembly.Location
            Dim host = Environment.GetEnvironmentVariable("DOTNET_HOST_PATH")
            Dim current = Environment.ProcessPath
            If String.IsNullOrEmpty(host) Then
                host = If(current IsNot Nothing AndAlso Path.GetFileNameWithoutExtension(current).Equals("dotnet", StringComparison.OrdinalIgnoreCase), current, "dotnet")
            End If
            Dim psi As New ProcessStartInfo(host) With {
                .RedirectStandardInput = True, .RedirectStandardOutput = True, .RedirectStandardError = True,
                .UseShellExecute = False, .StandardOutputEncoding = New UTF8Encoding(False)}
            psi.ArgumentList.Add(dll)
            psi.ArgumentList.Add("--worker")
            psi.ArgumentList.Add(Environment.ProcessId.ToString(CultureInfo.InvariantCulture))
            Return psi
        End Function

        Public Function Check(sceneText As String, solver As String, plan As RunPlan, stopAt As String) As CheckResult Implements ISceneChecker.Check
            If plan Is Nothing Then Throw New ArgumentNullException(NameOf(plan))
            File.WriteAllText(_scratch, sceneText, New UTF8Encoding(False))
            EnsureStarted()
            Dim result As New CheckResult()
            Dim sample = plan.Sample
            _process.StandardInput.WriteLine(WorkerProtocol.CheckLine(_scratch, solver, plan, stopAt))
            _process.StandardInput.Flush()
            Dim silence = TimeSpan.FromSeconds(2 * plan.Cap + 5)
            Do
                Dim pending = _process.StandardOutput.ReadLineAsync()
                If Not pending.Wait(silence) Then
                    Kill()
                    result.Violations.Add(New Violation(Invariants.WallTime, solver, sample, plan.Time,
                        "one advance ran for over " & silence.TotalSeconds.ToString("0", CultureInfo.InvariantCulture) & " s (cap " &
                        plan.Cap.ToString("R", CultureInfo.InvariantCulture) & " s); the worker process was killed"))
                    Return result
                End If
                Dim line = pending.Result
                If line Is Nothing Then
                    result.Violations.Add(New Violation(Invariants.Crash, solver, sample, plan.Time, "the worker process died: " & Died()))
                    Return result
                End If
                Select Case WorkerProtocol.VerbOf(line)
                    Case WorkerProtocol.StartVerb
                        sample = WorkerProtocol.Parse(WorkerProtocol.RestOf(line))
                    Case WorkerProtocol.ViolationVerb
                        result.Violations.Add(WorkerProtocol.ParseViolation(line))
                    Case WorkerProtocol.RefusedVerb
                        result.Violations.Add(New Violation(Invariants.Refused, solver, sample, 0, WorkerProtocol.RestOf(line)))
                        Return result
                    Case WorkerProtocol.DoneVerb
                        WorkerProtocol.ParseDone(line, result)
                        Return result
                    Case Else
                        Throw New InvalidOperationException("unexpected line from a worker: " & line)
                End Select
            Loop
        End Function

        Private Sub EnsureStarted()
            If _disposed Then Throw New ObjectDisposedException(NameOf(WorkerProcess))
            If _process IsNot Nothing AndAlso Not _process.HasExited Then Return
            _process?.Dispose()
            _stderr = New StringBuilder()
            Dim p = Process.Start(_start())
            Dim errors = _stderr
            AddHandler p.ErrorDataReceived, Sub(sender, e)
                                                If e.Data Is Nothing Then Return
                                                SyncLock errors
                                                    If errors.Length < 4000 Then errors.Append(e.Data).Append(" "c)
                                                End SyncLock
                                            End Sub
            p.BeginErrorReadLine()
            _process = p
        End Sub

        ''' <summary>Why the process ended: its exit code and the start of what it wrote to standard error.</summary>
        Private Function Died() As String
            ' Once it has exited, the wait without a timeout also waits for the last of standard error to be read
            ' (the timed one does not): its last words, such as "out of stack", are part of the answer.
            If _process.WaitForExit(5000) Then _process.WaitForExit()
            Dim code = If(_process.HasExited, _process.ExitCode.ToString(CultureInfo.InvariantCulture), "?")
            Dim text As String
            SyncLock _stderr
                text = _stderr.ToString()
            End SyncLock
            _process.Dispose()
            _process = Nothing
            Return "exit code " & code & If(text.Length > 0, ": " & SceneRunner.OneLine(text), "")
        End Function

        ''' <summary>Ends this worker's process (and only it), and forgets it; the next check starts a new one.</summary>
        Private Sub Kill()
            If _process Is Nothing Then Return
            Try
                If Not _process.HasExited Then _process.Kill(entireProcessTree:=True)
                _process.WaitForExit(5000)
            Catch ex As InvalidOperationException
                ' it exited on its own meanwhile
            End Try
            _process.Dispose()
            _process = Nothing
        End Sub

        Public Sub Dispose() Implements IDisposable.Dispose
            If _disposed Then Return
            _disposed = True
            If _process IsNot Nothing Then
                Try
                    _process.StandardInput.Close() ' the worker ends when its input does
                    If Not _process.WaitForExit(2000) Then Kill()
                Catch ex As IOException
                    Kill()
                End Try
                _process?.Dispose()
                _process = Nothing
            End If
            If File.Exists(_scratch) Then File.Delete(_scratch)
        End Sub
    End Class
End Namespace
