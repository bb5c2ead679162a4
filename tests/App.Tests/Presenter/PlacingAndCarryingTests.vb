Option Strict On
Imports PhysicsEngine.Presentation
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>A body never ends up inside another: placing finds room or says why; carrying stops at what it may not enter.</summary>
Public Class PlacingAndCarryingTests
    Private Shared Function WithTable() As PresenterHarness
        Dim h As New PresenterHarness()
        h.P.World.Add(New Rectangle(New Vector(3, 0), 2, 2, "table"))
        Return h
    End Function

    <Fact>
    Public Sub PlacingABallInsideARectangle_PutsItAtTheNearestFreePlace_AndSaysSo()
        Dim h = WithTable()
        h.P.BeginAddCircle("0.3", "1", False)
        h.LeftClick(4, 1.8)
        Dim ball = Assert.Single(h.P.World.Circles)
        Assert.Null(Placement.FindProblem(h.P.World))
        Assert.Equal(2.3, ball.Position.Y, 2) ' on top of the table, the nearest way out
        Assert.Equal(4.0, ball.Position.X, 1)
        Assert.Contains("at the nearest free place: there it would have overlapped fixed rectangle table", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Null(h.P.Draft)
    End Sub

    <Fact>
    Public Sub PlacingWhereThereIsNoRoomNear_IsRefused_AndTheBodyStaysOnTheCursor()
        Dim h As New PresenterHarness()
        h.P.World.Add(New Rectangle(New Vector(0, 0), 8, 4.5, "slab"))
        h.P.BeginAddCircle("0.4", "1", False)
        h.LeftClick(4, 2)
        Assert.Empty(h.P.World.Circles)
        Assert.NotNull(h.P.Draft)
        Assert.Equal("There is no room for the circle there: it would overlap fixed rectangle slab. Click on a free place (Esc cancels).", h.View.LastMessage)
    End Sub

    <Fact>
    Public Sub ThePreview_SaysWhetherItFitsWhereTheCursorIs()
        Dim h = WithTable()
        h.P.BeginAddCircle("0.3", "1", False)
        Dim inside = h.Px(4, 1), free = h.Px(1, 3)
        h.P.PointerMove(inside.X, inside.Y)
        Assert.False(h.P.DraftFits)
        h.P.PointerMove(free.X, free.Y)
        Assert.True(h.P.DraftFits)
    End Sub

    <Fact>
    Public Sub AFixedBall_MayBePlacedOnARectangle_ForFixedBodiesDoNotCollide()
        Dim h = WithTable()
        h.P.BeginAddCircle("0.3", "", True)
        h.LeftClick(4, 1)
        Dim peg = Assert.Single(h.P.World.Circles)
        Assert.Equal(4.0, peg.Position.X, 9)
        Assert.Equal(1.0, peg.Position.Y, 9)
    End Sub

    <Fact>
    Public Sub CarryingWhilePaused_StopsAtTheRectangle_AndDropsTheBallOutsideIt()
        Dim h = WithTable()
        Dim ball = h.Ball(1, 1, 0.3)
        h.P.TogglePause()
        h.Drag(PointerButton.Right, 1, 1, 4, 1) ' the cursor ends inside the table
        Assert.Equal(2.7, ball.Position.X, 9)
        Assert.Null(Placement.FindProblem(h.P.World))
    End Sub

    <Fact>
    Public Sub CarryingWhilePaused_SlidesAlongWhatStopsIt()
        Dim h = WithTable()
        Dim ball = h.Ball(1, 1, 0.3)
        h.P.TogglePause()
        h.Drag(PointerButton.Right, 1, 1, 4, 3.5) ' up and over the table
        Assert.Null(Placement.FindProblem(h.P.World))
        Assert.True(ball.Position.Y > 2.3 - 1.0E-9, $"it went over the table: {ball.Position}")
    End Sub

    <Fact>
    Public Sub CarryingWhilePaused_NeverJumpsOverABall()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim carried = h.Ball(1, 2, 0.3)
        Dim other = h.Ball(4, 2, 0.1)
        h.P.TogglePause()
        Dim a = h.Px(1, 2), b = h.Px(7, 2)
        h.P.PointerDown(PointerButton.Right, a.X, a.Y)
        h.P.PointerMove(b.X, b.Y) ' one jump of 6 m, straight through the small ball
        h.P.PointerUp(PointerButton.Right, b.X, b.Y)
        Assert.True(carried.Position.X < other.Position.X, $"the carried ball is at {carried.Position}, the other at {other.Position}")
        Assert.Null(Placement.FindProblem(h.P.World))
    End Sub

    <Fact>
    Public Sub CarryingFastWhileRunning_NeverEntersAFixedBody_OrJumpsThroughABall()
        Dim h As New PresenterHarness(Scenarios.Demo())
        h.P.World.Gravity = 0
        For k = 1 To 30
            h.P.Tick(1 / 60.0)
        Next
        Dim red = DirectCast(h.P.World.Find("red"), Circle)
        Dim a = h.Px(red.Position.X, red.Position.Y)
        h.P.PointerDown(PointerButton.Right, a.X, a.Y)
        Dim before = h.P.Log.TotalSeen
        ' The cursor leaps about, into the table and the peg, a frame at a time.
        For Each t In {New Vector(7, 4), New Vector(1, 1), New Vector(7, 0.5), New Vector(4.2, 1.5), New Vector(6.5, 1.5), New Vector(1, 4)}
            Dim s = h.Px(t.X, t.Y)
            h.P.PointerMove(s.X, s.Y)
            For k = 1 To 20
                h.P.Tick(1 / 60.0)
                Assert.Null(Placement.FindProblem(h.P.World))
            Next
        Next
        h.P.PointerUp(PointerButton.Right, a.X, a.Y)
        For k = 1 To 60
            h.P.Tick(1 / 60.0)
        Next
        Assert.Null(Placement.FindProblem(h.P.World))
        Dim collisions = h.P.Log.TotalSeen - before
        Assert.True(collisions < 200, $"{collisions} collisions from one drag")
        Assert.False(h.P.IsPaused, h.P.Message)
    End Sub

    <Fact>
    Public Sub CarryingAPolygonOnAStringPastItsLength_ThenLettingGo_RunsOn()
        ' The hand pulled a polygon on a string past the string's length; let go, the event solver could not get
        ' past that state, and every frame after spun on it until the window gave up. The hand now keeps the
        ' string at most taut, and the run goes on, frame after frame, with the string never longer than itself.
        Dim w As New World(10, 10, 9.81, 0.5)
        Dim p As New Polygon({New Vector(5, 3), New Vector(5.3, 3), New Vector(5.15, 3.3)}, 1, Vector.Zero, "p")
        w.Add(p)
        Dim s = Link.CreateTie(LinkKind.String, p, New Vector(5.15, 4.5), 1.5)
        w.Add(s)
        w.Solver = SolverFactory.Create("event")
        Dim h As New PresenterHarness(w)
        Dim a = h.Px(p.CentreOfMass.X, p.CentreOfMass.Y)
        h.P.PointerDown(PointerButton.Right, a.X, a.Y)
        For k = 1 To 30
            Dim c = h.Px(5.15 + 0.2 * k, 3.1 - 0.1 * k)
            h.P.PointerMove(c.X, c.Y)
            h.P.Tick(1 / 60.0)
            Assert.True(s.Distance <= 1.5 * (1 + 0.000000001), $"the string is {s.Distance} m long while carried")
        Next
        h.P.PointerUp(PointerButton.Right, a.X, a.Y)
        For k = 1 To 60
            Dim before = h.P.World.Time
            h.P.Tick(1 / 60.0)
            Assert.False(h.P.IsPaused, h.P.Message)
            Assert.True(h.P.World.Time > before, $"no time passed from t = {before} s: {h.P.Message}")
            Assert.True(s.Distance <= 1.5 * (1 + 0.000000001), $"the string is {s.Distance} m long at t = {h.P.World.Time} s")
        Next
        Assert.Equal("event", h.P.World.Solver.Name)
    End Sub

    <Fact>
    Public Sub CarryingABallIntoAnotherAgainstAWall_StopsInsteadOfSqueezingIt()
        ' Without the stop, the ball caught between the wall and the carried ball (infinitely heavy)
        ' bounces between them without end: tens of millions of collisions, and the carried ball
        ' ends up on the far side of it.
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim caught = h.Ball(1, 0.3, 0.2)
        Dim carried = h.Ball(4, 0.3, 0.3)
        Dim a = h.Px(4, 0.3)
        h.P.PointerDown(PointerButton.Right, a.X, a.Y)
        Dim before = h.P.Log.TotalSeen
        For k = 1 To 30
            Dim s = h.Px(4 - 0.15 * k, 0.3)
            h.P.PointerMove(s.X, s.Y)
            h.P.Tick(1 / 60.0)
        Next
        Dim collisions = h.P.Log.TotalSeen - before
        Assert.True(collisions < 100, $"{collisions} collisions")
        Assert.True(carried.Position.X > caught.Position.X, $"the carried ball at {carried.Position} passed the caught one at {caught.Position}")
        Assert.Null(Placement.FindProblem(h.P.World))
    End Sub

    <Fact>
    Public Sub CarryingARectangle_StopsAtAMovableBall()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        h.P.World.Add(New Rectangle(New Vector(0.5, 2), 1, 1, "box"))
        Dim ball = h.Ball(5, 2.5, 0.3)
        h.Drag(PointerButton.Right, 1, 2.5, 6, 2.5)
        Dim box = Assert.Single(h.P.World.Rectangles)
        Assert.Equal(5 - 0.3 - 1, box.Position.X, 9)
        Assert.Null(Placement.FindProblem(h.P.World))
        Assert.Equal(5.0, ball.Position.X, 9)
    End Sub

    <Fact>
    Public Sub EverySceneSavedAfterARandomSession_OpensAgain()
        Dim rng As New Random(42)
        Dim h As New PresenterHarness(Scenarios.Demo(), New SceneFileStore())
        Dim folder = IO.Path.Combine(IO.Path.GetTempPath(), "app-sessions-" & Guid.NewGuid().ToString("N"))
        IO.Directory.CreateDirectory(folder)
        Try
            For action = 1 To 400
                Dim x = rng.NextDouble() * 8, y = rng.NextDouble() * 5
                Dim s = h.Px(x, y)
                Select Case rng.Next(9)
                    Case 0 : h.P.BeginAddCircle((0.05 + rng.NextDouble() * 0.6).ToString(Globalization.CultureInfo.InvariantCulture), "1", rng.Next(4) = 0)
                    Case 1 : h.P.BeginAddRectangle((0.2 + rng.NextDouble() * 2).ToString(Globalization.CultureInfo.InvariantCulture), "0.5")
                    Case 2 : h.LeftClick(x, y)
                    Case 3 : h.Drag(PointerButton.Right, x, y, rng.NextDouble() * 8, rng.NextDouble() * 5, If(rng.Next(2) = 0, 1 / 60.0, 0))
                    Case 4 : h.Drag(PointerButton.Left, x, y, x - rng.NextDouble(), y - rng.NextDouble())
                    Case 5 : h.P.TogglePause()
                    Case 6 : h.P.ResizeContainer((2 + rng.NextDouble() * 8).ToString(Globalization.CultureInfo.InvariantCulture), (2 + rng.NextDouble() * 5).ToString(Globalization.CultureInfo.InvariantCulture))
                    Case 7
                        For k = 1 To 10
                            h.P.Tick(1 / 60.0)
                        Next
                    Case Else
                        Dim path = IO.Path.Combine(folder, "s" & action & ".json")
                        h.P.SaveScene(path)
                        Assert.True(IO.File.Exists(path), h.View.LastMessage)
                End Select
                Dim problem = Placement.FindProblem(h.P.World)
                Assert.True(problem Is Nothing, $"after action {action}: {problem}")
                Try
                    SceneFile.Load(SceneFile.Save(h.P.World))
                Catch ex As SceneFormatException
                    Assert.Fail($"after action {action}: {ex.Message}; {h.P.World.Bodies.Count} bodies")
                End Try
            Next
            Dim files = IO.Directory.GetFiles(folder)
            Assert.True(files.Length > 20, $"only {files.Length} saves")
            For Each f In files
                SceneFile.LoadFile(f) ' throws when a saved scene would not open
            Next
        Finally
            IO.Directory.Delete(folder, True)
        End Try
    End Sub
End Class
