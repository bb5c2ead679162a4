Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>
''' Why checkpoints are taken where the run restarts its solver: a state rebuilt from positions and
''' velocities at any other moment does not replay the run to the last bit (the solver's predictions
''' were made at earlier times, and resting contacts are its own state); one taken where the run
''' itself restarted does.
''' </summary>
Public Class CheckpointExactnessTests
    Private Shared Function Bouncy() As World
        Dim w As New World(6.0, 4.0, 9.81, 0.9)
        Dim rng As New Random(11)
        For i = 0 To 11
            w.Add(New Circle(New Vector(0.5 + (i Mod 6) * 0.95, 1.0 + (i \ 6) * 1.2), 0.2, 1.0 + (i Mod 3), New Vector(rng.NextDouble() * 6 - 3, rng.NextDouble() * 6 - 3), "b" & i))
        Next
        Return w
    End Function

    Private Shared Function State(w As World) As Double()
        Return w.Movables.SelectMany(Function(b) {b.Position.X, b.Position.Y, b.Velocity.X, b.Velocity.Y}).ToArray()
    End Function

    <Fact>
    Public Sub ARebuiltState_ReplaysExactly_OnlyWhereTheRunRestarted()
        ' The first run: 1 s in frames, then 3 s more.
        Dim original = Bouncy()
        original.Solver = SolverFactory.Create("event")
        For k = 1 To 60
            original.Advance(1 / 60.0)
        Next
        Dim midway = Timeline.Take(original, "event", 0)
        original.Advance(3.0)

        ' A copy of the positions and velocities at 1 s, with a fresh solver: not the same run.
        Dim rebuilt = Timeline.Build(midway)
        rebuilt.Solver = SolverFactory.Create("event")
        rebuilt.Advance(3.0)
        Assert.Equal(original.Time, rebuilt.Time)
        Assert.NotEqual(State(original), State(rebuilt))

        ' The same, where the first run restarted its solver at 1 s (as a recorded run does at a checkpoint): the same run.
        Dim restarted = Bouncy()
        restarted.Solver = SolverFactory.Create("event")
        For k = 1 To 60
            restarted.Advance(1 / 60.0)
        Next
        Dim point = Timeline.Take(restarted, "event", 0)
        restarted.Solver.Invalidate(Nothing)
        restarted.Advance(3.0)
        Dim replayed = Timeline.Build(point)
        replayed.Solver = SolverFactory.Create("event")
        replayed.Advance(3.0)
        Assert.Equal(restarted.Time, replayed.Time)
        Assert.Equal(State(restarted), State(replayed))
    End Sub
End Class
