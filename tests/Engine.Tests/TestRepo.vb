Option Strict On
Imports System.IO

''' <summary>
''' Where the repository lies, for tests that read its scene files (tests/cases, the lessons). Here and not
''' ProcessRunner.RepoRoot because these sources also build into the Mono test program, which leaves tests/Shared out.
''' </summary>
Friend Module TestRepo
    ''' <summary>The repository's root folder, as the build wrote it into the test assembly's metadata.</summary>
    Friend Function Root() As String
        For Each a In GetType(TestRepo).Assembly.GetCustomAttributes(GetType(Reflection.AssemblyMetadataAttribute), False).Cast(Of Reflection.AssemblyMetadataAttribute)()
            If a.Key = "RepoRoot" Then Return a.Value
        Next
        Throw New InvalidOperationException("no RepoRoot metadata")
    End Function

    ''' <summary>The path of a scene file in tests/cases.</summary>
    Friend Function CaseFile(name As String) As String
        Return Path.Combine(Root(), "tests", "cases", name)
    End Function
End Module
