Option Strict On
Imports System.IO
Imports System.Text
Imports System.Text.RegularExpressions
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
        Try
            SceneFile.Load(SceneFile.Save(world))
        Catch ex As SceneFormatException
            Throw New InvalidDataException("the scene would not open again (" & ex.Message & "), so nothing was written", ex)
        End Try
        Dim target As String
        Try
            target = IO.Path.GetFullPath(path)
        Catch ex As Exception When TypeOf ex Is ArgumentException OrElse TypeOf ex Is NotSupportedException OrElse TypeOf ex Is PathTooLongException
            Throw New IOException("'" & path & "' is not a file name this computer accepts", ex)
        End Try
        Dim folder = IO.Path.GetDirectoryName(target)
        Try
            SceneFile.SaveFile(world, target)
        Catch ex As UnauthorizedAccessException
            If File.Exists(target) AndAlso (File.GetAttributes(target) And FileAttributes.ReadOnly) <> 0 Then
                Throw New IOException("the file is read-only; nothing was written", ex)
            End If
            Throw New IOException("you may not write in the folder " & folder & "; nothing was written", ex)
        Catch ex As DirectoryNotFoundException
            Throw New IOException("the folder " & folder & " does not exist", ex)
        Catch ex As PathTooLongException
            Throw New IOException("the path is too long for this computer", ex)
        Catch ex As IOException
            ' The engine writes to a temporary file beside the target first: name the folder, not that file.
            Throw New IOException("the folder " & folder & " would not take a new file (the system said: " & WithoutTemporaryName(ex.Message) & "); nothing was written", ex)
        End Try
    End Sub

    Private Shared Function WithoutTemporaryName(message As String) As String
        Dim text = If(message, "").Replace(vbCr, " ").Replace(vbLf, " ").Trim()
        ' Drop the temporary file's name, quoted or not, and what is left of its quotes.
        text = Regex.Replace(text, "\s*[""']?[^\s'""]*\.[0-9a-f]{32}\.tmp[""']?", "")
        Return text.TrimEnd("."c, " "c, ":"c)
    End Function
End Class
