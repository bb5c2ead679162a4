Option Strict On
Imports System.IO
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Scenes

Namespace Workers
    ''' <summary>
    ''' The worker process's side (Fuzzer --worker PARENT): reads check lines from standard input until it
    ''' closes, loads each scene file as the command line does, checks it and writes the replies. A run
    ''' that never returns is ended by the campaign killing this process; a worker whose campaign is gone
    ''' (killed itself, so it never closed the input) ends on its own within a second or two.
    ''' </summary>
    Friend Module WorkerLoop
        ''' <param name="parent">the campaign's process id; 0 when there is none to watch</param>
        Friend Function Run(input As TextReader, output As TextWriter, parent As Integer) As Integer
            If parent > 0 Then WatchParent(parent)
            Do
                Dim line = input.ReadLine()
                If line Is Nothing Then Return 0
                If line.Length = 0 Then Continue Do
                Dim path As String = Nothing, solver As String = Nothing, plan As RunPlan = Nothing, stopAt As String = Nothing
                WorkerProtocol.ParseCheck(line, path, solver, plan, stopAt)
                Dim scene = File.ReadAllText(path, System.Text.Encoding.UTF8)
                Try
                    Dim result = SceneCheck.Check(scene, solver, plan, stopAt,
                                                  Sub(sample)
                                                      output.WriteLine(WorkerProtocol.StartLine(sample))
                                                      output.Flush()
                                                  End Sub)
                    For Each v In result.Violations
                        output.WriteLine(WorkerProtocol.ViolationLine(v))
                    Next
                    output.WriteLine(WorkerProtocol.DoneLine(result))
                Catch ex As SceneFormatException
                    output.WriteLine(WorkerProtocol.RefusedLine(ex.Message))
                End Try
                output.Flush()
            Loop
        End Function

        ''' <summary>Ends this process when the campaign's process no longer runs.</summary>
        Private Sub WatchParent(parent As Integer)
            Dim watcher As New Threading.Thread(
                Sub()
                    Do
                        Threading.Thread.Sleep(1000)
                        If Not IsRunning(parent) Then Environment.Exit(3)
                    Loop
                End Sub) With {.IsBackground = True, .Name = "parent watch"}
            watcher.Start()
        End Sub

        Private Function IsRunning(id As Integer) As Boolean
            Try
                Using p = Diagnostics.Process.GetProcessById(id)
                    Return Not p.HasExited
                End Using
            Catch ex As ArgumentException
                Return False
            Catch ex As InvalidOperationException
                Return False
            End Try
        End Function
    End Module
End Namespace
