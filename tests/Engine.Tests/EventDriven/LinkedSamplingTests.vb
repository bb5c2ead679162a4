Option Strict On
Imports PhysicsEngine
Imports PhysicsEngine.Scenes
Imports Xunit

Namespace EventDriven
    ''' <summary>
    ''' In a scene with links, as without, nothing depends on how a run is cut into advances: the same scene
    ''' advanced in one piece, every 0.05 s and every 0.013 s makes the same collisions (time, bodies,
    ''' velocities) and ends in the same state, to the bit (docs/event-driven.md, the links paragraph).
    ''' </summary>
    Public Class LinkedSamplingTests
        ''' <summary>
        ''' A pendulum on a string swinging right round, and three balls bouncing round the box, off the walls,
        ''' a fixed table and each other, e = 0.9, g = 9.81 m/s² (20 collisions in 2 s).
        ''' </summary>
        Private Shared Function Scene() As World
            Dim w As New World(4, 3, 9.81, 0.9)
            w.Solver = SolverFactory.Create("event")
            w.Add(New Rectangle(New Vector(2.6, 0), 0.8, 0.6, "table"))
            Dim bob As New Circle(New Vector(2, 1.2), 0.08, 1.0, New Vector(4.5, 0), "bob")
            w.Add(bob)
            w.Add(Link.CreateTie(LinkKind.String, bob, New Vector(2, 2.2), 1.0, "string"))
            w.Add(New Circle(New Vector(0.5, 2.0), 0.1, 0.3, New Vector(2.3, 1.1), "ball"))
            w.Add(New Circle(New Vector(1.0, 0.5), 0.12, 0.5, New Vector(-3.0, 2.0), "ball2"))
            w.Add(New Circle(New Vector(3.0, 2.5), 0.07, 0.2, New Vector(-1.5, -2.0), "ball3"))
            Return w
        End Function

        ''' <summary>Every collision of a run of 2 s advanced every <paramref name="sample"/> s, and the end state, as bits.</summary>
        Private Shared Function Run(sample As Double) As List(Of String)
            Return Run(Scene(), 2.0, sample)
        End Function

        ''' <summary>Every collision of world <paramref name="w"/> run for <paramref name="total"/> s advanced every <paramref name="sample"/> s, and the end state, as bits.</summary>
        Private Shared Function Run(w As World, total As Double, sample As Double) As List(Of String)
            Dim lines As New List(Of String)
            w.CollisionListener = Sub(c) lines.Add(String.Join(" ", Bits(c.Time), c.A.Id, c.BName, Bits(c.AVelocityBefore.X), Bits(c.AVelocityBefore.Y),
                                                               Bits(c.AVelocityAfter.X), Bits(c.AVelocityAfter.Y), Bits(c.BVelocityAfter.X), Bits(c.BVelocityAfter.Y)))
            Dim k = 0
            Do While w.Time < total
                k += 1
                w.Advance(Math.Min(k * sample, total) - w.Time)
            Loop
            For Each b In w.Movables
                lines.Add(String.Join(" ", b.Id, Bits(b.Position.X), Bits(b.Position.Y), Bits(b.Velocity.X), Bits(b.Velocity.Y)))
            Next
            Return lines
        End Function

        <Fact>
        Public Sub APendulumAndABall_MakeTheSameRun_WhateverTheAdvances()
            Dim whole = Run(2.0)
            ' Something happens: bounces off the walls, the table and each other (the last four lines are the end state).
            Assert.True(whole.Count - 4 >= 15, $"only {whole.Count - 4} collisions")
            For Each sample In {0.05, 0.013}
                AssertSameRun(whole, Run(sample), sample)
            Next
        End Sub

        ''' <summary>Fails unless run <paramref name="cut"/> (advanced every <paramref name="sample"/> s) is <paramref name="whole"/> line for line.</summary>
        Private Shared Sub AssertSameRun(whole As List(Of String), cut As List(Of String), sample As Double)
            Dim n = Math.Min(whole.Count, cut.Count)
            For i = 0 To n - 1
                Assert.True(whole(i) = cut(i), $"advanced every {sample} s, line {i} differs: '{cut(i)}', in one piece '{whole(i)}'")
            Next
            Assert.Equal(whole.Count, cut.Count)
        End Sub

        ''' <summary>
        ''' Six balls, no links, e = 0 (tests/cases/event-handed-over-mid-advance-sampled-two-ways.json): a jam at
        ''' t = 0.0035 s hands the world to the general path in the middle of an advance, which ran on to the advance's
        ''' start plus what was left of it, 0.012999999999999998 s where the world's clock said 0.013 s. The next advance
        ''' found the clocks apart and started the solver afresh, and collision 64 came out a unit in the last place
        ''' apart from the run advanced every 0.05 s. Advanced in one piece, every 0.013 s and every 0.0071 s, the runs
        ''' are now the same to the bit.
        ''' </summary>
        <Fact>
        Public Sub AWorldHandedOverMidAdvance_MakesTheSameRun_WhateverTheAdvances()
            Dim make = Function()
                           Dim w = SceneFile.LoadFile(TestRepo.CaseFile("event-handed-over-mid-advance-sampled-two-ways.json"))
                           w.Solver = SolverFactory.Create("event")
                           Return w
                       End Function
            Dim whole = Run(make(), 0.05, 0.05)
            Assert.True(whole.Count - 5 >= 64, $"only {whole.Count - 5} collisions")
            For Each sample In {0.013, 0.0071}
                AssertSameRun(whole, Run(make(), 0.05, sample), sample)
            Next
        End Sub
    End Class
End Namespace
