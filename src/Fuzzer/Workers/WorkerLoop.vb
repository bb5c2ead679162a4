Option Strict On
Imports System.IO
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Scenes

Namespace Workers
    ''' <summary>
    ''' The worker process's side (Fuzzer --worker): reads check lines from standard input until it
    ''' closes, loads each scene file as the command line does, checks it and writes the replies. A run
    ''' that never returns is ended by the campaign killing this process.
    ''' </summary>
    Friend Module WorkerLoop
        Friend Function Run(input As TextReader, output As TextWriter) As Integer
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
    End Module
End Namespace
