Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>Objective 3: adding (with the input checks) and deleting.</summary>
Public Class AddAndDeleteTests
    <Fact>
    Public Sub AddCircle_FollowsTheCursor_AndIsPlacedWhereClicked()
        Dim h As New PresenterHarness()
        h.P.BeginAddCircle("0.3", "2", False)
        Assert.NotNull(h.P.Draft)
        Dim s = h.Px(3, 2)
        h.P.PointerMove(s.X, s.Y)
        Assert.Equal(3.0, h.P.Draft.Centre.X, 6)
        Assert.Equal(2.0, h.P.Draft.Centre.Y, 6)
        s = h.Px(5, 3)
        h.P.PointerMove(s.X, s.Y)
        h.P.PointerDown(PointerButton.Left, s.X, s.Y)
        Assert.Null(h.P.Draft)
        Dim c = Assert.Single(h.P.World.Circles)
        Assert.Equal(5.0, c.Position.X, 6)
        Assert.Equal(3.0, c.Position.Y, 6)
        Assert.Equal(0.3, c.Radius)
        Assert.Equal(2.0, c.Mass)
        Assert.False(c.IsFixed)
        Assert.Contains(h.TraceLines, Function(l) l.StartsWith("placed circle " & c.Id & " at (5.000, 3.000)", StringComparison.Ordinal))
        Assert.True(h.View.BodiesShown > 0)
    End Sub

    <Fact>
    Public Sub AddFixedCircle_IgnoresMass_AndNeverMoves()
        Dim h As New PresenterHarness()
        h.P.BeginAddCircle("0.4", "", True)
        h.LeftClick(4, 4)
        Dim c = Assert.Single(h.P.World.Circles)
        Assert.True(c.IsFixed)
        h.P.Tick(0.1)
        Assert.Equal(4.0, c.Position.Y, 6)
    End Sub

    <Fact>
    Public Sub AddRectangle_IsFixed_AndCentredOnTheClick()
        Dim h As New PresenterHarness()
        h.P.BeginAddRectangle("2", "1")
        h.LeftClick(4, 1)
        Dim r = Assert.Single(h.P.World.Rectangles)
        Assert.Equal(3.0, r.Position.X, 6)
        Assert.Equal(0.5, r.Position.Y, 6)
        Assert.Equal(2.0, r.Width)
        Assert.True(r.IsFixed)
    End Sub

    <Theory>
    <InlineData("", "1")>
    <InlineData("0", "1")>
    <InlineData("0.2", "0")>
    <InlineData("0.2", "")>
    <InlineData("-1", "1")>
    <InlineData("abc", "1")>
    <InlineData("NaN", "1")>
    Public Sub AddCircle_EmptyZeroOrBadValues_AskForSuitableValues(radius As String, mass As String)
        Dim h As New PresenterHarness()
        h.P.BeginAddCircle(radius, mass, False)
        Assert.Null(h.P.Draft)
        Assert.StartsWith("Please enter a suitable value for the mass and radius!", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Contains(h.TraceLines, Function(l) l.StartsWith("message: Please enter a suitable value", StringComparison.Ordinal))
    End Sub

    <Fact>
    Public Sub AddCircle_Message_NamesTheField()
        Dim h As New PresenterHarness()
        h.P.BeginAddCircle("abc", "1", False)
        Assert.Contains("radius (m) 'abc' is not a number", h.View.LastMessage, StringComparison.Ordinal)
        h.P.BeginAddCircle("0.2", "0", False)
        Assert.Contains("mass (kg) must be greater than 0", h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Theory>
    <InlineData("", "1")>
    <InlineData("1", "0")>
    <InlineData("x", "1")>
    Public Sub AddRectangle_EmptyOrZero_AsksForSuitableValues(width As String, height As String)
        Dim h As New PresenterHarness()
        h.P.BeginAddRectangle(width, height)
        Assert.Null(h.P.Draft)
        Assert.StartsWith("Please enter a suitable value for the width and height!", h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub AddCircle_OverTheBounds_IsClampedToThem()
        Dim h As New PresenterHarness()
        h.P.BeginAddCircle("5", "5000", False)
        Assert.Equal(InputLimits.MaxRadius, h.P.Draft.Radius)
        Assert.Equal(InputLimits.MaxMass, h.P.Draft.Mass)
        Assert.Equal("2", h.P.Inputs.RadiusText)
        Assert.Equal("1000", h.P.Inputs.MassText)
        Assert.Contains("radius set to the maximum, 2.00 m", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Contains("mass set to the maximum, 1000 kg", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Equal(1, h.View.InputsShown)
    End Sub

    <Fact>
    Public Sub AddCircle_AtTheBounds_IsKeptAsIs()
        Dim h As New PresenterHarness()
        h.P.BeginAddCircle("2", "1000", False)
        Assert.Equal(2.0, h.P.Draft.Radius)
        Assert.Equal(1000.0, h.P.Draft.Mass)
        Assert.DoesNotContain("maximum", h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub AddRectangle_OverTheBounds_IsClamped()
        Dim h As New PresenterHarness()
        h.P.BeginAddRectangle("50", "20")
        Assert.Equal(InputLimits.MaxSide, h.P.Draft.Width)
        Assert.Equal(20.0, h.P.Draft.Height)
    End Sub

    <Fact>
    Public Sub Add_WhilePlacing_AsksToSpawnFirst()
        Dim h As New PresenterHarness()
        h.P.BeginAddCircle("0.2", "1", False)
        Dim first = h.P.Draft
        h.P.BeginAddRectangle("1", "1")
        Assert.Equal("Please spawn your current object first!", h.View.LastMessage)
        h.P.BeginAddCircle("0.3", "1", False)
        Assert.Equal("Please spawn your current object first!", h.View.LastMessage)
        Assert.Same(first, h.P.Draft)
    End Sub

    <Fact>
    Public Sub CancelPlacement_DropsTheDraft()
        Dim h As New PresenterHarness()
        h.P.BeginAddCircle("0.2", "1", False)
        h.P.CancelPlacement()
        Assert.Null(h.P.Draft)
        h.LeftClick(3, 3)
        Assert.Empty(h.P.World.Bodies)
    End Sub

    <Fact>
    Public Sub Input_AcceptsTheInvariantDecimalPoint()
        Dim v As Double
        Assert.True(NumberInput.TryParse("0.25", v))
        Assert.Equal(0.25, v)
        Assert.False(NumberInput.ReadPositive("  ", "radius (m)", 2).IsValid)
    End Sub

    <Fact>
    Public Sub NewBodies_GetColoursThatShow()
        Dim h As New PresenterHarness()
        h.P.BeginAddCircle("0.2", "1", False)
        h.LeftClick(2, 2)
        h.P.BeginAddRectangle("1", "1")
        h.LeftClick(5, 2)
        For Each b In h.P.World.Bodies
            Assert.True(BodyColours.ShowsOnBothCanvases(BodyColours.Parse(b.Color, -1)), b.Color)
        Next
        Assert.NotEqual(h.P.World.Bodies(0).Color, h.P.World.Bodies(1).Color)
    End Sub

    <Fact>
    Public Sub DeleteMode_RemovesCirclesAndRectangles_AndOnlyWhereClicked()
        Dim h As New PresenterHarness()
        Dim ball = h.Ball(2, 2)
        h.P.World.Add(New Rectangle(New Vector(5, 0), 2, 1))
        h.LeftClick(2, 2) ' normal mode: aims, does not delete
        Assert.Equal(2, h.P.World.Bodies.Count)
        h.P.ToggleDeleteMode()
        Assert.Equal(ClickMode.Delete, h.P.Mode)
        h.LeftClick(4, 4) ' empty space
        Assert.Equal(2, h.P.World.Bodies.Count)
        h.LeftClick(2, 2)
        Assert.DoesNotContain(ball, h.P.World.Circles)
        h.LeftClick(6, 0.5)
        Assert.Empty(h.P.World.Bodies)
        Assert.Contains("deleted " & ball.Id, h.TraceLines)
        h.P.ToggleDeleteMode()
        Assert.Equal(ClickMode.Move, h.P.Mode)
    End Sub

    <Fact>
    Public Sub DeleteMode_WorksWhilePaused()
        Dim h As New PresenterHarness()
        h.Ball(2, 2)
        h.P.TogglePause()
        h.P.ToggleDeleteMode()
        h.LeftClick(2, 2)
        Assert.Empty(h.P.World.Bodies)
    End Sub

    <Fact>
    Public Sub RightClick_OnEmptySpace_DoesNothing()
        Dim h As New PresenterHarness()
        Dim ball = h.Ball(2, 2)
        h.Drag(PointerButton.Right, 6, 4, 7, 4)
        Assert.Null(h.P.DraggedBody)
        Assert.Equal(2.0, ball.Position.X, 9)
    End Sub
End Class

''' <summary>Sizes at the edges: small values read back as typed, too-large balls and too-small containers refused with a message.</summary>
Public Class SizeEdgeTests
    <Fact>
    Public Sub ASmallAcceptedRadius_IsShownBackAsTyped_NotAsZero()
        Dim h As New PresenterHarness()
        h.P.BeginAddCircle("0.0125", "0.0125", False)
        Assert.NotNull(h.P.Draft)
        Assert.Equal("0.0125", h.P.Inputs.RadiusText)
        Assert.Equal("0.0125", h.P.Inputs.MassText)
        Assert.Equal(0, h.View.InputsShown)
    End Sub

    <Fact>
    Public Sub ABallWiderThanTheContainer_IsNotPlaced_AndTheTeacherIsTold()
        Dim h As New PresenterHarness()
        h.P.ResizeContainer("3", "3")
        h.P.BeginAddCircle("2", "1", False)
        Dim before = h.P.World.Circles.Count
        h.LeftClick(1.5, 1.5)
        Assert.Equal(before, h.P.World.Circles.Count)
        Assert.Contains("does not fit in the container", h.View.LastMessage)
        For i = 1 To 20
            h.P.Tick(0.05)
        Next
        For Each c In h.P.World.Circles
            If Not c.IsFixed Then Assert.InRange(c.Position.Y, c.Radius - 1.0E-9, h.P.World.Height - c.Radius + 1.0E-9)
        Next
    End Sub

    <Fact>
    Public Sub AContainerSmallerThanTheLargestBall_IsRefused_AndKeepsItsSize()
        Dim h As New PresenterHarness()
        h.P.BeginAddCircle("1", "1", False)
        h.LeftClick(2, 2)
        h.P.ResizeContainer("1.5", "1.5")
        Assert.Equal(8.0, h.P.World.Width)
        Assert.Contains("the widest ball is 2.00 m across and would not fit", h.View.LastMessage.Replace(Units.Nbsp, " "c), StringComparison.Ordinal)
    End Sub
End Class
