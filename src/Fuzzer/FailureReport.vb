Option Strict On
Imports System.Globalization
Imports System.IO
Imports System.Text
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Fuzzing.Shrinking

''' <summary>
''' Writes a shrunk failing scene as &lt;invariant&gt;-&lt;seed&gt;.json in the output folder, and one line
''' for it in the folder's README.md: what fails, and the command line's command that shows it.
''' </summary>
Friend Module FailureReport
    Private ReadOnly Gate As New Object()
    Private Const ReadmeName As String = "README.md"
    Private Const Header As String =
        "# Failing scenes" & vbLf & vbLf &
        "Each line names a scene file of this folder, what fails in it, and the command that shows it" & vbLf &
        "(run from the repository's root)." & vbLf & vbLf

    ''' <summary>The file name a failure is written under.</summary>
    Friend Function FileName(invariant As String, label As String) As String
        Return invariant & "-" & label & ".json"
    End Function

    ''' <summary>Writes the scene and its README line; returns the scene file's path.</summary>
    Friend Function Write(folder As String, outcome As SceneOutcome, original As Violation, result As ShrinkResult, alsoFailing As IEnumerable(Of String)) As String
        Directory.CreateDirectory(folder)
        Dim path = IO.Path.Combine(folder, FileName(original.Invariant, outcome.Label))
        File.WriteAllText(path, result.Doc.ToText(), New UTF8Encoding(False))
        Dim line = ReadmeLine(path, outcome, original, result, alsoFailing)
        SyncLock Gate
            Dim readme = IO.Path.Combine(folder, ReadmeName)
            Dim lines = If(File.Exists(readme), File.ReadAllLines(readme).Where(Function(l) l.StartsWith("- ", StringComparison.Ordinal)).ToList(), New List(Of String))
            Dim key = "- `" & IO.Path.GetFileName(path) & "`"
            lines.RemoveAll(Function(l) l.StartsWith(key, StringComparison.Ordinal))
            lines.Add(line)
            lines.Sort(StringComparer.Ordinal)
            File.WriteAllText(readme, Header & String.Join(vbLf, lines) & vbLf, New UTF8Encoding(False))
        End SyncLock
        Return path
    End Function

    ''' <summary>"- `file`: what fails … `command`".</summary>
    Friend Function ReadmeLine(path As String, outcome As SceneOutcome, original As Violation, result As ShrinkResult, alsoFailing As IEnumerable(Of String)) As String
        Dim inv = CultureInfo.InvariantCulture
        Dim v = result.Violation
        Dim also = alsoFailing.Where(Function(s) s <> v.Solver).ToList()
        Dim size = result.Doc.Bodies.Count.ToString(inv) & " of " & outcome.Doc.Bodies.Count.ToString(inv) & " bodies"
        Return "- `" & IO.Path.GetFileName(path) & "`: " & v.Invariant & " with the " & v.Solver & " solver" &
            If(also.Count > 0, " (also " & String.Join(", ", also) & ")", "") & ", " & size &
            If(result.Reproduced, "", " (did not fail again when probed: not shrunk)") & ": at t = " & v.Time.ToString("R", inv) & " s, " & v.Message &
            ". Shows with: `" & Command(path, v, result.Plan) & "`"
    End Function

    ''' <summary>The command line's command that shows the failure (two runs and a diff for the sampling invariant).</summary>
    Friend Function Command(path As String, v As Violation, plan As RunPlan) As String
        Dim file = Relative(path)
        If v.Invariant = Invariants.Refused Then Return Prefix & "validate " & file
        Dim run = Function(sample As Double) Prefix & "run " & file & " --time " & N(plan.Time) & " --solver " & v.Solver & " --sample " & N(sample) & " --states s.csv"
        Select Case v.Invariant
            Case Invariants.Sampling
                Return run(plan.Sample) & " --events a.csv && " & run(plan.SecondSample) & " --events b.csv && diff a.csv b.csv"
            Case Invariants.Energy, Invariants.WallTime, Invariants.Crash
                ' the summary gives the energy at T (where the failure was seen) and the run's wall time
                Return run(v.Sample) & " --json"
            Case Else
                Return run(v.Sample)
        End Select
    End Function

    Private Const Prefix As String = "dotnet run -c Release --project src/SimulatorCli -- "

    Private Function N(value As Double) As String
        Return value.ToString("R", CultureInfo.InvariantCulture)
    End Function

    ''' <summary>The path from the current folder (where the command runs), with forward slashes.</summary>
    Private Function Relative(path As String) As String
        Dim full = IO.Path.GetFullPath(path)
        Dim rel = IO.Path.GetRelativePath(Directory.GetCurrentDirectory(), full)
        Return rel.Replace("\"c, "/"c)
    End Function
End Module
