Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>Time controls: stepping, stepping back, the timeline, exact replay and the memory limit.</summary>
Public Class TimeTravelTests
    ''' <summary>Every movable body's position and velocity, to the last bit.</summary>
    Private Shared Function State(w As World) As String
        Dim inv = Globalization.CultureInfo.InvariantCulture
        Return String.Join(";", w.Movables.Select(Function(b) b.Id & " " & b.Position.X.ToString("R", inv) & " " & b.Position.Y.ToString("R", inv) & " " &
                                                              b.Velocity.X.ToString("R", inv) & " " & b.Velocity.Y.ToString("R", inv)))
    End Function

    ''' <summary>Twelve balls in a 6 m × 4 m box under gravity, at e = 0.9: a run with many collisions and bounces.</summary>
    Private Shared Function BouncyHarness() As PresenterHarness
        Dim w As New World(6.0, 4.0, 9.81, 0.9)
        Dim rng As New Random(7)
        For i = 0 To 11
            w.Add(New Circle(New Vector(0.5 + (i Mod 6) * 0.95, 1.0 + (i \ 6) * 1.2), 0.2, 1.0 + (i Mod 3), New Vector(rng.NextDouble() * 6 - 3, rng.NextDouble() * 6 - 3), "b" & i))
        Next
        ' Given to the presenter as the scene it opens: that is the start Restart goes back to.
        Return New PresenterHarness(w)
    End Function

    <Fact>
    Public Sub Rewind_ThenReplay_EndsBitForBitWhereTheFirstRunEnded_WithACueShotAndADrag()
        Dim h = BouncyHarness()
        Dim states As New Dictionary(Of Integer, (Time As Double, State As String))
        Dim frame = 0
        Dim tick = Sub()
                       h.P.Tick(1 / 60.0)
                       frame += 1
                       states(frame) = (h.P.World.Time, State(h.P.World))
                   End Sub
        For k = 1 To 40
            tick()
        Next
        ' A cue shot on b3 while running.
        Dim b3 = h.P.World.Find("b3")
        Dim a = h.P.View.ToScreen(b3.Position)
        h.P.PointerDown(PointerButton.Left, a.X, a.Y)
        h.P.PointerMove(a.X - 60, a.Y)
        h.P.PointerUp(PointerButton.Left, a.X - 60, a.Y)
        ' At the moment of a change the run shows the state after it (a rewind to that time does too).
        states(frame) = (h.P.World.Time, State(h.P.World))
        For k = 1 To 20
            tick()
        Next
        ' Carry b5 for a while with the right button, with time running.
        Dim b5 = h.P.World.Find("b5")
        Dim p = h.P.View.ToScreen(b5.Position)
        h.P.PointerDown(PointerButton.Right, p.X, p.Y)
        states(frame) = (h.P.World.Time, State(h.P.World))
        For k = 1 To 10
            h.P.PointerMove(p.X + 4 * k, p.Y - 3 * k)
            tick()
        Next
        h.P.PointerUp(PointerButton.Right, p.X + 40, p.Y - 30)
        states(frame) = (h.P.World.Time, State(h.P.World))
        For k = 1 To 120
            tick()
        Next
        Dim endTime = h.P.World.Time
        Dim endState = State(h.P.World)
        Assert.True(h.P.Log.TotalSeen > 20, "the run has collisions")
        Dim endCollisions = h.P.Log.TotalSeen

        ' Back to frame 30 (before the cue and the drag): the table is the state recorded there.
        h.P.RewindTo(states(30).Time)
        Assert.True(h.P.IsPaused)
        Assert.Equal(states(30).Time, h.P.World.Time)
        Assert.Equal(states(30).State, State(h.P.World))
        Dim row = Enumerable.Range(0, h.P.Snapshot.RowCount(0)).Select(Function(i) h.P.Snapshot.Row(0, i)).First(Function(r) r.Id = "b0")
        Assert.Equal(h.P.World.Find("b0").Position, row.Position)

        ' Going back into the carry stops at its start: the carry is kept as its two ends.
        h.P.RewindTo(states(65).Time)
        Assert.Equal(states(60).Time, h.P.World.Time)
        Assert.Equal(states(60).State, State(h.P.World))

        ' Replay forward in frames of the same length: the same run, to the last bit, through the cue and
        ' the drag (where the carried ball is while carried is not kept; from the moment it is let go, it is).
        h.P.RewindTo(states(30).Time)
        h.P.TogglePause()
        For k = 31 To frame
            h.P.Tick(1 / 60.0)
            If k > 60 AndAlso k < 70 Then Continue For
            Assert.True(states(k).Time = h.P.World.Time, "time at frame " & k)
            Assert.True(states(k).State = State(h.P.World), "state at frame " & k & ": " & states(k).State & " <> " & State(h.P.World))
        Next
        Assert.Equal(endTime, h.P.World.Time)
        Assert.Equal(endState, State(h.P.World))
        Assert.Equal(endCollisions, h.P.Log.TotalSeen)
    End Sub

    <Fact>
    Public Sub ScrubbingTheTimeline_ToEveryRecordedFrame_ShowsTheStateRecordedThere()
        Dim h = BouncyHarness()
        Dim states As New List(Of (Time As Double, State As String))
        For k = 1 To 90
            h.P.Tick(1 / 60.0)
            If k = 45 Then h.P.SetRestitution(0.5)
            states.Add((h.P.World.Time, State(h.P.World)))
        Next
        Dim latest = h.P.Timeline.Latest
        Assert.Equal(states(states.Count - 1).Time, latest)
        ' Backwards, then forwards again, past the change of e.
        For Each i In {80, 50, 44, 10, 0, 60, 89}
            h.P.RewindTo(states(i).Time)
            Assert.Equal(states(i).State, State(h.P.World))
            Assert.Equal(If(i >= 44, 0.5, 0.9), h.P.World.Restitution)
        Next
        ' The slider's ends are the first and the latest moment.
        h.P.TimelineSliderMoved(SimulationPresenter.TimelineSteps)
        Assert.Equal(latest, h.P.World.Time)
        Assert.Equal(states(89).State, State(h.P.World))
        h.P.TimelineSliderMoved(0)
        Assert.Equal(0.0, h.P.World.Time)
        Assert.Equal(0, h.P.TimelinePosition)
    End Sub

    <Fact>
    Public Sub StepToNextCollision_LandsAtTheClosedFormTime_WithTheImpulseGiven()
        ' Head-on: 3.6 m of gap closing at 2 m/s, so contact at t = 1.8 s; equal masses at e = 1 swap velocities.
        Dim h As New PresenterHarness(New World(8.0, 5.0, 0.0, 1.0))
        h.P.World.Add(New Circle(New Vector(2, 2.5), 0.2, 1.0, New Vector(1, 0), "a"))
        h.P.World.Add(New Circle(New Vector(6, 2.5), 0.2, 1.0, New Vector(-1, 0), "b"))
        h.P.Tick(0.25)
        h.P.StepToNextCollision()
        Assert.True(h.P.IsPaused)
        Assert.Equal(1.8, h.P.World.Time, 12)
        Assert.Equal(-1.0, h.P.World.Find("a").Velocity.X, 12)
        Assert.Equal(1.0, h.P.World.Find("b").Velocity.X, 12)
        Assert.Equal(1L, h.P.Log.TotalSeen)
        Assert.Contains("Collision 1: a ↔ b", h.View.LastMessage)
        ' The next one: from x = 3.8 and 4.2 each ball reaches its wall (x = 0.2 and 7.8) 3.6 m away at 1 m/s, at t = 5.4 s.
        h.P.StepToNextCollision()
        Assert.Equal(5.4, h.P.World.Time, 12)
        ' And back: the previous collision is the head-on one again.
        h.P.StepToPreviousCollision()
        Assert.Equal(1.8, h.P.World.Time, 12)
        Assert.Equal(-1.0, h.P.World.Find("a").Velocity.X, 12)
        Assert.Equal(1L, h.P.Log.TotalSeen)
    End Sub

    <Fact>
    Public Sub StepToNextCollision_LandsOnTheTimeTheEventSolverReports()
        Dim h = BouncyHarness()
        h.P.Tick(0.5)
        Dim start = h.P.World.Time
        ' An independent run of the same scene finds the first collision after the start.
        Dim copy = Scenes.SceneFile.Load(h.P.Timeline.Points(h.P.Timeline.Points.Count - 1).Scene)
        copy.Solver = SolverFactory.Create("event")
        Dim first As Double? = Nothing
        copy.CollisionListener = Sub(r) If Not first.HasValue AndAlso r.Time > start Then first = r.Time
        copy.Advance(start + 5)
        h.P.StepToNextCollision()
        Assert.True(first.HasValue)
        Assert.Equal(first.Value, h.P.World.Time, 9)
    End Sub

    <Fact>
    Public Sub StepAndStepBack_MoveOneFrame()
        Dim h = BouncyHarness()
        h.P.Tick(1 / 60.0)
        h.P.Tick(1 / 60.0)
        h.P.StepFrame()
        Assert.True(h.P.IsPaused)
        Dim t3 = h.P.World.Time
        Dim s3 = State(h.P.World)
        Assert.Equal(3 / 60.0, t3, 12)
        h.P.StepFrame()
        Assert.Equal(4 / 60.0, h.P.World.Time, 12)
        h.P.StepBackFrame()
        Assert.Equal(t3, h.P.World.Time, 15)
        h.P.StepBackFrame()
        h.P.StepBackFrame()
        h.P.StepBackFrame()
        Assert.Equal(0.0, h.P.World.Time, 15)
        h.P.StepBackFrame() ' at the start it stays there
        Assert.Equal(0.0, h.P.World.Time)
        h.P.RewindTo(t3)
        Assert.Equal(s3, State(h.P.World))
    End Sub

    <Fact>
    Public Sub AChangeAfterRewinding_EndsTheRecordedFuture()
        Dim h = BouncyHarness()
        For k = 1 To 60
            h.P.Tick(1 / 60.0)
        Next
        Dim t = 20 / 60.0
        h.P.RewindTo(t)
        Assert.True(h.P.Timeline.Latest > 0.9)
        h.P.SetGravity(1.62)
        Assert.Equal(h.P.World.Time, h.P.Timeline.Latest)
        Assert.All(h.P.Timeline.Points, Sub(p) Assert.True(p.Time <= h.P.World.Time))
        ' Stepping on now runs the Moon's gravity.
        h.P.StepFrame()
        Assert.Equal(1.62, h.P.World.Gravity)
        Assert.True(h.P.Timeline.Latest > t)
    End Sub

    <Fact>
    Public Sub GoingBack_IsNotBuilding_RestartStillGoesToTheStart()
        Dim h = BouncyHarness()
        h.P.Tick(1 / 60.0)
        Dim start = h.P.Timeline.Points(0)
        Dim startState = State(Timeline.Build(start))
        For k = 1 To 60
            h.P.Tick(1 / 60.0)
        Next
        Dim kept = h.TraceLines.Where(Function(l) l.StartsWith("start kept", StringComparison.Ordinal)).Count()
        h.P.RewindTo(0.5)
        h.P.StepBackFrame()
        Assert.Equal(kept, h.TraceLines.Where(Function(l) l.StartsWith("start kept", StringComparison.Ordinal)).Count())
        h.P.Restart()
        Assert.Equal(0.0, h.P.World.Time)
        Assert.Equal(startState, State(h.P.World))
        ' Restart begins a new run: its timeline holds only the new run's start (taken as the scene is
        ' put on show, not in its first frame).
        Dim only = Assert.Single(h.P.Timeline.Points)
        Assert.Equal(0.0, only.Time)
        Assert.Equal(startState, State(Timeline.Build(only)))
    End Sub

    <Fact>
    Public Sub ALongRun_KeepsAtMostTheLimit_AndTheTimelinesStartMovesOn()
        ' A change of g every frame makes a checkpoint every frame: past the limit the oldest go.
        Dim h = BouncyHarness()
        Dim frames = Timeline.MaxCheckpoints + 150
        For k = 1 To frames
            h.P.SetGravity(If(k Mod 2 = 0, 9.81, 9.8))
            h.P.Tick(1 / 60.0)
        Next
        Dim tl = h.P.Timeline
        Assert.Equal(Timeline.MaxCheckpoints, tl.Points.Count)
        Assert.True(tl.Dropped >= 150)
        Assert.True(tl.Bytes <= Timeline.MaxBytes)
        Assert.True(tl.Earliest > 2.0, "the start moved on past the dropped checkpoints")
        ' Going back further than kept lands on the earliest moment kept.
        h.P.RewindTo(0)
        Assert.Equal(tl.Earliest, h.P.World.Time)
        Assert.Contains("kept " & Units.Sig(tl.Earliest), h.P.TimelineText)
    End Sub

    <Fact>
    Public Sub ASceneRunWithTheVerletSolver_GoesBack_CloseToWhereItWas()
        ' Three balls on two rods beside a box resting on a fixed table on a level spring (at its natural length,
        ' so it pulls nothing yet), run with the Verlet solver chosen from the solver menu.
        Dim h As New PresenterHarness(New World(8.0, 5.0, 9.81, 1.0))
        Dim a = h.Ball(3, 3, id:="a"), b = h.Ball(4, 3, id:="b"), c = h.Ball(5, 3, id:="c")
        h.P.World.Add(Link.CreateTie(LinkKind.Rod, a, b, 1.0))
        h.P.World.Add(Link.CreateTie(LinkKind.Rod, b, c, 1.0))
        h.P.World.Add(New PhysicsEngine.Rectangle(New Vector(6.25, 0.0), 1.0, 0.5, "table"))
        Dim box = PhysicsEngine.Rectangle.CreateMovable(New Vector(6.5, 0.5), 0.3, 0.2, 2.0, Vector.Zero, "box")
        h.P.World.Add(box)
        h.P.World.Add(Link.CreateSpring(box, New Vector(7.15, 0.6), 10, 0.5))
        h.P.ChooseSolver("verlet")
        h.P.StepFrame()
        Assert.Equal("verlet", h.P.World.Solver.Name)
        Assert.Equal(1 / 60.0, h.P.World.Time, 12)
        Dim states As New List(Of String)
        For k = 1 To 20
            h.P.StepFrame()
            states.Add(State(h.P.World))
        Next
        Assert.True(h.P.World.Find("b").Position.Y < 3.0, "the chain falls")
        h.P.RewindTo(6 / 60.0)
        Assert.Equal(6 / 60.0, h.P.World.Time, 12)
        Assert.Equal("verlet", h.P.World.Solver.Name)
        ' Verlet keeps state of its own too (the previous positions), which a checkpoint does not hold: close, not to the last bit.
        Dim expected = states(4).Split(" "c, ";"c), actual = State(h.P.World).Split(" "c, ";"c)
        Assert.Equal(expected.Length, actual.Length)
        For i = 0 To expected.Length - 1
            Dim x As Double, y As Double
            If Double.TryParse(expected(i), Globalization.NumberStyles.Float, Globalization.CultureInfo.InvariantCulture, x) AndAlso
               Double.TryParse(actual(i), Globalization.NumberStyles.Float, Globalization.CultureInfo.InvariantCulture, y) Then
                Assert.Equal(x, y, 9)
            Else
                Assert.Equal(expected(i), actual(i))
            End If
        Next
    End Sub

    <Fact>
    Public Sub ALargeScene_IsLimitedByMemory()
        ' 1000 balls: each checkpoint is a few hundred kilobytes, so the byte limit comes first.
        Dim h As New PresenterHarness(Scenarios.ElasticGas(1000, 0.1, 0.05, 3))
        For k = 1 To 400
            h.P.SetRestitution(If(k Mod 2 = 0, 1.0, 0.99))
            h.P.Tick(1 / 60.0)
        Next
        Dim tl = h.P.Timeline
        Assert.True(tl.Dropped > 0)
        Assert.True(tl.Points.Count < 400)
        Assert.True(tl.Bytes <= Timeline.MaxBytes)
        Assert.True(tl.Bytes > Timeline.MaxBytes - 2 * tl.Points(0).Bytes)
    End Sub
End Class
