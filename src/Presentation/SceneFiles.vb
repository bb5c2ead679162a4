Option Strict On

''' <summary>Opening and saving scene files (physics-scene/1) through the <see cref="ISceneStore"/>.</summary>
Friend NotInheritable Class SceneFiles
    Private ReadOnly _stage As Stage

    Public Sub New(stage As Stage, store As ISceneStore)
        _stage = stage
        SceneStore = store
    End Sub

    ''' <summary>Reads and writes scene files; Nothing disables Open and Save with a message.</summary>
    Public Property SceneStore As ISceneStore

    ''' <summary>True when Open and Save can work (a scene store is present).</summary>
    Public ReadOnly Property CanOpenAndSave As Boolean
        Get
            Return SceneStore IsNot Nothing
        End Get
    End Property

    ''' <summary>The folder the Open and Save dialogs start in: the example scenes at first, then the last one used.</summary>
    Public Property SceneFolder As String

    ''' <summary>Opens the scene file at <paramref name="path"/>; on any problem shows a message and keeps the current scene.</summary>
    Public Sub OpenScene(path As String)
        If SceneStore Is Nothing Then
            _stage.ShowMessage("Opening scene files is not available in this build.")
            Return
        End If
        Dim loaded As World
        Try
            loaded = SceneStore.Load(path)
        Catch ex As Exception When IsFileProblem(ex)
            _stage.ShowMessage("Could not open " & SafeName(path) & ": " & Reason(ex, path))
            Return
        End Try
        Dim tooMuch = SceneLimits.Problem(loaded)
        If tooMuch IsNot Nothing Then
            _stage.ShowMessage("Could not open " & SafeName(path) & ": " & tooMuch & ". The scene on screen is kept.")
            Return
        End If
        Remember(path)
        _stage.Guarded(
            Sub()
                ' Rods and taut strings the file sets off their lengths, or with their ends moving apart, are put right
                ' before anything moves, as the command line does; the teacher is told what changed.
                Dim held = loaded.HoldLinks()
                _stage.Present(loaded)
                _stage.Emit("opened " & SafeName(path) & ": " & loaded.Bodies.Count & " bodies")
                _stage.ShowMessage("Opened " & SafeName(path) & "." & If(loaded.Walls, "", " This scene has no walls: balls can leave the box.") & SolverChoice.StiffSpringAddendum(loaded) &
                                   If(held.Count = 0, "", " Put right: " & String.Join("; ", held) & "."))
                _stage.TakeSnapshot()
                _stage.Window.ShowInputs()
                _stage.Window.ShowSettings()
            End Sub)
    End Sub

    ''' <summary>Saves the scene to <paramref name="path"/>; on any problem shows a message naming the file and why.</summary>
    Public Sub SaveScene(path As String)
        If SceneStore Is Nothing Then
            _stage.ShowMessage("Saving scene files is not available in this build.")
            Return
        End If
        Dim missing = FolderCheck.MissingFolder(path)
        If missing IsNot Nothing Then
            _stage.ShowMessage("Could not save " & SafeName(path) & ": " & missing & ".")
            Return
        End If
        Try
            SceneStore.Save(_stage.World, path)
        Catch ex As Exception When IsFileProblem(ex)
            _stage.ShowMessage("Could not save " & SafeName(path) & ": " & Reason(ex, path))
            Return
        End Try
        Remember(path)
        _stage.Emit("saved " & SafeName(path) & ": " & _stage.World.Bodies.Count & " bodies")
        _stage.ShowMessage("Saved " & SafeName(path) & ".")
    End Sub

    Private Sub Remember(path As String)
        Try
            Dim folder = IO.Path.GetDirectoryName(IO.Path.GetFullPath(path))
            If Not String.IsNullOrEmpty(folder) Then SceneFolder = folder
        Catch ex As Exception When TypeOf ex Is ArgumentException OrElse TypeOf ex Is NotSupportedException OrElse TypeOf ex Is IO.PathTooLongException OrElse TypeOf ex Is Security.SecurityException
            ' Keep the folder there was.
        End Try
    End Sub

    ''' <summary>Every exception a bad file or path can raise; programming errors (null references) still surface.</summary>
    Private Shared Function IsFileProblem(ex As Exception) As Boolean
        Return Not (TypeOf ex Is NullReferenceException OrElse TypeOf ex Is OutOfMemoryException OrElse TypeOf ex Is StackOverflowException)
    End Function

    Public Shared Function SafeName(path As String) As String
        If String.IsNullOrEmpty(path) Then Return "(no file)"
        Try
            Return IO.Path.GetFileName(path)
        Catch ex As ArgumentException
            Return path
        End Try
    End Function

    ''' <summary>The exception's one-line message without a leading "path: " (the file is already named).</summary>
    Private Shared Function Reason(ex As Exception, path As String) As String
        Dim text = Stage.OneLine(ex.Message)
        For Each prefix In {path, TryFullPath(path)}
            If Not String.IsNullOrEmpty(prefix) AndAlso text.StartsWith(prefix & ": ", StringComparison.Ordinal) Then Return text.Substring(prefix.Length + 2)
        Next
        Return text
    End Function

    Private Shared Function TryFullPath(path As String) As String
        Try
            Return IO.Path.GetFullPath(path)
        Catch ex As ArgumentException
            Return Nothing
        Catch ex As NotSupportedException
            Return Nothing
        Catch ex As IO.PathTooLongException
            Return Nothing
        Catch ex As Security.SecurityException
            Return Nothing
        End Try
    End Function
End Class
