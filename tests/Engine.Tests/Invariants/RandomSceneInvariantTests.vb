Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>What must hold in any scene: no NaN, nothing escapes the walls, energy never grows.</summary>
Public Class RandomSceneInvariantTests
    ' Relative energy growth allowed. Nothing in the model adds energy when e ≤ 1 and nothing is dragged:
    ' semi-implicit Euler loses ½ g² dt² per kg per step, position Verlet keeps it exactly in free flight,
    ' impulses with e ≤ 1 never add kinetic energy, and the lift out of an obstacle is paid from the normal
    ' speed. What is left is rounding: Verlet's velocity is a difference of positions, so each step carries
    ' an error of about one unit in the last place of a position (~4e-16 m) divided by dt, which has been
    ' seen to add up to ~1e-12 of the energy over a run. 1e-9 is far above that and far below what a real
    ' leak does (lifting a ball by one step's penetration, v dt, without paying is ~1e-3 of its energy).
    Private Const EnergyTolerance As Double = 1.0E-9

    <Theory>
    <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
    Public Sub RandomScenes_StayFinite_StayInside_AndNeverGainEnergy(solver As String)
        For seed = 1 To 12
            ' g = 0 every third scene; e cycles through 0.25, 0.5, 0.75, 1.
            Dim g = If(seed Mod 3 = 0, 0.0, 9.81)
            Dim e = If(seed Mod 4 = 0, 1.0, (seed Mod 4) / 4.0)
            Dim w = TestSolvers.Run(RandomScenes.Build(seed, 40, g, e), solver)
            Dim e0 = RandomScenes.Energy(w)
            For stepIndex = 1 To 1000
                w.Advance(0.001)
                For Each c In w.Circles
                    If Not (c.Position.IsFinite AndAlso c.Velocity.IsFinite) Then Assert.Fail($"seed {seed}: circle {c.Id} is not finite at t = {w.Time}")
                    If c.IsFixed Then Continue For
                    Const slack = 1.0E-9 ' m: rounding of the wall projection
                    Assert.InRange(c.Position.X, c.Radius - slack, w.Width - c.Radius + slack)
                    Assert.InRange(c.Position.Y, c.Radius - slack, w.Height - c.Radius + slack)
                Next
                Dim energy = RandomScenes.Energy(w)
                If energy > e0 * (1 + EnergyTolerance) Then Assert.Fail($"seed {seed} (g {g}, e {e}): energy grew from {e0} J to {energy} J at t = {w.Time}")
            Next
            Assert.True(w.CollisionCount > 0, $"seed {seed}: nothing collided, so the scene tested nothing")
        Next
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
    Public Sub EveryCircleCircleCollision_ConservesMomentum(solver As String)
        ' g = 0 and e = 0 or 1: every reported circle–circle impulse must conserve m_a v_a + m_b v_b.
        For Each e In {0.0, 1.0}
            Dim w = TestSolvers.Run(RandomScenes.Build(7, 40, 0.0, e), solver)
            Dim checkedCount = 0
            w.CollisionListener =
                Sub(r)
                    If r.Kind <> CollisionKind.CircleCircle Then Return
                    Dim b = DirectCast(r.B, Circle)
                    Dim before = r.AVelocityBefore * r.A.Mass + r.BVelocityBefore * b.Mass
                    Dim after = r.AVelocityAfter * r.A.Mass + r.BVelocityAfter * b.Mass
                    Dim scale = r.AVelocityBefore.Length * r.A.Mass + r.BVelocityBefore.Length * b.Mass
                    If (after - before).Length > 1.0E-12 * scale Then Assert.Fail($"momentum changed by {(after - before).Length} in a collision of {r.A.Id} and {b.Id}")
                    checkedCount += 1
                End Sub
            w.Advance(1.0)
            Assert.True(checkedCount > 10, "too few circle–circle collisions to test")
        Next
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
    Public Sub WithoutWallsOrObstacles_TotalMomentumIsConserved(solver As String)
        ' An elastic gas with the walls off: only circle–circle impulses act. Euler keeps every velocity
        ' between impulses exactly; Verlet re-derives it from positions each step (a rounding of ~1e-16 m
        ' over 1e-3 s), so the total drifts by ~1e-13 per step at worst: allow 1e-9 relative over 1000 steps.
        For Each e In {0.0, 1.0}
            Dim w = Scenarios.ElasticGas(200, 0.3, seed:=3)
            w.Walls = False
            w.Restitution = e
            TestSolvers.Run(w, solver)
            Dim p0 = w.Momentum()
            Dim scale = 0.0
            For Each c In w.Circles
                scale += c.Mass * c.Velocity.Length
            Next
            w.Advance(1.0)
            Assert.True(w.CollisionCount > 50, "too few collisions to test")
            Assert.True((w.Momentum() - p0).Length <= 1.0E-9 * scale, $"e = {e}: momentum moved from {p0} to {w.Momentum()}")
        Next
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
    Public Sub AppPresets_StayFiniteAndInside(solver As String)
        For Each w In {Scenarios.Demo(), Scenarios.Pile(100, 0.3), Scenarios.NewtonsCradle(), Scenarios.ElasticGas(300, 0.2)}
            TestSolvers.Run(w, solver)
            Dim e0 = RandomScenes.Energy(w)
            TestSolvers.Frames(w, 3.0, 1.0 / 60, Sub()
                                                      For Each c In w.Circles
                                                          If Not (c.Position.IsFinite AndAlso c.Velocity.IsFinite) Then Assert.Fail($"circle {c.Id} is not finite at t = {w.Time}")
                                                          If c.IsFixed OrElse Not w.Walls Then Continue For
                                                          Assert.InRange(c.Position.X, c.Radius - 1.0E-9, w.Width - c.Radius + 1.0E-9)
                                                          Assert.InRange(c.Position.Y, c.Radius - 1.0E-9, w.Height - c.Radius + 1.0E-9)
                                                      Next
                                                  End Sub)
            Assert.InRange(RandomScenes.Energy(w), Double.NegativeInfinity, e0 * (1 + EnergyTolerance) + 1.0E-12)
        Next
    End Sub
End Class
