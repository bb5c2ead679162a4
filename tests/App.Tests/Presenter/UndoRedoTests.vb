Option Strict On
Imports System.Globalization
Imports PhysicsEngine.Presentation
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>Ctrl+Z and Ctrl+Y: every kind of edit undone and redone, to the last bit of every number.</summary>
Public Class UndoRedoTests
    ''' <summary>The world as text with every number to the last bit, and its clock.</summary>
    Private Shared Function State(h As PresenterHarness) As String
        Return SceneFile.Save(h.P.World) & " t=" & h.P.World.Time.ToString("R", CultureInfo.InvariantCulture)
    End Function

    ''' <summary>A paused scene of two balls on the floor, a box, time run a little so the clock is not 0.</summary>
    Private Shared Function Scene() As PresenterHarness
        Dim w As New World(8, 5, 9.81, 0.9)
        w.Add(New Circle(New Vector(2, 0.3), 0.3, 1.0, New Vector(1.25, 0), "red"))
        w.Add(New Circle(New Vector(5, 0.4), 0.4, 2.0, id:="blue"))
        w.Add(Rectangle.CreateMovable(New Vector(6.5, 0), 0.6, 0.5, 3.0, Vector.Zero, "crate"))
        Dim h As New PresenterHarness(w)
        For k = 1 To 7
            h.P.Tick(1 / 60.0)
        Next
        h.P.TogglePause()
        Return h
    End Function

    ''' <summary>Each edit a teacher can make, by name.</summary>
    Private Shared ReadOnly EditNames As String() = {
        "add circle", "add polygon", "delete", "carry", "push", "typed vx", "typed size", "rod", "spring to anchor", "ramp", "corners", "resize", "reset"}

    ''' <summary>The edits, for the theory.</summary>
    Public Shared Function Edits() As TheoryData(Of String)
        Return New TheoryData(Of String)(EditNames)
    End Function

    Private Shared Sub MakeEdit(h As PresenterHarness, edit As String)
        Dim red = h.P.World.Find("red")
        Select Case edit
            Case "add circle"
                h.P.BeginAddCircle("0.2", "0.5", False)
                h.LeftClick(3.5, 3)
            Case "add polygon"
                h.P.BeginAddPolygon("6", "0.3", "15", "1.5", False)
                h.LeftClick(4, 3.5)
            Case "delete"
                h.P.ToggleDeleteMode()
                h.LeftClick(5, 0.4)
                h.P.ToggleDeleteMode()
            Case "carry"
                h.Drag(PointerButton.Right, red.Position.X, red.Position.Y, 3.1, 2.2)
            Case "push"
                h.Drag(PointerButton.Left, red.Position.X, red.Position.Y, red.Position.X - 0.4, red.Position.Y - 0.1)
            Case "typed vx"
                Assert.True(h.P.EditCell(0, 0, SimulationPresenter.ColumnOf(0, TableQuantity.Vx), "-2,75"))
            Case "typed size"
                Dim bodies = BodyTable.All.ToList().IndexOf(BodyTable.Bodies)
                Dim row = Enumerable.Range(0, h.P.Snapshot.RowCount(bodies)).First(Function(i) h.P.Snapshot.Row(bodies, i).Id = "crate")
                Assert.True(h.P.EditCell(bodies, row, SimulationPresenter.ColumnOf(bodies, TableQuantity.Size), "0.8 × 0.45"))
            Case "rod"
                h.P.BeginAddLink(LinkKind.Rod)
                h.LeftClick(red.Position.X, red.Position.Y)
                h.LeftClick(5, 0.4)
            Case "spring to anchor"
                h.P.BeginAddLink(LinkKind.Spring, "35")
                h.LeftClick(5, 0.4)
                h.LeftClick(5, 3.5)
            Case "ramp"
                h.P.BeginAddRamp()
                h.Drag(PointerButton.Left, 0.5, 3, 2.5, 2)
            Case "corners"
                h.P.BeginAddCorners("1", False)
                For Each c In {(3.0, 3.0), (3.6, 3.0), (3.3, 3.6)}
                    h.LeftClick(c.Item1, c.Item2)
                Next
                h.P.FinishCorners()
            Case "resize"
                h.P.ResizeContainer("7,5", "4.5")
            Case "reset"
                h.P.Reset()
        End Select
    End Sub

    <Theory>
    <MemberData(NameOf(Edits))>
    Public Sub AnEdit_IsUndone_AndRedone_ToTheLastBit(edit As String)
        Dim h = Scene()
        Dim before = State(h)
        Assert.False(h.P.CanUndo)
        MakeEdit(h, edit)
        Dim after = State(h)
        Assert.NotEqual(before, after)
        Assert.True(h.P.CanUndo, edit & " was not kept for Undo: " & h.View.LastMessage)
        h.P.Undo()
        Assert.Equal(before, State(h))
        Assert.StartsWith("Undone: ", h.P.Message, StringComparison.Ordinal)
        Assert.True(h.P.CanRedo)
        h.P.Redo()
        Assert.Equal(after, State(h))
        ' And back again: undo and redo are as exact the second time.
        h.P.Undo()
        Assert.Equal(before, State(h))
        h.P.Redo()
        Assert.Equal(after, State(h))
    End Sub

    <Fact>
    Public Sub UndoingSeveralEdits_GoesBackThroughThemInTurn_AndANewEditForgetsWhatWasUndone()
        Dim h = Scene()
        Dim s0 = State(h)
        MakeEdit(h, "add circle")
        Dim s1 = State(h)
        MakeEdit(h, "push")
        Dim s2 = State(h)
        MakeEdit(h, "typed vx")
        h.P.Undo()
        Assert.Equal(s2, State(h))
        h.P.Undo()
        Assert.Equal(s1, State(h))
        h.P.Undo()
        Assert.Equal(s0, State(h))
        h.P.Undo()
        Assert.Equal("There is nothing to undo.", h.P.Message)
        Assert.Equal(s0, State(h))
        h.P.Redo()
        Assert.Equal(s1, State(h))
        MakeEdit(h, "resize")
        Assert.False(h.P.CanRedo)
        h.P.Redo()
        Assert.Equal("There is nothing to redo.", h.P.Message)
    End Sub

    <Fact>
    Public Sub UndoAfterTimeHasRun_PutsBackTheMomentBeforeTheEdit_AndTheRunGoesOnFromIt()
        Dim h = Scene()
        h.P.TogglePause()
        Dim before = State(h)
        MakeEdit(h, "push")
        For k = 1 To 30
            h.P.Tick(1 / 60.0)
        Next
        h.P.Undo()
        Assert.Equal(before, State(h))
        ' Gravity is a setting, not an edit: it stays as set.
        h.P.SetGravity(1.62)
        MakeEdit(h, "add circle")
        h.P.Undo()
        Assert.Equal(1.62, h.P.World.Gravity, 12)
        Dim t = h.P.World.Time
        For k = 1 To 10
            h.P.Tick(1 / 60.0)
        Next
        Assert.True(h.P.World.Time > t)
    End Sub

    <Fact>
    Public Sub OpeningAScene_StartsAnEmptyHistory()
        Dim h = Scene()
        MakeEdit(h, "add circle")
        Assert.True(h.P.CanUndo)
        h.P.Restart()
        Assert.False(h.P.CanUndo)
    End Sub

    <Fact>
    Public Sub TheTutorial_ListsEveryKey()
        Dim page = HelpTexts.Tutorial.Single(Function(t) t.Title.StartsWith("10. Keys", StringComparison.Ordinal)).Text
        For Each key In {SimulationPresenter.PauseKey, SimulationPresenter.RestartKey, SimulationPresenter.ResetKey, SimulationPresenter.ScenesKey,
                         SimulationPresenter.UndoKey, SimulationPresenter.RedoKey, SimulationPresenter.StepKey, SimulationPresenter.StepBackKey,
                         SimulationPresenter.NextCollisionKey, SimulationPresenter.PreviousCollisionKey, "Esc", "Enter", "F2", "Tab", "Ctrl+0", "wheel", "middle button"}
            Assert.Contains(key, page, StringComparison.Ordinal)
        Next
    End Sub
End Class
