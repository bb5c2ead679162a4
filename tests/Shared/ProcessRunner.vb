Option Strict On
Imports System.Diagnostics
Imports System.IO
Imports System.Reflection

''' <summary>What a finished process left behind.</summary>
Public NotInheritable Class ProcessResult
    Public Property ExitCode As Integer
    Public Property StdOut As String
    Public Property StdErr As String

    Public Overrides Function ToString() As String
        Return "exit " & ExitCode & vbLf & "--- stdout ---" & vbLf & StdOut & vbLf & "--- stderr ---" & vbLf & StdErr
    End Function
End Class

''' <summary>Runs the real built programs, the way a person or a script would.</summary>
Public Module ProcessRunner
    ''' <summary>The repository's root folder.</summary>
    Public ReadOnly Property RepoRoot As String
        Get
            Return Meta("RepoRoot")
        End Get
    End Property

    ''' <summary>Debug or Release: the configuration these tests were built in.</summary>
    Public ReadOnly Property Configuration As String
        Get
            Return Meta("Configuration")
        End Get
    End Property

    Private Function Meta(key As String) As String
        For Each a In GetType(ProcessRunner).Assembly.GetCustomAttributes(Of AssemblyMetadataAttribute)()
            If a.Key = key Then Return a.Value
        Next
        Throw New InvalidOperationException("no assembly metadata " & key)
    End Function

    ''' <summary>The built command line, as a dll run with dotnet.</summary>
    Public ReadOnly Property CliDll As String
        Get
            Return Path.Combine(RepoRoot, "src", "SimulatorCli", "bin", Configuration, "net10.0", "SimulatorCli.dll")
        End Get
    End Property

    ''' <summary>Runs SimulatorCli with the arguments and waits for it (at most the timeout).</summary>
    Public Function RunCli(ParamArray args As String()) As ProcessResult
        Dim all As New List(Of String) From {CliDll}
        all.AddRange(args)
        Return Run("dotnet", all, Nothing, TimeSpan.FromMinutes(5))
    End Function

    ''' <summary>Runs a program to completion, capturing both streams.</summary>
    Public Function Run(fileName As String, args As IEnumerable(Of String), environment As IDictionary(Of String, String),
                        timeout As TimeSpan, Optional workingDirectory As String = Nothing) As ProcessResult
        Dim psi As New ProcessStartInfo(fileName) With {
            .RedirectStandardOutput = True, .RedirectStandardError = True, .RedirectStandardInput = True,
            .UseShellExecute = False, .WorkingDirectory = If(workingDirectory, RepoRoot)}
        For Each a In args
            psi.ArgumentList.Add(a)
        Next
        If environment IsNot Nothing Then
            For Each kv In environment
                psi.Environment(kv.Key) = kv.Value
            Next
        End If
        Using p = Process.Start(psi)
            p.StandardInput.Close()
            Dim outTask = p.StandardOutput.ReadToEndAsync()
            Dim errTask = p.StandardError.ReadToEndAsync()
            If Not p.WaitForExit(CInt(timeout.TotalMilliseconds)) Then
                p.Kill(True)
                Throw New TimeoutException(fileName & " did not finish within " & timeout.ToString())
            End If
            p.WaitForExit()
            Return New ProcessResult With {.ExitCode = p.ExitCode, .StdOut = outTask.Result, .StdErr = errTask.Result}
        End Using
    End Function
End Module
