Option Strict On
Imports System.Diagnostics
Imports System.Globalization
Imports System.Threading.Tasks

Namespace Mono
    ''' <summary>
    ''' Runs the engine's tests against its netstandard2.0 build (under Mono, or on .NET Framework):
    ''' one line per failure, then "mono: N passed, N failed, N skipped". Exit code 0 only when every
    ''' test passed and at least one ran.
    '''   Engine.Tests.exe [filter …]               only the tests whose name contains a filter
    '''   Engine.Tests.exe --collision-log SCENE     prints the scene's run (see CollisionLog), for
    '''                                             the net10.0 tests to compare with their own
    ''' </summary>
    Module Program
        Function Main(args As String()) As Integer
            If args.Length = 2 AndAlso args(0) = "--collision-log" Then
                For Each line In CollisionLog.Record(args(1), vectorScan:=False)
                    Console.Out.Write(line & vbLf)
                Next
                Return 0
            End If
            Return RunTests(args)
        End Function

        ''' <summary>What became of one test.</summary>
        Private NotInheritable Class Outcome
            Public SkipReason As String
            Public Failure As Exception
            Public Output As String
        End Class

        Private Function RunTests(filters As String()) As Integer
            Dim tests = TestCase.Discover(GetType(Program).Assembly)
            If filters.Length > 0 Then
                tests = tests.Where(Function(t) filters.Any(Function(f) t.Name.Contains(f))).ToList()
            End If
            Dim clock = Stopwatch.StartNew()
            ' Classes run side by side, each class's tests one after another, as xunit runs them on
            ' .NET 10 (so the tests are already written for it).
            Dim outcomes(tests.Count - 1) As Outcome
            Dim classes = Enumerable.Range(0, tests.Count).GroupBy(Function(k) tests(k).TestClass).ToList()
            Parallel.ForEach(classes, New ParallelOptions With {.MaxDegreeOfParallelism = Environment.ProcessorCount},
                Sub(group)
                    For Each k In group
                        outcomes(k) = Run(tests(k))
                    Next
                End Sub)
            Dim passed = 0, failed = 0, skipped = 0
            For k = 0 To tests.Count - 1
                Dim o = outcomes(k)
                If o.SkipReason IsNot Nothing Then
                    skipped += 1
                    Console.WriteLine($"SKIP {tests(k).Name}: {o.SkipReason}")
                ElseIf o.Failure IsNot Nothing Then
                    failed += 1
                    Console.WriteLine($"FAIL {tests(k).Name}: {o.Failure.GetType().Name}: {OneLine(o.Failure.Message)}")
                    Console.Error.WriteLine($"--- {tests(k).Name}")
                    Console.Error.WriteLine(o.Failure.ToString())
                    If o.Output.Length > 0 Then Console.Error.WriteLine(o.Output)
                Else
                    passed += 1
                End If
            Next
            Console.WriteLine(String.Format(CultureInfo.InvariantCulture, "{0} tests on the netstandard2.0 build in {1:F1} s", tests.Count, clock.Elapsed.TotalSeconds))
            Console.WriteLine($"mono: {passed} passed, {failed} failed, {skipped} skipped")
            Return If(failed = 0 AndAlso passed > 0, 0, 1)
        End Function

        Private Function Run(test As TestCase) As Outcome
            Dim reason = If(test.SkipReason, MonoExclusions.ReasonFor(test.Name))
            If reason IsNot Nothing Then Return New Outcome With {.SkipReason = reason}
            Dim output As New TestOutput()
            Dim failure = test.Run(output)
            Return New Outcome With {.Failure = failure, .Output = output.ToString()}
        End Function

        ''' <summary>The start of a message, on one line (the whole exception goes to standard error).</summary>
        Private Function OneLine(text As String) As String
            Dim line = text.Replace(vbCr, "").Replace(vbLf, " ")
            Return If(line.Length > 300, line.Substring(0, 300) & " …", line)
        End Function
    End Module
End Namespace
