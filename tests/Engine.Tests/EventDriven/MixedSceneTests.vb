Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>Invariants under random mixed scenes: rectangles, fixed circles, gravity, any e.</summary>
Public Class MixedSceneTests
    <Theory>
    <InlineData(0.0, 17)>
    <InlineData(0.5, 22)>
    <InlineData(0.9, 26)>
    <InlineData(1.0, 27)>
    Public Sub RandomMixedScene_NeverOverlaps_NeverEscapes_AndInelasticOnesSettle(e As Double, seed As Integer)
        Dim w As New World(6, 4, 9.81, e)
        w.Add(New Rectangle(New Vector(1, 0.5), 1.5, 0.3))
        w.Add(New Rectangle(New Vector(3.5, 1.2), 0.2, 1.5))
        w.Add(Circle.CreateFixed(New Vector(2.5, 2.0), 0.3))
        w.Add(Circle.CreateFixed(New Vector(5, 1.0), 0.15))
        Dim rng As New Random(seed)
        For k = 1 To 200
            w.Add(New Circle(New Vector(rng.NextDouble() * 6, 2 + rng.NextDouble() * 2), 0.02 + 0.04 * rng.NextDouble(), 1.0,
                             New Vector(rng.NextDouble() * 4 - 2, rng.NextDouble() * 4 - 2)))
        Next
        Dim solver = UseEventSolver(w)
        solver.MaxEventsPerAdvance = 5000000
        w.Advance(1.0E-9) ' spawn overlaps are pushed apart first, which moves bodies
        Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
        RunChecked(w, 10, 0.5, maxOverlap:=1.0E-9)
        For Each c In w.Circles
            Assert.True(c.Position.IsFinite AndAlso c.Velocity.IsFinite)
        Next
        If e < 1 Then
            Assert.True(w.KineticEnergy() < 0.01 * e0, $"KE {w.KineticEnergy()} of {e0}")
        Else
            Dim drift = Math.Abs(w.KineticEnergy() + w.PotentialEnergy() - e0) / e0
            Assert.True(drift < 1.0E-9, $"energy drift {drift}")
        End If
    End Sub
End Class
