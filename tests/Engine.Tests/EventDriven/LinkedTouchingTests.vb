Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace EventDriven
    ''' <summary>
    ''' Contacts of bodies that start touching, and bodies coming to rest, in a scene with links, in the event
    ''' solver. A touching pair that does not approach collides when it has pressed 10⁻⁹ m into the other
    ''' (docs/links.md, section 4). The search for the gap opening first must stop there: further on, a ball
    ''' that went right through a small peg has the gap open on the far side, and a search that took that as
    ''' the opening never looked for the contact between. A ball coming to rest on a fixed body rests there by
    ''' the one rule of lasting contact (docs/contact.md).
    ''' </summary>
    Public Class LinkedTouchingTests
        ''' <summary>How far a touching pair presses in before it collides, m (docs/links.md).</summary>
        Private Const Press As Double = 0.000000001

        ''' <summary>
        ''' No gravity; a ball (radius 5 mm, 0.01 kg) at rest touching a fixed peg (radius 1 mm) on its right, on a
        ''' spring of rest length 0 (k = 1 N/m) to a point 1.006 m to the left, through the peg's centre. The spring
        ''' pulls the ball straight into the peg: free, x(t) = x₀ cos ωt about the anchor, ω = √(k/m) = 10 rad/s, and
        ''' passing right through the peg would take about 16 ms, well within one advance. The peg pushes back along
        ''' the same line as hard as the spring pulls: the ball stays where it is, exactly.
        ''' </summary>
        <Theory>
        <InlineData(0.1)>
        <InlineData(0.01)>
        Public Sub BallPulledIntoAPegItTouches_RestsOnThePeg_NotPassedThrough(advance As Double)
            Dim w As New World(10, 10, 0, 0.5)
            w.Solver = SolverFactory.Create("event")
            Dim peg = Circle.CreateFixed(New Vector(3, 5), 0.001, "peg")
            w.Add(peg)
            Dim start = New Vector(3 + 0.001 + 0.005, 5)
            Dim ball As New Circle(start, 0.005, 0.01, Vector.Zero, "ball")
            w.Add(ball)
            w.Add(Link.CreateSpring(ball, New Vector(2, 5), 1.0, 0))
            ' The spring pulls straight through the peg's centre: the peg holds the ball where it is, for good.
            Do While w.Time < 1
                w.Advance(advance)
                Assert.Equal(start, ball.Position)
                Assert.Equal(Vector.Zero, ball.Velocity)
            Loop
        End Sub

        ''' <summary>
        ''' A ball (1 kg, r = 1 cm) at rest on top of a fixed peg (r = 5 cm), g = 9.81, e = 0.5, on a rod to a point below
        ''' and to its left, and on a string at full length to a point to its right, a little above it. The rod and the
        ''' string fix the ball's place between them, so the peg's contact seemed implied by them and was not held; but
        ''' the string would have to push (its tension, with the rod's, to hold the weight is negative), so it let go,
        ''' and the ball fell on the rod alone into the peg and struck it (in the random scene, bounce after bounce, each
        ''' 2·10⁻⁹ m deep, past the 10⁻⁹ m of touching, with energy plus dissipated rising). With the string gone the
        ''' peg's contact is not implied and holds: the ball stays where it is, never struck (the rod carries nothing).
        ''' </summary>
        <Fact>
        Public Sub BallOnARodRestingOnAPeg_WithAStringThatWouldPush_StaysOnThePeg()
            Dim w As New World(10, 10, 9.81, 0.5)
            w.Solver = SolverFactory.Create("event")
            Dim peg = Circle.CreateFixed(New Vector(5, 1), 0.05, "peg")
            w.Add(peg)
            Dim start = New Vector(5, 1 + 0.05 + 0.01)
            Dim ball As New Circle(start, 0.01, 1, Vector.Zero, "ball")
            w.Add(ball)
            Dim below = New Vector(4.8, 0.8), right = New Vector(6, 1.2)
            w.Add(Link.CreateTie(LinkKind.Rod, ball, below, (start - below).Length))
            w.Add(Link.CreateTie(LinkKind.String, ball, right, (start - right).Length))
            Dim hits = 0
            w.CollisionListener = Sub(r) hits += 1
            Do While w.Time < 0.1
                w.Advance(0.01)
                Dim gap = (ball.Position - peg.Position).Length - 0.06
                Assert.True(gap >= -Press, $"at t = {w.Time} s the ball is {-gap} m deep in the peg")
                Assert.True(ball.Velocity.Length < 0.000000000001, $"at t = {w.Time} s the ball moves at {ball.Velocity.Length} m/s")
            Loop
            Assert.Equal(0, hits)
        End Sub

        ''' <summary>A world 10 m square with a pendulum hanging still at its right, so that it has links.</summary>
        Private Shared Function WithPendulum(restitution As Double) As World
            Dim w = NewWorld("event", restitution)
            AddPendulum(w, LinkKind.Rod, New Vector(8, 9), 1, 0, 1)
            Return w
        End Function

        <Fact>
        Public Sub BallBouncingToRestOnAPegTop_BouncesAsTheSeriesSays_ThenRestsBalancedOnItsTop()
            ' Dropped 0.2 m straight onto the top of a fixed peg with e = 0.5: it hits at √(2 g h) and each rebound
            ' is e times the last (the normal is vertical, so it stays on the vertical through the peg's centre).
            ' When a rebound would rise less than four slops (v² < 8 g 1e-9 m) the ball rests: balanced on the top,
            ' where the peg's push is straight up and matches its weight, it stays (an unstable balance, but a
            ' balance: nothing pushes it off).
            Const E As Double = 0.5, H As Double = 0.2
            Dim w = WithPendulum(E)
            w.Add(Circle.CreateFixed(New Vector(3, 2.5), 0.5, "peg"))
            Dim ball As New Circle(New Vector(3, 3 + 0.1 + H), 0.1, 1, Vector.Zero, "ball")
            w.Add(ball)
            Dim speeds As New List(Of Double)
            w.CollisionListener = Sub(c)
                                      If c.A Is ball Then speeds.Add(c.AVelocityAfter.Y)
                                  End Sub
            For k = 1 To 40
                w.Advance(0.1)
                Assert.True(ball.Position.Y >= 3.1 - 0.000000001, $"{ball.Position.Y} m: in the peg")
            Next
            Assert.Equal(3.0, ball.Position.X)
            Assert.Equal(3.1, ball.Position.Y, 9)
            Assert.Equal(Vector.Zero, ball.Velocity)
            ' Every rebound reported was e times the one before, from e √(2 g h); all but the last rose more than four
            ' slops, and the last, which did not, is where the ball came to rest.
            Assert.True(speeds.Count >= 5, $"{speeds.Count} rebounds")
            Dim rebound = E * Math.Sqrt(2 * G * H)
            For k = 0 To speeds.Count - 1
                Dim v = speeds(k)
                Assert.True(Math.Abs(v - rebound) <= 0.000001 * Math.Sqrt(2 * G * H), $"rebound at {v} m/s, the series {rebound} m/s")
                Assert.Equal(k < speeds.Count - 1, v * v >= 8 * G * Press)
                rebound *= E
            Next
        End Sub

        <Fact>
        Public Sub FreeBallBouncingToRestOnTheFloor_BesideAPendulum_IsNotRefused()
            ' The floor has its rest rule: the ball ends exactly on it, at rest, and nothing is refused.
            Dim w = WithPendulum(0.5)
            Dim ball As New Circle(New Vector(3, 0.1 + 0.2), 0.1, 1, Vector.Zero, "ball")
            w.Add(ball)
            For k = 1 To 30
                w.Advance(0.1)
            Next
            Assert.Equal(0.1, ball.Position.Y, 12)
            Assert.Equal(0.0, ball.Velocity.Y)
        End Sub
    End Class
End Namespace
