Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>The link tool (spring, rod, string), the Links table, and deleting links.</summary>
Public Class LinkToolTests
    <Fact>
    Public Sub Spring_BetweenTwoBalls_RestsAtTheirDistance_WithTheTypedStiffness()
        Dim h As New PresenterHarness()
        Dim a = h.Ball(2, 2)
        Dim b = h.Ball(5, 2)
        h.P.BeginAddLink(LinkKind.Spring, "50")
        Assert.Equal(ClickMode.Link, h.P.Mode)
        h.LeftClick(2, 2)
        Assert.Same(a, h.P.LinkStart)
        h.LeftClick(5, 2)
        Dim l = Assert.Single(h.P.World.Links)
        Assert.Equal(LinkKind.Spring, l.Kind)
        Assert.Same(a, l.A)
        Assert.Same(b, l.B)
        Assert.Equal(50.0, l.Stiffness)
        Assert.Equal(3.0, l.Length, 12)
        Assert.Equal(ClickMode.Move, h.P.Mode)
        Assert.Null(h.P.LinkStart)
        Assert.Contains(h.TraceLines, Function(x) x.StartsWith("linked " & l.Id & " spring " & a.Id & " to " & b.Id & " length 3.000 m", StringComparison.Ordinal))
    End Sub

    <Fact>
    Public Sub Rod_FromABallToAnEmptyPlace_HangsFromAFixedAnchorThere()
        Dim h As New PresenterHarness()
        Dim ball = h.Ball(4, 2)
        h.P.BeginAddLink(LinkKind.Rod)
        h.LeftClick(4, 2)
        h.LeftClick(4, 4.5)
        Dim l = Assert.Single(h.P.World.Links)
        Assert.Equal(LinkKind.Rod, l.Kind)
        Assert.Same(ball, l.A)
        Assert.Null(l.B)
        Assert.Equal(4.0, l.Anchor.X, 6)
        Assert.Equal(4.5, l.Anchor.Y, 6)
        Assert.Equal(2.5, l.Length, 6)
    End Sub

    <Fact>
    Public Sub String_FromAFixedBodyToABall_PutsTheBallAtEndA()
        Dim h As New PresenterHarness()
        Dim peg = Circle.CreateFixed(New Vector(4, 4), 0.1)
        h.P.World.Add(peg)
        Dim ball = h.Ball(5, 3)
        h.P.BeginAddLink(LinkKind.String)
        h.LeftClick(4, 4)
        h.LeftClick(5, 3)
        Dim l = Assert.Single(h.P.World.Links)
        Assert.Same(ball, l.A)
        Assert.Same(peg, l.B)
        Assert.True(l.IsAnchored)
        Assert.Equal(Math.Sqrt(2), l.Length, 9)
    End Sub

    <Fact>
    Public Sub TwoFixedEnds_OrAFixedBodyToAnAnchor_AreRefused_WithAReason()
        Dim h As New PresenterHarness()
        h.P.World.Add(Circle.CreateFixed(New Vector(2, 2), 0.2))
        h.P.World.Add(New Rectangle(New Vector(5, 1), 1, 1))
        h.P.BeginAddLink(LinkKind.Rod)
        h.LeftClick(2, 2)
        h.LeftClick(5.5, 1.5)
        Assert.Empty(h.P.World.Links)
        Assert.Contains("Both bodies are fixed", h.View.LastMessage, StringComparison.Ordinal)
        h.LeftClick(3.5, 4)
        Assert.Empty(h.P.World.Links)
        Assert.Contains("cannot hang from an anchor", h.View.LastMessage, StringComparison.Ordinal)
        h.P.CancelPlacement()
        Assert.Equal(ClickMode.Move, h.P.Mode)
    End Sub

    <Fact>
    Public Sub TheFirstClick_OnEmptySpace_AsksForABody()
        Dim h As New PresenterHarness()
        h.P.BeginAddLink(LinkKind.Spring)
        h.LeftClick(4, 2)
        Assert.Null(h.P.LinkStart)
        Assert.Contains("Click a body to start the spring", h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Theory>
    <InlineData("", "stiffness k (N/m) is empty")>
    <InlineData("0", "stiffness k (N/m) must be greater than 0")>
    <InlineData("soft", "stiffness k (N/m) 'soft' is not a number")>
    Public Sub Spring_BadStiffness_AsksForASuitableValue(k As String, problem As String)
        Dim h As New PresenterHarness()
        h.P.BeginAddLink(LinkKind.Spring, k)
        Assert.Equal(ClickMode.Move, h.P.Mode)
        Assert.StartsWith(InputLimits.SpringMessage, h.View.LastMessage, StringComparison.Ordinal)
        Assert.Contains(problem, h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub Spring_StiffnessBeyondTheBound_IsBroughtToIt()
        Dim h As New PresenterHarness()
        h.P.BeginAddLink(LinkKind.Spring, "1e9")
        Assert.Equal(ClickMode.Link, h.P.Mode)
        Assert.Equal(Units.Input(InputLimits.MaxStiffness), h.P.Inputs.StiffnessText)
        Assert.Contains("stiffness k set to the maximum", h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub TheLinksTable_ShowsEndsLengthExtensionAndHookesTension()
        Dim h As New PresenterHarness(New World(8, 5, 0, 1))
        Dim a = h.Ball(2, 2)
        Dim b = h.Ball(4, 2)
        h.P.TogglePause()
        h.P.BeginAddLink(LinkKind.Spring, "20")
        h.LeftClick(2, 2)
        h.LeftClick(4, 2)
        ' Carry b 0.5 m farther: the spring stretches by 0.5 m and pulls with k x = 20 × 0.5 = 10 N.
        h.Drag(PointerButton.Right, 4, 2, 4.5, 2)
        Assert.Equal(1, h.P.Snapshot.LinkCount)
        Dim row = h.P.Snapshot.LinkRowAt(0)
        Assert.Equal(2.0, row.Length, 9)
        Assert.Equal(0.5, row.Extension, 9)
        Assert.Equal(10.0, row.Tension, 9)
        Dim cells = h.P.Snapshot.LinkCells(0)
        Assert.Equal(LinkTable.Headers.Count, cells.Length)
        Assert.Equal({row.Id, "spring, k " & Units.Quantity(20, "N/m"), a.Id, b.Id, Units.Sig(2.0), Units.Sig(0.5), Units.Sig(10.0)}, cells)
    End Sub

    <Fact>
    Public Sub TheLinksTable_NamesAnAnchorByItsPoint()
        Dim h As New PresenterHarness()
        h.Ball(4, 2)
        h.P.BeginAddLink(LinkKind.String)
        h.LeftClick(4, 2)
        h.LeftClick(4, 4)
        Assert.Equal("anchor " & Units.SigPair(New Vector(4, 4)), h.P.Snapshot.LinkCells(0)(3))
    End Sub

    <Fact>
    Public Sub DeleteMode_RemovesALink_ClickedNearItsLine_AndKeepsItsBodies()
        Dim h As New PresenterHarness()
        h.Ball(2, 2)
        h.Ball(6, 2)
        h.P.BeginAddLink(LinkKind.Rod)
        h.LeftClick(2, 2)
        h.LeftClick(6, 2)
        h.P.ToggleDeleteMode()
        h.LeftClick(4, 2.5)
        Assert.Single(h.P.World.Links)
        h.LeftClick(4, 2.02)
        Assert.Empty(h.P.World.Links)
        Assert.Equal(2, h.P.World.Bodies.Count)
        Assert.Equal(0, h.P.Snapshot.LinkCount)
    End Sub

    <Fact>
    Public Sub DeletingABody_DropsItsLinks_FromTheTable()
        Dim h As New PresenterHarness()
        h.Ball(2, 2)
        h.Ball(6, 2)
        h.P.BeginAddLink(LinkKind.Spring)
        h.LeftClick(2, 2)
        h.LeftClick(6, 2)
        Assert.Equal(1, h.P.Snapshot.LinkCount)
        h.P.ToggleDeleteMode()
        h.LeftClick(6, 2)
        Assert.Empty(h.P.World.Links)
        Assert.Equal(0, h.P.Snapshot.LinkCount)
    End Sub
End Class
