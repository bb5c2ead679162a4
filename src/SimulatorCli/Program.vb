Option Strict On

''' <summary>Entry point: dispatches the verb. Exit 0 on success, 2 on bad input, 1 on any other failure.</summary>
Public NotInheritable Class Program
    Private Sub New()
    End Sub

    Public Shared Function Main(args As String()) As Integer
        If args Is Nothing Then Throw New ArgumentNullException(NameOf(args))
        Try
            If args.Length = 0 Then
                ' Bad input gets one line on stderr; the full usage is --help's.
                Console.Error.WriteLine("usage: SimulatorCli validate SCENE | run SCENE --time T [options] (no verb given; --help lists the options)")
                Return ExitCodes.BadInput
            End If
            If args(0) = "--help" OrElse args(0) = "-h" Then
                Console.Out.WriteLine(Usage)
                Return ExitCodes.Ok
            End If
            Dim rest = args.Skip(1).ToList()
            If rest.Contains("--help") OrElse rest.Contains("-h") Then
                Console.Out.WriteLine(Usage)
                Return ExitCodes.Ok
            End If
            Select Case args(0)
                Case "validate"
                    Return ValidateCommand.Execute(rest)
                Case "run"
                    Return RunCommand.Execute(RunOptions.Parse(rest))
                Case Else
                    Console.Error.WriteLine("unknown verb '" & args(0) & "' (expected validate or run)")
                    Return ExitCodes.BadInput
            End Select
        Catch ex As BadInputException
            Console.Error.WriteLine(OneLine(ex.Message))
            Return ExitCodes.BadInput
        Catch ex As SpeedLimitException
            ' A valid scene the solvers cannot simulate: a failure of the run, not bad input (cli.md).
            Console.Error.WriteLine("run: " & OneLine(ex.Message))
            Return ExitCodes.Failure
        Catch ex As UnsupportedSceneException
            ' A valid scene the chosen solver cannot move yet; the message names the solver that can.
            Console.Error.WriteLine("run: " & OneLine(ex.Message))
            Return ExitCodes.Failure
        Catch ex As Exception When Not TypeOf ex Is OutOfMemoryException
            Console.Error.WriteLine("internal error: " & OneLine(ex.Message))
            Return ExitCodes.Failure
        End Try
    End Function

    ''' <summary>Messages promise one line on standard error.</summary>
    Private Shared Function OneLine(message As String) As String
        Return String.Join(" ", message.Split({ChrW(13), ChrW(10)}, StringSplitOptions.RemoveEmptyEntries))
    End Function

    Private Const Usage As String =
        "usage: SimulatorCli validate SCENE" & vbLf &
        "       SimulatorCli run SCENE --time T [--solver auto|event|euler|verlet] [--dt D] [--sample S]" & vbLf &
        "                    [--states FILE] [--events FILE] [--series FILE] [--json]"
End Class
