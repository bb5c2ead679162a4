Option Strict On
Imports System.IO
Imports System.Text

''' <summary>
''' An output file written to a temporary file beside it and moved into place only by
''' <see cref="Commit"/>, so a failed or interrupted run never leaves a half-written file.
''' </summary>
Friend NotInheritable Class OutputFile
    Implements IDisposable

    Private ReadOnly _target As String
    ''' <summary>The temporary file, or Nothing when the target is a stream written straight through.</summary>
    Private ReadOnly _temp As String
    Private _writer As StreamWriter
    Private _committed As Boolean

    Private Sub New(target As String, temp As String, writer As StreamWriter)
        _target = target
        _temp = temp
        _writer = writer
    End Sub

    ''' <summary>
    ''' Checks, before anything is written, that <paramref name="path"/> can be an output file: its
    ''' folder exists and it is not itself a folder. <paramref name="optionName"/> names it in messages.
    ''' </summary>
    Friend Shared Sub CheckTarget(optionName As String, path As String)
        Dim full As String
        Try
            full = IO.Path.GetFullPath(path)
        Catch ex As ArgumentException
            Throw New BadInputException(optionName & ": '" & path & "' is not a valid file name", ex)
        Catch ex As NotSupportedException
            Throw New BadInputException(optionName & ": '" & path & "' is not a valid file name", ex)
        End Try
        If Directory.Exists(full) Then Throw New BadInputException(optionName & ": '" & path & "' is a folder, not a file")
        Dim folder = IO.Path.GetDirectoryName(full)
        If Not Directory.Exists(folder) Then Throw New BadInputException(optionName & ": folder '" & folder & "' does not exist")
    End Sub

    ''' <summary>
    ''' Starts writing (UTF-8 without BOM, "\n" line ends) to a temporary file beside
    ''' <paramref name="path"/>, or beside the file it links to: a symbolic link is kept and its
    ''' target replaced. A pipe or a device (a FIFO, /dev/stdout) cannot be replaced and holds no file
    ''' to leave half-written: it is written straight through.
    ''' </summary>
    Friend Shared Function Create(optionName As String, path As String) As OutputFile
        Dim target = IO.Path.GetFullPath(path)
        Try
            Dim direct = OpenIfStream(target)
            If direct IsNot Nothing Then Return New OutputFile(target, Nothing, NewWriter(direct))
            Dim info As New FileInfo(target)
            If info.LinkTarget IsNot Nothing Then
                Dim final = info.ResolveLinkTarget(returnFinalTarget:=True)
                If final IsNot Nothing Then target = final.FullName
            End If
            Dim temp = IO.Path.Combine(IO.Path.GetDirectoryName(target), "." & IO.Path.GetFileName(target) & "." & Guid.NewGuid().ToString("N") & ".tmp")
            Dim stream As New FileStream(temp, FileMode.CreateNew, FileAccess.Write, FileShare.None, 1 << 16)
            Return New OutputFile(target, temp, NewWriter(stream))
        Catch ex As IOException
            Throw New BadInputException(optionName & ": cannot write in '" & IO.Path.GetDirectoryName(target) & "' (" & ex.Message & ")", ex)
        Catch ex As UnauthorizedAccessException
            Throw New BadInputException(optionName & ": cannot write in '" & IO.Path.GetDirectoryName(target) & "' (" & ex.Message & ")", ex)
        End Try
    End Function

    Private Shared Function NewWriter(stream As Stream) As StreamWriter
        Return New StreamWriter(stream, New UTF8Encoding(False)) With {.NewLine = vbLf}
    End Function

    ''' <summary>
    ''' The open target when it already exists and is a stream rather than a file (it cannot seek: a
    ''' pipe or a device); Nothing otherwise, and for anything that cannot be opened here (the
    ''' temporary file route then says why). Opening a FIFO waits for its reader, as it should.
    ''' </summary>
    Private Shared Function OpenIfStream(target As String) As FileStream
        If Not File.Exists(target) Then Return Nothing
        Dim probe As FileStream
        Try
            probe = New FileStream(target, FileMode.Open, FileAccess.Write, FileShare.ReadWrite, 1 << 16)
        Catch ex As IOException
            Return Nothing
        Catch ex As UnauthorizedAccessException
            Return Nothing
        End Try
        If Not probe.CanSeek Then Return probe
        probe.Dispose()
        Return Nothing
    End Function

    ''' <summary>True when the target is a stream (a FIFO, /dev/stdout) written straight through, not a file replaced whole.</summary>
    Friend ReadOnly Property IsStream As Boolean
        Get
            Return _temp Is Nothing
        End Get
    End Property

    ''' <summary>The full path written to (for a symbolic link, the file it points to).</summary>
    Friend ReadOnly Property Target As String
        Get
            Return _target
        End Get
    End Property

    Friend ReadOnly Property Writer As TextWriter
        Get
            Return _writer
        End Get
    End Property

    ''' <summary>Finishes the file and moves it over the target (a stream is only flushed and closed).</summary>
    Friend Sub Commit()
        _writer.Flush()
        If _temp IsNot Nothing Then DirectCast(_writer.BaseStream, FileStream).Flush(True)
        _writer.Dispose()
        _writer = Nothing
        If _temp IsNot Nothing Then File.Move(_temp, _target, overwrite:=True)
        _committed = True
    End Sub

    ''' <summary>Without <see cref="Commit"/>, throws the temporary file away.</summary>
    Public Sub Dispose() Implements IDisposable.Dispose
        If _committed Then Return
        ' Delete first: on Linux and macOS that works while the file is still open, which matters when a
        ' signal arrives while the main thread is writing; on Windows the second try does it.
        TryDelete()
        Try
            _writer?.Dispose()
        Catch ex As IOException
            ' the file is thrown away anyway; a failed flush must not hide the first error
        Catch ex As ObjectDisposedException
            ' disposed already, by a signal handler
        Catch ex As InvalidOperationException
            ' the main thread was writing when a signal arrived
        End Try
        _writer = Nothing
        TryDelete()
    End Sub

    Private Sub TryDelete()
        If _temp Is Nothing Then Return ' a stream: nothing to throw away
        Try
            If File.Exists(_temp) Then File.Delete(_temp)
        Catch ex As IOException
            ' still open (Windows): the caller tries again after closing it
        Catch ex As UnauthorizedAccessException
            ' nothing more can be done; the target file was never touched
        End Try
    End Sub
End Class
