Option Strict On
Imports System.Globalization
Imports System.IO

''' <summary>The arguments of run, checked: every problem is a <see cref="BadInputException"/> naming the option.</summary>
Friend NotInheritable Class RunOptions
    ''' <summary>Default sampling interval of the states CSV, s.</summary>
    Friend Const DefaultSample As Double = 0.1
    ''' <summary>The most sample times a run may ask for (T / S).</summary>
    Friend Const MaxSamples As Double = 10000000.0

    Private Const Known As String = "--time, --solver, --dt, --sample, --states, --events, --series, --json"

    Friend Property ScenePath As String
    ''' <summary>Simulated time, s, &gt; 0.</summary>
    Friend Property Time As Double
    Friend Property SolverName As String = "auto"
    ''' <summary>Time step of a stepping solver, s, or Nothing for the engine's default.</summary>
    Friend Property TimeStep As Double?
    ''' <summary>Interval between rows of the states CSV, s, &gt; 0.</summary>
    Friend Property Sample As Double = DefaultSample
    Friend Property StatesPath As String
    Friend Property EventsPath As String
    Friend Property SeriesPath As String
    Friend Property Json As Boolean

    Private Sub New()
    End Sub

    ''' <summary>Reads "SCENE --time T [--solver NAME] [--dt D] [--sample S] [--states FILE] [--events FILE] [--series FILE] [--json]" in any order.</summary>
    Friend Shared Function Parse(args As IReadOnlyList(Of String)) As RunOptions
        Dim o As New RunOptions()
        Dim seen As New HashSet(Of String)(StringComparer.Ordinal)
        Dim hasTime = False
        Dim i = 0
        Do While i < args.Count
            Dim arg = args(i)
            i += 1
            Dim name = arg
            Dim inline As String = Nothing
            If arg.StartsWith("--", StringComparison.Ordinal) AndAlso arg.Contains("="c) Then
                name = arg.Substring(0, arg.IndexOf("="c))
                inline = arg.Substring(arg.IndexOf("="c) + 1)
            End If
            If Not name.StartsWith("-"c) OrElse name = "-" Then
                If o.ScenePath IsNot Nothing Then Throw New BadInputException("run: unexpected argument '" & arg & "' (the scene is '" & o.ScenePath & "')")
                o.ScenePath = arg
                Continue Do
            End If
            If Not seen.Add(name) Then Throw New BadInputException(name & ": given more than once")
            If name = "--json" Then
                If inline IsNot Nothing Then Throw New BadInputException("--json: takes no value")
                o.Json = True
                Continue Do
            End If
            Dim value As String
            If inline IsNot Nothing Then
                value = inline
            ElseIf i < args.Count AndAlso Not args(i).StartsWith("--", StringComparison.Ordinal) Then
                value = args(i)
                i += 1
            Else
                value = Nothing
            End If
            Select Case name
                Case "--time"
                    o.Time = PositiveNumber(name, value, "seconds")
                    hasTime = True
                Case "--dt"
                    o.TimeStep = PositiveNumber(name, value, "seconds")
                Case "--sample"
                    o.Sample = PositiveNumber(name, value, "seconds")
                Case "--solver"
                    o.SolverName = Required(name, value, "a solver name: " & String.Join(", ", SolverFactory.Names))
                Case "--states"
                    o.StatesPath = Required(name, value, "a file name")
                Case "--events"
                    o.EventsPath = Required(name, value, "a file name")
                Case "--series"
                    o.SeriesPath = Required(name, value, "a file name")
                Case Else
                    Throw New BadInputException("run: unknown option '" & name & "' (expected " & Known & ")")
            End Select
        Loop
        If o.ScenePath Is Nothing Then Throw New BadInputException("run: no scene file given (usage: run SCENE --time T)")
        If Not hasTime Then Throw New BadInputException("run: --time T is required (simulated seconds, > 0)")
        ' Two tables in one file would each overwrite the other.
        Dim outputs = o.Outputs
        For k = 1 To outputs.Count - 1
            For j = 0 To k - 1
                If String.Equals(Path.GetFullPath(outputs(k).Path), Path.GetFullPath(outputs(j).Path), StringComparison.Ordinal) Then
                    Throw New BadInputException(outputs(k).Name & ": '" & outputs(k).Path & "' is also the " & outputs(j).Name & " file")
                End If
            Next
        Next
        ' Every sample time is a stop of the simulation loop; a count no spreadsheet could open is a typo.
        If o.Time / o.Sample > MaxSamples Then
            Throw New BadInputException("--sample: " & o.Sample.ToString("R", CultureInfo.InvariantCulture) & " s would take more than " &
                                        MaxSamples.ToString("N0", CultureInfo.InvariantCulture) & " samples over --time " & o.Time.ToString("R", CultureInfo.InvariantCulture) & " s")
        End If
        ' An output on top of the scene would destroy the input.
        For Each output In outputs
            If String.Equals(Path.GetFullPath(output.Path), Path.GetFullPath(o.ScenePath), StringComparison.Ordinal) Then
                Throw New BadInputException(output.Name & ": '" & output.Path & "' is the scene file itself")
            End If
        Next
        Return o
    End Function

    ''' <summary>The output files asked for, with the option that names each, in the order --states, --events, --series.</summary>
    Friend ReadOnly Property Outputs As IReadOnlyList(Of (Name As String, Path As String))
        Get
            Dim all = {("--states", StatesPath), ("--events", EventsPath), ("--series", SeriesPath)}
            Return all.Where(Function(f) f.Item2 IsNot Nothing).Select(Function(f) (Name:=f.Item1, Path:=f.Item2)).ToList()
        End Get
    End Property

    Private Shared Function Required(name As String, value As String, what As String) As String
        If String.IsNullOrEmpty(value) Then Throw New BadInputException(name & ": missing value (" & what & ")")
        Return value
    End Function

    Private Shared Function PositiveNumber(name As String, value As String, unit As String) As Double
        Required(name, value, unit)
        Dim number As Double
        If Not Double.TryParse(value, NumberStyles.Float, CultureInfo.InvariantCulture, number) Then
            Throw New BadInputException(name & ": '" & value & "' is not a number")
        End If
        If Double.IsNaN(number) OrElse Double.IsInfinity(number) Then Throw New BadInputException(name & ": '" & value & "' is not a finite number")
        If Not (number > 0) Then Throw New BadInputException(name & ": must be greater than 0, not " & value)
        Return number
    End Function
End Class
