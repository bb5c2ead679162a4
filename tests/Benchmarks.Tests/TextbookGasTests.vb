Option Strict On
Imports PhysicsEngine
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>
''' The textbook baseline the benchmark times beside the engine: it must simulate the same gas
''' (or its figures would compare different work), so it is checked against the engine's
''' event-driven solver, written independently, and against the conservation laws.
''' </summary>
Public Class TextbookGasTests
    ''' <summary>
    ''' Both are exact, so they agree on the same gas until chaos amplifies rounding: in a dilute gas
    ''' every collision magnifies a difference about tenfold, so only the first few collisions per
    ''' ball can be compared closely.
    ''' </summary>
    <Theory>
    <InlineData(40, 1)>
    <InlineData(40, 2)>
    <InlineData(200, 3)>
    Public Sub SameGas_SameCollisionsAndCoursesAsTheEngine(count As Integer, seed As Integer)
        Dim engine = Scenarios.ElasticGas(count, 0.1, seed:=seed)
        engine.Solver = New EventDrivenSolver()
        Dim baseline As New TextbookGas(Scenarios.ElasticGas(count, 0.1, seed:=seed))
        Dim duration = CollisionTimeFor(Scenarios.ElasticGas(count, 0.1, seed:=seed), 2 * count)
        engine.Advance(duration)
        baseline.Advance(duration)
        Assert.True(engine.CollisionCount >= count, $"only {engine.CollisionCount} collisions: the comparison would say little")
        Assert.Equal(engine.CollisionCount, baseline.CollisionCount)
        Assert.Equal(engine.Time, baseline.Time, 12)
        For i = 0 To count - 1
            Dim c = engine.Circles(i)
            Assert.True((c.Position - baseline.PositionOf(i)).Length < 1.0E-9, $"ball {i}: {c.Position} against {baseline.PositionOf(i)}")
            Assert.True((c.Velocity - baseline.VelocityOf(i)).Length < 1.0E-9, $"ball {i}: {c.Velocity} against {baseline.VelocityOf(i)}")
        Next
    End Sub

    ''' <summary>Simulated seconds in which the engine's gas has about <paramref name="collisions"/> collisions (two per ball).</summary>
    Private Shared Function CollisionTimeFor(world As World, collisions As Integer) As Double
        world.Solver = New EventDrivenSolver()
        Dim t = 0.0
        Do While world.CollisionCount < collisions
            world.Advance(0.001)
            t += 0.001
        Loop
        Return t
    End Function

    <Fact>
    Public Sub LongRun_ConservesEnergy_AndNoDiscOverlapsOrLeavesTheBox()
        Dim world = Scenarios.ElasticGas(300, 0.1)
        Dim e0 = world.Circles.Sum(Function(c) c.KineticEnergy)
        Dim gas As New TextbookGas(world)
        Do While gas.CollisionCount < 200_000
            gas.Advance(1.0)
        Loop
        Assert.Equal(0.0, (gas.KineticEnergy() - e0) / e0, 12)
        Dim radius = world.Circles(0).Radius
        For i = 0 To world.Circles.Count - 1
            Dim p = gas.PositionOf(i)
            Assert.InRange(p.X, radius - 1.0E-9, world.Width - radius + 1.0E-9)
            Assert.InRange(p.Y, radius - 1.0E-9, world.Height - radius + 1.0E-9)
            For j = i + 1 To world.Circles.Count - 1
                Assert.True((p - gas.PositionOf(j)).Length >= 2 * radius - 1.0E-9, $"discs {i} and {j} overlap")
            Next
        Next
        Assert.InRange(gas.EventCount / CDbl(gas.CollisionCount), 1.5, 6.0)
    End Sub

    ''' <summary>
    ''' One big disc makes the cells wide, so a cell holds more small discs than its first room and
    ''' the lists must grow; mixed radii and masses exercise the general impulse. Still the engine's result.
    ''' </summary>
    <Fact>
    Public Sub CrowdedCellsAndMixedMasses_StillTheEnginesCollisions()
        Dim build = Function()
                        Dim w As New World(1.0, 1.0, 0.0, 1.0)
                        w.Add(New Circle(New Vector(0.5, 0.5), 0.12, 20.0, New Vector(0.3, -0.2)))
                        Dim rng As New Random(7)
                        For k = 0 To 99
                            Dim x = 0.05 + 0.1 * (k Mod 10), y = 0.05 + 0.1 * (k \ 10)
                            If Math.Abs(x - 0.5) < 0.2 AndAlso Math.Abs(y - 0.5) < 0.2 Then Continue For ' the big disc's place
                            w.Add(New Circle(New Vector(x + 0.01 * (k Mod 3), y), 0.01 + 0.005 * (k Mod 4), 0.5 + (k Mod 5),
                                             New Vector(rng.NextDouble() - 0.5, rng.NextDouble() - 0.5)))
                        Next
                        Return w
                    End Function
        Dim engine = build()
        engine.Solver = New EventDrivenSolver()
        Dim baseline As New TextbookGas(build())
        engine.Advance(0.5)
        baseline.Advance(0.5)
        Assert.True(engine.CollisionCount >= 10, $"only {engine.CollisionCount} collisions")
        Assert.Equal(engine.CollisionCount, baseline.CollisionCount)
        For i = 0 To engine.Circles.Count - 1
            Assert.True((engine.Circles(i).Position - baseline.PositionOf(i)).Length < 1.0E-9, $"disc {i}")
        Next
    End Sub

    <Fact>
    Public Sub WhatTheBaselineDoesNotModel_IsRefused()
        Dim falling = Scenarios.ElasticGas(10, 0.1)
        falling.Gravity = 9.81
        Assert.Throws(Of ArgumentException)(Function() New TextbookGas(falling))
        Dim inelastic = Scenarios.ElasticGas(10, 0.1)
        inelastic.Restitution = 0.9
        Assert.Throws(Of ArgumentException)(Function() New TextbookGas(inelastic))
        Dim withBlock = Scenarios.ElasticGas(10, 0.1)
        withBlock.Add(New PhysicsEngine.Rectangle(New Vector(0, 0), 0.01, 0.01))
        Assert.Throws(Of ArgumentException)(Function() New TextbookGas(withBlock))
    End Sub

    <Fact>
    Public Sub SolversForTheGas_PutTheBaselineRightAfterTheEventSolver_AndOnlyWithIt()
        Assert.Equal(Values("euler", "event", "textbook", "verlet"), GasScaling.SolversFor(Values("euler", "event", "verlet")))
        Assert.Equal(Values("euler", "verlet"), GasScaling.SolversFor(Values("euler", "verlet")))
        Assert.Equal(Values("event", "textbook"), GasScaling.SolversFor(Values("event", "textbook")))
    End Sub

    <Fact>
    Public Sub TheGasTimeStep_IsTheEverydayStepForASteppingSolver_AndNoneForTheEventSolverOrTheBaseline()
        Assert.Equal((True, CType(0.001, Double?)), GasScaling.TimeStepFor("euler"))
        Assert.Equal((True, CType(0.001, Double?)), GasScaling.TimeStepFor("verlet"))
        Assert.Equal((True, CType(Nothing, Double?)), GasScaling.TimeStepFor("event"))
        Assert.Equal((True, CType(Nothing, Double?)), GasScaling.TimeStepFor("textbook"))
        Assert.False(GasScaling.TimeStepFor("no-such-solver").Available)
    End Sub
End Class
