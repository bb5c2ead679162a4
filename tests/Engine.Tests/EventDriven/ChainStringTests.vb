Option Strict On
Imports PhysicsEngine
Imports Xunit
Imports Xunit.Abstractions

Namespace EventDriven
    ''' <summary>
    ''' Strings in a chain (integrated, not in closed form): a bob whirled round a vertical circle on a string,
    ''' made a chain by a second, longer string that never tightens, goes slack at the textbook height, flies
    ''' and snaps taut exactly as the same bob on its one string does in closed form; a double pendulum on
    ''' strings keeps its energy through its strings going slack and snapping taut with e = 1.
    ''' </summary>
    Public Class ChainStringTests
        Private Const G As Double = 9.81
        Private Shared ReadOnly Anchor As New Vector(5, 5)
        Private ReadOnly _output As ITestOutputHelper

        Public Sub New(output As ITestOutputHelper)
            _output = output
        End Sub

        ''' <summary>A bob at the bottom of a 1 m string with speed u, u² = 3.5 gL; with <paramref name="chained"/>, also on a 3 m string to the same point.</summary>
        Private Shared Function VerticalCircle(chained As Boolean) As World
            Dim w As New World(10, 10, G, 1.0)
            w.Solver = SolverFactory.Create("event")
            Dim bob As New Circle(Anchor - New Vector(0, 1), 0.05, 0.5, New Vector(Math.Sqrt(3.5 * G), 0))
            w.Add(bob)
            w.Add(Link.CreateTie(LinkKind.String, bob, Anchor, 1))
            If chained Then w.Add(Link.CreateTie(LinkKind.String, bob, Anchor, 3))
            Return w
        End Function

        <Fact>
        Public Sub VerticalCircleInAChain_GoesSlackAtTheTextbookHeight_AndFollowsTheClosedForms()
            Dim chain = VerticalCircle(True)
            Dim alone = VerticalCircle(False)
            Dim bob = chain.Circles(0)
            ' Goes slack at (u² + gL)/(3g) = 1.5 L above the bottom, at the time the closed form gives.
            Dim slackAfter = New Pendulum(Anchor, 1, G, bob.Position, bob.Velocity).SlackTime()
            chain.Advance(slackAfter)
            alone.Advance(slackAfter)
            _output.WriteLine($"slack at {slackAfter} s, at height {bob.Position.Y - (Anchor.Y - 1)} m above the bottom")
            Assert.Equal(Anchor.Y + 0.5, bob.Position.Y, 9)
            Assert.Equal(1.0, (bob.Position - Anchor).Length, 9)
            ' From there, flight and snaps taut (e = 1) and flight again: the same path as the closed forms, every 10 ms for 2 s.
            Dim worst = 0.0, snaps = 0, wasSlack = False
            For k = 1 To 200
                chain.Advance(0.01)
                alone.Advance(0.01)
                worst = Math.Max(worst, (bob.Position - alone.Circles(0).Position).Length)
                Dim slack = chain.Links(0).Distance < 1 - 0.000001
                If wasSlack AndAlso Not slack Then snaps += 1
                wasSlack = slack
                Assert.True(chain.Links(0).Distance <= 1 + 0.000000001, $"the string is {chain.Links(0).Distance} m long at {chain.Time} s")
            Next
            _output.WriteLine($"largest distance from the closed forms over 2 s: {worst:E2} m, {snaps} snaps seen")
            Assert.True(worst <= 0.000000001, $"{worst:E2} m from the closed forms")
        End Sub

        <Fact>
        Public Sub DoublePendulumOnStrings_KeepsItsEnergy_ThroughSlackAndTaut_WithEOne()
            Dim w As New World(10, 10, G, 1.0)
            w.Solver = SolverFactory.Create("event")
            Dim upper As New Circle(Anchor + New Vector(1, 0), 0.05, 1)
            Dim lower As New Circle(Anchor + New Vector(1, -1), 0.05, 1, New Vector(6, 0))
            w.Add(upper)
            w.Add(lower)
            w.Add(Link.CreateTie(LinkKind.String, upper, Anchor, 1))
            w.Add(Link.CreateTie(LinkKind.String, lower, upper, 1))
            Dim energy As Func(Of Double) = Function() w.Circles.Sum(Function(c) 0.5 * c.Mass * c.Velocity.LengthSquared + c.Mass * G * c.Position.Y)
            Dim e0 = energy()
            Dim worstEnergy = 0.0, worstOver = 0.0, slackSeen = False
            For k = 1 To 300
                w.Advance(0.01)
                worstEnergy = Math.Max(worstEnergy, Math.Abs(energy() - e0) / (2 * G * 2))
                For Each l In w.Links
                    worstOver = Math.Max(worstOver, l.Distance - l.Length)
                    If l.Distance < l.Length - 0.001 Then slackSeen = True
                Next
            Next
            _output.WriteLine($"energy {worstEnergy:E2} of m g L, strings over-long by at most {worstOver:E2} m, slack seen: {slackSeen}")
            Assert.True(slackSeen, "no string went slack")
            Assert.True(worstOver <= 0.000000001, $"a string was {worstOver} m over its length")
            Assert.True(worstEnergy <= 0.000000001, $"energy drifted by {worstEnergy:E2} of m g L")
        End Sub
        <Fact>
        Public Sub DoublePendulumOnStringsReleasedLevel_StartsWithNoTension_AndKeepsItsEnergy()
            ' Released level at rest, both strings start with zero tension (the bobs fall together at first):
            ' the start must neither stall on the zero nor let a string stretch.
            Dim w As New World(10, 10, G, 1.0)
            w.Solver = SolverFactory.Create("event")
            Dim upper As New Circle(Anchor + New Vector(1, 0), 0.05, 1)
            Dim lower As New Circle(Anchor + New Vector(2, 0), 0.05, 1)
            w.Add(upper)
            w.Add(lower)
            w.Add(Link.CreateTie(LinkKind.String, upper, Anchor, 1))
            w.Add(Link.CreateTie(LinkKind.String, lower, upper, 1))
            Dim energy As Func(Of Double) = Function() w.Circles.Sum(Function(c) 0.5 * c.Mass * c.Velocity.LengthSquared + c.Mass * G * c.Position.Y)
            Dim e0 = energy()
            Dim worstEnergy = 0.0, worstOver = 0.0
            For k = 1 To 100
                w.Advance(0.02)
                worstEnergy = Math.Max(worstEnergy, Math.Abs(energy() - e0) / (2 * G * 2))
                worstOver = Math.Max(worstOver, w.Links.Max(Function(l) l.Distance - l.Length))
            Next
            _output.WriteLine($"energy {worstEnergy:E2} of m g L, over-long by at most {worstOver:E2} m, lower bob at {lower.Position}")
            Assert.True(lower.Position.Y < Anchor.Y - 1, $"the lower bob is at {lower.Position}")
            Assert.True(worstOver <= 0.000000001, $"a string was {worstOver} m over its length")
            Assert.True(worstEnergy <= 0.000000001, $"energy drifted by {worstEnergy:E2} of m g L")
        End Sub
    End Class
End Namespace
