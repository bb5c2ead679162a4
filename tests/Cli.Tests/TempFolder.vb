Option Strict On
Imports System.IO

''' <summary>A fresh folder for one test's scenes and outputs, deleted afterwards.</summary>
Public NotInheritable Class TempFolder
    Implements IDisposable

    Public ReadOnly Property Path As String = IO.Path.Combine(IO.Path.GetTempPath(), "cli-tests-" & Guid.NewGuid().ToString("N"))

    Public Sub New()
        Directory.CreateDirectory(Path)
    End Sub

    ''' <summary>The full path of a file in this folder.</summary>
    Public Function File(name As String) As String
        Return IO.Path.Combine(Path, name)
    End Function

    ''' <summary>Writes a file (JSON may use ' for ") and returns its path.</summary>
    Public Function Write(name As String, text As String) As String
        Dim full = File(name)
        IO.File.WriteAllText(full, text)
        Return full
    End Function

    ''' <summary>Names of every file in the folder, sorted.</summary>
    Public Function Files() As String()
        Return Directory.GetFileSystemEntries(Path).Select(Function(f) IO.Path.GetFileName(f)).OrderBy(Function(f) f, StringComparer.Ordinal).ToArray()
    End Function

    Public Sub Dispose() Implements IDisposable.Dispose
        Try
            Directory.Delete(Path, True)
        Catch ex As IOException
            ' a leftover temp folder is harmless
        End Try
    End Sub
End Class
