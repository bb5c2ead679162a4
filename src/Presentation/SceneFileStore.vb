Option Strict On
Imports System.IO
Imports System.Text
Imports PhysicsEngine.Scenes

''' <summary>
''' Scene files on disk through the engine's <see cref="SceneFile"/> (physics-scene/1). Saving is
''' whole or nothing, and only a scene that reads back is written. Every failure is an exception
''' whose one-line message says what is wrong in the teacher's words and names the file or folder,
''' never a temporary file.
''' </summary>
Public NotInheritable Class SceneFileStore
    Implements ISceneStore

    ''' <summary>Deepest nesting of brackets read: a scene needs 5 ([x, y] in a polygon's list in a body in the list).</summary>
    Public Const MaxNesting As Integer = 32

    ''' <summary>Reads a scene file; a bad one throws <see cref="SceneFormatException"/> with a one-line message.</summary>
    Public Function Load(path As String) As World Implements ISceneStore.Load
        If path Is Nothing Then Throw New ArgumentNullException(NameOf(path))
        Dim content As String
        Try
            content = File.ReadAllText(path, Encoding.UTF8)
        Catch ex As Exception When TypeOf ex Is IOException OrElse TypeOf ex Is UnauthorizedAccessException OrElse
                                  TypeOf ex Is ArgumentException OrElse TypeOf ex Is NotSupportedException
            ' The engine's reader says what is wrong with the file itself (missing, unreadable, bad path).
            Return SceneFile.LoadFile(path)
        End Try
        CheckNesting(content)
        Return SceneFile.Load(content)
    End Function

    ''' <summary>
    ''' Refuses text nested deeper than <see cref="MaxNesting"/> with a plain reason (the JSON reader
    ''' would otherwise name its own XML limit).
    ''' </summary>
    Public Shared Sub CheckNesting(text As String)
        Dim depth = 0, inString = False, escaped = False
        For Each ch In If(text, "")
            If inString Then
                If escaped Then
                    escaped = False
                ElseIf ch = "\"c Then
                    escaped = True
                ElseIf ch = """"c Then
                    inString = False
                End If
                Continue For
            End If
            Select Case ch
                Case """"c : inString = True
                Case "["c, "{"c
                    depth += 1
                    If depth > MaxNesting Then
                        Throw New SceneFormatException("document", "is nested too deeply: more than " & MaxNesting & " levels of brackets (a scene needs 5 at most)")
                    End If
                Case "]"c, "}"c : depth -= 1
            End Select
        Next
    End Sub

    ''' <summary>Writes the scene, whole or not at all, after checking that it reads back.</summary>
    Public Sub Save(world As World, path As String) Implements ISceneStore.Save
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If path Is Nothing Then Throw New ArgumentNullException(NameOf(path))
        Dim text = SceneFile.Save(world)
        Try
            SceneFile.Load(text)
        Catch ex As SceneFormatException
            Throw New InvalidDataException("the scene would not open again (" & ex.Message & "), so nothing was written", ex)
        End Try
        ' Written whole or not at all, as exports are; a failure names the folder, never the temporary file.
        WholeFile.Write(path,
            Sub(stream)
                Dim bytes = New UTF8Encoding(False).GetBytes(text)
                stream.Write(bytes, 0, bytes.Length)
            End Sub)
    End Sub
End Class
