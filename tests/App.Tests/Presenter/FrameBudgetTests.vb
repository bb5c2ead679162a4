Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>A frame never runs away with the window: heavy scenes slow the shown time and say so; a scene the event solver refuses runs with Verlet.</summary>
Public Class FrameBudgetTests
    <Fact>
    Public Sub AFrameOverItsBudget_ShowsSlowerTime_AndSaysSo()
        Dim w As New World(2.0, 2.0, 0.0, 1.0)
        ' An elastic gas of 400 small balls: thousands of collisions per simulated second.
        Dim k = 0
        For i = 0 To 19
            For j = 0 To 19
                k += 1
                Dim angle = k * 2.399
                w.Add(New Circle(New Vector(0.05 + 0.095 * i, 0.05 + 0.095 * j), 0.02, 1.0, New Vector(Math.Cos(angle), Math.Sin(angle)) * 5))
            Next
        Next
        Dim h As New PresenterHarness(w)
        h.P.FrameBudgetSeconds = 0
        h.P.Tick(0.02)
        Assert.True(h.P.IsRunningSlow)
        Assert.True(w.Time < 0.02 * h.P.Speed, $"the world advanced {w.Time} s of the {0.02 * h.P.Speed} s asked within no time at all")
        Assert.Contains("slower", h.View.LastMessage)
        ' With time enough, it keeps up again.
        h.P.FrameBudgetSeconds = 10
        h.P.Tick(0.02)
        Assert.False(h.P.IsRunningSlow)
    End Sub

    <Fact>
    Public Sub ABoxRestingOnATableInASceneWithLinks_TheEventSolverRefuses_RunsWithVerlet_AndSaysSo()
        Dim w As New World(4.0, 4.0, 9.81, 1.0)
        Dim bob As New Circle(New Vector(3.0, 3.0), 0.1, 1.0, id:="bob")
        w.Add(bob)
        ' The event solver lets a box rest on a table, but not one a spring pulls along it (off the vertical).
        w.Add(New PhysicsEngine.Rectangle(New Vector(0.25, 0.0), 1.0, 0.5, "table"))
        Dim box = PhysicsEngine.Rectangle.CreateMovable(New Vector(0.5, 0.5), 0.3, 0.2, 2.0, Vector.Zero, "box")
        w.Add(box)
        w.Add(Link.CreateSpring(box, New Vector(1.65, 0.6), 10, 0.5))
        w.Add(Link.CreateTie(LinkKind.Rod, bob, New Vector(2.0, 3.0), 1.0))
        w.Solver = SolverFactory.Create("event")
        Dim h As New PresenterHarness(w)
        ' Time enough for every frame (the first also compiles the code it runs): this is about the fall-back, not speed.
        h.P.FrameBudgetSeconds = 10
        For i = 1 To 10
            h.P.Tick(0.02)
        Next
        Assert.Equal("verlet", w.Solver.Name)
        Assert.Contains("Verlet", h.View.LastMessage)
        Assert.True(w.Time > 0, "time did not move")
        ' The pendulum swings: the bob has fallen below its start.
        Assert.True(bob.Position.Y < 3.0, $"the bob is at {bob.Position}")
    End Sub
End Class
