Option Strict On
Imports PhysicsEngine
Imports Xunit
Imports Xunit.Abstractions

Namespace EventDriven
    ''' <summary>
    ''' Coulomb friction in the event solver (docs/contact.md, "Friction"; docs/forces.md), against the textbook: a
    ''' block on a rough slope stays below the angle of repose and slides at g (sin θ − μk cos θ) above it, a block
    ''' pushed along a rough floor stops after v²/(2 μk g) at v/(μk g) and stays, a box landing obliquely keeps the
    ''' sliding speed Coulomb's law leaves it, and the energy friction takes is counted.
    ''' </summary>
    Public Class FrictionEventTests
        Private Const G As Double = 9.81
        Private ReadOnly _output As ITestOutputHelper

        Public Sub New(output As ITestOutputHelper)
            _output = output
        End Sub

        Private Shared Function RoughWorld(mu As Double, muS As Double, restitution As Double) As World
            Dim w As New World(10, 10, G, restitution) With {.Friction = mu, .StaticFriction = muS}
            w.Solver = SolverFactory.Create("event")
            Return w
        End Function

        ''' <summary>A 0.4 m box resting on a segment at angle θ through (2, 1), its lower-right corner on the slope 1 m along it.</summary>
        Private Shared Function BoxOnSlope(w As World, theta As Double) As Rectangle
            Dim start = New Vector(2, 1), along = New Vector(Math.Cos(theta), Math.Sin(theta))
            w.Add(New Segment(start, start + along * 6, "ramp"))
            ' A box that does not turn touches a slope rising to the right with its lower-right corner: on the line 1 m along.
            Dim corner = start + along * 1
            Dim box = Rectangle.CreateMovable(corner - New Vector(0.4, 0), 0.4, 0.4, 1.5, Vector.Zero, "box")
            w.Add(box)
            Return box
        End Function

        <Theory>
        <InlineData(0.3, 0.5)>
        <InlineData(0.45, 0.5)>
        Public Sub BlockOnARoughSlope_BelowTheAngleOfRepose_StaysToTheLastBit(theta As Double, muS As Double)
            Assert.True(Math.Tan(theta) <= muS)
            Dim w = RoughWorld(0.3, muS, 0.2)
            Dim box = BoxOnSlope(w, theta)
            Dim start = box.Position
            For k = 1 To 20
                w.Advance(0.5)
                Assert.Equal(start, box.Position)
                Assert.Equal(Vector.Zero, box.Velocity)
            Next
        End Sub

        <Theory>
        <InlineData(0.6, 0.3, 0.5)>
        <InlineData(0.9, 0.5, 0.6)>
        Public Sub BlockOnARoughSlope_AboveTheAngleOfRepose_SlidesAtGTimesSinMinusMuCos(theta As Double, mu As Double, muS As Double)
            Assert.True(Math.Tan(theta) > muS)
            Dim w = RoughWorld(mu, muS, 0.2)
            Dim box = BoxOnSlope(w, theta)
            Dim start = box.Position
            Dim a = G * (Math.Sin(theta) - mu * Math.Cos(theta))
            Dim along = New Vector(Math.Cos(theta), Math.Sin(theta))
            For k = 1 To 5
                w.Advance(0.1)
                Dim s = 0.5 * a * w.Time * w.Time
                Dim expected = start - along * s
                Assert.Equal(expected.X, box.Position.X, 9)
                Assert.Equal(expected.Y, box.Position.Y, 9)
            Next
        End Sub

        <Theory>
        <InlineData(2.0, 0.4)>
        <InlineData(3.5, 0.25)>
        Public Sub BlockPushedAlongARoughFloor_StopsAfterVSquaredOverTwoMuG_AtVOverMuG_AndStays(speed As Double, mu As Double)
            Dim w = RoughWorld(mu, mu, 0.2)
            Dim box = Rectangle.CreateMovable(New Vector(1, 0), 0.5, 0.3, 2, New Vector(speed, 0), "box")
            w.Add(box)
            Dim stops = speed / (mu * G)
            Dim distance = speed * speed / (2 * mu * G)
            Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
            w.Advance(stops / 2)
            Assert.Equal(1 + speed * w.Time - 0.5 * mu * G * w.Time * w.Time, box.Position.X, 9)
            w.Advance(stops / 2)
            Assert.Equal(1 + distance, box.Position.X, 9)
            Assert.True(Math.Abs(box.Velocity.X) <= 0.000000001, $"{box.Velocity.X} m/s")
            Dim stopped = box.Position
            w.Advance(3)
            Assert.Equal(stopped, box.Position)
            Assert.Equal(Vector.Zero, box.Velocity)
            ' Every joule of the kinetic energy went to friction, and is counted.
            Assert.Equal(e0, w.KineticEnergy() + w.PotentialEnergy() + w.Dissipated, 9)
        End Sub

        <Fact>
        Public Sub BoxLandingObliquelyOnARoughFloor_SlidesOnAtCoulombsSpeed()
            ' Landing at u across and v down with e: the floor's normal impulse is m (1 + e) v, and friction takes at most
            ' μk times it from the sliding, m u → m (u − μk (1 + e) v) when that is still positive.
            Const U As Double = 3, V As Double = 2, E As Double = 0.3, Mu As Double = 0.2
            Dim w = RoughWorld(Mu, Mu, E)
            w.Gravity = 0
            Dim box = Rectangle.CreateMovable(New Vector(1, 0.5), 0.4, 0.2, 1, New Vector(U, -V), "box")
            w.Add(box)
            Dim landing As CollisionRecord? = Nothing
            w.CollisionListener = Sub(r) If landing Is Nothing Then landing = r
            w.Advance(0.5)
            Assert.True(landing.HasValue)
            Assert.Equal(U - Mu * (1 + E) * V, landing.Value.AVelocityAfter.X, 12)
            Assert.Equal(E * V, landing.Value.AVelocityAfter.Y, 12)
        End Sub

        <Fact>
        Public Sub BallOnARoughSlope_TakesNoFriction_ItWouldRoll()
            ' Circles take no friction (they would roll; nothing turns here): a ball on a slope steeper than μs's angle
            ' is not held, and slides at g sin θ as on ice.
            Const Theta As Double = 0.3
            Dim w = RoughWorld(0.5, 0.9, 0.2)
            Dim start = New Vector(2, 1), along = New Vector(Math.Cos(Theta), Math.Sin(Theta))
            w.Add(New Segment(start, start + along * 6, "ramp"))
            Dim normal = New Vector(-Math.Sin(Theta), Math.Cos(Theta))
            Dim ball As New Circle(start + along * 3 + normal * 0.2, 0.2, 1, Vector.Zero, "ball")
            w.Add(ball)
            Dim p0 = ball.Position
            w.Advance(0.3)
            Dim s = 0.5 * G * Math.Sin(Theta) * 0.3 * 0.3
            Assert.Equal((p0 - along * s).X, ball.Position.X, 9)
        End Sub

        <Fact>
        Public Sub BoxCarriedOnASlidingBox_SticksToIt_AndBothStopTogether()
            ' A 1 kg box on a 2 kg box sliding at 2 m/s on a floor, μk = 0.3, μs = 0.5 everywhere. Together they slow at
            ' μk g (the floor's friction on the whole weight); the top one needs m μk g of friction to keep up, less than
            ' μs m g: it sticks, and both stop after v/(μk g) having gone v²/(2 μk g).
            Const Speed As Double = 2, Mu As Double = 0.3
            Dim w = RoughWorld(Mu, 0.5, 0.2)
            Dim bottom = Rectangle.CreateMovable(New Vector(1, 0), 0.6, 0.2, 2, New Vector(Speed, 0), "bottom")
            Dim top = Rectangle.CreateMovable(New Vector(1.1, 0.2), 0.3, 0.2, 1, New Vector(Speed, 0), "top")
            w.Add(bottom)
            w.Add(top)
            w.Advance(0.3)
            Assert.Equal(Speed - Mu * G * 0.3, bottom.Velocity.X, 9)
            Assert.Equal(bottom.Velocity.X, top.Velocity.X, 9)
            Assert.Equal(0.2, top.Position.Y - bottom.Position.Y, 12)
            w.Advance(Speed / (Mu * G))
            Dim distance = Speed * Speed / (2 * Mu * G)
            Assert.Equal(1 + distance, bottom.Position.X, 9)
            Assert.Equal(1.1 + distance, top.Position.X, 9)
            Assert.Equal(Vector.Zero, bottom.Velocity)
            Assert.Equal(Vector.Zero, top.Velocity)
        End Sub

        <Fact>
        Public Sub BoxOnASlidingBox_ThatNeedsMoreThanStaticFriction_SlidesOnIt()
            ' A 1 kg box on a 2 kg box, both at 2 m/s on a floor with μk = μs = 0.3; between the boxes μ = 0.1 (a
            ' surface's own μ meets another's as their geometric mean: √(μ_top × 0.3) = 0.1). Held together they would
            ' slow at 0.3 g, which needs more than the 0.1 g the top box can take: it slides forward on the bottom one,
            ' slowed at 0.1 g, while the bottom one feels the floor's 0.3 × 3 g backwards and the top's 0.1 g forwards,
            ' (0.9 − 0.1) g / 2 kg = 0.4 g.
            Const Speed As Double = 2, T As Double = 0.3
            Dim w = RoughWorld(0.3, 0.3, 0.2)
            Dim bottom = Rectangle.CreateMovable(New Vector(1, 0), 1.5, 0.2, 2, New Vector(Speed, 0), "bottom")
            Dim top = Rectangle.CreateMovable(New Vector(1.1, 0.2), 0.3, 0.2, 1, New Vector(Speed, 0), "top")
            top.Friction = 0.01 / 0.3
            top.StaticFriction = 0.01 / 0.3
            w.Add(bottom)
            w.Add(top)
            w.Advance(T)
            Assert.Equal(Speed - 0.1 * G * T, top.Velocity.X, 9)
            Assert.Equal(Speed - 0.4 * G * T, bottom.Velocity.X, 9)
            Assert.Equal(1.1 + Speed * T - 0.5 * 0.1 * G * T * T, top.Position.X, 9)
            Assert.Equal(1 + Speed * T - 0.5 * 0.4 * G * T * T, bottom.Position.X, 9)
        End Sub

        ''' <summary>
        ''' A 2 kg box on a rough floor (μk = 0.4, μs = 0.6) tied by a spring (8 N/m, 1 m long) to a 1 kg bob on a 1 m
        ''' rod, let go level with the rod's anchor on the box's side. As the bob swings over to the far side the
        ''' spring's pull grows until it needs more than μs times the floor's push: the box slips, slides, stops and
        ''' sticks again. At the slip the judgement "slips" and the new group's "stays stuck" once disagreed by a
        ''' rounding, and the run stopped at t = 0.728 s with 100 001 events within a nanosecond.
        ''' </summary>
        <Fact>
        Public Sub BoxPulledByASwingingBob_SlipsOnceItsPullOutgrowsMuSTimesItsPush_ThenSticksAgain()
            Dim w = RoughWorld(0.4, 0.6, 0.3)
            Dim box = Rectangle.CreateMovable(New Vector(0.8, 0), 0.4, 0.2, 2, Vector.Zero, "box")
            Dim bob As New Circle(New Vector(1, 2), 0.05, 1, Vector.Zero, "bob")
            w.Add(box)
            w.Add(bob)
            w.Add(Link.CreateTie(LinkKind.Rod, bob, New Vector(2, 2), 1))
            Dim spring = Link.CreateSpring(box, bob, 8, 1)
            w.Add(spring)
            Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
            Dim slipped = False, stuckAgain = False
            For k = 1 To 300
                Dim before = box.Position.X
                ' The spring's pull on the box and what static friction can take, from the state before this step.
                Dim along = (bob.Position - box.CentreOfMass) / (bob.Position - box.CentreOfMass).Length
                Dim pull = 8 * ((bob.Position - box.CentreOfMass).Length - 1) * along
                Dim grip = 0.6 * (2 * G - pull.Y)
                w.Advance(0.01)
                If box.Position.X <> before Then
                    slipped = True
                ElseIf slipped Then
                    stuckAgain = True
                ElseIf Not slipped Then
                    Assert.True(Math.Abs(pull.X) <= grip * (1 + 0.000001), $"t = {w.Time} s: the box stayed stuck under a pull of {pull.X} N, more than μs N = {grip} N")
                End If
                Dim books = w.KineticEnergy() + w.PotentialEnergy() + w.Dissipated
                Assert.True(Math.Abs(books - e0) <= 0.000000001 * e0, $"t = {w.Time} s: energy plus dissipated {books} J against {e0} J")
            Next
            Assert.True(slipped, "the box never slipped")
            Assert.True(stuckAgain, "the box never stuck again")
            Assert.Equal(3, w.Time, 12)
        End Sub
    End Class
End Namespace
