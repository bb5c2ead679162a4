Option Strict On
Imports System.IO
Imports PhysicsEngine.Scenes

''' <summary>Reads the scene named on the command line; every problem is bad input naming the file.</summary>
Friend Module SceneInput
    ''' <summary>The scene in <paramref name="path"/>, checked; a <see cref="BadInputException"/> "path: place: problem" otherwise.</summary>
    Friend Function Load(path As String) As World
        If Directory.Exists(path) Then Throw New BadInputException(path & ": is a folder, not a scene file")
        If Not File.Exists(path) Then Throw New BadInputException(path & ": file not found")
        Dim text As String
        Try
            text = File.ReadAllText(path, System.Text.Encoding.UTF8)
        Catch ex As IOException
            Throw New BadInputException(path & ": cannot be read (" & ex.Message & ")", ex)
        Catch ex As UnauthorizedAccessException
            Throw New BadInputException(path & ": cannot be read (" & ex.Message & ")", ex)
        End Try
        Try
            Return SceneFile.Load(text)
        Catch ex As SceneFormatException
            Throw New BadInputException(path & ": " & ex.Message, ex)
        End Try
    End Function
End Module
