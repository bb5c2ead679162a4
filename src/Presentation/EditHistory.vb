Option Strict On

''' <summary>
''' Undo and redo of the teacher's edits: a body added or deleted, moved, pushed or given a velocity
''' with its arrow, a value typed into a table, a link, a ramp, the container resized, Reset. Each
''' edit keeps the scene as it was just before and just after it, as checkpoints of the recorded run
''' (every number to the last bit), so Undo puts the world back exactly as it was before the edit,
''' clock included, and Redo exactly as it was after. Gravity, restitution and friction are settings, not
''' edits: they stay as they are set (except across Reset, which sets them too). Undo and Redo are changes like any other, so the run goes on
''' from what they put back. A new scene (opened, restarted) starts an empty history.
''' </summary>
Friend NotInheritable Class EditHistory
    ''' <summary>The most edits kept for Undo (older ones are forgotten).</summary>
    Public Const Depth As Integer = 100

    Private ReadOnly _stage As Stage
    Private ReadOnly _capture As Func(Of Checkpoint)
    Private ReadOnly _putBack As Action(Of Checkpoint, Boolean)
    Private ReadOnly _undo As New List(Of Edit)
    Private ReadOnly _redo As New List(Of Edit)

    ''' <summary>One edit: what it was, and the world just before and just after it.</summary>
    Private NotInheritable Class Edit
        Public Sub New(name As String, before As Checkpoint, after As Checkpoint, withSettings As Boolean)
            Me.Name = name
            Me.Before = before
            Me.After = after
            Me.WithSettings = withSettings
        End Sub

        Public ReadOnly Property Name As String
        ''' <summary>Whether the edit changed gravity and restitution too (Reset): they are put back with the world.</summary>
        Public ReadOnly Property WithSettings As Boolean
        Public ReadOnly Property Before As Checkpoint
        Public ReadOnly Property After As Checkpoint
    End Class

    ''' <param name="capture">the world on show now, as a checkpoint</param>
    ''' <param name="putBack">puts a checkpoint's world on show as a change (a new run goes on from it), with its own gravity and restitution or not</param>
    Public Sub New(stage As Stage, capture As Func(Of Checkpoint), putBack As Action(Of Checkpoint, Boolean))
        _stage = stage
        _capture = capture
        _putBack = putBack
    End Sub

    ''' <summary>The undo key, as the tutorial names it.</summary>
    Public Const UndoKey As String = "Ctrl+Z"
    ''' <summary>The redo key, as the tutorial names it.</summary>
    Public Const RedoKey As String = "Ctrl+Y"

    ''' <summary>Whether there is an edit to undo.</summary>
    Public ReadOnly Property CanUndo As Boolean
        Get
            Return _undo.Count > 0
        End Get
    End Property

    ''' <summary>Whether there is an undone edit to redo.</summary>
    Public ReadOnly Property CanRedo As Boolean
        Get
            Return _redo.Count > 0
        End Get
    End Property

    ''' <summary>The world as it is now, to keep as the state before an edit about to be made.</summary>
    Public Function Capture() As Checkpoint
        Return _capture()
    End Function

    ''' <summary>An edit was made: <paramref name="before"/> is the world before it (see <see cref="Capture"/>); the world now is after it.</summary>
    Public Sub Commit(name As String, before As Checkpoint, Optional withSettings As Boolean = False)
        If before Is Nothing Then Return ' the world could not be written down: nothing to go back to
        Dim after = _capture()
        If after Is Nothing Then Return
        _undo.Add(New Edit(name, before, after, withSettings))
        If _undo.Count > Depth Then _undo.RemoveAt(0)
        _redo.Clear()
        _stage.Emit("edit kept: " & name)
    End Sub

    ''' <summary>Undoes the last edit: the world as it was just before it.</summary>
    Public Sub Undo()
        If _undo.Count = 0 Then
            _stage.ShowMessage("There is nothing to undo.")
            Return
        End If
        Dim e = _undo(_undo.Count - 1)
        _undo.RemoveAt(_undo.Count - 1)
        _putBack(e.Before, e.WithSettings)
        _redo.Add(e)
        _stage.Emit("undo " & e.Name)
        _stage.ShowMessage("Undone: " & e.Name & ". " & RedoKey & " does it again.")
    End Sub

    ''' <summary>Redoes the last edit undone: the world as it was just after it.</summary>
    Public Sub Redo()
        If _redo.Count = 0 Then
            _stage.ShowMessage("There is nothing to redo.")
            Return
        End If
        Dim e = _redo(_redo.Count - 1)
        _redo.RemoveAt(_redo.Count - 1)
        _putBack(e.After, e.WithSettings)
        _undo.Add(e)
        _stage.Emit("redo " & e.Name)
        _stage.ShowMessage("Done again: " & e.Name & ". " & UndoKey & " undoes it.")
    End Sub

    ''' <summary>A new scene: the edits of the old one cannot be undone in it.</summary>
    Public Sub Clear()
        _undo.Clear()
        _redo.Clear()
    End Sub
End Class
