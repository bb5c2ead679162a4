Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>The corner tool: a polygon drawn by clicking its corners, and the convex hull it is made from.</summary>
Public Class CornerToolTests
    ' ---- the convex hull, against brute force ----------------------------------------------------

    ''' <summary>Whether p lies in the closed triangle abc (exact for small whole numbers).</summary>
    Private Shared Function InTriangle(p As Vector, a As Vector, b As Vector, c As Vector) As Boolean
        Dim d1 = Vector.Cross(b - a, p - a), d2 = Vector.Cross(c - b, p - b), d3 = Vector.Cross(a - c, p - c)
        Dim hasNeg = d1 < 0 OrElse d2 < 0 OrElse d3 < 0
        Dim hasPos = d1 > 0 OrElse d2 > 0 OrElse d3 > 0
        If Not (hasNeg AndAlso hasPos) Then
            ' A degenerate triangle (a line) holds only the points on its segment.
            If Vector.Cross(b - a, c - a) <> 0 Then Return True
            Dim lo = New Vector(Math.Min(a.X, Math.Min(b.X, c.X)), Math.Min(a.Y, Math.Min(b.Y, c.Y)))
            Dim hi = New Vector(Math.Max(a.X, Math.Max(b.X, c.X)), Math.Max(a.Y, Math.Max(b.Y, c.Y)))
            Return d1 = 0 AndAlso d2 = 0 AndAlso d3 = 0 AndAlso p.X >= lo.X AndAlso p.X <= hi.X AndAlso p.Y >= lo.Y AndAlso p.Y <= hi.Y
        End If
        Return False
    End Function

    ''' <summary>Brute force: a point is a corner of the hull when it repeats no earlier point and lies in no triangle (or segment) of the others.</summary>
    Private Shared Function ExtremePoints(pts As Vector()) As HashSet(Of Vector)
        Dim result As New HashSet(Of Vector)
        For index = 0 To pts.Length - 1
            Dim i = index
            Dim others = pts.Where(Function(q, j) j <> i).ToArray()
            If others.Contains(pts(i)) Then Continue For ' a repeated point is a corner at most once (see below)
            Dim inside = False
            For a = 0 To others.Length - 1
                For b = a To others.Length - 1
                    For c = b To others.Length - 1
                        If InTriangle(pts(i), others(a), others(b), others(c)) Then inside = True
                    Next
                Next
            Next
            If Not inside Then result.Add(pts(i))
        Next
        ' Repeated points: a repeated point is a corner when, taken once, it lies in no triangle of the rest.
        For Each p In pts.Distinct()
            If pts.Count(Function(q) q = p) < 2 Then Continue For
            Dim rest = pts.Where(Function(q) q <> p).ToArray()
            Dim inside = False
            For a = 0 To rest.Length - 1
                For b = a To rest.Length - 1
                    For c = b To rest.Length - 1
                        If InTriangle(p, rest(a), rest(b), rest(c)) Then inside = True
                    Next
                Next
            Next
            If Not inside Then result.Add(p)
        Next
        Return result
    End Function

    <Fact>
    Public Sub ConvexHull_OnAGrid_KeepsExactlyTheExtremePoints_Anticlockwise()
        ' Whole-number points on a small grid: many repeats and points in a line, all exact.
        Dim rng As New Random(11)
        For trial = 1 To 300
            Dim n = rng.Next(3, 10)
            Dim pts = Enumerable.Range(0, n).Select(Function(i) New Vector(rng.Next(0, 5), rng.Next(0, 5))).ToArray()
            Dim hull = ConvexHull.Corners(pts).Select(Function(i) pts(i)).ToArray()
            Dim expected = ExtremePoints(pts)
            If expected.Count < 3 Then
                Assert.True(hull.Length < 3, $"trial {trial}: points on a line made a hull of {hull.Length}")
                Continue For
            End If
            Assert.Equal(expected.Count, hull.Length)
            Assert.True(expected.SetEquals(hull), $"trial {trial}")
            Assert.True(ConvexHull.SignedArea(hull) > 0, "anticlockwise")
            Assert.True(ConvexHull.IsConvexInOrder(hull))
            ' Every point is inside or on the hull.
            For Each p In pts
                For k = 0 To hull.Length - 1
                    Assert.True(Vector.Cross(hull((k + 1) Mod hull.Length) - hull(k), p - hull(k)) >= 0)
                Next
            Next
            ' The engine takes it as it is.
            Dim shape = Polygon.CreateFixed(hull)
            Assert.Equal(ConvexHull.SignedArea(hull), shape.Area, 9)
        Next
    End Sub

    <Fact>
    Public Sub ConvexHull_OfARegularPolygonsCornersAndPointsInside_IsThePolygon()
        Dim corners = RegularPolygon.Corners(7, 1.3, 10)
        Dim rng As New Random(5)
        Dim inner = Enumerable.Range(0, 20).Select(Function(i) New Vector(rng.NextDouble() - 0.5, rng.NextDouble() - 0.5)).ToArray()
        Dim pts = inner.Concat(corners).ToArray()
        Dim hull = ConvexHull.Corners(pts)
        Assert.Equal(7, hull.Length)
        Assert.True(hull.All(Function(i) i >= inner.Length))
        ' Area of a regular n-gon of circumradius r: ½ n r² sin(2π/n).
        Assert.Equal(0.5 * 7 * 1.3 * 1.3 * Math.Sin(2 * Math.PI / 7), ConvexHull.SignedArea(hull.Select(Function(i) pts(i)).ToArray()), 12)
    End Sub

    <Fact>
    Public Sub LeastWidth_IsTheClosedFormForARectangleAndATriangle()
        Dim rect = {New Vector(0, 0), New Vector(3, 0), New Vector(3, 0.5), New Vector(0, 0.5)}
        Assert.Equal(0.5, ConvexHull.LeastWidth(rect), 12)
        ' An equilateral triangle of side s is s·√3/2 across at its narrowest (a corner to the opposite side).
        Dim tri = RegularPolygon.Corners(3, 1.0, 0)
        Dim side = (tri(1) - tri(0)).Length
        Assert.Equal(side * Math.Sqrt(3) / 2, ConvexHull.LeastWidth(tri), 12)
    End Sub

    <Fact>
    Public Sub IsConvexInOrder_SaysNoToADentACrossingAndAStar()
        Dim square = {New Vector(0, 0), New Vector(1, 0), New Vector(1, 1), New Vector(0, 1)}
        Assert.True(ConvexHull.IsConvexInOrder(square))
        Assert.True(ConvexHull.IsConvexInOrder(square.Reverse().ToArray()))
        Assert.False(ConvexHull.IsConvexInOrder({New Vector(0, 0), New Vector(1, 0), New Vector(0, 1), New Vector(1, 1)}))
        Assert.False(ConvexHull.IsConvexInOrder({New Vector(0, 0), New Vector(2, 0), New Vector(1, 0.5), New Vector(2, 2), New Vector(0, 2)}))
        Dim star = Enumerable.Range(0, 5).Select(Function(i) New Vector(Math.Cos(i * 4 * Math.PI / 5), Math.Sin(i * 4 * Math.PI / 5))).ToArray()
        Assert.False(ConvexHull.IsConvexInOrder(star))
    End Sub

    ' ---- the tool in the presenter ---------------------------------------------------------------

    Private Shared Sub ClickCorners(h As PresenterHarness, ParamArray xy As Double())
        For i = 0 To xy.Length - 1 Step 2
            h.LeftClick(xy(i), xy(i + 1))
        Next
    End Sub

    ''' <summary>The corners as a set of points rounded to a millimetre (a click lands on a pixel).</summary>
    Private Shared Function Rounded(vs As IEnumerable(Of Vector), Optional places As Integer = 6) As HashSet(Of (Double, Double))
        Return New HashSet(Of (Double, Double))(vs.Select(Function(v) (Math.Round(v.X, places), Math.Round(v.Y, places))))
    End Function

    <Fact>
    Public Sub ClickingFourCorners_AndTheFirstAgain_AddsThatPolygon_WithTheTypedMass()
        Dim h As New PresenterHarness()
        h.P.BeginAddCorners("2", False)
        Assert.Equal(ClickMode.Corners, h.P.Mode)
        Assert.Contains("first corner", h.View.LastMessage, StringComparison.Ordinal)
        ClickCorners(h, 2, 1, 5, 1, 5, 3)
        Assert.Equal(3, h.P.CornerDraft.Count)
        Assert.Empty(h.P.World.Polygons)
        Assert.Contains("click the first corner again, double-click, or press Enter", h.View.LastMessage, StringComparison.Ordinal)
        h.LeftClick(2, 3)
        h.LeftClick(2.03, 1.02) ' the first corner again (within a few pixels)
        Dim p = Assert.Single(h.P.World.Polygons)
        Assert.False(p.IsFixed)
        Assert.Equal(2.0, p.Mass)
        Assert.Equal(Rounded({New Vector(2, 1), New Vector(5, 1), New Vector(5, 3), New Vector(2, 3)}), Rounded(p.Vertices))
        ' A 3 m × 2 m rectangle: area 6 m², centre (3.5, 2), density m / A.
        Assert.Equal(6.0, p.Area, 9)
        Assert.Equal(3.5, p.CentreOfMass.X, 9)
        Assert.Equal(2.0, p.CentreOfMass.Y, 9)
        Assert.Equal(2.0 / 6.0, p.Density, 12)
        Assert.Equal(ClickMode.Move, h.P.Mode)
        Assert.Null(h.P.CornerDraft)
        Assert.Equal("", h.View.LastMessage)
        Assert.Contains(h.TraceLines, Function(l) l = "placed polygon " & p.Id & " at (3.500, 2.000) corners (2.000, 1.000) (5.000, 1.000) (5.000, 3.000) (2.000, 3.000)")
        Assert.Null(Placement.FindProblem(h.P.World))
    End Sub

    <Fact>
    Public Sub CornersClockwise_MakeTheSamePolygon_AsAnticlockwise()
        Dim a As New PresenterHarness()
        a.P.BeginAddCorners("1", False)
        ClickCorners(a, 1, 1, 3, 1.5, 2.5, 3.5)
        a.P.FinishCorners()
        Dim b As New PresenterHarness()
        b.P.BeginAddCorners("1", False)
        ClickCorners(b, 2.5, 3.5, 3, 1.5, 1, 1)
        b.P.FinishCorners()
        Dim pa = Assert.Single(a.P.World.Polygons), pb = Assert.Single(b.P.World.Polygons)
        Assert.Equal(Rounded(pa.Vertices, 9), Rounded(pb.Vertices, 9))
        Assert.Equal(pa.Area, pb.Area, 12)
        ' Area of the triangle by the cross product: ½ |(b − a) × (c − a)|.
        Assert.Equal(0.5 * Math.Abs(Vector.Cross(New Vector(2, 0.5), New Vector(1.5, 2.5))), pb.Area, 9)
        ' Either way round is a polygon as clicked: nothing to say.
        Assert.Equal("", a.View.LastMessage)
        Assert.Equal("", b.View.LastMessage)
        Assert.True(ConvexHull.SignedArea(pb.Vertices) > 0, "the engine keeps its corners anticlockwise")
    End Sub

    <Fact>
    Public Sub ClickingTheLastCornerAgain_ADoubleClick_Finishes()
        Dim h As New PresenterHarness()
        h.P.BeginAddCorners("1", False)
        ClickCorners(h, 1, 1, 3, 1, 2, 3)
        h.LeftClick(2, 3) ' the second click of a double click
        Dim p = Assert.Single(h.P.World.Polygons)
        Assert.Equal(3, p.Vertices.Count)
        Assert.Equal(ClickMode.Move, h.P.Mode)
    End Sub

    <Fact>
    Public Sub Escape_AndARightClick_Cancel_WithoutAPolygon()
        Dim h As New PresenterHarness()
        h.P.BeginAddCorners("1", False)
        ClickCorners(h, 1, 1, 3, 1, 2, 3)
        h.P.CancelPlacement()
        Assert.Equal(ClickMode.Move, h.P.Mode)
        Assert.Null(h.P.CornerDraft)
        h.P.FinishCorners()
        Assert.Empty(h.P.World.Polygons)
        h.P.BeginAddCorners("1", False)
        ClickCorners(h, 1, 1, 3, 1, 2, 3)
        Dim s = h.Px(4, 4)
        h.P.PointerDown(PointerButton.Right, s.X, s.Y)
        h.P.PointerUp(PointerButton.Right, s.X, s.Y)
        Assert.Equal(ClickMode.Move, h.P.Mode)
        Assert.Empty(h.P.World.Polygons)
        Assert.Contains("tool cancelled", h.TraceLines)
        ' Clicks after cancelling are the normal mode's again: nothing is added.
        h.LeftClick(1, 1)
        Assert.Empty(h.P.World.Bodies)
    End Sub

    <Fact>
    Public Sub FewerThanThreeCorners_AreNotAPolygon_AndTheToolWaitsForMore()
        Dim h As New PresenterHarness()
        h.P.BeginAddCorners("1", False)
        ClickCorners(h, 1, 1, 3, 1)
        h.P.FinishCorners()
        Assert.Equal("A polygon needs at least 3 corners: you have clicked 2. Click more corners (Esc cancels).", h.View.LastMessage)
        h.LeftClick(1, 1) ' the first corner again, too early
        Assert.StartsWith("A polygon needs at least 3 corners: you have clicked 2.", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Equal(2, h.P.CornerDraft.Count)
        Assert.Equal(ClickMode.Corners, h.P.Mode)
        h.LeftClick(2, 2)
        h.P.FinishCorners()
        Assert.Single(h.P.World.Polygons)
    End Sub

    <Fact>
    Public Sub CornersOnOneLine_EncloseNoArea_AndAreRefused_UntilOneIsOffTheLine()
        Dim h As New PresenterHarness()
        h.P.BeginAddCorners("1", False)
        ClickCorners(h, 1, 1, 2, 2, 3, 3)
        h.P.FinishCorners()
        Assert.Empty(h.P.World.Polygons)
        Assert.Equal("These corners lie on one straight line, so they enclose no area. Click another corner off the line (Esc starts again).", h.View.LastMessage)
        Assert.Equal(ClickMode.Corners, h.P.Mode)
        h.LeftClick(3, 1)
        h.P.FinishCorners()
        Dim p = Assert.Single(h.P.World.Polygons)
        ' (2, 2) lies on the side from (1, 1) to (3, 3): the triangle keeps the three others.
        Assert.Equal(Rounded({New Vector(1, 1), New Vector(3, 1), New Vector(3, 3)}), Rounded(p.Vertices))
        Assert.Contains("corner 2 lies inside it or on a side, and was left out", h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub ASliverThinnerThanTheLeastSide_IsRefused()
        ' Three corners 5 mm off one line: a triangle 4 m long and 5 mm high.
        Dim h As New PresenterHarness()
        h.P.BeginAddCorners("1", False)
        ClickCorners(h, 1, 1, 5, 1, 3, 1.005)
        h.P.FinishCorners()
        Assert.Empty(h.P.World.Polygons)
        Assert.StartsWith("This polygon would be only " & Units.Quantity(0.005, "m") & " across at its thinnest; it must be at least " & Units.Quantity(0.01, "m"), h.View.LastMessage, StringComparison.Ordinal)
        Assert.Equal(ClickMode.Corners, h.P.Mode)
    End Sub

    <Fact>
    Public Sub CornersWithADent_MakeTheirConvexHull_AndTheMessageSaysWhichWasLeftOut()
        Dim h As New PresenterHarness()
        h.P.BeginAddCorners("1", False)
        ' An arrow head: corner 4 is pushed in, inside the outline of the others.
        ClickCorners(h, 1, 1, 4, 1, 4, 4, 3, 2, 1, 4)
        h.P.FinishCorners()
        Dim p = Assert.Single(h.P.World.Polygons)
        Assert.Equal(Rounded({New Vector(1, 1), New Vector(4, 1), New Vector(4, 4), New Vector(1, 4)}), Rounded(p.Vertices))
        Assert.Equal(9.0, p.Area, 9)
        Assert.Equal("The corners you clicked do not make a convex shape, so the polygon is their convex hull (the outline of a rubber band stretched round them): " &
                     "corner 4 lies inside it or on a side, and was left out.", h.View.LastMessage)
        Assert.True(ConvexHull.IsConvexInOrder(p.Vertices))
    End Sub

    <Fact>
    Public Sub CornersClickedAcross_AreJoinedInOrderRound_AndSaySo()
        Dim h As New PresenterHarness()
        h.P.BeginAddCorners("1", False)
        ' A bow tie: the same square's corners, taken across.
        ClickCorners(h, 1, 1, 3, 3, 3, 1, 1, 3)
        h.P.FinishCorners()
        Dim p = Assert.Single(h.P.World.Polygons)
        Assert.Equal(4.0, p.Area, 9)
        Assert.Equal("The sides you clicked crossed, so the corners were joined in order round the outline.", h.View.LastMessage)
    End Sub

    <Fact>
    Public Sub TheFixedBox_MakesAFixedPolygon_ThatNeedsNoMass()
        Dim h As New PresenterHarness()
        h.P.BeginAddCorners("", True)
        Assert.Equal(ClickMode.Corners, h.P.Mode)
        ClickCorners(h, 1, 1, 3, 1, 2, 2.5)
        h.P.FinishCorners()
        Dim p = Assert.Single(h.P.World.Polygons)
        Assert.True(p.IsFixed)
        h.P.Tick(0.1)
        Assert.Equal(2.5, p.Vertices.Max(Function(v) v.Y), 9)
        Assert.Equal(1.0, p.Vertices.Min(Function(v) v.Y), 9)
    End Sub

    <Theory>
    <InlineData("", "mass (kg) is empty")>
    <InlineData("0", "mass (kg) must be greater than 0")>
    <InlineData("heavy", "mass (kg) 'heavy' is not a number")>
    Public Sub ABadMass_AsksForASuitableValue_AndTheToolDoesNotStart(mass As String, problem As String)
        Dim h As New PresenterHarness()
        h.P.BeginAddCorners(mass, False)
        Assert.Equal(ClickMode.Move, h.P.Mode)
        Assert.Null(h.P.CornerDraft)
        Assert.StartsWith(InputLimits.CornersMessage, h.View.LastMessage, StringComparison.Ordinal)
        Assert.Contains(problem, h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub TheToolReadsTheMassBoxAndTheFixedBox()
        Dim h As New PresenterHarness()
        h.P.InputChanged(InputField.Mass, "5000")
        h.P.BeginAddCorners()
        Assert.Equal(InputLimits.MaxMass, h.P.CornerDraft.Mass)
        Assert.Equal("1000", h.P.Inputs.MassText)
        Assert.Contains("mass set to the maximum", h.View.LastMessage, StringComparison.Ordinal)
        h.P.CancelPlacement()
        h.P.FixedChanged(True)
        h.P.BeginAddCorners()
        Assert.True(h.P.CornerDraft.IsFixed)
    End Sub

    <Fact>
    Public Sub ClicksOutsideAWalledContainer_PutTheCornersOnItsWalls()
        Dim h As New PresenterHarness()
        h.P.BeginAddCorners("1", False)
        ' The container is 8 m × 5 m: these corners are past its lower-left corner and its right wall.
        ClickCorners(h, -0.05, -0.05, 8.05, 0.5, 4, 2)
        h.P.FinishCorners()
        Dim p = Assert.Single(h.P.World.Polygons)
        Assert.Equal(0.0, p.BoundsMin.X, 9)
        Assert.Equal(0.0, p.BoundsMin.Y, 9)
        Assert.Equal(8.0, p.BoundsMax.X, 9)
        Assert.Null(Placement.FindProblem(h.P.World))
    End Sub

    <Fact>
    Public Sub APolygonDrawnOverABall_IsMovedClearOfIt_AndSaysSo()
        Dim h As New PresenterHarness()
        Dim ball = h.Ball(4, 1, 0.2, id:="ball")
        h.P.BeginAddCorners("1", False)
        ClickCorners(h, 3, 1, 5, 1.05, 4, 2.5)
        h.P.FinishCorners()
        Dim p = Assert.Single(h.P.World.Polygons)
        Assert.True(Placement.OverlapDepth(p, Vector.Zero, ball) <= Placement.Tolerance)
        Assert.Null(Placement.FindProblem(h.P.World))
        Assert.Matches("^Placed 0\.\d+.m from where you drew it: there it would have overlapped circle ball\.$", h.View.LastMessage)
        ' Moved, not reshaped: the same area as drawn.
        Assert.Equal(0.5 * Math.Abs(Vector.Cross(New Vector(2, 0.05), New Vector(1, 1.5))), p.Area, 9)
    End Sub

    <Fact>
    Public Sub APolygonDrawnInsideAFixedBlock_HasNoRoom_AndTheCornersStartAgain()
        Dim h As New PresenterHarness()
        h.P.World.Add(New Rectangle(New Vector(1, 0), 5, 4.5, "block"))
        h.P.BeginAddCorners("1", False)
        ClickCorners(h, 2, 1, 4, 1, 3, 3)
        h.P.FinishCorners()
        Assert.Empty(h.P.World.Polygons)
        Assert.Equal("There is no room for the polygon there: it would overlap fixed rectangle block. Click its corners again on a free place (Esc cancels).", h.View.LastMessage)
        Assert.Equal(ClickMode.Corners, h.P.Mode)
        Assert.Equal(0, h.P.CornerDraft.Count)
        ' A fixed polygon may stand on a fixed block (fixed bodies never collide).
        h.P.CancelPlacement()
        h.P.BeginAddCorners("", True)
        ClickCorners(h, 2, 1, 4, 1, 3, 3)
        h.P.FinishCorners()
        Assert.Single(h.P.World.Polygons)
    End Sub

    <Fact>
    Public Sub ThePreview_IsTheHullOfTheCornersAndTheCursor_AndTurnsRedOverABody()
        Dim h As New PresenterHarness()
        h.Ball(6, 3, 0.3)
        h.P.BeginAddCorners("1", False)
        ClickCorners(h, 1, 1, 3, 1)
        Dim c = h.Px(2, 2)
        h.P.PointerMove(c.X, c.Y)
        Assert.Equal(3, h.P.CornerPreview.Count)
        Assert.True(h.P.CornerPreviewFits)
        c = h.Px(6, 3)
        h.P.PointerMove(c.X, c.Y)
        Assert.False(h.P.CornerPreviewFits)
    End Sub

    <Fact>
    Public Sub AnotherAddButton_EndsTheCornerTool_AndAddWhileABodyWaits_IsRefused()
        Dim h As New PresenterHarness()
        h.P.BeginAddCircle("0.2", "1", False)
        h.P.BeginAddCorners("1", False)
        Assert.Equal(InputLimits.SpawnFirstMessage, h.View.LastMessage)
        Assert.Equal(ClickMode.Move, h.P.Mode)
        h.P.CancelPlacement()
        h.P.BeginAddCorners("1", False)
        ClickCorners(h, 1, 1, 3, 1)
        h.P.BeginAddRamp()
        Assert.Equal(ClickMode.Ramp, h.P.Mode)
        Assert.Null(h.P.CornerDraft)
    End Sub

    <Fact>
    Public Sub APolygonDrawnByCorners_SavesAndOpensAgain()
        Dim path = IO.Path.Combine(IO.Path.GetTempPath(), "app-corners-" & Guid.NewGuid().ToString("N") & ".json")
        Try
            Dim h As New PresenterHarness(store:=New SceneFileStore())
            h.P.BeginAddCorners("3", False)
            ClickCorners(h, 1, 1, 4, 1.5, 3.5, 3, 1.5, 2.5)
            h.P.FinishCorners()
            Dim drawn = Assert.Single(h.P.World.Polygons)
            h.P.SaveScene(path)
            Assert.True(IO.File.Exists(path), h.View.LastMessage)
            Dim other As New PresenterHarness(store:=New SceneFileStore())
            other.P.OpenScene(path)
            Dim opened = Assert.Single(other.P.World.Polygons)
            Assert.Equal(drawn.Id, opened.Id)
            Assert.Equal(drawn.Color, opened.Color)
            Assert.Equal(3.0, opened.Mass)
            Assert.False(opened.IsFixed)
            Assert.Equal(drawn.Vertices.Count, opened.Vertices.Count)
            For i = 0 To drawn.Vertices.Count - 1
                Assert.Equal(drawn.Vertices(i).X, opened.Vertices(i).X, 12)
                Assert.Equal(drawn.Vertices(i).Y, opened.Vertices(i).Y, 12)
            Next
        Finally
            IO.File.Delete(path)
        End Try
    End Sub

    ''' <summary>Every movable body's id, position (m) and velocity (m/s).</summary>
    Private Shared Function State(w As World) As List(Of (Id As String, Values As Double()))
        Return w.Movables.Select(Function(b) (b.Id, New Double() {b.Position.X, b.Position.Y, b.Velocity.X, b.Velocity.Y})).ToList()
    End Function

    ''' <summary>
    ''' The same bodies in the same states. To 1e-12 rather than to the last bit: after a body is added
    ''' while time runs (by any Add tool), a replay gives a falling ball's height differently in the last bit.
    ''' </summary>
    Private Shared Sub SameState(expected As List(Of (Id As String, Values As Double())), actual As List(Of (Id As String, Values As Double())))
        Assert.Equal(expected.Select(Function(e) e.Id), actual.Select(Function(a) a.Id))
        For i = 0 To expected.Count - 1
            For k = 0 To 3
                Assert.Equal(expected(i).Values(k), actual(i).Values(k), 12)
            Next
        Next
    End Sub

    <Fact>
    Public Sub APolygonDrawnByCorners_IsPartOfTheRecordedRun_GoingBackAndForth()
        Dim h As New PresenterHarness()
        h.Ball(6, 1, 0.3, id:="ball")
        For k = 1 To 10
            h.P.Tick(1 / 60.0)
        Next
        Dim before = h.P.World.Time
        h.P.BeginAddCorners("2", False)
        ClickCorners(h, 1, 3, 2, 3, 1.5, 4)
        h.P.FinishCorners()
        Dim id = Assert.Single(h.P.World.Polygons).Id
        Dim states As New List(Of (Time As Double, State As List(Of (Id As String, Values As Double()))))
        For k = 1 To 40
            h.P.Tick(1 / 60.0)
            states.Add((h.P.World.Time, State(h.P.World)))
        Next
        ' The polygon falls: going back to a moment after it was drawn finds it exactly where it was.
        h.P.RewindTo(states(19).Time)
        SameState(states(19).State, State(h.P.World))
        Assert.Equal(id, Assert.Single(h.P.World.Polygons).Id)
        ' Before it was drawn, it is not there; forward again, it is back.
        h.P.RewindTo(before / 2)
        Assert.Empty(h.P.World.Polygons)
        h.P.RewindTo(states(39).Time)
        SameState(states(39).State, State(h.P.World))
    End Sub
End Class
