Option Strict On
Imports Xunit

Namespace EventDriven
    ''' <summary>
    ''' World.Dissipated, the energy inelastic collisions, friction, drag and spring damping take: never negative,
    ''' never falling, zero when nothing is lost, and with the event solver energy + dissipated stays what the
    ''' energy was at the start, to rounding.
    ''' </summary>
    Public Class DissipatedTests
        Private Const G As Double = 9.81

        Private Shared Function Energy(w As World) As Double
            Return w.KineticEnergy() + w.PotentialEnergy()
        End Function

        <Fact>
        Public Sub AHeadOnBlow_TakesHalfMuOneLessESquaredUSquared()
            Dim w = Scenarios.HeadOn(1.0, 2.0, 3.0, -1.0, 0.5)
            w.Solver = SolverFactory.Create("event")
            w.Advance(3)
            Dim mu = 1.0 * 3.0 / 4.0, u = 3.0
            Assert.Equal(0.5 * mu * (1 - 0.25) * u * u, w.Dissipated, 12)
            Assert.Equal(0.5 * 1 * 4 + 0.5 * 3 * 1, Energy(w) + w.Dissipated, 12)
        End Sub

        <Theory>
        <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
        Public Sub ElasticScenes_LoseNothing(solver As String)
            Dim w = Scenarios.ElasticGas(200)
            TestSolvers.Run(w, solver)
            w.Advance(1)
            Assert.Equal(0.0, w.Dissipated)
            Dim p = Scenarios.Pendulum()
            TestSolvers.Run(p, solver)
            p.Advance(1)
            Assert.Equal(0.0, p.Dissipated)
        End Sub

        <Fact>
        Public Sub ABallBouncingToRest_EnergyPlusDissipatedStaysTheDropsEnergy()
            Dim w = Scenarios.BouncingBall(1.0, 0.6)
            w.Solver = SolverFactory.Create("event")
            Dim e0 = Energy(w)
            Dim previous = 0.0
            For k = 1 To 40
                w.Advance(0.05)
                Assert.True(w.Dissipated >= previous)
                previous = w.Dissipated
                Assert.True(Math.Abs(Energy(w) + w.Dissipated - e0) < 0.000000001 * e0, $"t = {w.Time}: {Energy(w)} + {w.Dissipated} against {e0}")
            Next
            ' At rest on the floor: all it had above the floor is gone.
            Assert.Equal(1.0 * G * 1.0, w.Dissipated, 9)
        End Sub

        ''' <summary>
        ''' A ball set at rest on a slope it would slide down (the shoulder of a ball asleep on the floor, or of a fixed
        ''' dome whose exact slide is refused because another ball lies beside it) leaves it by the slope hop
        ''' (RestRules.HopDownSlope): too slow to pay the hop from its speed, it first moves down the tangent by the
        ''' height that pays for it, h = u²/(2 g) = 10⁻⁶ r. That drop shows at once; and as the height pays for the
        ''' hop, kinetic + potential + dissipated energy stays what it was at the start to 10⁻⁹ over every later hop.
        ''' A hop given rather than paid (no drop), or paid and also counted as dissipated, is about 10⁻⁶ J a hop.
        ''' </summary>
        <Theory>
        <InlineData("sleeper", 0.0)>
        <InlineData("sleeper", 0.5)>
        <InlineData("sleeper", 1.0)>
        <InlineData("dome", 0.5)>
        <InlineData("dome", 1.0)>
        Public Sub AHopDownASlope_IsPaidByItsHeight_EnergyPlusDissipatedStays(support As String, restitution As Double)
            Const R As Double = 0.1
            Dim w As World
            Dim ball As Circle
            Dim solver As EventDrivenSolver
            If support = "sleeper" Then
                w = New World(4, 4, G, restitution)
                Dim below As New Circle(New Vector(2, R), R, 1.0, id:="below")
                w.Add(below)
                solver = UseEventSolver(w)
                w.Advance(0.1)
                Assert.True(solver.IsAsleep(below), "the ball on the floor should be asleep")
                ball = New Circle(below.Position + New Vector(Math.Sin(0.3), Math.Cos(0.3)) * (2 * R), R, 1.0, id:="ball")
                w.Add(ball)
            Else
                w = New World(10, 10, G, restitution)
                Dim centre = New Vector(5, 3)
                w.Add(Circle.CreateFixed(centre, 1.0, "dome"))
                ball = New Circle(centre + New Vector(Math.Sin(0.2), Math.Cos(0.2)) * (1 + R), R, 1.0, id:="ball")
                w.Add(ball)
                w.Add(New Circle(centre + New Vector(Math.Sin(0.45), Math.Cos(0.45)) * (1 + R), R, 1.0, id:="beside"))
                solver = UseEventSolver(w)
            End If
            Dim e0 = Energy(w) + w.Dissipated
            Dim y0 = ball.Position.Y
            ' Within a microsecond it has dropped by the hop's height (less the 1.3 nm its hop has lifted it since);
            ' sliding, it would have dropped 10⁻¹³ m.
            w.Advance(0.000001)
            Dim drop = y0 - ball.Position.Y
            Assert.True(drop > 0.95 * 0.000001 * R AndAlso drop <= 0.000001 * R * (1 + 1.0E-6), $"dropped {drop} m at once")
            For k = 1 To 200
                w.Advance(0.0025)
                Assert.True(Math.Abs(Energy(w) + w.Dissipated - e0) < 0.000000001 * e0, $"t = {w.Time}: {Energy(w)} + {w.Dissipated} against {e0}")
            Next
            Assert.True(solver.EventCount > 100, $"{solver.EventCount} events: it should have hopped down the slope")
        End Sub

        <Fact>
        Public Sub ADampedSpring_InTheEventSolver_CountsWhatTheDampingTook()
            Dim w As New World(3.0, 4.0, G, 1.0)
            Dim anchor = New Vector(1.5, 3.5)
            Dim body As New Circle(anchor - New Vector(0, 1.0), 0.15, 0.5, id:="mass")
            w.Add(body)
            w.Add(Link.CreateSpring(body, anchor, 20, 1.0, 0.8, "spring"))
            w.Solver = SolverFactory.Create("event")
            Dim e0 = Energy(w)
            Dim previous = 0.0
            For k = 1 To 30
                w.Advance(0.1)
                Assert.True(w.Dissipated >= previous)
                previous = w.Dissipated
                Assert.True(Math.Abs(Energy(w) + w.Dissipated - e0) < 0.000000001 * Math.Abs(e0), $"t = {w.Time}: {Energy(w)} + {w.Dissipated} against {e0}")
            Next
            Assert.True(previous > 0.1)
        End Sub

        <Theory>
        <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
        Public Sub ADampedSpring_InTheSteppingSolvers_CountsWhatTheDampingTook(solver As String)
            Dim w As New World(3.0, 4.0, G, 1.0)
            Dim anchor = New Vector(1.5, 3.5)
            Dim body As New Circle(anchor - New Vector(0, 1.0), 0.15, 0.5, id:="mass")
            w.Add(body)
            w.Add(Link.CreateSpring(body, anchor, 20, 1.0, 0.8, "spring"))
            TestSolvers.Run(w, solver)
            Dim e0 = Energy(w)
            w.Advance(3)
            Assert.True(w.Dissipated > 0.1)
            Assert.True(Math.Abs(Energy(w) + w.Dissipated - e0) < 0.01 * w.Dissipated, $"{Energy(w)} + {w.Dissipated} against {e0}")
        End Sub

        <Theory>
        <InlineData("event", 0.000000001)>
        <InlineData("euler", 0.01)>
        <InlineData("verlet", 0.01)>
        Public Sub AStringSnappingTaut_TakesWhatItsInelasticJerkTakes(solver As String, tolerance As Double)
            ' A bob 0.6 m straight out from the anchor on a 1 m string, dropped: it falls, and the string snaps taut (e = 0.5).
            Dim w As New World(6, 6, G, 0.5)
            Dim anchor = New Vector(3, 5)
            Dim bob As New Circle(anchor + New Vector(0.6, 0), 0.05, 0.5, id:="bob")
            w.Add(bob)
            w.Add(Link.CreateTie(LinkKind.String, bob, anchor, 1.0))
            TestSolvers.Run(w, solver)
            Dim e0 = Energy(w)
            w.Advance(0.8)
            Assert.True(w.Dissipated > 0.1, $"{w.Dissipated} J")
            Assert.True(Math.Abs(Energy(w) + w.Dissipated - e0) < tolerance * Math.Abs(e0), $"{Energy(w)} + {w.Dissipated} against {e0}")
        End Sub

        <Theory>
        <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
        Public Sub APile_NeverGainsFromTheBooks(solver As String)
            Dim w = Scenarios.Pile(60, 0.3)
            TestSolvers.Run(w, solver)
            Dim e0 = Energy(w)
            Dim previous = 0.0
            For k = 1 To 20
                w.Advance(0.1)
                Assert.True(w.Dissipated >= previous)
                previous = w.Dissipated
            Next
            ' What the collisions took is most of what the pile lost settling (the stepping solvers' resting
            ' contacts and the event solver's clusters of touching balls take a little more, uncounted).
            Dim lost = e0 - Energy(w)
            Assert.True(w.Dissipated <= lost * 1.01 + 0.000001, $"{w.Dissipated} J counted, {lost} J lost")
            Assert.True(w.Dissipated >= 0.9 * lost, $"{w.Dissipated} J counted, {lost} J lost")
        End Sub
    End Class
End Namespace
