Option Strict On
Imports System.Globalization
Imports System.Text.RegularExpressions
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>
''' Messages that are true when shown and go when they are not; numbers at rounding noise shown as 0;
''' the decimal separator of any class; the colour a table gives a fixed body; what a save to a
''' folder that is not there says; collision times with enough figures to tell two apart.
''' </summary>
Public Class MessagesAndTablesTests
    ''' <summary>Runs <paramref name="body"/> with <paramref name="culture"/> as the machine's culture.</summary>
    Private Shared Sub InCulture(culture As String, body As Action)
        Dim was = CultureInfo.CurrentCulture
        CultureInfo.CurrentCulture = New CultureInfo(culture)
        Try
            body()
        Finally
            CultureInfo.CurrentCulture = was
        End Try
    End Sub

    <Theory>
    <InlineData("en-US")>
    <InlineData("de-DE")>
    <InlineData("fr-FR")>
    Public Sub ADecimalCommaAndADecimalPoint_AreBothRead_OnAnyMachine(culture As String)
        InCulture(culture,
            Sub()
                Assert.Equal(0.25, NumberInput.ReadPositive("0,25", "radius (m)", 2).Value)
                Assert.Equal(0.25, NumberInput.ReadPositive("0.25", "radius (m)", 2).Value)
                Assert.Equal(-1.5, NumberInput.ReadFinite("-1,5", "vx (m/s)", 10).Value)
                Dim h As New PresenterHarness()
                h.P.BeginAddCircle("0,3", "1,5", False)
                Assert.NotNull(h.P.Draft)
                Assert.Equal(0.3, h.P.Draft.Width / 2, 12)
                Assert.Equal(1.5, h.P.Draft.Mass)
            End Sub)
    End Sub

    <Fact>
    Public Sub WhereThePointIsTheSeparator_ACommaBeforeThreeDigits_IsRefusedWithAHint_NotReadAsOne()
        InCulture("en-US",
            Sub()
                Dim read = NumberInput.ReadPositive("1,000", "mass (kg)", 1000)
                Assert.False(read.IsValid)
                Assert.Contains("'1,000' is not a number (write a decimal as 0.25 or 0,25", read.Problem, StringComparison.Ordinal)
                Assert.False(NumberInput.ReadPositive("1,2,3", "mass (kg)", 1000).IsValid)
            End Sub)
        ' Where the comma is the machine's own separator, it is the decimal it means there.
        InCulture("de-DE", Sub() Assert.Equal(1.0, NumberInput.ReadPositive("1,000", "mass (kg)", 1000).Value))
    End Sub

    <Fact>
    Public Sub ALinksExtensionAndPull_AtRoundingNoise_AreShownAs0_AndARealStretchIsNot()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim a = h.Ball(1.1, 2.2)
        Dim b = h.Ball(3.3, 2.7)
        Dim d = (b.Position - a.Position).Length
        ' A rod whose length differs from the distance by the last bit of a double.
        h.P.World.Add(Link.CreateTie(LinkKind.Rod, a, b, d * (1 + 2.0E-16)))
        Dim c = h.Ball(5.0, 1.0)
        Dim e = h.Ball(6.0, 1.0)
        h.P.World.Add(Link.CreateSpring(c, e, 100.0, 0.99))
        h.P.TogglePause()
        Assert.NotEqual(0.0, h.P.World.Links(0).Extension)
        Assert.Equal("0", h.P.Snapshot.LinkCells(0)(5))
        Assert.Equal("0", h.P.Snapshot.LinkCells(0)(6))
        ' The spring is stretched 1 cm: that is no noise.
        Assert.Equal("0.0100", h.P.Snapshot.LinkCells(1)(5))
        Assert.Equal("1.00", h.P.Snapshot.LinkCells(1)(6))
    End Sub

    <Fact>
    Public Sub VelocitiesAndTotalMomentum_AtRoundingNoise_AreShownAs0()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        ' 0.1 + 0.2 is 0.30000000000000004: the two momenta cancel but for the last bit.
        h.P.World.Add(New Circle(New Vector(2, 2), 0.2, 1.0, New Vector(0.1 + 0.2, 1.0E-17)))
        h.P.World.Add(New Circle(New Vector(6, 2), 0.2, 1.0, New Vector(-0.3, -1.0E-17)))
        h.P.TogglePause()
        Assert.NotEqual(0.0, h.P.World.Momentum().X)
        Assert.Equal("0", h.P.Snapshot.Cells(0, 0)(5))
        Assert.Contains("Σp" & Units.Nbsp & "=" & Units.Nbsp & "(0," & Units.Nbsp & "0)", h.P.TotalsText, StringComparison.Ordinal)
        Assert.Equal("0.300", h.P.Snapshot.Cells(0, 0)(4))
    End Sub

    <Fact>
    Public Sub AFixedRectangle_IsListedInTheFixedColour_ItIsDrawnIn_AFixedBallInItsOwn()
        Dim w As New World(8, 5, 9.81, 1.0)
        w.Add(New Rectangle(New Vector(1, 0), 2, 1, "table") With {.Color = "#e53935"})
        w.Add(Circle.CreateFixed(New Vector(5, 2), 0.3, "peg"))
        w.Add(Rectangle.CreateMovable(New Vector(4, 3), 0.5, 0.5, 1.0, Vector.Zero, "box"))
        Dim h As New PresenterHarness(w)
        Dim rectangles = BodyTable.All.ToList().IndexOf(BodyTable.Rectangles)
        Dim rows = Enumerable.Range(0, h.P.Snapshot.RowCount(rectangles)).Select(Function(i) h.P.Snapshot.Cells(rectangles, i)).ToDictionary(Function(c) c(0))
        Assert.Equal(BodyTable.FixedColourCell, rows("table")(1))
        Assert.StartsWith("#", rows("box")(1), StringComparison.Ordinal)
        Dim peg = h.P.Snapshot.Cells(0, 0)
        Assert.Equal("peg", peg(0))
        Assert.StartsWith("#", peg(1), StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub ACountBroughtToItsLimit_IsSaidAsTheWholeNumberItIs()
        Dim h As New PresenterHarness()
        h.P.BeginAddPolygon("2", "0.5", "0", "1", False)
        Assert.NotNull(h.P.Draft)
        Assert.Contains("sides set to the minimum, 3.", h.View.LastMessage, StringComparison.Ordinal)
        Assert.DoesNotContain("3.00", h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub AContainerSideBelowTheLeast_IsBroughtToIt_AsEveryOtherBoxIs()
        Dim h As New PresenterHarness()
        h.P.ResizeContainer("0.1", "5")
        Assert.Equal(InputLimits.MinContainer, h.P.World.Width)
        Assert.Equal(5.0, h.P.World.Height)
        Assert.Equal("0.5", h.P.Inputs.ContainerWidthText)
        Assert.Equal("container width set to the minimum, 0.500 m.", h.View.LastMessage)
    End Sub

    <Fact>
    Public Sub ALinkFromABodyToItself_SaysWhyNothingHappened()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        h.Ball(4, 2, radius:=0.3)
        h.P.BeginAddLink(LinkKind.Rod)
        h.LeftClick(4, 2)
        h.LeftClick(4.1, 2)
        Assert.Empty(h.P.World.Links)
        Assert.Contains("A rod joins two different bodies", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Equal(ClickMode.Link, h.P.Mode)
    End Sub

    <Fact>
    Public Sub AfterGoingBack_TheReplayMessage_GoesWhenGravityChangesAndTheRunAheadIsForgotten()
        Dim h As New PresenterHarness(New World(8, 5, 9.81, 1.0))
        h.Ball(4, 4)
        For k = 1 To 60
            h.P.Tick(1 / 60.0)
        Next
        h.P.RewindTo(0.5)
        Assert.Contains("Resume replays the run as it was", h.P.Message, StringComparison.Ordinal)
        h.P.SetGravity(1.62)
        Assert.Equal("", h.P.Message)
        Assert.Equal("", h.View.LastMessage)
        ' A new run from there; going back again and replaying up to its latest moment uses the run ahead up, and the message goes.
        h.P.TogglePause()
        For k = 1 To 30
            h.P.Tick(1 / 60.0)
        Next
        h.P.RewindTo(0.9)
        Assert.Contains("Resume replays", h.P.Message, StringComparison.Ordinal)
        h.P.TogglePause()
        For k = 1 To 3
            h.P.Tick(1 / 60.0)
        Next
        ' 0.05 s into the 0.1 s replayed: still true.
        Assert.Contains("Resume replays", h.P.Message, StringComparison.Ordinal)
        For k = 1 To 60
            h.P.Tick(1 / 60.0)
        Next
        Assert.Equal("", h.P.Message)
    End Sub

    <Fact>
    Public Sub TheRunningSlowMessage_GoesOnceTheSceneHasKeptUpForASecond()
        Dim w As New World(2.0, 2.0, 0.0, 1.0)
        w.Add(New Circle(New Vector(1.0, 1.0), 0.1, 1.0))
        Dim h As New PresenterHarness(w)
        Dim solver As New CostlySolver(Nothing, 3.0)
        w.Solver = solver
        h.P.WallClock = Function() solver.Clock
        For k = 1 To 60
            h.P.Tick(1 / 60.0)
        Next
        Assert.Equal(SimulationPresenter.SlowMessage, h.P.Message)
        ' Every ball at rest: the frames keep up again. Half a second later the message still stands (it does not flicker)...
        solver.CostPerSimulatedSecond = 0
        For k = 1 To 30
            h.P.Tick(1 / 60.0)
        Next
        Assert.Equal(SimulationPresenter.SlowMessage, h.P.Message)
        ' ... and after a second of keeping up it is no longer true, and goes.
        For k = 1 To 31
            h.P.Tick(1 / 60.0)
        Next
        Assert.Equal("", h.P.Message)
    End Sub

    <Fact>
    Public Sub DeleteMode_ItsMessageIsWhole_AndGoesWithTheMode()
        Dim h As New PresenterHarness()
        h.P.ToggleDeleteMode()
        Assert.Equal(SimulationPresenter.DeleteModeMessage, h.P.Message)
        Assert.EndsWith("to stop.", SimulationPresenter.DeleteModeMessage, StringComparison.Ordinal)
        h.P.Reset()
        Assert.Equal(ClickMode.Move, h.P.Mode)
        Assert.Equal("", h.P.Message)
    End Sub

    <Fact>
    Public Sub SavingIntoAFolderThatIsNotThere_SaysSo_AndNamesNoTemporaryFile()
        Dim h As New PresenterHarness(store:=New SceneFileStore())
        Dim folder = IO.Path.Combine(IO.Path.GetTempPath(), "no-such-folder-" & Guid.NewGuid().ToString("N"))
        h.P.SaveScene(IO.Path.Combine(folder, "lesson.json"))
        Assert.Equal("Could not save lesson.json: the folder " & folder & " does not exist; nothing was written.", h.View.LastMessage)
        Assert.False(IO.Directory.Exists(folder))
        h.P.ExportCsv(ExportKind.BodiesCsv, IO.Path.Combine(folder, "bodies.csv"))
        Assert.Equal("Could not export bodies.csv: the folder " & folder & " does not exist; nothing was written.", h.View.LastMessage)
    End Sub

    <Fact>
    Public Sub StepsToTheNextCollision_GiveTimesThatTellTwoCollisionsApart()
        ' A ball at 1 m/s meets a second ball; that one meets a third 10 µm away 10 µs later.
        Dim w As New World(8, 5, 0.0, 1.0)
        w.Add(New Circle(New Vector(1.0, 2.5), 0.2, 1.0, New Vector(1.0, 0), "a"))
        w.Add(New Circle(New Vector(1.9, 2.5), 0.2, 1.0, id:="b"))
        w.Add(New Circle(New Vector(2.30001, 2.5), 0.2, 1.0, id:="c"))
        Dim h As New PresenterHarness(w)
        h.P.StepToNextCollision()
        Dim first = h.P.Message
        h.P.StepToNextCollision()
        Dim second = h.P.Message
        Dim time = Function(m As String) Regex.Match(m, "at t = (\S+) s").Groups(1).Value
        Assert.Matches("^Collision 1: a ↔ b at t = ", first)
        Assert.Matches("^Collision 2: b ↔ c at t = ", second)
        Assert.NotEqual(time(first), time(second))
        ' Each time read back is the collision's to the figures shown: 0.5 s, then 10 µs later.
        Dim t2 = Double.Parse(time(second).Replace("−", "-"), CultureInfo.InvariantCulture)
        Assert.InRange(t2, 0.50001 - 0.000001, 0.50001 + 0.000001)
    End Sub
End Class
