Option Strict On
Imports Xunit

Namespace EventDriven
    ''' <summary>
    ''' Drag and liquids in the event solver (docs/forces.md, "In the event solver"): a scene with them goes to the
    ''' linked solver, which moves a body with linear drag alone in closed form and anything else by an integral
    ''' with error control, finding contacts by conservative advancement. Against the closed forms to 1e-9: the
    ''' linear-drag projectile and the time it lands, the tanh fall, the floating depth, the undamped bobbing;
    ''' energy plus what drag and blows took stays constant to rounding.
    ''' </summary>
    Public Class ForcesEventTests
        Private Const G As Double = 9.81

        Private Shared Function EventWorld(width As Double, height As Double, Optional restitution As Double = 1.0) As World
            Dim w As New World(width, height, G, restitution)
            w.Solver = SolverFactory.Create("event")
            Return w
        End Function

        <Fact>
        Public Sub LinearDragProjectile_FollowsTheClosedForm_AndLandsAtItsRoot()
            Const m = 0.5, b = 0.3, r = 0.05
            Dim w = EventWorld(100, 30, 0.5)
            Dim x0 = New Vector(1, 2), v0 = New Vector(12, 9)
            Dim ball As New Circle(x0, r, m, v0, "ball") With {.LinearDrag = b}
            w.Add(ball)
            Dim hits As New List(Of CollisionRecord)
            w.CollisionListener = Sub(c) hits.Add(c)
            Dim tau = LinearDrag.TimeConstant(m, b), vt = LinearDrag.TerminalVelocity(m, b, G)
            ' The landing: the root of y(t) = r, by bisection on the closed form (it rises, then falls for good).
            Dim lo = 1.0, hi = 10.0
            For k = 1 To 200
                Dim mid = 0.5 * (lo + hi)
                If LinearDrag.Position(x0, v0, vt, tau, mid).Y > r Then lo = mid Else hi = mid
            Next
            Dim landing = 0.5 * (lo + hi)
            Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
            For Each t In {0.1, 0.5, 1.0, 1.7, landing - 0.01}
                w.Advance(t - w.Time)
                Dim expected = LinearDrag.Position(x0, v0, vt, tau, t)
                Assert.True((ball.Position - expected).Length < 0.000000001, $"t = {t}: {ball.Position} against {expected}")
                Assert.True((ball.Velocity - LinearDrag.Velocity(v0, vt, tau, t)).Length < 0.000000001)
                ' The energy drag took, in closed form: energy + dissipated is what it was.
                Assert.True(Math.Abs(w.KineticEnergy() + w.PotentialEnergy() + w.Dissipated - e0) < 0.000000001 * e0)
            Next
            Assert.Empty(hits)
            w.Advance(landing + 0.01 - w.Time)
            Assert.True(hits.Count >= 1)
            Assert.Equal("wall:bottom", hits(0).BName)
            Assert.True(Math.Abs(hits(0).Time - landing) < 0.000000001, $"landed at {hits(0).Time} s, the root is {landing} s")
            Dim atLanding = LinearDrag.Velocity(v0, vt, tau, landing)
            Assert.True((hits(0).AVelocityBefore - atLanding).Length < 0.000000001)
            ' The bounce, e = 0.5, took ½ m (1 − e²) v_y² on top of the drag.
            Assert.True(Math.Abs(w.KineticEnergy() + w.PotentialEnergy() + w.Dissipated - e0) < 0.000000001 * e0)
        End Sub

        <Fact>
        Public Sub QuadraticDrag_VerticalFall_IsTheTanh()
            Const m = 0.2, rho = 1.2, cd = 0.8, r = 0.15
            Dim w = EventWorld(10, 100)
            w.AirDensity = rho
            Dim ball As New Circle(New Vector(5, 90), r, m, id:="ball") With {.DragCoefficient = cd}
            w.Add(ball)
            Dim vt = QuadraticDrag.TerminalSpeed(m, G, rho, cd, 2 * r)
            Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
            Dim previous = 0.0
            For Each t In {0.25, 0.5, 1.0, 2.0, 3.0}
                w.Advance(t - w.Time)
                Assert.True(Math.Abs(-ball.Velocity.Y - QuadraticDrag.FallSpeed(vt, G, t)) < 0.000000001, $"t = {t}: {ball.Velocity.Y}")
                Assert.True(Math.Abs(90 - ball.Position.Y - QuadraticDrag.FallDistance(vt, G, t)) < 0.000000001, $"t = {t}: {ball.Position.Y}")
                Assert.Equal(5.0, ball.Position.X)
                Assert.True(w.Dissipated >= previous)
                previous = w.Dissipated
                Assert.True(Math.Abs(w.KineticEnergy() + w.PotentialEnergy() + w.Dissipated - e0) < 0.000000001 * e0)
            Next
        End Sub

        ''' <summary>A 0.4 m × 0.5 m box of mass m in water (1000 kg/m², surface at 1.5 m), its bottom <paramref name="depth"/> under the surface.</summary>
        Private Shared Function Floating(m As Double, depth As Double, damping As Double) As (World As World, Box As Rectangle)
            Dim w = EventWorld(4, 3, 0.3)
            w.Add(New Liquid(New Vector(0, 0), 4, 1.5, 1000, "water") With {.LinearDrag = damping})
            Dim box = Rectangle.CreateMovable(New Vector(1.5, 1.5 - depth), 0.4, 0.5, m, id:="box")
            w.Add(box)
            Return (w, box)
        End Function

        <Fact>
        Public Sub ABoxAtItsFloatingDepth_StaysThere()
            Const m = 40.0
            Dim d = Buoyancy.FloatingDepth(m, 0.4, 1000)
            Dim s = Floating(m, d, 0)
            For k = 1 To 10
                s.World.Advance(1)
                Assert.True(Math.Abs(s.Box.Position.Y - (1.5 - d)) < 0.000000001, $"y = {s.Box.Position.Y}")
            Next
        End Sub

        <Fact>
        Public Sub ABoxBobsUndamped_AsTheCosineOfItsPeriod()
            Const m = 40.0, amplitude = 0.03
            Dim d = Buoyancy.FloatingDepth(m, 0.4, 1000)
            Dim s = Floating(m, d - amplitude, 0)
            Dim period = Buoyancy.BobbingPeriod(m, 0.4, 1000, G)
            Dim omega = 2 * Math.PI / period
            Dim e0 = s.World.KineticEnergy() + s.World.PotentialEnergy()
            For k = 1 To 100
                Dim t = 5 * period * k / 100
                s.World.Advance(t - s.World.Time)
                Dim expected = 1.5 - d + amplitude * Math.Cos(omega * t)
                Assert.True(Math.Abs(s.Box.Position.Y - expected) < 0.000000001, $"t = {t}: {s.Box.Position.Y} against {expected}")
                ' Buoyancy's potential is in the potential energy: nothing is lost, at any moment of the swing.
                Assert.True(Math.Abs(s.World.KineticEnergy() + s.World.PotentialEnergy() - e0) < 0.000000001 * Math.Abs(e0))
            Next
            Assert.Equal(0.0, s.World.Dissipated)
        End Sub

        <Fact>
        Public Sub ABoxDroppedIn_SettlesAtTheFloatingDepth_CountingWhatTheWaterTook()
            Const m = 40.0
            Dim s = Floating(m, 0, 300)
            Dim e0 = s.World.KineticEnergy() + s.World.PotentialEnergy()
            Dim previous = 0.0
            For k = 1 To 30
                s.World.Advance(1)
                Assert.True(s.World.Dissipated >= previous)
                previous = s.World.Dissipated
                Assert.True(Math.Abs(s.World.KineticEnergy() + s.World.PotentialEnergy() + s.World.Dissipated - e0) < 0.000000001 * Math.Abs(e0))
            Next
            Assert.True(Math.Abs(1.5 - s.Box.Position.Y - Buoyancy.FloatingDepth(m, 0.4, 1000)) < 0.000000001, $"y = {s.Box.Position.Y}")
        End Sub

        <Fact>
        Public Sub ABoxLighterThanTheLiquid_StartingOnTheBottom_FloatsUp()
            Dim s = Floating(40, 1.5, 300) ' on the floor of the tank
            s.World.Advance(20)
            Assert.True(Math.Abs(1.5 - s.Box.Position.Y - Buoyancy.FloatingDepth(40, 0.4, 1000)) < 0.000001, $"y = {s.Box.Position.Y}")
        End Sub

        <Fact>
        Public Sub ABoxDenserThanTheLiquid_SinksAndStaysOnTheBottom()
            Dim s = Floating(250, 0, 300)
            s.World.Advance(10)
            Assert.True(Math.Abs(s.Box.Position.Y) < 0.000000001, $"y = {s.Box.Position.Y}")
            Assert.True(s.Box.Velocity.Length < 0.000001)
        End Sub

        ''' <summary>θ'' = −(g/L) sin θ − (b/m) θ' (the drag's part across the rod; the rod takes the rest), by classical Runge–Kutta with 10 μs steps.</summary>
        Private Shared Function DampedPendulum(L As Double, b As Double, m As Double, theta0 As Double, t As Double) As Double
            Dim th = theta0, om = 0.0, h = 0.00001
            Dim n = CInt(Math.Round(t / h))
            Dim f = Function(a As Double, w As Double) -(G / L) * Math.Sin(a) - (b / m) * w
            For k = 1 To n
                Dim k1a = om, k1w = f(th, om)
                Dim k2a = om + 0.5 * h * k1w, k2w = f(th + 0.5 * h * k1a, om + 0.5 * h * k1w)
                Dim k3a = om + 0.5 * h * k2w, k3w = f(th + 0.5 * h * k2a, om + 0.5 * h * k2w)
                Dim k4a = om + h * k3w, k4w = f(th + h * k3a, om + h * k3w)
                th += h / 6 * (k1a + 2 * k2a + 2 * k3a + k4a)
                om += h / 6 * (k1w + 2 * k2w + 2 * k3w + k4w)
            Next
            Return th
        End Function

        <Fact>
        Public Sub APendulumInAir_WithLinearDrag_FollowsTheDampedEquation_AndCountsWhatTheAirTook()
            Const L = 1.0, b = 0.3, m = 0.5
            Dim w = EventWorld(10, 10)
            Dim anchor = New Vector(5, 8)
            Dim theta0 = Math.PI / 3
            Dim bob As New Circle(anchor + L * New Vector(Math.Sin(theta0), -Math.Cos(theta0)), 0.05, m, id:="bob") With {.LinearDrag = b}
            w.Add(bob)
            w.Add(Link.CreateTie(LinkKind.Rod, bob, anchor, L))
            Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
            Dim previous = 0.0
            For Each t In {0.5, 1.0, 2.0}
                w.Advance(t - w.Time)
                Dim theta = DampedPendulum(L, b, m, theta0, t)
                Dim expected = anchor + L * New Vector(Math.Sin(theta), -Math.Cos(theta))
                Assert.True((bob.Position - expected).Length < 0.000000001, $"t = {t}: {bob.Position} against {expected}")
                Assert.True(w.Dissipated > previous)
                previous = w.Dissipated
                Assert.True(Math.Abs(w.KineticEnergy() + w.PotentialEnergy() + w.Dissipated - e0) < 0.000000001 * Math.Abs(e0))
                Assert.True(Math.Abs((bob.Position - anchor).Length - L) < 0.000000000001)
            Next
        End Sub

        <Fact>
        Public Sub ABoxOnASpring_InWater_SettlesWhereSpringBuoyancyAndWeightBalance()
            Const m = 40.0, k = 2000.0
            Dim w = EventWorld(4, 4, 0.3)
            w.Add(New Liquid(New Vector(0, 0), 4, 1.5, 1000, "water") With {.LinearDrag = 400})
            Dim box = Rectangle.CreateMovable(New Vector(1.8, 1.2), 0.4, 0.5, m, id:="box")
            w.Add(box)
            ' A spring from the box's centre up to a point 1.55 m above it, at its natural length 1.5 m: it pulls 100 N.
            Dim anchor = box.CentreOfMass + New Vector(0, 1.55)
            w.Add(Link.CreateSpring(box, anchor, k, 1.5))
            w.Advance(30)
            ' At rest: k (d − L) + ρ_l g w s = m g, d = anchor − centre, s the depth of its bottom.
            Dim d = anchor.Y - box.CentreOfMass.Y
            Dim depth = 1.5 - box.Position.Y
            Assert.True(Math.Abs(k * (d - 1.5) + 1000 * G * 0.4 * depth - m * G) < 0.000001, $"depth {depth} m, spring {d} m")
            Assert.True(box.Velocity.Length < 0.000000001)
        End Sub

        <Fact>
        Public Sub ABallFarFromALiquid_FliesItsParabola_AndLandsWhenSuvatSays()
            ' A liquid makes every body's motion an integral; one that never reaches it must still land exactly.
            Dim w = EventWorld(20, 10, 0.5)
            w.Add(New Liquid(New Vector(15, 0), 5, 1, 1000, "pool"))
            Dim ball As New Circle(New Vector(1, 0.05), 0.05, 1, New Vector(4, 7), "ball")
            w.Add(ball)
            Dim hits As New List(Of CollisionRecord)
            w.CollisionListener = Sub(c) hits.Add(c)
            w.Advance(0.7)
            Assert.Equal(1 + 4 * 0.7, ball.Position.X, 9)
            Assert.Equal(0.05 + 7 * 0.7 - 0.5 * G * 0.49, ball.Position.Y, 9)
            w.Advance(1.0)
            Assert.Equal("wall:bottom", hits(0).BName)
            Assert.True(Math.Abs(hits(0).Time - 2 * 7 / G) < 0.000000001, $"landed at {hits(0).Time} s")
        End Sub

        <Fact>
        Public Sub ADenseBallWithoutDrag_SlidesAlongTheTankFloorAtItsSpeed()
            ' Nothing slows it along the level floor, and the water only lightens it: resting on the floor is exact.
            Dim w = EventWorld(6, 3, 0.3)
            w.Add(New Liquid(New Vector(0, 0), 6, 1.5, 1000, "water"))
            Dim ball As New Circle(New Vector(1, 0.15), 0.15, 150, New Vector(0.5, 0), "ball")
            w.Add(ball)
            w.Advance(4)
            Assert.Equal(3.0, ball.Position.X, 9)
            Assert.Equal(0.15, ball.Position.Y, 12)
            Assert.Equal(0.5, ball.Velocity.X, 12)
        End Sub

        <Fact>
        Public Sub ADenseBallThatWaterSlows_SettlesOnTheFloor_AndSlidesOnAsLinearDragSays()
            ' It sinks, bounces to rest on the tank's floor, and slides on with the water's linear drag alone along the
            ' floor: v = v₀ e^(−t/τ), x = x₀ + v₀ τ (1 − e^(−t/τ)), τ = m/b (fully under water, so all of b acts).
            Dim w = EventWorld(6, 3, 0.3)
            w.Add(New Liquid(New Vector(0, 0), 6, 1.5, 1000, "water") With {.LinearDrag = 20})
            Dim ball As New Circle(New Vector(1, 0.6), 0.15, 150, New Vector(0.8, 0), "ball")
            w.Add(ball)
            Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
            Do While Not (Math.Abs(ball.Position.Y - 0.15) <= 0.000000000001 AndAlso Math.Abs(ball.Velocity.Y) <= 0.000000000001)
                w.Advance(0.01)
                Assert.True(w.Time < 3, "never settled on the floor")
            Loop
            Dim t0 = w.Time, x0 = ball.Position.X, v0 = ball.Velocity.X
            Assert.True(v0 > 0.1, $"{v0} m/s")
            Dim tau = 150 / 20.0
            w.Advance(1)
            Dim e = Math.Exp(-(w.Time - t0) / tau)
            Assert.Equal(x0 + v0 * tau * (1 - e), ball.Position.X, 9)
            Assert.Equal(v0 * e, ball.Velocity.X, 9)
            Assert.Equal(0.15, ball.Position.Y, 12)
            Assert.True(Math.Abs(w.KineticEnergy() + w.PotentialEnergy() + w.Dissipated - e0) < 4 * 150 * G * 0.000000001, $"{w.KineticEnergy() + w.PotentialEnergy() + w.Dissipated - e0} J")
        End Sub

        <Fact>
        Public Sub ADenseBallSinkingStraightDown_ComesToRestOnTheFloor()
            Dim w = EventWorld(6, 3, 0.3)
            w.Add(New Liquid(New Vector(0, 0), 6, 1.5, 1000, "water") With {.LinearDrag = 20})
            Dim ball As New Circle(New Vector(3, 1.0), 0.15, 150, id:="ball")
            w.Add(ball)
            Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
            w.Advance(5)
            Assert.Equal(0.15, ball.Position.Y, 12)
            Assert.Equal(3.0, ball.Position.X)
            Assert.True(ball.Velocity.Length < 0.000000001)
            ' To rounding: contacts are found, and rests placed, within the touching slop of 1e-9 m, which for 150 kg is
            ' m g × 1e-9 m = 1.5e-6 J of height at each.
            Assert.True(Math.Abs(w.KineticEnergy() + w.PotentialEnergy() + w.Dissipated - e0) < 4 * 150 * G * 0.000000001, $"{w.KineticEnergy() + w.PotentialEnergy() + w.Dissipated - e0} J")
        End Sub

        <Fact>
        Public Sub ASceneWithFriction_IsTakenByTheEventSolver_AndAutoChoosesIt()
            Dim w = EventWorld(4, 3)
            w.Friction = 0.5
            Dim box = Rectangle.CreateMovable(New Vector(1, 0), 0.3, 0.2, 1, New Vector(2, 0), "box")
            w.Add(box)
            Assert.Equal("event", SolverFactory.Create("auto", Nothing, w).Name)
            ' Sliding at 2 m/s on a floor with μk = 0.5, it slows at μk g: after 0.3 s it has gone 2 t − ½ μk g t².
            w.Advance(0.3)
            Assert.Equal(1 + 2 * 0.3 - 0.5 * 0.5 * 9.81 * 0.09, box.Position.X, 9)
            Assert.Equal(2 - 0.5 * 9.81 * 0.3, box.Velocity.X, 9)
            ' One rough box among icy surfaces rubs nothing: it slides on at its speed.
            Dim icy = EventWorld(4, 3)
            Dim rough = Rectangle.CreateMovable(New Vector(1, 0), 0.3, 0.2, 1, New Vector(2, 0), "rough")
            rough.Friction = 0.8
            icy.Add(rough)
            Assert.False(icy.HasFriction)
            icy.Advance(0.5)
            Assert.Equal(2.0, rough.Position.X, 12)
            ' Two rough surfaces do.
            icy.Add(New Segment(New Vector(3, 1), New Vector(4, 1), "ledge") With {.Friction = 0.3})
            Assert.True(icy.HasFriction)
        End Sub

        <Fact>
        Public Sub ARoughWorld_WhoseMovableBodiesAreAllBalls_HasNoFriction()
            ' Balls take no friction and two fixed bodies never rub: nothing here can.
            Dim w = EventWorld(4, 3)
            w.Friction = 0.5
            w.Add(New Rectangle(New Vector(1, 0), 1, 0.5, "table"))
            w.Add(New Segment(New Vector(3, 1), New Vector(4, 1), "ledge"))
            w.Add(New Circle(New Vector(1.5, 1), 0.1, 1, New Vector(1, 0), "ball"))
            Assert.False(w.HasFriction)
            ' A box can rub on the walls and the table.
            Dim box = Rectangle.CreateMovable(New Vector(3, 0), 0.3, 0.2, 1, New Vector(0, 0), "box")
            w.Add(box)
            Assert.True(w.HasFriction)
            ' Not when its own surface is ice.
            box.Friction = 0
            Assert.False(w.HasFriction)
        End Sub

        <Fact>
        Public Sub BodiesWithoutDrag_InASceneWithDrag_StillFlyTheirParabolas()
            Dim w = EventWorld(20, 20)
            Dim plain As New Circle(New Vector(2, 10), 0.1, 1, New Vector(3, 4), "plain")
            Dim draggy As New Circle(New Vector(10, 10), 0.1, 1, New Vector(3, 4), "draggy") With {.LinearDrag = 0.1}
            w.Add(plain)
            w.Add(draggy)
            w.Advance(1.0)
            Assert.Equal(5.0, plain.Position.X, 12)
            Assert.Equal(10 + 4 - 0.5 * G, plain.Position.Y, 12)
            Assert.True(draggy.Position.X < 13)
        End Sub
    End Class
End Namespace
