Option Strict On
Imports System.Globalization
Imports PhysicsEngine.Fuzzing.Generation

''' <summary>What a campaign does: which scenes, which solvers, how long each run, where failures go.</summary>
Friend NotInheritable Class FuzzOptions
    ''' <summary>How many scenes (seeds First, First + 1, …).</summary>
    Friend Property Scenes As Integer = 100
    ''' <summary>The first scene's seed.</summary>
    Friend Property Seed As Long = 1
    ''' <summary>Where shrunk failing scenes and their README go.</summary>
    Friend Property Out As String = "fuzz-failures"
    Friend Property Solvers As IReadOnlyList(Of String) = {"event", "euler", "verlet"}
    Friend Property Kinds As BodyKinds = BodyKinds.Default
    ''' <summary>The fraction of generated scenes with friction, 0 to 1.</summary>
    Friend Property Rough As Double
    ''' <summary>Simulated time T of a run, s (shorter for fast scenes: see <see cref="Campaign.PlanFor"/>).</summary>
    Friend Property Time As Double = 1.0
    ''' <summary>Sampling interval S, s.</summary>
    Friend Property Sample As Double = 0.05
    ''' <summary>The event solver's second sampling interval, s; 0 skips the comparison.</summary>
    Friend Property SecondSample As Double = 0.013
    ''' <summary>Wall-clock seconds one run may take.</summary>
    Friend Property Cap As Double = 10.0
    ''' <summary>About how many bodies a scene has at most (obstacles come on top).</summary>
    Friend Property MaxBodies As Integer = 40
    ''' <summary>Scenes checked at once, each in its own worker process.</summary>
    Friend Property Jobs As Integer = Environment.ProcessorCount
    Friend Property Shrink As Boolean = True
    ''' <summary>Wall-clock seconds spent shrinking one failure at most.</summary>
    Friend Property ShrinkBudget As Double = 120.0
    ''' <summary>Check in this process instead of in workers (a run that never returns then hangs the campaign).</summary>
    Friend Property InProcess As Boolean
    ''' <summary>A scene file to check instead of generated scenes.</summary>
    Friend Property SceneFile As String
    ''' <summary>Print each generated scene's text instead of checking it.</summary>
    Friend Property Print As Boolean

    Friend Const Usage As String =
        "usage: Fuzzer [--scenes N] [--seed S] [--out DIR] [--solvers event,euler,verlet] [--kinds circle,rectangle|all]" & vbLf &
        "              [--rough FRACTION]" & vbLf &
        "              [--time T] [--sample S] [--second-sample S2] [--cap SECONDS] [--bodies N] [--jobs N]" & vbLf &
        "              [--no-shrink] [--shrink-budget SECONDS] [--in-process] [--scene FILE] [--print]" & vbLf &
        "Generates N scenes from seeds S, S+1, …, runs each with every solver in worker processes, checks the" & vbLf &
        "invariants at every sample, shrinks each failing scene and writes it to DIR with the command that shows it." & vbLf &
        "Exit 0 when nothing failed, 1 when something did, 2 on bad options."

    ''' <summary>Reads the command line; throws ArgumentException with a one-line message on bad input.</summary>
    Friend Shared Function Parse(args As IReadOnlyList(Of String)) As FuzzOptions
        Dim o As New FuzzOptions()
        Dim i = 0
        Do While i < args.Count
            Dim name = args(i)
            i += 1
            Select Case name
                Case "--no-shrink" : o.Shrink = False : Continue Do
                Case "--in-process" : o.InProcess = True : Continue Do
                Case "--print" : o.Print = True : Continue Do
            End Select
            If i >= args.Count Then Throw New ArgumentException(name & ": needs a value")
            Dim value = args(i)
            i += 1
            Select Case name
                Case "--scenes" : o.Scenes = PositiveInteger(name, value)
                Case "--seed" : o.Seed = Long.Parse(value, NumberStyles.Integer, CultureInfo.InvariantCulture)
                Case "--out" : o.Out = value
                Case "--solvers" : o.Solvers = ParseSolvers(value)
                Case "--kinds" : o.Kinds = BodyKindNames.Parse(value)
                Case "--rough"
                    Dim fraction As Double
                    If Not Double.TryParse(value, NumberStyles.Float, CultureInfo.InvariantCulture, fraction) OrElse Not (fraction >= 0 AndAlso fraction <= 1) Then
                        Throw New ArgumentException(name & ": must be a fraction from 0 to 1, not '" & value & "'")
                    End If
                    o.Rough = fraction
                Case "--time" : o.Time = PositiveNumber(name, value)
                Case "--sample" : o.Sample = PositiveNumber(name, value)
                Case "--second-sample" : o.SecondSample = If(value = "0", 0.0, PositiveNumber(name, value))
                Case "--cap" : o.Cap = PositiveNumber(name, value)
                Case "--bodies" : o.MaxBodies = PositiveInteger(name, value)
                Case "--jobs" : o.Jobs = PositiveInteger(name, value)
                Case "--shrink-budget" : o.ShrinkBudget = PositiveNumber(name, value)
                Case "--scene" : o.SceneFile = value
                Case Else : Throw New ArgumentException("unknown option '" & name & "'")
            End Select
        Loop
        Return o
    End Function

    Private Shared Function ParseSolvers(value As String) As IReadOnlyList(Of String)
        Dim list = value.Split(","c).Select(Function(s) s.Trim()).ToList()
        For Each s In list
            If s <> "event" AndAlso s <> "euler" AndAlso s <> "verlet" Then Throw New ArgumentException("--solvers: unknown solver '" & s & "' (expected event, euler, verlet)")
        Next
        Return list
    End Function

    Private Shared Function PositiveNumber(name As String, value As String) As Double
        Dim v As Double
        If Not Double.TryParse(value, NumberStyles.Float, CultureInfo.InvariantCulture, v) OrElse Not (v > 0) OrElse Double.IsInfinity(v) Then
            Throw New ArgumentException(name & ": must be a number greater than 0, not '" & value & "'")
        End If
        Return v
    End Function

    Private Shared Function PositiveInteger(name As String, value As String) As Integer
        Dim v As Integer
        If Not Integer.TryParse(value, NumberStyles.Integer, CultureInfo.InvariantCulture, v) OrElse v < 1 Then
            Throw New ArgumentException(name & ": must be a whole number of at least 1, not '" & value & "'")
        End If
        Return v
    End Function
End Class
