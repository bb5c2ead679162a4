Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>Objectives 6 and 7: carrying with the right button, the cue with the left.</summary>
Public Class DragAndCueTests
    <Fact>
    Public Sub RightDrag_CarriesTheBall_AndDropsItFromRest()
        Dim h As New PresenterHarness()
        Dim ball = h.Ball(2, 2)
        Dim a = h.Px(2, 2), b = h.Px(4, 3)
        h.P.PointerDown(PointerButton.Right, a.X, a.Y)
        Assert.Same(ball, h.P.World.DraggedCircle)
        h.P.PointerMove(b.X, b.Y)
        For k = 1 To 30
            h.P.Tick(1 / 60.0)
        Next
        Assert.Equal(4.0, ball.Position.X, 3)
        Assert.Equal(3.0, ball.Position.Y, 3)
        h.P.PointerUp(PointerButton.Right, b.X, b.Y)
        Assert.Null(h.P.World.DraggedCircle)
        Assert.Null(h.P.DraggedBody)
        Assert.Equal(Vector.Zero, ball.Velocity)
        h.P.Tick(0.05)
        Assert.True(ball.Position.Y < 3.0, "it drops back into the simulation and falls")
        Assert.Contains(h.TraceLines, Function(l) l.StartsWith("drag end " & ball.Id, StringComparison.Ordinal))
    End Sub

    <Fact>
    Public Sub RightDrag_KeepsTheGrabOffset()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim ball = h.Ball(2, 2, radius:=0.4)
        h.Drag(PointerButton.Right, 2.2, 2, 5.2, 2, 0.1)
        Assert.Equal(5.0, ball.Position.X, 2)
    End Sub

    <Fact>
    Public Sub DraggedBall_StopsAtABallInItsWay_AndBallsBounceOffIt()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim carried = h.Ball(2, 2)
        Dim resting = h.Ball(3, 2)
        Dim moving = h.Ball(2.6, 4.5)
        h.P.World.SetVelocity(moving, New Vector(0, -3))
        Dim a = h.Px(2, 2)
        h.P.PointerDown(PointerButton.Right, a.X, a.Y)
        For k = 1 To 60
            Dim s = h.Px(Math.Min(5, 2 + 0.1 * k), 2)
            h.P.PointerMove(s.X, s.Y)
            h.P.Tick(1 / 60.0)
        Next
        ' It comes up to the resting ball and stops there, touching: it never goes into or over it.
        Assert.Equal(2.6, carried.Position.X, 5)
        Assert.Equal(3.0, resting.Position.X, 9)
        ' The falling ball met the carried one (as heavy as a wall) and went back up.
        Assert.True(moving.Velocity.Y > 0, $"the moving ball has v = {moving.Velocity}")
        Assert.Null(Placement.FindProblem(h.P.World))
    End Sub

    <Fact>
    Public Sub RightDrag_WhilePaused_MovesTheBallDirectly()
        Dim h As New PresenterHarness()
        Dim ball = h.Ball(2, 2)
        h.P.TogglePause()
        h.Drag(PointerButton.Right, 2, 2, 6, 4)
        Assert.Equal(6.0, ball.Position.X, 6)
        Assert.Equal(4.0, ball.Position.Y, 6)
        Assert.Equal(0.0, h.P.World.Time)
    End Sub

    <Fact>
    Public Sub RightDrag_MovesFixedBodies_KeepingIdAndColour()
        Dim h As New PresenterHarness()
        h.P.World.Add(New Rectangle(New Vector(1, 1), 2, 1, "table") With {.Color = "#336699"})
        h.Drag(PointerButton.Right, 2, 1.5, 5, 2.5)
        Dim r = Assert.Single(h.P.World.Rectangles)
        Assert.Equal("table", r.Id)
        Assert.Equal("#336699", r.Color)
        Assert.Equal(4.0, r.Position.X, 6)
        Assert.Equal(2.0, r.Position.Y, 6)
    End Sub

    <Fact>
    Public Sub RightDrag_OfAFixedBody_KeepsItsPlaceInTheTables()
        Dim h As New PresenterHarness()
        h.P.World.Add(New Rectangle(New Vector(1, 1), 2, 1, "table"))
        h.P.World.Add(Circle.CreateFixed(New Vector(6, 3), 0.3, "peg"))
        h.Ball(4, 4)
        Dim before = h.P.World.Bodies.Select(Function(b) b.Id).ToArray()
        h.Drag(PointerButton.Right, 2, 1.5, 3, 2.5)
        h.Drag(PointerButton.Right, 6, 3, 7, 1)
        Assert.Equal(before, h.P.World.Bodies.Select(Function(b) b.Id).ToArray())
        Assert.Equal(7.0, h.P.World.Circles.Single(Function(c) c.Id = "peg").Position.X, 6)
    End Sub

    <Fact>
    Public Sub Cue_PullBackAndRelease_GivesDeltaVOfJOverM()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim ball = h.Ball(4, 2, mass:=2)
        Dim a = h.Px(4, 2), back = h.Px(3.5, 2)
        h.P.PointerDown(PointerButton.Left, a.X, a.Y)
        h.P.PointerMove(back.X, back.Y)
        Assert.Same(ball, h.P.AimedBody)
        Dim j = h.P.CueImpulse
        Assert.Equal(0.5 * CueShot.ImpulsePerMetre, j.X, 6)
        Assert.Contains("J = 2.00 N·s", h.P.CueLabel.Replace(Units.Nbsp, " "c), StringComparison.Ordinal)
        Assert.Contains("Δv = J/m = 1.00 m/s", h.P.CueLabel.Replace(Units.Nbsp, " "c), StringComparison.Ordinal)
        h.P.PointerUp(PointerButton.Left, back.X, back.Y)
        Assert.Null(h.P.AimedBody)
        Assert.Equal(1.0, ball.Velocity.X, 6)
        Assert.Equal(0.0, ball.Velocity.Y, 6)
        Assert.Contains(h.TraceLines, Function(l) l.StartsWith("fired " & ball.Id, StringComparison.Ordinal))
    End Sub

    <Fact>
    Public Sub Cue_SamePull_MovesAHeavierBallLess()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim light = h.Ball(2, 1, mass:=1)
        Dim heavy = h.Ball(2, 4, mass:=4)
        h.Drag(PointerButton.Left, 2, 1, 2, 0.6)
        h.Drag(PointerButton.Left, 2, 4, 2, 3.6)
        Assert.Equal(4.0 * light.Velocity.Y, 4.0 * heavy.Velocity.Y * 4, 6)
        Assert.True(light.Velocity.Y > heavy.Velocity.Y AndAlso heavy.Velocity.Y > 0)
    End Sub

    <Fact>
    Public Sub Cue_FiredBall_MovesInTheShotDirection()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim ball = h.Ball(4, 2)
        h.Drag(PointerButton.Left, 4, 2, 3.8, 2.1)
        h.P.Tick(0.1)
        Assert.True(ball.Position.X > 4.05 AndAlso ball.Position.Y < 2.0)
    End Sub

    <Fact>
    Public Sub Cue_ImpulseIsCapped()
        Dim j = CueShot.ImpulseFor(New Vector(0, 0), New Vector(-1000, 0))
        Assert.Equal(CueShot.MaxImpulse, j.Length, 9)
        Assert.True(j.X > 0)
    End Sub

    <Fact>
    Public Sub Cue_OnFixedBodiesOrEmptySpace_DoesNothing()
        Dim h As New PresenterHarness()
        h.P.World.Add(Circle.CreateFixed(New Vector(2, 2), 0.3))
        h.P.World.Add(New Rectangle(New Vector(5, 0), 2, 1))
        h.Drag(PointerButton.Left, 2, 2, 1, 2)
        h.Drag(PointerButton.Left, 6, 0.5, 5, 0.5)
        h.Drag(PointerButton.Left, 4, 4, 3, 4)
        Assert.DoesNotContain(h.TraceLines, Function(l) l.StartsWith("fired", StringComparison.Ordinal))
        Assert.Null(h.P.AimedBody)
    End Sub

    <Fact>
    Public Sub Cue_WorksWhilePaused_AndTheBallMovesOnResume()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim ball = h.Ball(4, 2)
        h.P.TogglePause()
        h.Drag(PointerButton.Left, 4, 2, 3.5, 2)
        Assert.Equal(4.0, ball.Position.X, 9)
        Assert.Equal(2.0, ball.Velocity.X, 6)
        h.P.TogglePause()
        h.P.Tick(0.1)
        Assert.Equal(4.2, ball.Position.X, 3)
    End Sub
End Class
