Option Strict On
Imports System.IO
Imports PhysicsEngine
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>
''' The work of the linked event solver's contact searches, counted exactly (gap measurements), on scenes of
''' tests/cases whose searches crawled: each ran for seconds of CPU on a handful of collisions. Counts, not
''' timings, so they are repeatable; the time itself is the benchmark's and the fuzzer's cap's.
''' </summary>
Public Class LinkedSearchWorkTests
    ''' <summary>Runs case <paramref name="name"/> for <paramref name="duration"/> s in one advance of the linked solver alone.</summary>
    Private Shared Function Run(name As String, duration As Double, ByRef evaluations As Long, Optional ByRef collisions As Long = 0) As World
        Dim w = SceneFile.LoadFile(TestRepo.CaseFile(name))
        Dim s As New LinkedEventSolver()
        s.Attach(w)
        s.Advance(duration)
        evaluations = s.GapEvaluations
        collisions = w.CollisionCount
        Return w
    End Function

    ''' <summary>
    ''' Runs case <paramref name="name"/> in <paramref name="advances"/> advances of <paramref name="seconds"/> s of the
    ''' linked solver alone, <paramref name="solver"/>, and checks after each that energy plus dissipated has not grown
    ''' from the start's and that no two bodies overlap.
    ''' </summary>
    Private Shared Function RunKeepingLaws(name As String, seconds As Double, advances As Integer, ByRef solver As LinkedEventSolver) As World
        Dim w = SceneFile.LoadFile(TestRepo.CaseFile(name))
        Dim e0 = w.KineticEnergy() + w.PotentialEnergy() + w.Dissipated
        solver = New LinkedEventSolver()
        solver.Attach(w)
        For k = 1 To advances
            solver.Advance(seconds)
            EventSolverTestKit.AssertNoEnergyGainNorOverlap(w, e0)
        Next
        Return w
    End Function

    ''' <summary>
    ''' Ball c2 is caged with no room between c1 and c3, which a rod holds apart; after the first blow at t = 0 the
    ''' three fly on together, g = 100. c2 flies its parabola and the rod its dumbbell: every search of c2 against
    ''' either end, with the sum of their speed bounds (up to 40 m/s) and a gap that stays at nothing, ran through
    ''' its whole budget of a hundred thousand steps, every 20 ms: 86 million gap measurements for 2 s (about
    ''' 8 s of CPU). Seen from a frame falling with them, neither moves: the search is over at once.
    ''' </summary>
    <Fact>
    Public Sub CagedBall_FlyingWithItsCage_IsSearchedInFewSteps()
        Dim evaluations As Long
        Dim w = Run("event-linked-caged-ball.json", 2, evaluations)
        Assert.True(evaluations < 100000, $"{evaluations} gap measurements for 2 s")
        Assert.True(EventSolverTestKit.DeepestOverlap(w) <= 0.000000001, $"overlap {EventSolverTestKit.DeepestOverlap(w)} m")
    End Sub

    ''' <summary>
    ''' A pyramid of six 232 kg balls on a table, the bottom right one pulled up and away by a stiff spring (g = 75,
    ''' e = 1). At t ≈ 0.015 s the group's integrated motion finds a contact lifting off; the searches of its pairs,
    ''' which looked 20 ms ahead whatever the motion's own event, carried the integration on past that event, on
    ''' contacts that no longer held there, in steps of femtoseconds, and their bounds (10¹⁶ m/s² from those steps)
    ''' made every search crawl: hundreds of millions of gap measurements, minutes of CPU, before t = 0.02 s. A search
    ''' now ends at the motions' own events.
    ''' </summary>
    <Fact>
    Public Sub PyramidPulledBySpring_SearchesStopAtTheGroupsEvent()
        Dim evaluations As Long
        Run("event-linked-pyramid-pulled-by-spring.json", 0.02, evaluations)
        Assert.True(evaluations < 100000, $"{evaluations} gap measurements for 0.02 s")
    End Sub

    ''' <summary>The same pyramid over 2 s: no overlap, and kinetic, gravitational and spring energy kept (e = 1).</summary>
    <Fact>
    Public Sub PyramidPulledBySpring_KeepsItsEnergy_AndNeverOverlaps()
        Dim w = SceneFile.LoadFile(TestRepo.CaseFile("event-linked-pyramid-pulled-by-spring.json"))
        EventSolverTestKit.RunEventSolverChecked(w, 2, 0.05, EnergyLaw.PlusDissipatedKept(0.000000001), maxOverlap:=0.000000001)
    End Sub

    ''' <summary>
    ''' A row of six 1.4 mg balls on a table, one on a 59 kN/m spring (ω ≈ 2·10⁵ rad/s), one on a rod. The spring's
    ''' integrated motion, made anew at each collision, was integrated and searched a whole 20 ms horizon ahead
    ''' (650 of its periods, at up to 10⁴ m/s) every time. It now looks ahead from its first step, doubling.
    ''' </summary>
    <Fact>
    Public Sub StiffSpringOnAMilligramBall_IsSearchedOnlyAsFarAsNeeded()
        Dim evaluations As Long, collisions As Long
        Dim w = Run("event-linked-stiff-spring-milligram-ball.json", 0.01, evaluations, collisions)
        Assert.True(evaluations < 100000, $"{evaluations} gap measurements for 0.01 s ({collisions} collisions)")
        Assert.True(EventSolverTestKit.DeepestOverlap(w) <= 0.000000001, $"overlap {EventSolverTestKit.DeepestOverlap(w)} m")
    End Sub

    ''' <summary>
    ''' Two balls (11 and 19 mg) joined by a 4 kN/m spring and nothing else (ω ≈ 2.4·10⁴ rad/s), the spring stretched
    ''' so that it drives one of them into a third ball, which it strikes every microsecond or so (random scene seed
    ''' 4017, cut to the three; e = 1, g = 45). The pair's motion, made anew at each collision, was integrated and
    ''' searched a whole 20 ms horizon ahead every time: 28 000 integrator steps a collision, 19 s of CPU for 0.1 s
    ''' of the full scene. It now looks ahead from its first step, doubling, as every integrated group does.
    ''' </summary>
    <Fact>
    Public Sub StiffSpringPair_StrikingABall_IsSearchedOnlyAsFarAsNeeded()
        Dim w = SceneFile.LoadFile(TestRepo.CaseFile("event-linked-stiff-spring-pair-rattles-ball.json"))
        Dim s As New LinkedEventSolver()
        s.Attach(w)
        Dim e0 = w.KineticEnergy() + w.PotentialEnergy() + w.Dissipated
        s.Advance(0.005)
        Assert.True(w.CollisionCount >= 30, $"{w.CollisionCount} collisions")
        Assert.True(s.IntegratorSteps < 100000, $"{s.IntegratorSteps} integrator steps for 0.005 s ({w.CollisionCount} collisions)")
        Assert.True(EventSolverTestKit.DeepestOverlap(w) <= 0.000000001, $"overlap {EventSolverTestKit.DeepestOverlap(w)} m")
        Dim drift = (w.KineticEnergy() + w.PotentialEnergy() + w.Dissipated - e0) / Math.Abs(e0)
        Assert.True(Math.Abs(drift) <= 0.000000001, $"the energy drifted by {drift} of itself")
    End Sub

    ''' <summary>
    ''' Two boxes and three balls joined by a rod, a string and two springs, with friction (g = 9.81, e = 0.35): the
    ''' group's searches crawled (millions of gap measurements against the wall and the fixed polygon), and 2 s did
    ''' not end within 90 s. Now about 100 000 measurements and 600 collisions.
    ''' </summary>
    <Fact>
    Public Sub BoxesAndBallsOnLinks_TwoSeconds_InFewSearchSteps()
        Dim evaluations As Long, collisions As Long
        Dim w = Run("event-linked-boxes-balls-string-springs.json", 2, evaluations, collisions)
        Assert.True(evaluations < 1000000, $"{evaluations} gap measurements for 2 s ({collisions} collisions)")
    End Sub

    ''' <summary>
    ''' A 0.17 g ball on a rod to a 6.5 t ball rattles between the floor and another 6.5 t ball coming down on it
    ''' (e = 1, g = 73), a bounce every 30 to 100 ns, beside a heap of 6.5 t balls (random scene seed 453, cut to
    ''' the balls near it at t = 0.25 s). After every bounce its searches against the heap were carried to the 20 ms
    ''' horizon at up to 1750 m/s, hundreds of gap measurements each, and thrown away at the next bounce: 10 ms took
    ''' 15 s of CPU (87 million gap measurements, 5000 a collision). They now look only twice as far ahead as its
    ''' soonest contact: under 100 a collision.
    ''' </summary>
    <Fact>
    Public Sub LightBallRattlingUnderAHeavyOne_IsSearchedOnlyToItsNextBounces()
        Dim s As LinkedEventSolver = Nothing
        Dim w = RunKeepingLaws("event-linked-light-ball-rattling-under-heavy.json", 0.01, 1, s)
        Assert.True(w.CollisionCount > 10000, $"{w.CollisionCount} collisions in 0.01 s")
        Assert.True(s.GapEvaluations < 200 * w.CollisionCount, $"{s.GapEvaluations} gap measurements for {w.CollisionCount} collisions")
    End Sub

    ''' <summary>
    ''' A pile of nine bodies from 17 mg to 890 t pressed together on the floor, g = 100 (random scene seed 6006, at
    ''' t = 0.2 s): ball c0 (17 mg) lies on a ledge under c3 (8.7 t), pushed along by c4 (370 t). Its accelerations are
    ''' the small difference of forces 10¹¹ times its weight, so each carries a rounding error of about 10⁻⁵ m/s², and
    ''' measured against the integrator's 10⁻¹² m/s that held its steps to 10⁻⁷ s: 0.3 s took 640 000 steps and 30 s
    ''' of CPU. The rows fix that velocity from the heavy bodies', and the error is now measured in what the rows leave
    ''' free, with the quintic between the ends kept on the rows.
    ''' </summary>
    <Fact>
    Public Sub LightBallPinnedUnderAHeavyPile_IsIntegratedInLongSteps()
        Dim s As LinkedEventSolver = Nothing
        Dim w = RunKeepingLaws("event-linked-light-ball-pinned-under-heavy-pile.json", 0.005, 4, s)
        Assert.True(s.IntegratorSteps < 2000, $"{s.IntegratorSteps} integrator steps for 0.02 s ({w.CollisionCount} collisions)")
    End Sub

    ''' <summary>
    ''' Twelve bodies from 1 µg to 755 t, e = 0, g = 48, pressed together in a corner from t ≈ 0.31 s (reduced from random
    ''' scene 30541). The 2 µg ball c196's acceleration, among forces on bodies up to 755 t, comes out of the solve only
    ''' to 2⁻¹⁴ m/s² (−31.72381591796875 m/s², and −31.7237548828125 at positions 4·10⁻¹⁶ of themselves away): the error
    ''' of its velocity, held to 10⁻¹² m/s, was that rounding whatever the step, and the group was integrated in steps of
    ''' 2 µs (116 000 steps and 21 s of CPU for 0.4 s). h times that rounding is now allowed for
    ''' (ConstraintSet.AccelerationRounding): about 400 steps. No overlap and no energy gained.
    ''' </summary>
    ''' <summary>
    ''' A bob on a rod and on a stiff spring (10⁸ N/m) to a second anchor: nothing of its own ends the group's motion, so
    ''' it is looked at a stretch at a time, each twice as long as the last up to 0.1 s, in steps of microseconds. An
    ''' advance out of wall-clock time takes one event only, and one event looked as far as 17 000 steps ahead, so a
    ''' window waited on it; it now takes at most 256 steps each time it looks further.
    ''' </summary>
    <Fact>
    Public Sub AStiffGroupLookingFurther_TakesABoundedNumberOfStepsAtATime()
        Dim w As New World(10.0, 10.0, 9.81, 1.0)
        Dim bob As New Circle(New Vector(5.0, 4.0), 0.1, 1.0, New Vector(1.0, 0.0))
        w.Add(bob)
        w.Add(Link.CreateTie(LinkKind.Rod, bob, New Vector(5.0, 5.0), 1.0))
        w.Add(Link.CreateSpring(bob, New Vector(6.0, 4.0), 100000000.0, 0.9))
        Dim s = UseEventSolver(w).General
        Dim mostAtOnce = 0L
        Dim calls = 0
        Do While w.Time < 0.05
            Dim before = s.IntegratorSteps
            ' No wall-clock time at all: one event per advance.
            w.AdvanceWithin(0.05 - w.Time, 0.0)
            mostAtOnce = Math.Max(mostAtOnce, s.IntegratorSteps - before)
            calls += 1
        Loop
        Assert.True(s.IntegratorSteps > 5000, $"{s.IntegratorSteps} steps: the spring is not stiff enough to test this")
        Assert.True(mostAtOnce <= 256 + 2, $"one advance took {mostAtOnce} steps ({s.IntegratorSteps} steps in {calls} advances)")
    End Sub

    <Fact>
    Public Sub LightBallsAmongHeavyBodiesInACorner_AreIntegratedInLongSteps()
        Dim w = SceneFile.LoadFile(TestRepo.CaseFile("event-wedged-light-ball-in-corner-behind-heavy-box.json"))
        EventSolverTestKit.RunEventSolverChecked(w, 0.4, 0.01, EnergyLaw.NeverGained(0.000000001), maxOverlap:=0.000000001)
        Dim steps = DirectCast(w.Solver, EventDrivenSolver).General.IntegratorSteps
        Assert.True(steps < 5000, $"{steps} integrator steps for 0.4 s ({w.CollisionCount} collisions)")
    End Sub
End Class
