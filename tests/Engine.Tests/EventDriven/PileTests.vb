Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>A dense inelastic pile must settle: bounded events, no overlap, nothing escapes, energy at its floor.</summary>
Public Class PileTests
    <Fact>
    Public Sub Pile_OfTwoHundred_AtE03_Settles()
        Dim w = Scenarios.Pile(200, 0.3)
        Dim solver = UseEventSolver(w)
        solver.MaxEventsPerAdvance = 5000000
        Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
        Dim worst = 0.0
        For k = 1 To 10
            w.Advance(0.5)
            worst = Math.Max(worst, DeepestOverlap(w))
        Next
        Dim settledCollisions = w.CollisionCount
        Dim settledEvents = solver.EventCount
        w.Advance(5.0)
        worst = Math.Max(worst, DeepestOverlap(w))
        ' Bounded: the whole fall and settling took far fewer than a million collisions, and once
        ' settled nothing more happens.
        Assert.True(settledCollisions < 1000000, $"{settledCollisions} collisions")
        Assert.True(w.CollisionCount - settledCollisions < 100, $"{w.CollisionCount - settledCollisions} collisions after settling")
        Assert.True(solver.EventCount - settledEvents < 1000)
        Assert.True(worst <= 1.0E-6, $"overlap {worst} m")
        Dim mass = 0.0, area = 0.0
        For Each c In w.Circles
            Assert.True(c.Position.X >= c.Radius - 1.0E-9 AndAlso c.Position.X <= w.Width - c.Radius + 1.0E-9, $"{c.Id} escaped: {c.Position}")
            Assert.True(c.Position.Y >= c.Radius - 1.0E-9 AndAlso c.Position.Y <= w.Height - c.Radius + 1.0E-9, $"{c.Id} escaped: {c.Position}")
            mass += c.Mass
            area += c.Area
        Next
        ' Energy at its floor: no motion left, and the centre of mass no higher than half the height of
        ' the same circles packed loosely (packing fraction 0.6) against the floor.
        Assert.True(w.KineticEnergy() < 1.0E-9 * e0, $"KE {w.KineticEnergy()}")
        Dim looseHeight = area / (w.Width * 0.6)
        Assert.True(w.PotentialEnergy() < mass * w.Gravity * (looseHeight / 2 + 0.05), $"PE {w.PotentialEnergy()} vs {mass * w.Gravity * (looseHeight / 2 + 0.05)}")
        For Each c In w.Circles
            Assert.True(solver.IsAsleep(c), $"{c.Id} still awake")
        Next
    End Sub
End Class
