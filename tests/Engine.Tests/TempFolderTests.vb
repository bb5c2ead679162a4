Option Strict On
Imports System.IO

''' <summary>
''' A base for tests that write files: each test gets a fresh empty folder of its own under the system's
''' temporary folder, deleted with everything in it when the test ends.
''' </summary>
Public MustInherit Class TempFolderTests
    Implements IDisposable

    ''' <summary>The test's own folder, empty at the start.</summary>
    Protected ReadOnly Property Folder As String

    ''' <summary>Makes the folder, named <paramref name="prefix"/> and a fresh GUID.</summary>
    Protected Sub New(prefix As String)
        Folder = Path.Combine(Path.GetTempPath(), prefix & Guid.NewGuid().ToString("N"))
        Directory.CreateDirectory(Folder)
    End Sub

    ''' <summary>Deletes the folder and all in it.</summary>
    Public Sub Dispose() Implements IDisposable.Dispose
        Directory.Delete(Folder, True)
        GC.SuppressFinalize(Me)
    End Sub
End Class
