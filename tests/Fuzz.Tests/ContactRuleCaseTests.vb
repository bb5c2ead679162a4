Option Strict On
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>
''' Scenes of tests/cases with links that broke the event solver before lasting contact had one rule
''' (docs/contact.md); each test states the law it checks (see tests/cases/README.md).
''' </summary>
<Collection(FuzzRuns.Name)>
Public Class ContactRuleCaseTests
    Private Const RodLinkedBoxes As String = "event-rod-linked-boxes-overlap.json"
    Private Const SnapBesideRod As String = "event-string-snap-beside-rod-energy.json"
    Private Const SpringThroughCeiling As String = "event-spring-pulls-through-ceiling.json"
    Private Const StuckAtInstant As String = "event-linked-stuck-at-instant.json"
    Private Const LinkedSlow As String = "event-linked-slow.json"
    Private Const StringTaut As String = "string-taut-not-in-events.json"
    ''' <summary>These runs are known to end in seconds; the cap only stops a runaway, s.</summary>
    Private Const GenerousCap As Double = 300

    ''' <summary>The event solver's checks (no overlap, nothing out of the container, the energy laws, the same run however sampled) over <paramref name="total"/> s.</summary>
    Private Shared Sub AssertKeepsEveryInvariant(name As String, total As Double)
        Dim text = IO.File.ReadAllText(TestPaths.Case_(name))
        Dim result = SceneCheck.Check(text, "event", New RunPlan(total, 0.05, 0.013, GenerousCap))
        Assert.True(result.Violations.Count = 0, String.Join("; ", result.Violations))
    End Sub

    Private Shared Function Load(name As String) As World
        Dim world = SceneFile.LoadFile(TestPaths.Case_(name))
        world.Solver = SolverFactory.Create("event")
        Return world
    End Function

    <Fact>
    Public Sub RodLinkedBoxes_Collide_AndNeverOverlap()
        ' Two 0.8 m boxes on a 1 m rod, one moving sideways at 2 m/s, g = 0, e = 1: as the rod turns their corners
        ' meet. Bodies on a rod were never searched for contact, and overlapped by 0.083 m.
        Dim world = Load(RodLinkedBoxes)
        Dim hits = 0
        world.CollisionListener = Sub(r) If r.B IsNot Nothing AndAlso Not r.B.IsFixed Then hits += 1
        Do While world.Time < 2 - 0.000000001
            world.Advance(0.05)
            Assert.Null(StateChecks.Overlap(world))
        Loop
        Assert.True(hits >= 1, "the boxes never met")
        AssertKeepsEveryInvariant(RodLinkedBoxes, 2)
    End Sub

    <Fact>
    Public Sub StringSnapBesideRod_TheBoxComesBackAtMinusThreeMetresASecond_EnergyKept_AndTheSnapIsReported()
        ' A ball on a rod to a fixed point, a 350 kg box on a slack string to the ball, all in line, g = 0, e = 1.
        ' The rod holds the ball, so the string's jerk turns the box back at the speed it came: −3 m/s, energy
        ' kept. The projected Gauss–Seidel solve of the old blow stopped short (−0.454 m/s, 97.7 % of the energy
        ' gone), and no string-taut row was written.
        Dim world = Load(SnapBesideRod)
        Dim box = world.Find("box")
        Dim snaps As New List(Of CollisionRecord)
        world.CollisionListener = Sub(r) If r.Kind = CollisionKind.StringTaut Then snaps.Add(r)
        Dim e0 = world.KineticEnergy + world.PotentialEnergy
        ' The string snaps taut at t = 0.1 s; the box meets the ball at t ≈ 0.497 s.
        world.Advance(0.3)
        Assert.Single(snaps)
        Assert.Equal("str", snaps(0).BName)
        Assert.Equal("string-taut", snaps(0).KindName)
        Assert.Equal(-3.0, snaps(0).BVelocityAfter.X, 9)
        Assert.Equal(-3.0, box.Velocity.X, 9)
        Assert.True(Math.Abs(world.KineticEnergy + world.PotentialEnergy - e0) <= 0.000000001 * e0, $"energy {world.KineticEnergy + world.PotentialEnergy} J, from {e0} J")
        AssertKeepsEveryInvariant(SnapBesideRod, 2)
    End Sub

    <Fact>
    Public Sub SpringThroughCeiling_NothingLeavesTheContainer()
        ' A triangle pulled up by a stiff spring crept through the ceiling: 0.34 mm out by t = 2 s.
        AssertKeepsEveryInvariant(SpringThroughCeiling, 2)
    End Sub

    <Fact>
    Public Sub StuckAtInstant_GetsPast_AndKeepsEveryInvariant()
        ' "could not get past t = 0.110 s with links (100001 events within a nanosecond)": a corner of one box on a
        ' corner of another, resolved along the bisector, still closed on both faces, and was hit again for ever.
        AssertKeepsEveryInvariant(StuckAtInstant, 2)
    End Sub

    <Fact>
    Public Sub LinkedSlow_TakesAFewDozenCollisions_NotMillions()
        ' A polygon on a string and a stiff spring (e = 0.035, g = 0): the string's snaps never settled, because
        ' what stretches it (the turning of its line, the spring) was not counted, only gravity: 1.8 million
        ' collisions and a minute of CPU for 2 simulated seconds.
        Dim world = Load(LinkedSlow)
        Dim count = 0
        world.CollisionListener = Sub(r) count += 1
        world.Advance(2)
        Assert.True(count < 1000, $"{count} collisions")
        AssertKeepsEveryInvariant(LinkedSlow, 2)
    End Sub

    <Fact>
    Public Sub StringTaut_IsReportedWithTheStringsId()
        ' A bob on a slack string snaps taut at t ≈ 0.42 s: a collision of kind string-taut, b the string's id.
        Dim world = Load(StringTaut)
        Dim rows As New List(Of CollisionRecord)
        world.CollisionListener = Sub(r) rows.Add(r)
        world.Advance(1)
        Dim snap = Assert.Single(rows, Function(r) r.Kind = CollisionKind.StringTaut AndAlso r.Time < 0.5)
        Assert.Equal("bob", snap.A.Id)
        Assert.Equal("s", snap.BName)
        Assert.InRange(snap.Time, 0.4, 0.45)
        ' Its jerk takes the speed outwards along the string away (e = 1: it comes back as fast).
        Assert.True(snap.AVelocityAfter <> snap.AVelocityBefore)
    End Sub
End Class
