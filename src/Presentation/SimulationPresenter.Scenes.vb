Option Strict On


' Opening and saving scene files (physics-scene/1) through the ISceneStore.
Partial Public NotInheritable Class SimulationPresenter
    ''' <summary>True when Open and Save can work (a scene store is present).</summary>
    Public ReadOnly Property CanOpenAndSave As Boolean
        Get
            Return SceneStore IsNot Nothing
        End Get
    End Property

    ''' <summary>Opens the scene file at <paramref name="path"/>; on any problem shows a message and keeps the current scene.</summary>
    Public Sub OpenScene(path As String)
        If SceneStore Is Nothing Then
            ShowMessage("Opening scene files is not available in this build.")
            Return
        End If
        Dim loaded As World
        Try
            loaded = SceneStore.Load(path)
        Catch ex As Exception When IsFileProblem(ex)
            ShowMessage("Could not open " & SafeName(path) & ": " & OneLine(ex.Message))
            Return
        End Try
        EndGestures()
        _Draft = Nothing
        Attach(loaded)
        Emit("opened " & SafeName(path) & ": " & loaded.Bodies.Count & " bodies")
        ShowMessage("Opened " & SafeName(path) & ".")
        _window.ShowSettings()
        _window.ShowBodies()
    End Sub

    ''' <summary>Saves the scene to <paramref name="path"/>; on any problem shows a message.</summary>
    Public Sub SaveScene(path As String)
        If SceneStore Is Nothing Then
            ShowMessage("Saving scene files is not available in this build.")
            Return
        End If
        Try
            SceneStore.Save(World, path)
        Catch ex As Exception When IsFileProblem(ex)
            ShowMessage("Could not save " & SafeName(path) & ": " & OneLine(ex.Message))
            Return
        End Try
        Emit("saved " & SafeName(path) & ": " & World.Bodies.Count & " bodies")
        ShowMessage("Saved " & SafeName(path) & ".")
    End Sub

    ''' <summary>Every exception a bad file or path can raise; programming errors (null references) still surface.</summary>
    Private Shared Function IsFileProblem(ex As Exception) As Boolean
        Return Not (TypeOf ex Is NullReferenceException OrElse TypeOf ex Is OutOfMemoryException OrElse TypeOf ex Is StackOverflowException)
    End Function

    Private Shared Function SafeName(path As String) As String
        If String.IsNullOrEmpty(path) Then Return "(no file)"
        Try
            Return IO.Path.GetFileName(path)
        Catch ex As ArgumentException
            Return path
        End Try
    End Function

    Private Shared Function OneLine(text As String) As String
        Return If(text, "").Replace(vbCr, " ").Replace(vbLf, " ").Trim()
    End Function
End Class
