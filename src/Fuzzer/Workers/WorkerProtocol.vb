Option Strict On
Imports System.Globalization
Imports PhysicsEngine.Fuzzing.Checking

Namespace Workers
    ''' <summary>
    ''' The lines a campaign and its worker processes exchange, one tab-separated line each:
    ''' <list type="bullet">
    ''' <item>to the worker: <c>check FILE SOLVER T S S2 CAP STOP</c> (STOP is an invariant, or "-");</item>
    ''' <item>from it: <c>start S</c> before each run, <c>violation INVARIANT SOLVER S TIME MESSAGE</c> for
    ''' each broken invariant, then <c>done COLLISIONS WALL</c>, or <c>refused MESSAGE</c> when the scene
    ''' reader refuses the file.</item>
    ''' </list>
    ''' Numbers are written round-trip ("R"), so the worker runs exactly the plan it was sent.
    ''' </summary>
    Friend Module WorkerProtocol
        Friend Const CheckVerb As String = "check"
        Friend Const StartVerb As String = "start"
        Friend Const ViolationVerb As String = "violation"
        Friend Const DoneVerb As String = "done"
        Friend Const RefusedVerb As String = "refused"
        Private Const Tab As Char = ChrW(9)
        Private Const NoStop As String = "-"

        ''' <summary>The request line for one scene file and solver.</summary>
        Friend Function CheckLine(path As String, solver As String, plan As RunPlan, stopAt As String) As String
            Return String.Join(Tab, CheckVerb, path, solver, Number(plan.Time), Number(plan.Sample), Number(plan.SecondSample), Number(plan.Cap), If(stopAt, NoStop))
        End Function

        ''' <summary>Reads a request line: file, solver, plan and the invariant to stop at (Nothing: none).</summary>
        Friend Sub ParseCheck(line As String, ByRef path As String, ByRef solver As String, ByRef plan As RunPlan, ByRef stopAt As String)
            Dim f = line.Split(Tab)
            If f.Length <> 8 OrElse f(0) <> CheckVerb Then Throw New FormatException("not a check line: " & line)
            path = f(1)
            solver = f(2)
            plan = New RunPlan(Parse(f(3)), Parse(f(4)), Parse(f(5)), Parse(f(6)))
            stopAt = If(f(7) = NoStop, Nothing, f(7))
        End Sub

        Friend Function StartLine(sample As Double) As String
            Return StartVerb & Tab & Number(sample)
        End Function

        Friend Function ViolationLine(v As Violation) As String
            Return String.Join(Tab, ViolationVerb, v.Invariant, v.Solver, Number(v.Sample), Number(v.Time), SceneRunner.OneLine(v.Message))
        End Function

        Friend Function ParseViolation(line As String) As Violation
            Dim f = line.Split(Tab)
            If f.Length <> 6 OrElse f(0) <> ViolationVerb Then Throw New FormatException("not a violation line: " & line)
            Return New Violation(f(1), f(2), Parse(f(3)), Parse(f(4)), f(5))
        End Function

        Friend Function DoneLine(result As CheckResult) As String
            Return String.Join(Tab, DoneVerb, result.Collisions.ToString(CultureInfo.InvariantCulture), Number(result.WallSeconds))
        End Function

        Friend Sub ParseDone(line As String, result As CheckResult)
            Dim f = line.Split(Tab)
            If f.Length <> 3 OrElse f(0) <> DoneVerb Then Throw New FormatException("not a done line: " & line)
            result.Collisions = Long.Parse(f(1), CultureInfo.InvariantCulture)
            result.WallSeconds = Parse(f(2))
        End Sub

        Friend Function RefusedLine(message As String) As String
            Return RefusedVerb & Tab & SceneRunner.OneLine(message)
        End Function

        ''' <summary>The first word of a reply line.</summary>
        Friend Function VerbOf(line As String) As String
            Dim i = line.IndexOf(Tab)
            Return If(i < 0, line, line.Substring(0, i))
        End Function

        ''' <summary>What follows the verb.</summary>
        Friend Function RestOf(line As String) As String
            Dim i = line.IndexOf(Tab)
            Return If(i < 0, "", line.Substring(i + 1))
        End Function

        Friend Function Number(value As Double) As String
            Return value.ToString("R", CultureInfo.InvariantCulture)
        End Function

        Friend Function Parse(text As String) As Double
            Return Double.Parse(text, NumberStyles.Float, CultureInfo.InvariantCulture)
        End Function
    End Module
End Namespace
