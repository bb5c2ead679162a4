Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>A dense inelastic pile must settle: bounded events, no overlap, nothing escapes, energy at its floor.</summary>
Public Class PileTests
    <Fact>
    Public Sub Pile_OfTwoHundred_AtE03_Settles()
        Dim w = Scenarios.Pile(200, 0.3)
        Dim solver = UseEventSolver(w)
        solver.MaxEventsPerAdvance = 5000000
        Dim e0 = w.KineticEnergy() + w.PotentialEnergy()
        Dim worst = 0.0
        For k = 1 To 10
            w.Advance(0.5)
            worst = Math.Max(worst, DeepestOverlap(w))
        Next
        Dim settledCollisions = w.CollisionCount
        Dim settledEvents = solver.EventCount
        w.Advance(5.0)
        worst = Math.Max(worst, DeepestOverlap(w))
        ' Bounded: the whole fall and settling took far fewer than a million collisions, and once
        ' settled nothing more happens.
        Assert.True(settledCollisions < 1000000, $"{settledCollisions} collisions")
        Assert.True(w.CollisionCount - settledCollisions < 100, $"{w.CollisionCount - settledCollisions} collisions after settling")
        Assert.True(solver.EventCount - settledEvents < 1000)
        Assert.True(worst <= 1.0E-6, $"overlap {worst} m")
        Dim mass = 0.0, area = 0.0
        For Each c In w.Circles
            Assert.True(c.Position.X >= c.Radius - 1.0E-9 AndAlso c.Position.X <= w.Width - c.Radius + 1.0E-9, $"{c.Id} escaped: {c.Position}")
            Assert.True(c.Position.Y >= c.Radius - 1.0E-9 AndAlso c.Position.Y <= w.Height - c.Radius + 1.0E-9, $"{c.Id} escaped: {c.Position}")
            mass += c.Mass
            area += c.Area
        Next
        ' Energy at its floor: no motion left, and the centre of mass no higher than half the height of
        ' the same circles packed loosely (packing fraction 0.6) against the floor.
        Assert.True(w.KineticEnergy() < 1.0E-9 * e0, $"KE {w.KineticEnergy()}")
        Dim looseHeight = area / (w.Width * 0.6)
        Assert.True(w.PotentialEnergy() < mass * w.Gravity * (looseHeight / 2 + 0.05), $"PE {w.PotentialEnergy()} vs {mass * w.Gravity * (looseHeight / 2 + 0.05)}")
        For Each c In w.Circles
            Assert.True(solver.IsAsleep(c), $"{c.Id} still awake")
        Next
    End Sub

    ''' <summary>
    ''' A settling pile keeps to the fast path. Balls wedged at one instant while the balls around them still move
    ''' are held by those neighbours (their normals straddle the vertical), so they sleep there; only a ball that
    ''' nothing would hold, moving or not, hands the world over to the general path, which is far slower on a
    ''' pile (RestRules.WouldBeHeld). A pile of 40 handed over took about 3 s of wall clock per simulated second instead of 6 ms.
    ''' </summary>
    <Fact>
    Public Sub Pile_OfForty_SettlesWithoutHandingOver()
        Dim w = Scenarios.Pile(40, 0.3)
        Dim solver = UseEventSolver(w)
        For k = 1 To 15
            w.Advance(0.1)
            Assert.True(Double.IsPositiveInfinity(solver.HandedOverAt), $"handed over to the general path at t = {solver.HandedOverAt} s")
        Next
        For Each c In w.Circles
            Assert.True(solver.IsAsleep(c), $"{c.Id} still awake at t = {w.Time} s")
        Next
    End Sub

    <Theory>
    <InlineData(60)>
    <InlineData(2)>
    Public Sub BoxPile_ThreeMetresWide_EveryBoxAsleepIsHeld_AndTheEnergyBooksClose(looksPerSecond As Integer)
        ' 200 frictionless boxes that cannot turn, stacked ten and more deep: boxes fall asleep on
        ' boxes that later drop (when what they stand on is found no longer held and falls), and what
        ' sleeps on a box that falls must fall after it, however many sleep in a stack; a box still falling
        ' holds nothing up. Boxes put exactly on their support when they fall asleep drop the last crumb
        ' of their fall: counted as dissipated. Looked at often or seldom, the runs differ in rounding.
        Dim w = Scenarios.BoxPile(200, 3.0, 0.3)
        Dim solver = UseEventSolver(w)
        RunChecked(w, 8, 1.0 / looksPerSecond, EnergyLaw.PlusDissipatedKept(1.0E-12))
        Dim boxes = w.Rectangles
        Dim asleep = boxes.Where(Function(a) solver.IsAsleep(a)).ToList()
        Assert.Equal(200, asleep.Count)
        For Each a In asleep
            ' On the floor, or on the top of a box with some width in common (corner on corner holds too).
            Dim held = a.Min.Y = 0 OrElse boxes.Any(Function(o) o IsNot a AndAlso Math.Abs(o.Max.Y - a.Min.Y) <= 1.0E-9 AndAlso
                                                                  Math.Min(a.Max.X, o.Max.X) - Math.Max(a.Min.X, o.Min.X) >= 0)
            Assert.True(held, $"{a.Id} asleep at y = {a.Min.Y} m with nothing under it")
        Next
    End Sub

    ''' <summary>
    ''' With e &lt; 1 the energy never rises: KE + PE + dissipated stays at or below its value at the start
    ''' (to 1e-9 of it), looked at every 0.1 s for 20 s, in a pile of 40 balls and in the 500-ball Galton
    ''' board. A free ball touching gently a ball that rests on the floor but still slides must not bounce
    ''' off it as off the ground, a moving wall: the touch is shared with the floor, and a bounce too small to
    ''' follow ends with the two sliding on together (RestRules.AfterSliderContact).
    ''' </summary>
    <Theory>
    <InlineData("pile")>
    <InlineData("galton")>
    Public Sub EnergyNeverRises_InAPileOrAGaltonBoard(scene As String)
        Dim w = If(scene = "pile", Scenarios.Pile(40, 0.3), Scenarios.GaltonBoard(500, 12, 20, 10))
        RunEventSolverChecked(w, 20, 0.1, EnergyLaw.NeverGained(1.0E-9))
    End Sub
End Class
