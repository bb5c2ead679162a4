Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>A frame never runs away with the window: heavy scenes slow the shown time and say so; a scene with links and resting contact stays with the event solver.</summary>
Public Class FrameBudgetTests
    Private Const Frame As Double = 1.0 / 60 ' s

    <Fact>
    Public Sub TheBudget_IsTheFrameLessTheReserveAndTheMostOtherWorkOfTheLastFrames()
        Dim b As New FrameBudget()
        Assert.Equal(FrameBudget.TargetSeconds - FrameBudget.ReserveSeconds, b.StepSeconds, 12)
        ' One frame paints for 3 ms and refreshes a graph for 2 ms: 5 ms of other work.
        b.AddOtherWork(0.003)
        b.AddOtherWork(0.002)
        Assert.Equal(0.016 - 0.002 - 0.005, b.StepSeconds, 12)
        ' Cheaper frames after it do not lift the budget while it is remembered ...
        For k = 1 To FrameBudget.RememberedFrames - 1
            b.NextFrame()
            b.AddOtherWork(0.001)
        Next
        Assert.Equal(0.016 - 0.002 - 0.005, b.StepSeconds, 12)
        ' ... and do once it is forgotten.
        b.NextFrame()
        b.AddOtherWork(0.001)
        Assert.Equal(0.016 - 0.002 - 0.001, b.StepSeconds, 12)
        ' A paint that fills the whole frame still leaves the world its least advance.
        b.AddOtherWork(0.1)
        Assert.Equal(FrameBudget.MinStepSeconds, b.StepSeconds, 12)
    End Sub

    <Fact>
    Public Sub AFrameOfACostlyScene_StopsWithinItsBudget_AndCountsTheTimeHeldBack_AndAStretchOfThemSaysSo()
        Dim w As New World(2.0, 2.0, 0.0, 1.0)
        w.Add(New Circle(New Vector(1.0, 1.0), 0.1, 1.0))
        Dim h As New PresenterHarness(w)
        ' Each simulated second costs 3 s of the test's clock: a whole frame would take 50 ms.
        Dim solver As New CostlySolver(Nothing, 3.0)
        w.Solver = solver
        h.P.WallClock = Function() solver.Clock
        Dim budget = h.P.FrameBudgetSeconds
        Assert.Equal(FrameBudget.TargetSeconds - FrameBudget.ReserveSeconds, budget, 12)

        Dim before = solver.Clock
        h.P.Tick(Frame)
        Dim spent = solver.Clock - before
        Assert.True(spent <= budget + 1.0E-12, $"the frame spent {spent * 1000} ms of a {budget * 1000} ms budget")
        Assert.True(spent > budget / 2, $"the frame spent only {spent * 1000} ms of a {budget * 1000} ms budget")
        Assert.Equal(spent / 3.0, w.Time, 12)
        Assert.True(h.P.IsRunningSlow)
        Assert.Equal(1L, h.P.SlowedFrames)
        Assert.Equal(Frame - w.Time, h.P.HeldBackSeconds, 12)
        ' One slow frame is not worth a message.
        Assert.DoesNotContain(SimulationPresenter.SlowMessage, h.View.Messages)

        ' The window then paints for 8 ms: the next frame leaves room for it.
        h.P.NoteFrameWork(0.008)
        budget = h.P.FrameBudgetSeconds
        Assert.Equal(0.016 - 0.002 - 0.008, budget, 12)
        before = solver.Clock
        h.P.Tick(Frame)
        spent = solver.Clock - before
        Assert.True(spent <= budget + 1.0E-12, $"the frame spent {spent * 1000} ms of a {budget * 1000} ms budget")
        Assert.Equal(2L, h.P.SlowedFrames)
        Assert.Equal(2 * Frame - w.Time, h.P.HeldBackSeconds, 12)

        ' Slow frames in a row: the message comes once time on screen is a tenth of a second behind, and only once.
        Dim frames = 2
        Do While h.P.HeldBackSeconds < SimulationPresenter.SlowNoticeSeconds
            Assert.DoesNotContain(SimulationPresenter.SlowMessage, h.View.Messages)
            h.P.Tick(Frame)
            frames += 1
            Assert.True(frames < 100, "time on screen never fell behind")
        Loop
        Assert.Equal(frames * Frame - w.Time, h.P.HeldBackSeconds, 12)
        Assert.Equal(SimulationPresenter.SlowMessage, h.View.LastMessage)
        h.P.Tick(Frame)
        Assert.Single(h.View.Messages.Where(Function(m) m = SimulationPresenter.SlowMessage))

        ' A cheap scene keeps up again, and holds nothing more back.
        solver.CostPerSimulatedSecond = 0.3
        Dim heldBack = h.P.HeldBackSeconds
        Dim slowed = h.P.SlowedFrames
        Dim t = w.Time
        h.P.Tick(Frame)
        Assert.False(h.P.IsRunningSlow)
        Assert.Equal(t + Frame, w.Time, 12)
        Assert.Equal(heldBack, h.P.HeldBackSeconds)
        Assert.Equal(slowed, h.P.SlowedFrames)
    End Sub

    <Fact>
    Public Sub AFrameAdvancedInPieces_LandsExactlyWhereOneAdvancePerFrameDoes()
        Dim shown = Scenarios.ElasticGas(60)
        shown.Gravity = 9.81
        Dim plain = Scenarios.ElasticGas(60)
        plain.Gravity = 9.81
        Dim h As New PresenterHarness(shown)
        ' A known cost (0.5 s per simulated second) makes the presenter cut each frame into pieces of about 3 ms simulated.
        Dim solver As New CostlySolver(SolverFactory.Create("event"), 0.5)
        shown.Solver = solver
        h.P.WallClock = Function() solver.Clock
        h.P.FrameBudgetSeconds = 10
        plain.Solver = SolverFactory.Create("event")
        For f = 1 To 60
            h.P.Tick(Frame)
            plain.Advance(Frame)
        Next
        Assert.True(solver.Durations.Count >= 4 * 60, $"only {solver.Durations.Count} advances for 60 frames: the frames were not cut into pieces")
        Assert.False(h.P.IsRunningSlow)
        Assert.Equal(plain.Time, shown.Time)
        Assert.Equal(plain.Circles.Count, shown.Circles.Count)
        For i = 0 To plain.Circles.Count - 1
            Assert.Equal(plain.Circles(i).Position, shown.Circles(i).Position)
            Assert.Equal(plain.Circles(i).Velocity, shown.Circles(i).Velocity)
        Next
    End Sub

    <Fact>
    Public Sub AFrameOverItsBudget_ShowsSlowerTime_AndCountsIt()
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
        Assert.Equal(0.02 * h.P.Speed - w.Time, h.P.HeldBackSeconds, 12)
        ' (When a stretch of such frames says so: see the costly scene's test, on a clock of its own.)
        ' With time enough, it keeps up again.
        h.P.FrameBudgetSeconds = 10
        h.P.Tick(0.02)
        Assert.False(h.P.IsRunningSlow)
    End Sub

    <Fact>
    Public Sub ABoxASpringPullsAlongATable_InASceneWithLinks_StaysWithTheEventSolver_OnTheTable()
        Dim w As New World(4.0, 4.0, 9.81, 1.0)
        Dim bob As New Circle(New Vector(3.0, 3.0), 0.1, 1.0, id:="bob")
        w.Add(bob)
        ' A box on a table, pulled along it by a spring off the vertical (once refused by the event solver and run
        ' with Verlet instead), beside a pendulum on a rod.
        w.Add(New PhysicsEngine.Rectangle(New Vector(0.25, 0.0), 1.0, 0.5, "table"))
        Dim box = PhysicsEngine.Rectangle.CreateMovable(New Vector(0.5, 0.5), 0.3, 0.2, 2.0, Vector.Zero, "box")
        w.Add(box)
        w.Add(Link.CreateSpring(box, New Vector(1.65, 0.6), 10, 0.5))
        w.Add(Link.CreateTie(LinkKind.Rod, bob, New Vector(2.0, 3.0), 1.0))
        w.Solver = SolverFactory.Create("event")
        Dim h As New PresenterHarness(w)
        ' Time enough for every frame (the first also compiles the code it runs): this is about the solver, not speed.
        h.P.FrameBudgetSeconds = 10
        Dim start = box.Position
        For i = 1 To 10
            h.P.Tick(0.02)
            ' Held by the table exactly: never a rounding error below its top.
            Assert.True(box.Position.Y >= 0.5, $"the box is {0.5 - box.Position.Y} m into the table at t = {w.Time} s")
        Next
        Assert.Equal("event", w.Solver.Name)
        Assert.DoesNotContain("Verlet", If(h.View.LastMessage, ""))
        Assert.True(w.Time > 0, "time did not move")
        ' The spring pulls the box along the table (no friction), and the pendulum swings.
        Assert.True(box.Position.X > start.X + 0.01, $"the box is at {box.Position}")
        Assert.Equal(0.5, box.Position.Y, 9)
        Assert.True(bob.Position.Y < 3.0, $"the bob is at {bob.Position}")
    End Sub
End Class
