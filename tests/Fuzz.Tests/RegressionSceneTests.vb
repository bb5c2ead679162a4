Option Strict On
Imports System.IO
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Fuzzing.Workers
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>
''' The scenes of tests/cases, each of which random scenes once caught breaking the engine; each test checks
''' that its defect is gone (see tests/cases/README.md).
''' </summary>
<Collection(FuzzRuns.Name)>
Public Class RegressionSceneTests
    Private Const FellThrough As String = "event-fell-through-rectangle.json"
    Private Const CentreInside As String = "stepping-centre-inside-rectangle.json"
    Private Const HeavyBoxLightSquare As String = "stepping-heavy-box-through-light-square.json"
    Private Const SlowMixed As String = "event-slow-mixed-scene.json"
    Private Const CrowdedSlide As String = "event-galton-crowded-slide.json"
    Private Const SlopeFromRest As String = "event-slope-start-from-rest.json"
    Private Const ElasticPeg As String = "event-elastic-ball-on-small-peg.json"
    Private Const OffRectangleEnd As String = "event-flies-off-rectangle-end.json"
    Private Const OffRectangleEndMixed As String = "event-flies-off-rectangle-end-mixed.json"
    Private Const PillarStack As String = "event-stack-on-pillar-extreme-masses.json"
    ''' <summary>How far the energy may drift from its start, as a fraction of it: the fuzzer's rounding allowance.</summary>
    Private Const EnergyTolerance As Double = 0.000000001
    ''' <summary>These runs are known to end; the cap only stops a runaway, s.</summary>
    Private Const GenerousCap As Double = 300

    ''' <summary>Loads a case, gives it the solver and advances to each sample time as the command line does, calling check after each.</summary>
    Private Shared Sub Run(name As String, solver As String, total As Double, sample As Double, check As Action(Of World, Double))
        Dim world = SceneFile.LoadFile(TestPaths.Case_(name))
        world.Solver = SolverFactory.Create(solver)
        For Each t In SampleClock.Times(total, sample)
            world.Advance(t - world.Time)
            check(world, t)
        Next
    End Sub

    ''' <summary>
    ''' Loads a case and advances it <paramref name="advances"/> times by <paramref name="slice"/> s with
    ''' an event solver that throws after 100 000 events in one advance (so a runaway fails at once
    ''' instead of running for minutes).
    ''' </summary>
    Private Shared Function RunCapped(name As String, advances As Integer, slice As Double) As World
        Dim world = SceneFile.LoadFile(TestPaths.Case_(name))
        world.Solver = New EventDrivenSolver() With {.MaxEventsPerAdvance = 100000}
        For k = 1 To advances
            world.Advance(slice)
        Next
        Return world
    End Function

    <Theory>
    <InlineData(0.15)>
    <InlineData(0.01)>
    Public Sub FellThrough_BallC64_NeverSinksBelowTheTopOfRectangleR2(sample As Double)
        Run(FellThrough, "event", 3.0, sample,
            Sub(world, t)
                Dim ball = DirectCast(world.Find("c64"), Circle)
                Dim r2 = DirectCast(world.Find("r2"), Rectangle)
                Dim p = ball.Position
                ' r2 reaches below the floor, so over its width no ball may be lower than resting on its top
                If p.X >= r2.Min.X AndAlso p.X <= r2.Max.X AndAlso p.Y - ball.Radius < r2.Max.Y - StateChecks.Tolerance Then
                    Assert.Fail($"sampled every {sample} s: at t = {t} s c64 is at {p}, its bottom {r2.Max.Y - (p.Y - ball.Radius)} m below r2's top (y = {r2.Max.Y} m)")
                End If
            End Sub)
    End Sub

    <Fact>
    Public Sub FellThrough_NoBallEndsInsideAnotherBody()
        ' c58 used to end 0.89 mm deep in r2's left face after going round its corner
        Run(FellThrough, "event", 3.0, 0.15,
            Sub(world, t)
                Dim overlap = StateChecks.Overlap(world)
                If overlap IsNot Nothing Then Assert.Fail($"at t = {t} s: {overlap}")
            End Sub)
    End Sub

    <Fact>
    Public Sub FellThrough_TwoSamplingIntervals_GiveTheSameCollisionsAndEndState()
        Dim text = File.ReadAllText(TestPaths.Case_(FellThrough))
        Dim result = SceneCheck.Check(text, "event", New RunPlan(3.0, 0.15, 0.01, GenerousCap), stopAt:=Invariants.Sampling)
        Dim sampling = result.Violations.FirstOrDefault(Function(v) v.Invariant = Invariants.Sampling)
        Assert.True(sampling Is Nothing, "sampled every 0.15 s and every 0.01 s: " & sampling?.Message)
        Assert.True(result.Violations.All(Function(v) v.Invariant <> Invariants.WallTime AndAlso v.Invariant <> Invariants.Crash AndAlso v.Invariant <> Invariants.NotFinite),
                    "the runs did not both finish: " & String.Join("; ", result.Violations))
    End Sub

    <Theory>
    <InlineData("euler")>
    <InlineData("verlet")>
    Public Sub SteppingCentreInside_NoCentreEverInsideAFixedBody(solver As String)
        ' c0 (r = 0.66 m) used to have its centre inside r1 at t = 0.15 s
        Run(CentreInside, solver, 3.0, 0.15,
            Sub(world, t)
                Dim inside = StateChecks.CentreInside(world)
                If inside IsNot Nothing Then Assert.Fail($"{solver}, at t = {t} s: {inside}")
            End Sub)
    End Sub

    <Theory>
    <InlineData("euler")>
    <InlineData("verlet")>
    Public Sub SteppingHeavyBoxOnLightSquare_TheSquareAgainstTheWallStopsTheBox(solver As String)
        ' A 403 kg thin box at 4.5 m/s runs into an 11.5 g square lying against the left wall, g = 0, e = 0.
        ' The pair's push shared by mass moved the square into the wall and the wall moved it back into the
        ' box, step after step: the box went 0.151 m into the square by t = 0.4 s. Held by the wall, the
        ' square holds the box as a fixed body would, so the box stops across and slides on along its face.
        Run(HeavyBoxLightSquare, solver, 2.0, 0.05,
            Sub(world, t)
                Dim overlap = StateChecks.Overlap(world)
                If overlap IsNot Nothing Then Assert.Fail($"{solver}, at t = {t} s: {overlap}")
                ' After the blow (e = 0) the box no longer moves towards the wall.
                If t >= 1 Then Assert.InRange(world.Find("b0").Velocity.X, -0.000001, 0.000001)
            End Sub)
    End Sub

    <Fact>
    Public Sub SlowMixedScene_RunsWithinTheCap_AndKeepsEveryEventSolverInvariant()
        ' Radii from 1 mm to 1 m, speeds to 10⁴ m/s, e = 1: about 6 million collisions in 0.5 s, which ran at
        ' 135 000 collisions/s (45 s). It now runs at about the elastic gas's rate (docs/benchmarks.md), 5 to
        ' 11 s on the 2-core build machine. The cap only stops an advance that never ends: it is generous so
        ' that a busy machine does not trip it; the speed itself is the benchmark's to measure.
        ' Both sampling intervals and every event-solver invariant, in a worker process so that one endless
        ' advance is killed.
        Dim text = File.ReadAllText(TestPaths.Case_(SlowMixed))
        Using worker As New WorkerProcess(Path.Combine(Path.GetTempPath(), "fuzz-case-" & Guid.NewGuid().ToString("N") & ".json"))
            Dim result = worker.Check(text, "event", New RunPlan(0.5, 0.05, 0.013, SlowMixedCap), Nothing)
            Assert.True(result.Violations.Count = 0, String.Join(vbLf, result.Violations))
        End Using
    End Sub

    ''' <summary>Wall-clock seconds one run of the slow mixed scene may take.</summary>
    Private Const SlowMixedCap As Double = 120
    <Fact>
    Public Sub GaltonCrowdedSlide_GetsPastTheBallPressedAgainstOneRoundingAPeg_InFewEvents()
        ' 200 balls fed from shelves through a chute into pegs, e = 0.3: at t ≈ 3.87 s ball b131 pressed
        ' against b130 while b130 slid round peg p47, and following that slide exactly took ever shorter
        ' looks (hundreds of thousands of events per simulated millisecond).
        Dim world = RunCapped(CrowdedSlide, 12, 0.5)
        Dim solver = DirectCast(world.Solver, EventDrivenSolver)
        Assert.True(solver.EventCount < 400000, $"{solver.EventCount} events in 6 s")
        Dim overlap = StateChecks.Overlap(world)
        Assert.True(overlap Is Nothing, overlap)
    End Sub
    <Fact>
    Public Sub PillarStack_SettlesInAFewThousandEvents_WithNoOverlap()
        ' Balls of 5·10⁻⁵ kg to 9·10⁵ kg stacked on a narrow pillar, e = 0, g = 100. The ball at the
        ' bottom lies 0.7 mm from another on the pillar's top, so it is not alone there: a blow from above
        ' leaves it still, as the pile's rule says, and the stack settles (2 714 collisions in 1 s). When
        ' it shared the blow with the ground instead, it was driven into the stack of extreme masses and
        ' the second took 46 million collisions.
        Dim world = RunCapped(PillarStack, 4, 0.25)
        Assert.True(world.CollisionCount < 10000, $"{world.CollisionCount} collisions in 1 s")
        Dim overlap = StateChecks.Overlap(world)
        Assert.True(overlap Is Nothing, overlap)
    End Sub

    <Fact>
    Public Sub GaltonBoardOf500Balls_NoBallEverEndsInsideAnother()
        ' Balls rounding the tops of the bin dividers used to run into a neighbour that was already
        ' within reach when the slide began, or into one asleep on a pile: neither was looked for, and
        ' a pair ended 4 mm deep in each other (t = 10.03 s) and 1.2 mm (t = 11.38 s).
        Dim world = Scenarios.GaltonBoard(500, 12, 20, 10)
        world.Solver = SolverFactory.Create("event")
        For k = 1 To 30
            world.Advance(0.5)
            Dim overlap = StateChecks.Overlap(world)
            If overlap IsNot Nothing Then Assert.Fail($"at t = {world.Time} s: {overlap}")
        Next
    End Sub

    <Fact>
    Public Sub SlopeFromRest_BallC2SlidesDownFixedCircleF0_AsTheExactSlideDoes_WithItsEnergyKept()
        ' c2 starts at rest on f0, 20.6° from its top; an exact slide round f0 would reach the walls, so it
        ' hops down the slope instead. The hops used to be paid for with new energy: ½ m u² at the start
        ' (1e-7 of the total). Now they follow the frictionless slide, θ(t) by quadrature, until it leaves
        ' f0 (at cos θ* = ⅔ cos θ0, t ≈ 0.45 s).
        Dim world = SceneFile.LoadFile(TestPaths.Case_(SlopeFromRest))
        world.Solver = SolverFactory.Create("event")
        Dim ball = DirectCast(world.Find("c2"), Circle)
        Dim peg = DirectCast(world.Find("f0"), Circle)
        Dim arc = ball.Radius + peg.Radius
        Dim g = world.Gravity
        Dim theta0 = AngleOnPeg(ball, peg)
        Dim leave = CornerSlide.LeaveAngle(0, g, arc, theta0)
        Dim start = world.KineticEnergy() + world.PotentialEnergy()
        For k = 1 To 8
            world.Advance(0.05)
            Dim energy = world.KineticEnergy() + world.PotentialEnergy()
            Assert.True(Math.Abs(energy - start) <= EnergyTolerance * start, $"at t = {world.Time} s the energy went from {start} J to {energy} J")
            Dim exact = CornerSlide.AngleAfter(0, g, arc, theta0, leave, world.Time)
            Dim theta = AngleOnPeg(ball, peg)
            Assert.True(Math.Abs(theta - exact) < 0.0001, $"at t = {world.Time} s c2 is {theta} rad round f0, the slide {exact} rad")
        Next
    End Sub

    ''' <summary>How far round the peg the ball is, rad from its top, positive towards −x (the way c2 slides).</summary>
    Private Shared Function AngleOnPeg(ball As Circle, peg As Circle) As Double
        Return Math.Atan2(peg.Position.X - ball.Position.X, ball.Position.Y - peg.Position.Y)
    End Function

    <Fact>
    Public Sub ElasticPeg_BallC0RollsOffPegF1_WithItsEnergyKept()
        ' e = 1: c0 (36 t) starts at rest on the 11 mm peg f1, far down its side, too near the ceiling for
        ' an exact slide. Its hops used to add ½ m u² at the start and a little more at each hop where the
        ' peg fell away beneath it: +6e-8 of the energy in 0.05 s.
        Dim world = SceneFile.LoadFile(TestPaths.Case_(ElasticPeg))
        world.Solver = SolverFactory.Create("event")
        Dim start = world.KineticEnergy() + world.PotentialEnergy()
        For k = 1 To 12
            world.Advance(0.05)
            Dim energy = world.KineticEnergy() + world.PotentialEnergy()
            Assert.True(Math.Abs(energy - start) <= EnergyTolerance * start, $"at t = {world.Time} s the energy went from {start} J to {energy} J")
        Next
        ' And it did leave the peg: falling freely, clear of it.
        Dim ball = DirectCast(world.Find("c0"), Circle)
        Dim peg = DirectCast(world.Find("f1"), Circle)
        Assert.True((ball.Position - peg.Position).Length > 2 * (ball.Radius + peg.Radius), $"c0 is still at {ball.Position}")
    End Sub

    <Theory>
    <InlineData(OffRectangleEnd)>
    <InlineData(OffRectangleEndMixed)>
    Public Sub OffRectangleEnd_RunsOneSecond_InFewEvents(name As String)
        ' A ball exactly at the end of a rectangle's top, moving outwards, used to be caught by that face
        ' again at once, and leave it again a few ulps of time later, for ever: the run never ended.
        Dim world = SceneFile.LoadFile(TestPaths.Case_(name))
        Dim solver As New EventDrivenSolver() With {.MaxEventsPerAdvance = 10000}
        world.Solver = solver
        world.Advance(1.0)
        Assert.True(solver.EventCount < 10000, $"{solver.EventCount} events in 1 s")
        Dim overlap = StateChecks.Overlap(world)
        Assert.True(overlap Is Nothing, overlap)
    End Sub

    <Fact>
    Public Sub OffRectangleEnd_BallC58FliesOffTheEndOfR0_AndLandsAsAProjectile()
        ' c58 sits at the right end of r0's top moving right at 0.85 m/s, faster than √(g r): it flies
        ' straight off, and the floor is the first thing it meets, at t = √(2 (y0 − r) / g).
        Dim world = SceneFile.LoadFile(TestPaths.Case_(OffRectangleEnd))
        Dim ball = DirectCast(world.Find("c58"), Circle)
        Dim y0 = ball.Position.Y, vx = ball.Velocity.X, g = world.Gravity
        Dim first As CollisionRecord? = Nothing
        world.CollisionListener = Sub(record)
                                      If first Is Nothing AndAlso record.A Is ball Then first = record
                                  End Sub
        world.Solver = New EventDrivenSolver() With {.MaxEventsPerAdvance = 10000}
        world.Advance(0.1)
        Assert.True(first.HasValue, "c58 met nothing in 0.1 s")
        Dim landing = Math.Sqrt(2 * (y0 - ball.Radius) / g)
        Assert.Equal(WallSide.Bottom, first.Value.Wall)
        Assert.True(Math.Abs(first.Value.Time - landing) < 0.000000001, $"c58 landed at t = {first.Value.Time} s, a projectile at {landing} s")
        Assert.True(Math.Abs(first.Value.AVelocityBefore.X - vx) < 0.000000001 AndAlso Math.Abs(first.Value.AVelocityBefore.Y + g * landing) < 0.000001,
                    $"c58 came down at {first.Value.AVelocityBefore} m/s, a projectile at ({vx}, {-g * landing})")
    End Sub
End Class
