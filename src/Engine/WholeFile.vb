Option Strict On
Imports System.IO

''' <summary>
''' Writes a file whole or not at all (a saved scene, an exported table or picture): to a temporary
''' file in the same folder, then moved over the target, so a failure (a full disk, a folder one may
''' not write in) never leaves a half-written file. A failure is an <see cref="IOException"/> whose
''' message says why in a teacher's words, names the folder, and never names the temporary file.
''' </summary>
Public NotInheritable Class WholeFile
    Private Sub New()
    End Sub

    ''' <summary>Writes what <paramref name="write"/> puts into the stream to <paramref name="path"/>.</summary>
    Public Shared Sub Write(path As String, write As Action(Of Stream))
        If path Is Nothing Then Throw New ArgumentNullException(NameOf(path))
        If write Is Nothing Then Throw New ArgumentNullException(NameOf(write))
        Dim target As String
        Try
            target = IO.Path.GetFullPath(path)
        Catch ex As Exception When TypeOf ex Is ArgumentException OrElse TypeOf ex Is NotSupportedException OrElse TypeOf ex Is PathTooLongException
            Throw New IOException("'" & path & "' is not a file name this computer accepts", ex)
        End Try
        Dim folder = IO.Path.GetDirectoryName(target)
        Dim temp = IO.Path.Combine(folder, "." & IO.Path.GetFileName(target) & "." & Guid.NewGuid().ToString("N") & ".tmp")
        Try
            Using stream As New FileStream(temp, FileMode.CreateNew, FileAccess.Write, FileShare.None)
                write(stream)
                stream.Flush(True)
            End Using
            ' netstandard2.0 has no File.Move that overwrites: File.Replace swaps over an existing file in one
            ' step, and File.Move (which refuses an existing target) puts down a new one.
            If File.Exists(target) Then
                File.Replace(temp, target, Nothing)
            Else
                File.Move(temp, target)
            End If
        Catch ex As UnauthorizedAccessException
            If File.Exists(target) AndAlso (File.GetAttributes(target) And FileAttributes.ReadOnly) <> 0 Then
                Throw New IOException("the file is read-only; nothing was written", ex)
            End If
            Throw New IOException("you may not write in the folder " & folder & "; nothing was written", ex)
        Catch ex As DirectoryNotFoundException
            Throw New IOException("the folder " & folder & " does not exist; nothing was written", ex)
        Catch ex As PathTooLongException
            Throw New IOException("the path is too long for this computer; nothing was written", ex)
        Catch ex As IOException
            Throw New IOException("the folder " & folder & " would not take the file (the system said: " & Plain(ex.Message, temp) & "); nothing was written", ex)
        Finally
            Try
                If File.Exists(temp) Then File.Delete(temp)
            Catch ex As IOException
                ' Nothing more can be done; the target is untouched either way.
            Catch ex As UnauthorizedAccessException
            End Try
        End Try
    End Sub

    ''' <summary>The system's message on one line without the temporary file's name.</summary>
    Private Shared Function Plain(message As String, temp As String) As String
        Dim text = If(message, "").Replace(vbCr, " ").Replace(vbLf, " ").Replace(temp, "the file").Replace(IO.Path.GetFileName(temp), "the file").Trim()
        Return text.TrimEnd("."c, " "c, ":"c)
    End Function
End Class
