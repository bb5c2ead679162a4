Option Strict On
Imports System.IO
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>A surface's own μk and μs, typed into the μk and μs columns of the tables under the canvas.</summary>
Public Class SurfaceFrictionTests
    Private Const RectanglesTable As Integer = 1
    Private Const BodiesTable As Integer = 2

    ''' <summary>The inclined-plane lesson (event solver): world μk 0.4, μs 0.5; the "slides" block rests on the "steep" ramp, steeper than tan⁻¹ 0.5.</summary>
    Private Shared Function InclinedPlane() As PresenterHarness
        Dim h As New PresenterHarness(store:=New SceneFileStore())
        h.P.LessonFolder = Path.Combine(ProcessRunner.RepoRoot, "scenes")
        h.P.OpenLesson(h.P.Lessons().Single(Function(l) l.FileName = "inclined-plane.json"))
        Assert.Equal("event", h.P.World.Solver.Name)
        Return h
    End Function

    ''' <summary>The row of body <paramref name="id"/> in table <paramref name="table"/> of the presenter's snapshot.</summary>
    Private Shared Function RowOf(h As PresenterHarness, table As Integer, id As String) As Integer
        Dim snap = h.P.Snapshot
        For r = 0 To snap.RowCount(table) - 1
            If snap.Row(table, r).Id = id Then Return r
        Next
        Throw New InvalidOperationException(id & " is not listed")
    End Function

    Private Shared Function Column(table As Integer, q As TableQuantity) As Integer
        Dim c = SimulationPresenter.ColumnOf(table, q)
        Assert.True(c >= 0, $"table {table} has a {q} column")
        Return c
    End Function

    Private Shared Sub RunTo(h As PresenterHarness, seconds As Double)
        Do While h.P.World.Time < seconds - 0.000000001
            h.P.Tick(Math.Min(1 / 60.0, seconds - h.P.World.Time))
        Loop
    End Sub

    Private Shared Function Saved(h As PresenterHarness) As String
        Return Scenes.SceneFile.Save(h.P.World)
    End Function

    <Fact>
    Public Sub RampsOwnMu_TypedInTheTable_HoldsABlockSteeperThanTheWorldsAngleOfRepose()
        Dim h = InclinedPlane()
        Dim w = h.P.World
        Dim steep = DirectCast(w.Find("steep"), Segment)
        Dim d = steep.EndPoint - steep.StartPoint
        Dim tanTheta = Math.Abs(d.Y / d.X)
        Dim worldMuS = w.StaticFriction.Value
        Assert.True(tanTheta > worldMuS) ' on the world's own surface the block slides
        ' The contact's μs is √(μs_block·μs_ramp): the ramp's 1.5 gives √0.75 = 0.87, above tan θ = 0.70.
        Assert.True(Math.Sqrt(worldMuS * 1.5) > tanTheta)
        Dim row = RowOf(h, BodiesTable, "steep")
        Assert.Equal("0.4 (world)", h.P.Snapshot.Cells(BodiesTable, row)(Column(BodiesTable, TableQuantity.KineticFriction)))
        Assert.True(h.P.CanEditCell(BodiesTable, row, Column(BodiesTable, TableQuantity.KineticFriction)))
        Assert.True(h.P.EditCell(BodiesTable, row, Column(BodiesTable, TableQuantity.KineticFriction), "1.2"))
        Assert.Equal(1.2, w.KineticFrictionOf(steep))
        Assert.Equal(1.2, w.StaticFrictionOf(steep)) ' an empty μs follows the surface's own μk
        ' A decimal comma is read as the point is.
        Assert.True(h.P.EditCell(BodiesTable, row, Column(BodiesTable, TableQuantity.StaticFriction), "1,5"))
        Assert.Equal(1.5, w.StaticFrictionOf(steep))
        Assert.Equal(0.4, w.KineticFrictionOf(Nothing)) ' the world's own is untouched
        Dim cells = h.P.Snapshot.Cells(BodiesTable, RowOf(h, BodiesTable, "steep"))
        Assert.Equal("1.2", cells(Column(BodiesTable, TableQuantity.KineticFriction)))
        Assert.Equal("1.5", cells(Column(BodiesTable, TableQuantity.StaticFriction)))
        Assert.Contains(h.TraceLines, Function(l) l = "edited steep μs = 1.5")
        Dim slides = w.Find("slides")
        Dim start = slides.CentreOfMass
        RunTo(h, 2.0)
        Assert.Equal(start, slides.CentreOfMass) ' held, to the last bit
        Assert.Equal(Vector.Zero, slides.Velocity)

        ' The same block with the ramp at the world's μ slides.
        Dim control = InclinedPlane()
        Dim start2 = control.P.World.Find("slides").CentreOfMass
        RunTo(control, 1.0)
        Assert.True((control.P.World.Find("slides").CentreOfMass - start2).Length > 0.5)
    End Sub

    <Fact>
    Public Sub OwnMu_UndoAndRedo_ToTheLastBit_AndSaveKeepsIt()
        Dim h = InclinedPlane()
        h.P.TogglePause()
        Dim before = Saved(h)
        Dim row = RowOf(h, BodiesTable, "steep")
        Dim typed = 0.1 + 0.2 ' 0.30000000000000004: every bit must survive
        Assert.True(h.P.EditCell(BodiesTable, row, Column(BodiesTable, TableQuantity.KineticFriction), typed.ToString("R", Globalization.CultureInfo.InvariantCulture)))
        Dim after = Saved(h)
        Assert.Equal(typed, h.P.World.Find("steep").Friction.Value)
        Dim reopened = Scenes.SceneFile.Load(after)
        Assert.Equal(typed, reopened.Find("steep").Friction.Value)
        Assert.Null(reopened.Find("steep").StaticFriction)
        h.P.Undo()
        Assert.Equal(before, Saved(h))
        Assert.Null(h.P.World.Find("steep").Friction)
        h.P.Redo()
        Assert.Equal(after, Saved(h))
        Assert.Equal(typed, h.P.World.KineticFrictionOf(h.P.World.Find("steep")))
        ' An empty cell gives the surface back the world's value.
        Assert.True(h.P.EditCell(BodiesTable, RowOf(h, BodiesTable, "steep"), Column(BodiesTable, TableQuantity.KineticFriction), ""))
        Assert.Null(h.P.World.Find("steep").Friction)
        Assert.Equal(0.4, h.P.World.KineticFrictionOf(h.P.World.Find("steep")))
    End Sub

    <Theory>
    <InlineData("μk", "-0.2", "must be 0 or more")>
    <InlineData("μk", "rough", "rough")>
    <InlineData("μs", "0.1", "must be at least μk (0.4)")>
    <InlineData("μk", "0.6", "must be at least μk (0.6)")>
    Public Sub BadMu_IsRefusedNamingTheCell_AndNothingChanges(header As String, text As String, says As String)
        Dim h = InclinedPlane()
        h.P.TogglePause()
        Dim row = RowOf(h, BodiesTable, "stays")
        ' A μs of its own below the 0.6 typed as μk in the last case.
        Assert.True(h.P.EditCell(BodiesTable, row, Column(BodiesTable, TableQuantity.StaticFriction), "0.5"))
        Dim before = Saved(h)
        Dim q = If(header = "μk", TableQuantity.KineticFriction, TableQuantity.StaticFriction)
        Assert.False(h.P.EditCell(BodiesTable, row, Column(BodiesTable, q), text))
        Assert.Equal(before, Saved(h))
        Assert.StartsWith("stays's " & header & " is unchanged: ", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Contains(says, h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub ABall_ShowsNoMu_AndATypedOneIsRefusedSayingBallsTakeNoFriction()
        Dim w As New World(8, 5, 9.81, 0.5)
        w.Add(New Rectangle(New Vector(1, 0), 2, 0.5, "floor"))
        Dim h As New PresenterHarness(w)
        h.Ball(5, 2, 0.2, 1.0, "ball")
        h.P.TogglePause()
        Dim before = Saved(h)
        Dim row = RowOf(h, BodiesTable, "ball")
        Dim col = Column(BodiesTable, TableQuantity.KineticFriction)
        Assert.Equal(BodyTable.NoFrictionCell, h.P.Snapshot.Cells(BodiesTable, row)(col))
        Assert.False(h.P.CanEditCell(BodiesTable, row, col))
        Assert.False(h.P.EditCell(BodiesTable, row, col, "0.3"))
        Assert.Equal("ball's μk cannot be set. " & SimulationPresenter.FrictionBallsNote, h.View.LastMessage)
        Assert.Equal(before, Saved(h))
        ' A fixed rectangle is a surface: its μ is typed in the Rectangles table too, and shown beside the world's.
        Dim floorRow = RowOf(h, RectanglesTable, "floor")
        Dim rectCol = Column(RectanglesTable, TableQuantity.StaticFriction)
        Assert.Equal("0 (world)", h.P.Snapshot.Cells(RectanglesTable, floorRow)(rectCol))
        Assert.True(h.P.EditCell(RectanglesTable, floorRow, rectCol, "0.7"))
        Assert.Equal(0.7, h.P.World.StaticFrictionOf(h.P.World.Find("floor")))
        Assert.Equal("0.7", h.P.Snapshot.Cells(RectanglesTable, floorRow)(rectCol))
    End Sub

    <Fact>
    Public Sub ABoxKeepsItsOwnMuAndDrag_WhenItsMassOrSizeIsTyped()
        Dim h = InclinedPlane()
        h.P.TogglePause()
        Dim row = RowOf(h, RectanglesTable, "stays")
        Assert.True(h.P.EditCell(RectanglesTable, row, Column(RectanglesTable, TableQuantity.KineticFriction), "0.7"))
        h.P.World.SetDrag(h.P.World.Find("stays"), 0.8, 0.3)
        Assert.True(h.P.EditCell(RectanglesTable, row, Column(RectanglesTable, TableQuantity.Mass), "3"))
        Assert.True(h.P.EditCell(RectanglesTable, row, Column(RectanglesTable, TableQuantity.Size), "0.4 × 0.4"))
        Dim box = h.P.World.Find("stays")
        Assert.Equal(3.0, box.Mass)
        Assert.Equal(0.7, box.Friction.Value)
        Assert.Equal(0.8, box.DragCoefficient)
        Assert.Equal(0.3, box.LinearDrag)
    End Sub
End Class
