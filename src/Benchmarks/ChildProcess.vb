Option Strict On
Imports System.Diagnostics
Imports System.IO
Imports System.Reflection

''' <summary>
''' Runs this benchmark again as a child process with hidden options, so each case gets its own peak
''' working set and a solver that hangs can be stopped. The child prints one "RESULT {json}" line per
''' finished case; what arrived before a timeout is kept.
''' </summary>
Friend Module ChildProcess
    ''' <summary>The prefix of a result line on the child's standard output.</summary>
    Public Const ResultPrefix As String = "RESULT "

    ''' <summary>What a child left behind.</summary>
    Friend NotInheritable Class Outcome
        Public ReadOnly Property Results As New List(Of BenchResult)
        Public Property TimedOut As Boolean
        Public Property ExitCode As Integer
        Public Property ErrorText As String = ""
    End Class

    ''' <summary>
    ''' Runs the child with these arguments (and these environment variables, if any) and waits at
    ''' most <paramref name="timeout"/>.
    ''' </summary>
    Public Function Run(args As IEnumerable(Of String), timeout As TimeSpan, Optional environment As IReadOnlyDictionary(Of String, String) = Nothing) As Outcome
        Return RunProgram(SelfStartInfo(), args, timeout, environment)
    End Function

    ''' <summary>
    ''' Runs another build of this benchmark (<paramref name="psi"/> starts it) as a child, with these
    ''' arguments after the ones <paramref name="psi"/> already has: it speaks the same RESULT lines.
    ''' </summary>
    Public Function RunProgram(psi As ProcessStartInfo, args As IEnumerable(Of String), timeout As TimeSpan,
                               Optional environment As IReadOnlyDictionary(Of String, String) = Nothing) As Outcome
        If psi Is Nothing Then Throw New ArgumentNullException(NameOf(psi))
        If args Is Nothing Then Throw New ArgumentNullException(NameOf(args))
        For Each a In args
            psi.ArgumentList.Add(a)
        Next
        If environment IsNot Nothing Then
            For Each pair In environment
                psi.Environment(pair.Key) = pair.Value
            Next
        End If
        psi.RedirectStandardOutput = True
        psi.RedirectStandardError = True
        psi.UseShellExecute = False
        Dim outcome As New Outcome
        Dim lines As New List(Of String)
        Dim errors As New Text.StringBuilder
        Using p As New Process With {.StartInfo = psi}
            AddHandler p.OutputDataReceived, Sub(s, e)
                                                 If e.Data IsNot Nothing Then SyncLock lines : lines.Add(e.Data) : End SyncLock
                                             End Sub
            AddHandler p.ErrorDataReceived, Sub(s, e)
                                                If e.Data IsNot Nothing Then SyncLock errors : errors.AppendLine(e.Data) : End SyncLock
                                            End Sub
            p.Start()
            p.BeginOutputReadLine()
            p.BeginErrorReadLine()
            If Not p.WaitForExit(CInt(timeout.TotalMilliseconds)) Then
                outcome.TimedOut = True
                p.Kill(True)
            End If
            p.WaitForExit()
            outcome.ExitCode = If(outcome.TimedOut, -1, p.ExitCode)
        End Using
        SyncLock lines
            outcome.Results.AddRange(ReadResults(lines))
        End SyncLock
        outcome.ErrorText = errors.ToString().Trim()
        Return outcome
    End Function

    ''' <summary>The results in a child's standard output: its RESULT lines, in order; other lines are ignored.</summary>
    Public Function ReadResults(lines As IEnumerable(Of String)) As List(Of BenchResult)
        If lines Is Nothing Then Throw New ArgumentNullException(NameOf(lines))
        Return lines.Where(Function(line) line IsNot Nothing AndAlso line.StartsWith(ResultPrefix, StringComparison.Ordinal)).
                     Select(Function(line) JsonReport.Parse(line.Substring(ResultPrefix.Length))).ToList()
    End Function

    ''' <summary>Writes a finished case for the parent, at once, so it survives a later timeout.</summary>
    Public Sub Report(result As BenchResult)
        Console.Out.WriteLine(ResultPrefix & JsonReport.ToLine(result))
        Console.Out.Flush()
    End Sub

    ''' <summary>How to start this program again: the apphost directly, or "dotnet Benchmarks.dll".</summary>
    Private Function SelfStartInfo() As ProcessStartInfo
        Dim host = Environment.ProcessPath
        Dim dll = Assembly.GetEntryAssembly().Location
        If host IsNot Nothing AndAlso Not String.Equals(Path.GetFileNameWithoutExtension(host), "dotnet", StringComparison.OrdinalIgnoreCase) Then
            Return New ProcessStartInfo(host)
        End If
        Dim psi As New ProcessStartInfo(If(host, "dotnet"))
        psi.ArgumentList.Add(dll)
        Return psi
    End Function
End Module
