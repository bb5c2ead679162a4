Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>Typing x, y, vx, vy, mass and radius into a row of the tables.</summary>
Public Class TableEditingTests
    Private Const CirclesTable As Integer = 0
    Private Const RectanglesTable As Integer = 1
    Private Const BodiesTable As Integer = 2
    Private Shared ReadOnly EditableCircleHeaders As String() = {"x (m)", "y (m)", "vx (m/s)", "vy (m/s)", "m (kg)", "r (m)"}

    Private Shared Function TwoBalls() As PresenterHarness
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        h.Ball(2, 2, 0.2, 1.0, "a")
        h.Ball(5, 2, 0.3, 2.0, "b")
        h.P.TogglePause()
        Return h
    End Function

    Private Shared Function Column(table As Integer, q As TableQuantity) As Integer
        Dim c = SimulationPresenter.ColumnOf(table, q)
        Assert.True(c >= 0, $"table {table} has a {q} column")
        Return c
    End Function

    Private Shared Function Saved(h As PresenterHarness) As String
        Return Scenes.SceneFile.Save(h.P.World)
    End Function

    <Fact>
    Public Sub EditableColumns_AreThePositionVelocityMassAndRadius()
        Dim headers = SimulationPresenter.Tables(CirclesTable).Headers
        Dim editable = Enumerable.Range(0, headers.Count).Where(Function(c) SimulationPresenter.EditableQuantity(CirclesTable, c) <> TableQuantity.None).Select(Function(c) headers(c)).ToList()
        Assert.Equal(EditableCircleHeaders, editable)
        Assert.Equal(TableQuantity.X, SimulationPresenter.EditableQuantity(BodiesTable, 3))
        Assert.Equal(TableQuantity.None, SimulationPresenter.EditableQuantity(CirclesTable, 0))
        Assert.Equal(TableQuantity.None, SimulationPresenter.EditableQuantity(CirclesTable, 6)) ' speed follows from vx, vy
    End Sub

    <Theory>
    <InlineData("2.345", 2.345)>
    <InlineData("-0.1", -0.1)>
    <InlineData("0", 0.0)>
    <InlineData("1e-3", 0.001)>
    Public Sub TypedVx_LandsInTheWorldExactly(text As String, expected As Double)
        Dim h = TwoBalls()
        Dim a = h.P.World.Find("a")
        h.P.World.SetVelocity(a, New Vector(0.5, 0.25))
        Assert.True(h.P.EditCell(CirclesTable, 0, Column(CirclesTable, TableQuantity.Vx), text))
        Assert.Equal(expected, a.Velocity.X) ' exact, not to some places
        Assert.Equal(0.25, a.Velocity.Y)
        Assert.Equal(Units.Sig(expected), h.P.Snapshot.Cells(CirclesTable, 0)(4))
        Assert.Contains(h.TraceLines, Function(l) l = "edited a vx (m/s) = " & expected.ToString("R", Globalization.CultureInfo.InvariantCulture))
    End Sub

    <Fact>
    Public Sub TypedVy_AndPosition_LandInTheWorld()
        Dim h = TwoBalls()
        Dim a = h.P.World.Find("a")
        Assert.True(h.P.EditCell(CirclesTable, 0, Column(CirclesTable, TableQuantity.Vy), "-3.5"))
        Assert.Equal(New Vector(0, -3.5), a.Velocity)
        Assert.True(h.P.EditCell(CirclesTable, 0, Column(CirclesTable, TableQuantity.X), "1.25"))
        Assert.True(h.P.EditCell(CirclesTable, 0, Column(CirclesTable, TableQuantity.Y), "4.5"))
        Assert.Equal(New Vector(1.25, 4.5), a.Position)
    End Sub

    <Theory>
    <InlineData("abc")>
    <InlineData("")>
    <InlineData("0")>
    <InlineData("-2")>
    Public Sub BadMass_IsRefused_WithTheAddPanelsMessage_AndTheWorldIsUnchanged(text As String)
        Dim h = TwoBalls()
        Dim before = Saved(h)
        Assert.False(h.P.EditCell(CirclesTable, 0, Column(CirclesTable, TableQuantity.Mass), text))
        Assert.Equal(before, Saved(h))
        ' The Add panel, given the same mass, says the same.
        Dim panel = TwoBalls()
        panel.P.BeginAddCircle("0.2", text, False)
        Assert.Equal(panel.View.LastMessage, h.View.LastMessage)
        Assert.StartsWith(InputLimits.CircleMessage, h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub BadRadius_IsRefused_WithTheAddPanelsMessage()
        Dim h = TwoBalls()
        Dim before = Saved(h)
        Assert.False(h.P.EditCell(CirclesTable, 0, Column(CirclesTable, TableQuantity.Radius), "big"))
        Assert.Equal(before, Saved(h))
        Dim panel = TwoBalls()
        panel.P.BeginAddCircle("big", "1", False)
        Assert.Equal(panel.View.LastMessage, h.View.LastMessage)
    End Sub

    <Fact>
    Public Sub BadVelocity_IsRefused_AndTheWorldIsUnchanged()
        Dim h = TwoBalls()
        Dim before = Saved(h)
        Assert.False(h.P.EditCell(CirclesTable, 0, Column(CirclesTable, TableQuantity.Vx), "fast"))
        Assert.Equal(before, Saved(h))
        Assert.Equal("Please enter a suitable value for vx (m/s)! vx (m/s) 'fast' is not a number.", h.View.LastMessage)
    End Sub

    <Fact>
    Public Sub ASpeedBeyondTheLimit_IsSetToIt_AndTheMessageSaysSo()
        Dim h = TwoBalls()
        Assert.True(h.P.EditCell(CirclesTable, 0, Column(CirclesTable, TableQuantity.Vx), "-5000"))
        Assert.Equal(-SimulationPresenter.MaxTypedSpeed, h.P.World.Find("a").Velocity.X)
        Assert.Contains("set to the minimum", h.View.LastMessage)
    End Sub

    <Fact>
    Public Sub APositionInsideAnotherBody_OrOutsideTheBox_IsRefused_AndTheWorldIsUnchanged()
        Dim h = TwoBalls()
        Dim before = Saved(h)
        ' b is at x = 5 with radius 0.3; a (radius 0.2) at x = 4.6 would overlap it.
        Assert.False(h.P.EditCell(CirclesTable, 0, Column(CirclesTable, TableQuantity.X), "4.6"))
        Assert.Contains("into b", h.View.LastMessage)
        Assert.Equal(before, Saved(h))
        Assert.False(h.P.EditCell(CirclesTable, 0, Column(CirclesTable, TableQuantity.X), "7.9"))
        Assert.Contains("outside the container", h.View.LastMessage)
        Assert.Equal(before, Saved(h))
        ' Touching is allowed: 5 − 0.3 − 0.2 = 4.5.
        Assert.True(h.P.EditCell(CirclesTable, 0, Column(CirclesTable, TableQuantity.X), "4.5"))
        Assert.Equal(4.5, h.P.World.Find("a").Position.X)
    End Sub

    <Fact>
    Public Sub Mass_IsReplaced_KeepingPlaceVelocityIdAndColour()
        Dim h = TwoBalls()
        Dim a = h.P.World.Find("a")
        h.P.World.SetVelocity(a, New Vector(2, 0))
        Dim colour = a.Color
        Assert.True(h.P.EditCell(CirclesTable, 0, Column(CirclesTable, TableQuantity.Mass), "3.5"))
        Dim now = h.P.World.Find("a")
        Assert.Equal(3.5, now.Mass)
        Assert.Equal(New Vector(2, 0), now.Velocity)
        Assert.Equal(New Vector(2, 2), now.Position)
        Assert.Equal(colour, now.Color)
        Assert.Equal(0, h.P.World.Bodies.ToList().IndexOf(now)) ' same row
        Assert.Equal(7.0, h.P.Momentum.Momentum.X, 12)
    End Sub

    <Fact>
    Public Sub Radius_TooLargeToFitBesideItsNeighbour_IsRefused_ElseApplied()
        Dim h = TwoBalls()
        Assert.True(h.P.EditCell(CirclesTable, 0, Column(CirclesTable, TableQuantity.X), "4"))
        Dim before = Saved(h)
        ' Centres 1 m apart, b's radius 0.3: a radius of 0.9 would reach 0.2 m into b.
        Assert.False(h.P.EditCell(CirclesTable, 0, Column(CirclesTable, TableQuantity.Radius), "0.9"))
        Assert.Contains("into b", h.View.LastMessage)
        Assert.Equal(before, Saved(h))
        Assert.True(h.P.EditCell(CirclesTable, 0, Column(CirclesTable, TableQuantity.Radius), "0.7"))
        Assert.Equal(0.7, DirectCast(h.P.World.Find("a"), Circle).Radius)
    End Sub

    <Fact>
    Public Sub AFixedBody_CannotBeTypedInto()
        Dim h = TwoBalls()
        h.P.World.Add(Circle.CreateFixed(New Vector(6, 4), 0.3, "peg"))
        h.P.TogglePause()
        h.P.TogglePause()
        Assert.False(h.P.CanEditCell(CirclesTable, 2, Column(CirclesTable, TableQuantity.X)))
        Dim before = Saved(h)
        Assert.False(h.P.EditCell(CirclesTable, 2, Column(CirclesTable, TableQuantity.X), "1"))
        Assert.Equal(before, Saved(h))
        Assert.Contains("fixed", h.View.LastMessage)
    End Sub

    <Fact>
    Public Sub TheBodiesTable_MovesABoxByItsCentreOfMass()
        Dim h = TwoBalls()
        h.P.World.Add(Rectangle.CreateMovable(New Vector(1, 3), 1.0, 0.5, 2.0, id:="box"))
        h.P.TogglePause()
        h.P.TogglePause()
        Dim row = Enumerable.Range(0, h.P.Snapshot.RowCount(BodiesTable)).First(Function(i) h.P.Snapshot.Row(BodiesTable, i).Id = "box")
        Assert.True(h.P.EditCell(BodiesTable, row, Column(BodiesTable, TableQuantity.X), "3"))
        Assert.Equal(3.0, h.P.World.Find("box").CentreOfMass.X, 12)
        ' In the Rectangles table x is the lower-left corner.
        Assert.True(h.P.EditCell(RectanglesTable, 0, Column(RectanglesTable, TableQuantity.X), "6"))
        Assert.Equal(6.0, h.P.World.Find("box").Position.X, 12)
        Assert.True(h.P.EditCell(RectanglesTable, 0, Column(RectanglesTable, TableQuantity.Mass), "0.5"))
        Assert.Equal(0.5, h.P.World.Find("box").Mass)
        ' Its width × height is typed as two numbers; it keeps its centre of mass, mass and velocity.
        Dim centre = h.P.World.Find("box").CentreOfMass
        Assert.True(h.P.EditCell(RectanglesTable, 0, Column(RectanglesTable, TableQuantity.Size), "0.8 × 0.4"))
        Dim box = DirectCast(h.P.World.Find("box"), Rectangle)
        Assert.Equal(0.8, box.Width, 12)
        Assert.Equal(0.4, box.Height, 12)
        Assert.Equal(centre.X, box.CentreOfMass.X, 12)
        Assert.Equal(centre.Y, box.CentreOfMass.Y, 12)
        Assert.Equal(0.5, box.Mass)
    End Sub

    <Theory>
    <InlineData("0.8")>
    <InlineData("0.8 × 0")>
    <InlineData("wide × tall")>
    <InlineData("")>
    Public Sub ABadSize_IsRefused_WithTheAddPanelsMessage_AndTheWorldIsUnchanged(text As String)
        Dim h = TwoBalls()
        h.P.World.Add(Rectangle.CreateMovable(New Vector(1, 3), 1.0, 0.5, 2.0, id:="box"))
        h.P.TogglePause()
        h.P.TogglePause()
        Dim before = Saved(h)
        Assert.False(h.P.EditCell(RectanglesTable, 0, Column(RectanglesTable, TableQuantity.Size), text))
        Assert.StartsWith(InputLimits.BoxMessage, h.View.LastMessage, StringComparison.Ordinal)
        Assert.Equal(before, Saved(h))
    End Sub

    <Fact>
    Public Sub ASizeThatWouldReachANeighbour_IsRefused_AndAPolygonIsStretchedAboutItsCentre()
        Dim h = TwoBalls()
        ' A box beside ball a (centre (2, 2), r 0.2): 1 m wide would reach into it.
        h.P.World.Add(Rectangle.CreateMovable(New Vector(2.5, 1.8), 0.4, 0.4, 1.0, id:="box"))
        h.P.World.Add(New Polygon({New Vector(3.5, 4), New Vector(4.5, 4), New Vector(4, 4.6)}, 1.0, id:="tri"))
        h.P.TogglePause()
        h.P.TogglePause()
        Dim before = Saved(h)
        Dim boxRow = Enumerable.Range(0, h.P.Snapshot.RowCount(BodiesTable)).First(Function(i) h.P.Snapshot.Row(BodiesTable, i).Id = "box")
        Assert.False(h.P.EditCell(BodiesTable, boxRow, Column(BodiesTable, TableQuantity.Size), "1.4 × 0.4"))
        Assert.Contains("into a", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Equal(before, Saved(h))
        Dim triRow = Enumerable.Range(0, h.P.Snapshot.RowCount(BodiesTable)).First(Function(i) h.P.Snapshot.Row(BodiesTable, i).Id = "tri")
        Dim centre = h.P.World.Find("tri").CentreOfMass
        Assert.Equal("1 × 0.6", h.P.CellEditText(BodiesTable, triRow, Column(BodiesTable, TableQuantity.Size)))
        Assert.True(h.P.EditCell(BodiesTable, triRow, Column(BodiesTable, TableQuantity.Size), "0.5 x 0.3"))
        Dim tri = h.P.World.Find("tri")
        Assert.Equal(0.5, tri.BoundsMax.X - tri.BoundsMin.X, 12)
        Assert.Equal(0.3, tri.BoundsMax.Y - tri.BoundsMin.Y, 12)
        Assert.Equal(centre.X, tri.CentreOfMass.X, 12)
        Assert.Equal(centre.Y, tri.CentreOfMass.Y, 12)
        Assert.Equal(1.0, tri.Mass)
    End Sub

    <Fact>
    Public Sub Restart_ComesBackToTheEditedValues()
        Dim h = TwoBalls()
        h.P.EditCell(CirclesTable, 0, Column(CirclesTable, TableQuantity.Vx), "1.5")
        h.P.TogglePause()
        For i = 1 To 30
            h.P.Tick(1.0 / 60)
        Next
        h.P.Restart()
        Dim a = h.P.World.Find("a")
        Assert.Equal(New Vector(2, 2), a.Position)
        Assert.Equal(1.5, a.Velocity.X)
    End Sub

    <Fact>
    Public Sub TheEditBox_OpensWithTheValueToSixFigures()
        Dim h = TwoBalls()
        h.P.World.SetVelocity(h.P.World.Find("a"), New Vector(1.23456789, 0))
        h.P.TogglePause()
        h.P.TogglePause()
        Assert.Equal("1.23457", h.P.CellEditText(CirclesTable, 0, Column(CirclesTable, TableQuantity.Vx)))
        Assert.Equal("", h.P.CellEditText(CirclesTable, 0, 0))
    End Sub
End Class
