Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>The shared hard cases: coincident centres, spawn overlaps, mixed sizes, extreme gravity.</summary>
Public Class HardCaseTests
    <Fact>
    Public Sub CoincidentCentres_ArePushedApart_WithoutNaN()
        Dim w As New World(4, 4, 9.81, 0.8)
        For k = 1 To 3
            w.Add(New Circle(New Vector(2, 2), 0.2, 1.0))
        Next
        UseEventSolver(w)
        w.Advance(2.0)
        For Each c In w.Circles
            Assert.True(c.Position.IsFinite AndAlso c.Velocity.IsFinite)
        Next
        Assert.True(DeepestOverlap(w) <= 1.0E-9)
    End Sub

    <Fact>
    Public Sub SpawnOverlap_WithARectangleAndACircle_IsResolved()
        Dim w As New World(4, 4, 9.81, 0.5)
        w.Add(New Rectangle(New Vector(1, 0), 2, 1))
        w.Add(New Circle(New Vector(2, 0.95), 0.2, 1.0))
        w.Add(New Circle(New Vector(2.1, 1.1), 0.2, 1.0))
        UseEventSolver(w)
        w.Advance(3.0)
        Assert.True(DeepestOverlap(w) <= 1.0E-9)
    End Sub

    <Theory>
    <InlineData(0.0)>
    <InlineData(100.0)>
    Public Sub TinyAndHugeCircles_InOneScene_NeverOverlap(g As Double)
        Dim w As New World(10, 10, g, 0.9)
        w.Add(New Circle(New Vector(5, 5), 2.0, 100.0, New Vector(1, 0.5), "big"))
        Dim rng As New Random(11)
        For k = 1 To 60
            w.Add(New Circle(New Vector(0.5 + rng.NextDouble() * 9, 0.5 + rng.NextDouble() * 2), 0.001, 0.001,
                             New Vector(rng.NextDouble() * 4 - 2, rng.NextDouble() * 4 - 2)))
        Next
        w.Add(Circle.CreateFixed(New Vector(8, 8), 0.5))
        Dim solver = UseEventSolver(w)
        solver.MaxEventsPerAdvance = 2000000
        For k = 1 To 10
            w.Advance(0.3)
            Assert.True(DeepestOverlap(w) <= 1.0E-9, $"overlap {DeepestOverlap(w)} at {w.Time}")
        Next
        Assert.False(solver.GuardTripped)
        For Each c In w.Circles
            Assert.True(c.Position.IsFinite AndAlso c.Velocity.IsFinite)
        Next
    End Sub

    <Fact>
    Public Sub Demo_RunsWithoutOverlap()
        Dim w = Scenarios.Demo()
        Dim solver = UseEventSolver(w)
        For k = 1 To 20
            w.Advance(0.5)
            Assert.True(DeepestOverlap(w) <= 1.0E-9, $"overlap {DeepestOverlap(w)} at {w.Time}")
        Next
        Assert.False(solver.GuardTripped)
    End Sub
End Class
