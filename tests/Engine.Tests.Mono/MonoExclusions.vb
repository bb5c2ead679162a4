Option Strict On

Namespace Mono
    ''' <summary>
    ''' Tests that compile for net48 but cannot run under Mono, by name (Class.Method), each with the
    ''' reason. They are reported as skipped, never dropped silently. None at present: every engine
    ''' test that compiles for net48 passes under Mono 6.8.
    ''' </summary>
    Friend Module MonoExclusions
        ' For example: {"SomeTests.Method", "needs X, which Mono does not have"}
        Private ReadOnly Reasons As New Dictionary(Of String, String)(StringComparer.Ordinal)

        ''' <summary>Why the named test (Class.Method, any theory row) does not run here, or Nothing.</summary>
        Public Function ReasonFor(testName As String) As String
            Dim key = testName
            Dim open = key.IndexOf("("c)
            If open >= 0 Then key = key.Substring(0, open)
            Dim reason As String = Nothing
            Return If(Reasons.TryGetValue(key, reason), reason, Nothing)
        End Function
    End Module
End Namespace
