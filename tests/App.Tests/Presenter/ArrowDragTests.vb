Option Strict On
Imports System.Globalization
Imports System.Text.RegularExpressions
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>While paused, dragging the tip of a velocity arrow sets the velocity, shown as it is dragged.</summary>
Public Class ArrowDragTests
    ''' <summary>A paused scene of one ball at (3, 2) m moving at (1.5, 0.5) m/s, no gravity.</summary>
    Private Shared Function Scene() As (H As PresenterHarness, Ball As Circle)
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim ball = New Circle(New Vector(3, 2), 0.25, 2.0, New Vector(1.5, 0.5), "red")
        h.P.World.Add(ball)
        h.P.TogglePause()
        Return (h, ball)
    End Function

    <Fact>
    Public Sub DraggingTheTip_SetsTheVelocityTheLabelShows_AndTheTableShowsTheSame()
        Dim s = Scene()
        Dim h = s.H, ball = s.Ball
        Dim seconds = h.P.Arrows.Seconds
        Dim tip = h.Px(3 + 1.5 * seconds, 2 + 0.5 * seconds)
        Dim target = h.Px(3 - 0.8 * seconds, 2 + 1.2 * seconds) ' v = (−0.8, 1.2) m/s
        h.P.PointerDown(PointerButton.Left, tip.X + 3, tip.Y - 2)
        Assert.Same(ball, h.P.ArrowBody)
        Assert.Null(h.P.AimedBody)
        h.P.PointerMove((tip.X + target.X) / 2, (tip.Y + target.Y) / 2)
        h.P.PointerMove(target.X + 3, target.Y - 2)
        ' As it is dragged, the label shows the velocity set, and the table the same numbers.
        Dim label = h.P.ArrowLabel
        Dim m = Regex.Match(label, "^v = \((\S+), (\S+)\) m/s   \|v\| = ([^ ]+)" & Units.Nbsp & "m/s$")
        Assert.True(m.Success, label)
        Dim cells = h.P.Snapshot.Cells(0, 0)
        Assert.Equal(cells(4), m.Groups(1).Value)
        Assert.Equal(cells(5), m.Groups(2).Value)
        Assert.Equal(cells(6), m.Groups(3).Value)
        ' The grab's offset from the tip is kept, so the velocity is where the tip was dragged to, to a pixel.
        h.P.PointerUp(PointerButton.Left, target.X + 3, target.Y - 2)
        Assert.Null(h.P.ArrowBody)
        Dim pixel = 1.0 / h.P.View.Scale / seconds
        Assert.InRange(ball.Velocity.X, -0.8 - 4 * pixel, -0.8 + 4 * pixel)
        Assert.InRange(ball.Velocity.Y, 1.2 - 4 * pixel, 1.2 + 4 * pixel)
        ' The arrows' scale stayed put while dragging; the edit can be undone.
        Assert.True(h.P.CanUndo)
        h.P.Undo()
        Assert.Equal(New Vector(1.5, 0.5), h.P.World.Movables(0).Velocity)
    End Sub

    <Fact>
    Public Sub WhileRunning_OrWithArrowsOff_APressNearTheTip_IsNoArrowDrag()
        Dim s = Scene()
        Dim h = s.H
        Dim seconds = h.P.Arrows.Seconds
        Dim tip = h.Px(3 + 1.5 * seconds, 2 + 0.5 * seconds)
        h.P.SetShowArrows(False)
        h.P.PointerDown(PointerButton.Left, tip.X, tip.Y)
        Assert.Null(h.P.ArrowBody)
        h.P.PointerUp(PointerButton.Left, tip.X, tip.Y)
        h.P.SetShowArrows(True)
        h.P.TogglePause()
        h.P.PointerDown(PointerButton.Left, tip.X, tip.Y)
        Assert.Null(h.P.ArrowBody)
        h.P.PointerUp(PointerButton.Left, tip.X, tip.Y)
    End Sub
End Class

''' <summary>After a jump back in time, only the impulses of the last collision are drawn, not every collision replayed on the way.</summary>
Public Class ImpulsesAfterAScrubTests
    <Fact>
    Public Sub AfterScrubbingBack_OnlyTheLastInstantsImpulsesAreShown()
        Dim h As New PresenterHarness(New World(4, 3, 0.0, 1.0))
        h.P.World.Add(New Circle(New Vector(1, 1.5), 0.2, 1.0, New Vector(7, 0.3), "a"))
        h.P.World.Add(New Circle(New Vector(3, 1.2), 0.2, 1.0, New Vector(-5, 0.2), "b"))
        h.P.SetShowImpulses(True)
        For k = 1 To 240
            h.P.Tick(1 / 60.0)
        Next
        Assert.True(h.P.Log.TotalSeen > 10, "the balls bounced about")
        h.P.RewindTo(2.5)
        h.P.Tick(1 / 60.0) ' paused: the frame places the marks, and ages none
        Dim marks = h.P.Impulses.Marks
        Assert.NotEmpty(marks)
        Assert.True(marks.Select(Function(m) m.Time).Distinct().Count() = 1, "marks of " & marks.Select(Function(m) m.Time).Distinct().Count() & " instants")
        Assert.True(marks.All(Function(m) m.Time <= h.P.World.Time), "a mark from after the moment on show")
        Assert.True(marks.All(Function(m) h.P.World.Bodies.Any(Function(b) ReferenceEquals(b, m.Body))), "a mark of a body of the run before the jump")
        Assert.True(marks.Count <= 2)
    End Sub
End Class
