Option Strict On
Imports System.IO
Imports System.Reflection

''' <summary>Where the repository's files are: the regression scenes in tests/cases, and the built command line.</summary>
Public Module TestPaths
    ''' <summary>The repository's root folder.</summary>
    Public ReadOnly Property RepoRoot As String
        Get
            Return Meta("RepoRoot")
        End Get
    End Property

    ''' <summary>A regression scene of tests/cases.</summary>
    Public Function Case_(name As String) As String
        Return Path.Combine(RepoRoot, "tests", "cases", name)
    End Function

    ''' <summary>The built command line, run with dotnet.</summary>
    Public ReadOnly Property CliDll As String
        Get
            Return Path.Combine(RepoRoot, "src", "SimulatorCli", "bin", Meta("Configuration"), "net10.0", "SimulatorCli.dll")
        End Get
    End Property

    Private Function Meta(key As String) As String
        For Each a In GetType(TestPaths).Assembly.GetCustomAttributes(Of AssemblyMetadataAttribute)()
            If a.Key = key Then Return a.Value
        Next
        Throw New InvalidOperationException("no assembly metadata " & key)
    End Function
End Module
