Option Strict On
Imports PhysicsEngine
Imports Xunit
Imports Xunit.Abstractions

Namespace EventDriven
    ''' <summary>
    ''' Lasting contact in a scene with links, by the one rule (docs/contact.md), against textbook answers: a ball
    ''' sliding off a peg leaves where cos θ = ⅔ cos θ₀, a bob on a string leaning on a wall stays with the tension
    ''' m g / cos θ, a box pressed onto a table by a spring stays with the table holding both.
    ''' </summary>
    Public Class LinkedContactTests
        Private ReadOnly _output As ITestOutputHelper

        Public Sub New(output As ITestOutputHelper)
            _output = output
        End Sub

        <Theory>
        <InlineData(0.05)>
        <InlineData(0.3)>
        <InlineData(0.6)>
        Public Sub BallReleasedOnAPeg_SlidesOff_LeavingWhereCosThetaIsTwoThirdsCosThetaNought(theta0 As Double)
            ' A ball at rest θ₀ from the top of a fixed circle (R the sum of the radii), frictionless: v² = 2gR(cos θ₀ −
            ' cos θ), and the circle pushes only while g cos θ > v²/R, so it lets go at cos θ* = ⅔ cos θ₀, moving along
            ' the tangent at √(g R cos θ*). After that it flies: its horizontal speed stays √(g R cos θ*) cos θ*.
            ' Another ball rests on the floor meanwhile, held there, and a pendulum swings far off.
            Dim w = NewWorld("event", 0.5)
            AddFarPendulum(w)
            w.Add(Circle.CreateFixed(New Vector(4, 2), 0.5, "peg"))
            Const R As Double = 0.6
            Dim ball As New Circle(New Vector(4 + R * Math.Sin(theta0), 2 + R * Math.Cos(theta0)), 0.1, 1, Vector.Zero, "ball")
            w.Add(ball)
            Dim resting As New Circle(New Vector(1, 0.2), 0.2, 3, Vector.Zero, "resting")
            w.Add(resting)
            Dim leaveCos = 2 / 3.0 * Math.Cos(theta0)
            Dim expected = Math.Sqrt(G * R * leaveCos) * leaveCos
            Do While (ball.Position - New Vector(4, 2)).Length < R + 0.05
                w.Advance(0.01)
                Assert.True(w.Time < 3, "never left the peg")
            Loop
            _output.WriteLine($"left by t = {w.Time} s; vx = {ball.Velocity.X} m/s, the textbook {expected} m/s")
            Assert.Equal(1.0, ball.Velocity.X / expected, 9)
            Assert.Equal(New Vector(1, 0.2), resting.Position)
            Assert.Equal(Vector.Zero, resting.Velocity)
        End Sub

        <Theory>
        <InlineData(0.2)>
        <InlineData(0.9)>
        Public Sub BobOnAStringLeaningOnAWall_StaysThere_PullingMgOverCosTheta(theta As Double)
            ' The anchor is up and to the right of the bob, beyond the right wall, so the bob would swing right: it leans
            ' on the wall at θ from the string's vertical, and the string's pull and the wall's push balance its weight,
            ' T cos θ = m g. Nothing moves, for good.
            Const L As Double = 1, M As Double = 0.4, Radius As Double = 0.05
            Dim w = NewWorld("event", 0.5)
            Dim wallX = w.Width
            Dim bobCentre = New Vector(wallX - Radius, 6)
            Dim anchor = bobCentre + New Vector(L * Math.Sin(theta), L * Math.Cos(theta))
            Dim bob As New Circle(bobCentre, Radius, M, Vector.Zero, "bob")
            w.Add(bob)
            Dim s = Link.CreateTie(LinkKind.String, bob, anchor, L)
            w.Add(s)
            For k = 1 To 20
                w.Advance(0.5)
                Assert.Equal(bobCentre, bob.Position)
                Assert.Equal(Vector.Zero, bob.Velocity)
            Next
            Assert.Equal(M * G / Math.Cos(theta), s.Tension, 9)
        End Sub

        <Fact>
        Public Sub BoxPressedOntoATableByASpring_StaysStill_ToTheLastBit()
            ' A spring from above pulls the box down onto a table (anchor below the box's centre): the table carries
            ' the weight and the pull; nothing moves for ten seconds.
            Dim w = NewWorld("event", 0.3)
            w.Add(New Rectangle(New Vector(2, 0), 3, 1, "table"))
            Dim box = Rectangle.CreateMovable(New Vector(3, 1), 0.4, 0.2, 2, Vector.Zero, "box")
            w.Add(box)
            w.Add(Link.CreateSpring(box, New Vector(3.2, 0.5), 50, 0.2))
            For k = 1 To 20
                w.Advance(0.5)
                Assert.Equal(New Vector(3, 1), box.Position)
                Assert.Equal(Vector.Zero, box.Velocity)
            Next
        End Sub
    End Class
End Namespace
