Option Strict On
Imports Xunit

''' <summary>
''' Drag, buoyancy, liquid drag and Coulomb friction in the stepping solvers (docs/forces.md), against the
''' closed forms within the stepping error: terminal velocity and the exponential approach to it, the tanh
''' fall, floating at depth m/(ρ_l w), bobbing with period 2π√(m/(ρ_l g w)), a block on a rough ramp that
''' stays or slides at g (sin θ − μk cos θ), a block stopping on a rough floor in v²/(2 μk g); circles take no
''' friction; and the energy these remove is counted (energy + dissipated stays what it was).
''' </summary>
Public Class ForcesSteppingTests
    Private Const G As Double = 9.81

    Private Shared Function StepOf(w As World) As Double
        Return w.Solver.TimeStep.Value
    End Function

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub LinearDrag_ThrownBall_FollowsTheExponentialApproach_AndReachesTerminalVelocity(solver As String)
        Const m = 0.5, b = 0.4
        Dim w As New World(200, 200, G, walls:=False)
        Dim ball As New Circle(New Vector(1, 100), 0.05, m, New Vector(8, 6), "ball")
        ball.LinearDrag = b
        w.Add(ball)
        TestSolvers.Run(w, solver)
        Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
        Dim tau = LinearDrag.TimeConstant(m, b), vt = LinearDrag.TerminalVelocity(m, b, G)
        Dim previous = 0.0
        For k = 1 To 30
            w.Advance(0.1)
            Assert.True(w.Dissipated >= previous)
            previous = w.Dissipated
        Next
        Dim t = 3.0
        Dim expected = LinearDrag.Position(New Vector(1, 100), New Vector(8, 6), vt, tau, t)
        ' First order: the error is about the step times the speeds involved (here under 20 m/s).
        Dim h = StepOf(w)
        Assert.True((ball.Position - expected).Length < 20 * h, $"{ball.Position} against {expected}")
        Assert.True((ball.Velocity - LinearDrag.Velocity(New Vector(8, 6), vt, tau, t)).Length < 20 * G * h)
        ' Energy plus what drag took stays what it was, within the stepping error.
        Dim e = w.KineticEnergy() + w.PotentialEnergy()
        Assert.True(Math.Abs(e + w.Dissipated - e0) < 0.01 * e0, $"{e} + {w.Dissipated} against {e0}")
        ' Long after: at the terminal velocity m g/b.
        w.Advance(20 * tau)
        Assert.True((ball.Velocity - vt).Length < 0.000001 * vt.Length, $"{ball.Velocity} against {vt}")
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub QuadraticDrag_VerticalFall_IsTheTanh(solver As String)
        Const m = 0.2, rho = 1.2, cd = 0.8, r = 0.15
        Dim w As New World(10, 100, G, walls:=False) With {.AirDensity = rho}
        Dim ball As New Circle(New Vector(5, 90), r, m, id:="ball") With {.DragCoefficient = cd}
        w.Add(ball)
        TestSolvers.Run(w, solver)
        Dim vt = QuadraticDrag.TerminalSpeed(m, G, rho, cd, 2 * r)
        For Each t In {0.25, 0.5, 1.0, 2.0}
            w.Advance(t - w.Time)
            Dim expected = QuadraticDrag.FallSpeed(vt, G, t)
            Assert.True(Math.Abs(-ball.Velocity.Y - expected) < 2 * G * StepOf(w), $"t = {t}: {ball.Velocity.Y} against {-expected}")
            Assert.True(Math.Abs(90 - ball.Position.Y - QuadraticDrag.FallDistance(vt, G, t)) < 2 * G * StepOf(w) * t)
        Next
    End Sub

    ''' <summary>A box of mass m, width w in water of density ρ_l, its bottom <paramref name="depth"/> below the surface.</summary>
    Private Shared Function Floating(solver As String, m As Double, width As Double, rho As Double, depth As Double, damping As Double) As (World As World, Box As Rectangle)
        Dim w As New World(4, 3, G, 0.3)
        w.Add(New Liquid(New Vector(0, 0), 4, 1.5, rho, "water") With {.LinearDrag = damping})
        Dim box = Rectangle.CreateMovable(New Vector(1.5, 1.5 - depth), width, 0.5, m, id:="box")
        w.Add(box)
        TestSolvers.Run(w, solver)
        Return (w, box)
    End Function

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub ABox_SettlesAtTheFloatingDepth(solver As String)
        Const m = 40.0, width = 0.4, rho = 1000.0
        ' Dropped in at the surface, damped by the water's linear drag.
        Dim s = Floating(solver, m, width, rho, 0, 300)
        s.World.Advance(20)
        Dim depth = 1.5 - s.Box.Position.Y
        Assert.True(Math.Abs(depth - Buoyancy.FloatingDepth(m, width, rho)) < 0.000001, $"depth {depth} m")
        Assert.True(s.Box.Velocity.Length < 0.000001)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub ABox_BobsWithThePeriodOfItsSpring(solver As String)
        Const m = 40.0, width = 0.4, rho = 1000.0
        Dim d = Buoyancy.FloatingDepth(m, width, rho)
        Dim s = Floating(solver, m, width, rho, d - 0.02, 0)
        Dim period = Buoyancy.BobbingPeriod(m, width, rho, G)
        ' Upward crossings of the equilibrium, by linear interpolation between samples.
        Dim crossings As New List(Of Double)
        Dim yEq = 1.5 - d
        Dim last = s.Box.Position.Y - yEq
        Const dt = 0.001
        For k = 1 To CInt(5 * period / dt)
            s.World.Advance(dt)
            Dim now = s.Box.Position.Y - yEq
            If last < 0 AndAlso now >= 0 Then crossings.Add(s.World.Time - dt * now / (now - last))
            last = now
        Next
        Assert.True(crossings.Count >= 4)
        Dim measured = (crossings(crossings.Count - 1) - crossings(0)) / (crossings.Count - 1)
        Assert.True(Math.Abs(measured - period) < 0.001 * period, $"period {measured} s against {period} s")
        ' Undamped: it still swings 2 cm either way.
        Assert.True(Math.Abs(s.Box.Position.Y - yEq) <= 0.0201)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub ABoxDenserThanTheLiquid_SinksToTheBottom(solver As String)
        Dim s = Floating(solver, 250, 0.4, 1000, 0, 100) ' 1250 kg/m²
        s.World.Advance(10)
        Assert.True(s.Box.Position.Y < 0.00001, $"y = {s.Box.Position.Y}")
    End Sub

    ''' <summary>A 3 m ramp at θ (a segment going down to the right), a 0.1 m box on it (its lower-left corner on the slope), μs and μk everywhere.</summary>
    Private Shared Function RoughRamp(solver As String, theta As Double, muS As Double, muK As Double) As (World As World, Box As Rectangle, Down As Vector)
        Dim w As New World(4.0, 3.0, G, 0.5) With {.Friction = muK, .StaticFriction = muS}
        Dim top = New Vector(0.2, 2.5)
        Dim down = New Vector(Math.Cos(theta), -Math.Sin(theta))
        w.Add(New Segment(top, top + 3 * down, "ramp"))
        Dim box = Rectangle.CreateMovable(top + 1.2 * down, 0.1, 0.1, 1.0, id:="box")
        w.Add(box)
        TestSolvers.Run(w, solver)
        Return (w, box, down)
    End Function

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub ABlockOnARoughRamp_BelowTheAngleOfRepose_Stays(solver As String)
        Dim theta = Math.Atan(0.5) - 0.05 ' tan θ < μs = 0.5
        Dim s = RoughRamp(solver, theta, 0.5, 0.4)
        Dim start = s.Box.Position
        TestSolvers.Frames(s.World, 10, 1.0 / 60)
        Assert.True((s.Box.Position - start).Length < 0.000001, $"moved {(s.Box.Position - start).Length} m")
        Assert.True(s.Box.Velocity.Length < 0.00001)
        ' At rest nothing is rubbed away.
        Assert.True(s.World.Dissipated < 0.000001, $"{s.World.Dissipated} J")
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub ABlockOnARoughRamp_AboveTheAngleOfRepose_SlidesAtGSinThetaLessMuKGCosTheta(solver As String)
        Dim theta = Math.PI / 6 ' tan 30° = 0.577 > μs = 0.5
        Dim s = RoughRamp(solver, theta, 0.5, 0.3)
        Dim start = s.Box.Position
        Dim e0 = s.World.KineticEnergy() + s.World.PotentialEnergy()
        Const t = 0.8
        TestSolvers.Frames(s.World, t, 1.0 / 60)
        Dim a = ContactFriction.SlidingAcceleration(theta, G, 0.3)
        Dim h = StepOf(s.World)
        Dim moved = Vector.Dot(s.Box.Position - start, s.Down)
        Assert.True(Math.Abs(moved - 0.5 * a * t * t) < 2 * a * h * t, $"moved {moved} m against {0.5 * a * t * t} m")
        Assert.True(Math.Abs(Vector.Dot(s.Box.Velocity, s.Down) - a * t) < 2 * G * h)
        ' The energy friction took: μk m g cos θ × the distance, within the stepping error.
        Dim e = s.World.KineticEnergy() + s.World.PotentialEnergy()
        Assert.True(Math.Abs(e + s.World.Dissipated - e0) < 0.01 * (e0 - e), $"{e} + {s.World.Dissipated} against {e0}")
        Assert.True(Math.Abs(s.World.Dissipated - 0.3 * G * Math.Cos(theta) * moved) < 0.01 * s.World.Dissipated)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub ABlockPushedAlongARoughFloor_StopsAfterVSquaredOverTwoMuKG_AndStays(solver As String)
        Const v = 3.0, muK = 0.4
        Dim w As New World(10, 2, G, 0.5) With {.Friction = muK, .StaticFriction = 0.6}
        Dim box = Rectangle.CreateMovable(New Vector(1, 0), 0.3, 0.2, 2.0, New Vector(v, 0), "box")
        w.Add(box)
        TestSolvers.Run(w, solver)
        Dim stopAt = v / (muK * G)
        w.Advance(stopAt + 0.05)
        Dim distance = box.Position.X - 1
        Dim expected = ContactFriction.StoppingDistance(v, G, muK)
        Assert.True(Math.Abs(distance - expected) < 2 * v * StepOf(w), $"{distance} m against {expected} m")
        Assert.True(box.Velocity.Length < 0.000001)
        Dim kinetic = 0.5 * 2 * v * v
        Assert.True(Math.Abs(w.Dissipated - kinetic) < 0.01 * kinetic, $"{w.Dissipated} J against {kinetic} J")
        Dim x = box.Position.X
        w.Advance(2)
        Assert.True(Math.Abs(box.Position.X - x) < 0.000001)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub CirclesTakeNoFriction(solver As String)
        Dim w As New World(10, 2, G) With {.Friction = 0.8}
        Dim ball As New Circle(New Vector(1, 0.1), 0.1, 1.0, New Vector(2, 0), "ball") With {.Friction = 0.9}
        w.Add(ball)
        TestSolvers.Run(w, solver)
        w.Advance(1)
        Assert.Equal(2.0, ball.Velocity.X, 12)
        Assert.Equal(3.0, ball.Position.X, 9)
        Assert.Equal(0.0, w.Dissipated)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub AStrongLinearDrag_OnlySlows(solver As String)
        ' c h/m = 50: an explicit step would reverse and grow the velocity every step.
        Dim w As New World(10, 10, 0, walls:=False)
        Dim ball As New Circle(New Vector(5, 5), 0.05, 0.001, New Vector(1, 0), "ball") With {.LinearDrag = 50}
        w.Add(ball)
        TestSolvers.Run(w, solver)
        Dim previous = ball.Velocity.X
        For k = 1 To 20
            w.Advance(0.001)
            Assert.InRange(ball.Velocity.X, 0, previous)
            previous = ball.Velocity.X
        Next
        Assert.True(ball.Position.X - 5 < 1.0 * 0.001 / 50 * 2 + 0.001)
    End Sub
End Class
