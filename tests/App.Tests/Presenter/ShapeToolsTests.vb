Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>The polygon, box and ramp tools, the Bodies table, and the cue and carry on every movable kind.</summary>
Public Class ShapeToolsTests
    Private Shared ReadOnly FixedAndMovableKinds As String() = {"fixed quadrilateral", "quadrilateral", "fixed ball"}
    Private Shared ReadOnly EveryKind As String() = {"ball", "fixed ball", "fixed box", "box", "fixed ramp", "pentagon", "fixed triangle"}

    <Theory>
    <InlineData(3, 0.5, 0.0)>
    <InlineData(5, 0.3, 17.0)>
    <InlineData(12, 1.2, -40.0)>
    Public Sub RegularPolygon_HasTheClosedFormArea_AndEveryCornerAtTheSize(sides As Integer, size As Double, angle As Double)
        Dim corners = RegularPolygon.Corners(sides, size, angle)
        Assert.Equal(sides, corners.Length)
        For Each c In corners
            Assert.Equal(size, c.Length, 12)
        Next
        ' The first corner is turned the angle anticlockwise from straight up.
        Dim first = Math.Atan2(corners(0).Y, corners(0).X) * 180 / Math.PI
        Assert.Equal(0.0, Math.IEEERemainder(first - 90 - angle, 360), 9)
        ' Area of a regular n-gon with circumradius r: ½ n r² sin(2π/n).
        Dim expected = 0.5 * sides * size * size * Math.Sin(2 * Math.PI / sides)
        Dim shape = Polygon.CreateFixed(corners)
        Assert.Equal(expected, shape.Area, 12)
    End Sub

    <Fact>
    Public Sub AddPolygon_IsPlacedWhereClicked_WithTheTypedSidesSizeAngleAndMass()
        Dim h As New PresenterHarness()
        h.P.BeginAddPolygon("6", "0.5", "30", "2", False)
        Assert.Equal("polygon", h.P.Draft.KindName)
        h.LeftClick(4, 2.5)
        Dim p = Assert.Single(h.P.World.Polygons)
        Assert.False(p.IsFixed)
        Assert.Equal(2.0, p.Mass)
        Assert.Equal(6, p.Vertices.Count)
        Assert.Equal(4.0, p.CentreOfMass.X, 9)
        Assert.Equal(2.5, p.CentreOfMass.Y, 9)
        Assert.Equal(0.5 * 6 * 0.25 * Math.Sin(Math.PI / 3), p.Area, 9)
        Assert.Contains(h.TraceLines, Function(l) l.StartsWith("placed polygon " & p.Id & " at (4.000, 2.500)", StringComparison.Ordinal))
    End Sub

    <Fact>
    Public Sub AddFixedPolygon_NeverMoves()
        Dim h As New PresenterHarness()
        h.P.BeginAddPolygon("3", "0.4", "0", "", True)
        h.LeftClick(4, 3)
        Dim p = Assert.Single(h.P.World.Polygons)
        Assert.True(p.IsFixed)
        h.P.Tick(0.1)
        Assert.Equal(3.0, p.CentreOfMass.Y, 9)
    End Sub

    <Theory>
    <InlineData("", "0.4", "0", "1", "sides is empty")>
    <InlineData("4.5", "0.4", "0", "1", "sides must be a whole number")>
    <InlineData("five", "0.4", "0", "1", "sides 'five' is not a number")>
    <InlineData("5", "0", "0", "1", "radius (m) must be greater than 0")>
    <InlineData("5", "0.4", "abc", "1", "angle (°) 'abc' is not a number")>
    <InlineData("5", "0.4", "0", "", "mass (kg) is empty")>
    Public Sub AddPolygon_BadValues_AskForSuitableValues_NamingTheField(sides As String, size As String, angle As String, mass As String, problem As String)
        Dim h As New PresenterHarness()
        h.P.BeginAddPolygon(sides, size, angle, mass, False)
        Assert.Null(h.P.Draft)
        Assert.StartsWith(InputLimits.PolygonMessage, h.View.LastMessage, StringComparison.Ordinal)
        Assert.Contains(problem, h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub AddPolygon_BeyondTheBounds_IsBroughtToThem_AndSaysSo()
        Dim h As New PresenterHarness()
        h.P.BeginAddPolygon("40", "5", "-720", "1", False)
        Assert.NotNull(h.P.Draft)
        Assert.Equal(CStr(InputLimits.MaxSides), h.P.Inputs.SidesText)
        Assert.Equal("2", h.P.Inputs.RadiusText)
        Assert.Equal("-360", h.P.Inputs.PolygonAngleText)
        Assert.Contains("sides set to the maximum, 12,", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Contains("radius set to the maximum, 2.00 m", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Equal(1, h.View.InputsShown)
        ' A negative angle is a turn the other way, not a mistake.
        Dim h2 As New PresenterHarness()
        h2.P.BeginAddPolygon("4", "0.3", "-45", "1", False)
        Assert.NotNull(h2.P.Draft)
        Assert.Equal("-45", h2.P.Inputs.PolygonAngleText)
    End Sub

    <Fact>
    Public Sub AddBox_WithFixedCleared_IsMovable_WithTheTypedMass_AndFalls()
        Dim h As New PresenterHarness()
        h.P.BeginAddRectangle("1", "0.5", False, "3")
        Assert.Equal("box", h.P.Draft.KindName)
        h.LeftClick(4, 3)
        Dim r = Assert.Single(h.P.World.Rectangles)
        Assert.False(r.IsFixed)
        Assert.Equal(3.0, r.Mass)
        Assert.Equal(3.5, r.Position.X, 9)
        Assert.Equal(2.75, r.Position.Y, 9)
        h.P.Tick(0.1)
        ' Free fall from rest for 0.1 s: y drops by ½ g t².
        Assert.Equal(2.75 - 0.5 * 9.81 * 0.01, r.Position.Y, 6)
    End Sub

    <Fact>
    Public Sub AddBox_WithoutAMass_AsksForOne_AndTheFixedRectangleNeedsNone()
        Dim h As New PresenterHarness()
        h.P.BeginAddRectangle("1", "0.5", False, "")
        Assert.Null(h.P.Draft)
        Assert.StartsWith(InputLimits.BoxMessage, h.View.LastMessage, StringComparison.Ordinal)
        Assert.Contains("mass (kg) is empty", h.View.LastMessage, StringComparison.Ordinal)
        h.P.BeginAddRectangle("1", "0.5", True, "")
        Assert.NotNull(h.P.Draft)
        Assert.True(h.P.Draft.IsFixed)
    End Sub

    <Fact>
    Public Sub TheRectangleTool_ReadsItsFixedBox()
        Dim h As New PresenterHarness()
        Assert.True(h.P.Inputs.RectangleFixed)
        h.P.RectangleFixedChanged(False)
        h.P.InputChanged(InputField.Mass, "4")
        h.P.BeginAddRectangle()
        Assert.False(h.P.Draft.IsFixed)
        Assert.Equal(4.0, h.P.Draft.Mass)
    End Sub

    <Fact>
    Public Sub NewPolygonsAndBoxes_KeepOutOfOtherBodies()
        Dim h As New PresenterHarness()
        Dim ball = h.Ball(4, 2.5, 0.4)
        h.P.BeginAddPolygon("5", "0.5", "0", "1", False)
        h.LeftClick(4.2, 2.5)
        Dim p = Assert.Single(h.P.World.Polygons)
        Assert.True(Placement.OverlapDepth(p, Vector.Zero, ball) <= Placement.Tolerance)
        Assert.Contains("nearest free place", h.View.LastMessage, StringComparison.Ordinal)
        h.P.BeginAddRectangle("1", "1", False, "1")
        h.LeftClick(4, 2.5)
        Dim box = h.P.World.Rectangles.Single()
        Assert.True(Placement.IsFree(h.P.World, box, Vector.Zero))
        Assert.Null(Placement.FindProblem(h.P.World))
    End Sub

    <Fact>
    Public Sub AddRamp_ByDragging_RunsFromThePressToTheRelease()
        Dim h As New PresenterHarness()
        h.P.BeginAddRamp()
        Assert.Equal(ClickMode.Ramp, h.P.Mode)
        h.Drag(PointerButton.Left, 1, 1, 5, 3)
        Dim s = Assert.Single(h.P.World.Segments)
        Assert.Equal(1.0, s.StartPoint.X, 6)
        Assert.Equal(1.0, s.StartPoint.Y, 6)
        Assert.Equal(5.0, s.EndPoint.X, 6)
        Assert.Equal(3.0, s.EndPoint.Y, 6)
        Assert.Equal(ClickMode.Move, h.P.Mode)
        Assert.Contains(h.TraceLines, Function(l) l.StartsWith("placed ramp " & s.Id & " from (1.000, 1.000) to (5.000, 3.000)", StringComparison.Ordinal))
    End Sub

    <Fact>
    Public Sub AddRamp_ATinyDrag_MakesNoRamp_AndSaysWhy()
        Dim h As New PresenterHarness()
        h.P.BeginAddRamp()
        h.Drag(PointerButton.Left, 2, 2, 2.01, 2)
        Assert.Empty(h.P.World.Segments)
        Assert.Contains("too short", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Equal(ClickMode.Ramp, h.P.Mode)
    End Sub

    <Fact>
    Public Sub AddRamp_ThroughABall_IsMovedClearOfIt()
        Dim h As New PresenterHarness()
        h.Ball(3, 2, 0.2)
        h.P.BeginAddRamp()
        h.Drag(PointerButton.Left, 1, 2, 5, 2)
        Dim s = Assert.Single(h.P.World.Segments)
        Assert.True(Placement.IsFree(h.P.World, s, Vector.Zero))
        Assert.Null(Placement.FindProblem(h.P.World))
        Assert.Contains("would have crossed", h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub Escape_CancelsTheRampTool()
        Dim h As New PresenterHarness()
        h.P.BeginAddRamp()
        h.P.CancelPlacement()
        Assert.Equal(ClickMode.Move, h.P.Mode)
        h.Drag(PointerButton.Left, 1, 1, 5, 3)
        Assert.Empty(h.P.World.Segments)
    End Sub

    <Fact>
    Public Sub TheBodiesTable_ListsEveryBody_WithItsKind()
        Dim h As New PresenterHarness()
        h.Ball(1, 1)
        h.P.World.Add(Circle.CreateFixed(New Vector(2, 4), 0.2))
        h.P.World.Add(New Rectangle(New Vector(3, 0), 1, 0.5))
        h.P.World.Add(Rectangle.CreateMovable(New Vector(5, 1), 1, 0.5, 2))
        h.P.World.Add(New Segment(New Vector(0.5, 3), New Vector(2.5, 2)))
        h.P.World.Add(New Polygon(RegularPolygon.Corners(5, 0.3, 0).Select(Function(v) v + New Vector(6.5, 3.5)).ToArray(), 1))
        h.P.World.Add(Polygon.CreateFixed(RegularPolygon.Corners(3, 0.3, 0).Select(Function(v) v + New Vector(7.5, 4.5)).ToArray()))
        h.P.TogglePause()
        Dim t = SimulationPresenter.Tables.ToList().IndexOf(BodyTable.Bodies)
        Assert.True(t >= 0)
        Assert.Equal(h.P.World.Bodies.Count, h.P.Snapshot.RowCount(t))
        Dim kind = BodyTable.Bodies.Headers.ToList().IndexOf("Kind")
        Dim kinds = Enumerable.Range(0, h.P.Snapshot.RowCount(t)).Select(Function(i) h.P.Snapshot.Cells(t, i)(kind)).ToList()
        Assert.Equal(EveryKind, kinds)
        ' A ramp's centre is its middle.
        Dim ramp = h.P.Snapshot.Cells(t, 4)
        Assert.Equal(Units.Sig(1.5), ramp(3))
        Assert.Equal(Units.Sig(2.5), ramp(4))
        Assert.Equal("length " & Units.Sig(Math.Sqrt(5)), ramp(9))
    End Sub

    <Fact>
    Public Sub TheBodiesTable_NamesAFixedPolygon_FixedAsItDoesAFixedBall()
        Dim h As New PresenterHarness()
        Dim kite = {New Vector(4, 3.4), New Vector(3.6, 3), New Vector(4, 2.4), New Vector(4.4, 3)}
        h.P.World.Add(Polygon.CreateFixed(kite))
        h.P.World.Add(New Polygon(kite.Select(Function(v) v + New Vector(2, 0)).ToArray(), 1.5))
        h.P.World.Add(Circle.CreateFixed(New Vector(1, 4), 0.2))
        h.P.TogglePause()
        Dim t = SimulationPresenter.Tables.ToList().IndexOf(BodyTable.Bodies)
        Dim kind = BodyTable.Bodies.Headers.ToList().IndexOf("Kind")
        Dim kinds = Enumerable.Range(0, h.P.Snapshot.RowCount(t)).Select(Function(i) h.P.Snapshot.Cells(t, i)(kind)).ToList()
        Assert.Equal(FixedAndMovableKinds, kinds)
    End Sub

    <Fact>
    Public Sub Cue_OnAPolygon_GivesDeltaVOfJOverM_FromItsCentre()
        Dim h As New PresenterHarness(New World(8, 5, 0, 1))
        Dim p As New Polygon(RegularPolygon.Corners(6, 0.4, 0).Select(Function(v) v + New Vector(4, 2.5)).ToArray(), 2)
        h.P.World.Add(p)
        h.P.TogglePause()
        ' Pull back 0.3 m to the left of the centre: J = 4 N·s/m × 0.3 m = 1.2 N·s to the right, Δv = 0.6 m/s.
        h.Drag(PointerButton.Left, 4, 2.5, 3.7, 2.5)
        Assert.Equal(0.6, p.Velocity.X, 6)
        Assert.Equal(0.0, p.Velocity.Y, 6)
    End Sub

    <Fact>
    Public Sub RightDrag_CarriesABox_AndAFixedPolygon()
        Dim h As New PresenterHarness()
        Dim box = Rectangle.CreateMovable(New Vector(1.5, 1.5), 1, 1, 2)
        h.P.World.Add(box)
        Dim fixedPoly = Polygon.CreateFixed(RegularPolygon.Corners(4, 0.4, 45).Select(Function(v) v + New Vector(6, 3)).ToArray())
        h.P.World.Add(fixedPoly)
        h.P.TogglePause()
        h.Drag(PointerButton.Right, 2, 2, 4, 3)
        Assert.Equal(4.0, box.CentreOfMass.X, 6)
        Assert.Equal(3.0, box.CentreOfMass.Y, 6)
        Dim id = fixedPoly.Id
        h.Drag(PointerButton.Right, 6, 3, 6.5, 1.5)
        Dim moved = DirectCast(h.P.World.Find(id), Polygon)
        Assert.True(moved.IsFixed)
        Assert.Equal(6.5, moved.CentreOfMass.X, 6)
        Assert.Equal(1.5, moved.CentreOfMass.Y, 6)
    End Sub

    <Fact>
    Public Sub DeleteMode_RemovesARamp_ClickedNearItsLine()
        Dim h As New PresenterHarness()
        h.P.World.Add(New Segment(New Vector(1, 1), New Vector(5, 3)))
        h.P.ToggleDeleteMode()
        h.LeftClick(3, 3)
        Assert.Single(h.P.World.Segments)
        h.LeftClick(3, 2)
        Assert.Empty(h.P.World.Segments)
    End Sub
End Class
