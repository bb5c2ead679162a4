Option Strict On
Imports System.IO
Imports System.Text

Namespace Scenes
    ''' <summary>
    ''' Scene files (physics-scene/1, see docs/scene-files.md): JSON documents that describe the
    ''' container, gravity, restitution, the bodies and the links between them. Reading checks
    ''' everything before it builds the world; writing is exact, so a saved scene reads back identical.
    ''' </summary>
    Public Module SceneFile
        ''' <summary>
        ''' Reads a scene from its JSON text. The world has no solver yet. Throws
        ''' <see cref="SceneFormatException"/> ("bodies[3].radius: must be greater than 0") when the text is
        ''' not a valid scene; nothing is built then.
        ''' </summary>
        Public Function Load(text As String) As World
            Return SceneReader.Read(text)
        End Function

        ''' <summary>
        ''' Reads a scene file. A file that is missing or cannot be read is a <see cref="SceneFormatException"/>
        ''' whose <see cref="SceneFormatException.Place"/> is the path; format errors are as for <see cref="Load"/>.
        ''' </summary>
        Public Function LoadFile(path As String) As World
            If path Is Nothing Then Throw New ArgumentNullException(NameOf(path))
            Dim text As String
            Try
                text = File.ReadAllText(path, Encoding.UTF8)
            Catch ex As FileNotFoundException
                Throw New SceneFormatException(path, "file not found", ex)
            Catch ex As DirectoryNotFoundException
                Throw New SceneFormatException(path, "file not found", ex)
            Catch ex As IOException
                Throw New SceneFormatException(path, "cannot be read (" & ex.Message & ")", ex)
            Catch ex As UnauthorizedAccessException
                Throw New SceneFormatException(path, "cannot be read (" & ex.Message & ")", ex)
            Catch ex As ArgumentException
                Throw New SceneFormatException(path, "is not a valid file path", ex)
            Catch ex As NotSupportedException
                Throw New SceneFormatException(path, "is not a valid file path", ex)
            End Try
            Return Load(text)
        End Function

        ''' <summary>The scene as JSON text (indented, UTF-8 friendly, every id and setting explicit).</summary>
        Public Function Save(world As World) As String
            Return SceneWriter.Write(world)
        End Function

        ''' <summary>
        ''' Writes the scene to <paramref name="path"/> whole or not at all (<see cref="WholeFile.Write"/>): an
        ''' existing file is replaced only by a complete one and is left as it was on failure. A failure is an
        ''' <see cref="IOException"/> whose message names the folder, never the temporary file.
        ''' </summary>
        Public Sub SaveFile(world As World, path As String)
            If path Is Nothing Then Throw New ArgumentNullException(NameOf(path))
            Dim bytes = New UTF8Encoding(False).GetBytes(Save(world))
            WholeFile.Write(path, Sub(stream) stream.Write(bytes, 0, bytes.Length))
        End Sub
    End Module
End Namespace
