Option Strict On

''' <summary>Checks made before a file is written (a scene saved, a table exported).</summary>
Friend Module FolderCheck
    ''' <summary>
    ''' "the folder /media/usb/lessons does not exist; nothing was written" when the folder of
    ''' <paramref name="path"/> is not there, else Nothing. Checked before writing: Mono reports a
    ''' missing folder as a missing file, and names the temporary file the write goes through.
    ''' </summary>
    Public Function MissingFolder(path As String) As String
        Dim folder As String
        Try
            folder = IO.Path.GetDirectoryName(IO.Path.GetFullPath(path))
        Catch ex As Exception When TypeOf ex Is ArgumentException OrElse TypeOf ex Is NotSupportedException OrElse TypeOf ex Is IO.PathTooLongException OrElse TypeOf ex Is Security.SecurityException
            Return Nothing ' the write itself says what is wrong with the name
        End Try
        If String.IsNullOrEmpty(folder) OrElse IO.Directory.Exists(folder) Then Return Nothing
        Return "the folder " & folder & " does not exist; nothing was written"
    End Function
End Module
