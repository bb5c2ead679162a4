Option Strict On
Imports System.IO
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>The lesson scenes in scenes/ show what their lines in the Scenes menu say, against closed forms.</summary>
Public Class LessonScenesTests
    Private Shared Function Run(name As String, seconds As Double) As World
        Dim w = SceneFile.LoadFile(Path.Combine(TestRepo.Root(), "scenes", name))
        w.Solver = SolverFactory.Create("event")
        w.Advance(seconds)
        Return w
    End Function

    Private Shared Function Ball(w As World, id As String) As Shape
        Return w.Find(id)
    End Function

    <Fact>
    Public Sub HeadOn_Elastic_LeavesAtTheClosedFormSpeeds()
        ' 1 kg at u1 = 2 m/s, 3 kg at u2 = −1 m/s, e = 1: v1 = ((m1 − m2)u1 + 2 m2 u2)/(m1 + m2), v2 likewise.
        Dim w = Run("head-on.json", 3.0)
        Dim m1 = 1.0, m2 = 3.0, u1 = 2.0, u2 = -1.0
        Assert.Equal(((m1 - m2) * u1 + 2 * m2 * u2) / (m1 + m2), Ball(w, "light").Velocity.X, 12)
        Assert.Equal(((m2 - m1) * u2 + 2 * m1 * u1) / (m1 + m2), Ball(w, "heavy").Velocity.X, 12)
        Assert.Equal(1, w.CollisionCount)
    End Sub

    <Fact>
    Public Sub HeadOn_PerfectlyInelastic_MovesOnTogether()
        Dim w = Run("head-on-inelastic.json", 3.0)
        Dim common = (1.0 * 2.0 + 3.0 * -1.0) / (1.0 + 3.0) ' m/s: momentum shared, e = 0
        Assert.Equal(common, Ball(w, "light").Velocity.X, 12)
        Assert.Equal(common, Ball(w, "heavy").Velocity.X, 12)
        Dim ke = 0.5 * 1.0 * common * common + 0.5 * 3.0 * common * common
        Assert.Equal(ke, w.Movables.Sum(Function(b) b.KineticEnergy), 12)
    End Sub

    <Fact>
    Public Sub GlancingBlow_EqualMasses_LeaveAtRightAngles()
        Dim w = Run("glancing-blow.json", 1.0)
        Dim a = Ball(w, "striker").Velocity, b = Ball(w, "target").Velocity
        Assert.Equal(0.0, Vector.Dot(a, b), 12)
        ' Impact parameter = r, so the line of centres is 30° from the approach: sin 30° = r / 2r.
        Assert.Equal(2.0 * Math.Sin(Math.PI / 6), a.Length, 12)
        Assert.Equal(2.0 * Math.Cos(Math.PI / 6), b.Length, 12)
    End Sub

    <Fact>
    Public Sub NewtonsCradle_OnlyTheLastBallLeaves_AtTheStrikersSpeed()
        Dim w = Run("newtons-cradle.json", 5.0)
        Assert.Equal(1.0, Ball(w, "ball5").Velocity.X, 9)
        For Each id In {"striker", "ball1", "ball2", "ball3", "ball4"}
            Assert.Equal(0.0, Ball(w, id).Velocity.Length, 9)
        Next
    End Sub

    <Fact>
    Public Sub GaltonBoard_EveryBallEndsInABin_AndTheBinsFillToABellCentredUnderTheChute()
        ' Balls slide off the shelves one after another, fall through the funnel and the chute onto the
        ' pegs, and pile up in the bins. Each row of pegs sends a ball left or right by half a peg
        ' spacing, so the counts make a binomial (bell) shape centred under the chute.
        ' The file is the board Scenarios builds (which the benchmark runs with more balls).
        SceneRoundTripTests.AssertSameScene(Scenarios.GaltonBoard(), SceneFile.LoadFile(Path.Combine(TestRepo.Root(), "scenes", "galton-board.json")), "galton-board.json")
        Dim w = Run("galton-board.json", 14.0)
        Dim balls = w.Movables.OfType(Of Circle)().ToList()
        Assert.True(balls.Count >= 200, $"{balls.Count} balls")
        Dim dividers = w.Rectangles.Where(Function(r) r.Id.StartsWith("bin", StringComparison.Ordinal)).OrderBy(Function(r) r.Min.X).ToList()
        Dim sides = w.Segments.Where(Function(s) s.Id.StartsWith("side", StringComparison.Ordinal)).Select(Function(s) s.StartPoint.X).OrderBy(Function(x) x).ToList()
        Dim edges As New List(Of Double) From {sides(0)}
        edges.AddRange(dividers.Select(Function(r) (r.Min.X + r.Max.X) / 2))
        edges.Add(sides(1))
        Dim binTop = dividers(0).Max.Y
        Dim counts(edges.Count - 2) As Integer
        For Each b In balls
            Assert.True(b.Position.Y < binTop, $"{b.Id} at {b.Position} is not down in a bin")
            Dim k = edges.FindLastIndex(Function(x) x <= b.Position.X)
            Assert.InRange(k, 0, counts.Length - 1)
            counts(k) += 1
        Next
        Dim centre = (sides(0) + sides(1)) / 2
        Dim mean = balls.Average(Function(b) b.Position.X)
        Dim spacing = edges(2) - edges(1)
        Assert.True(Math.Abs(mean - centre) < spacing, $"the balls' mean x {mean} m is more than a bin from the centre {centre} m: {String.Join(",", counts)}")
        ' A bell: the middle third of the bins holds most balls, the outermost few (a flat spread would put a
        ' third in the middle and over a quarter in the outermost bins). The run is chaotic: the netstandard2.0
        ' build's arithmetic gives another spread, so the bounds leave room for it.
        Dim n = counts.Length, third = n \ 3
        Dim middle = counts.Skip(third).Take(n - 2 * third).Sum()
        Assert.True(middle > 0.5 * balls.Count, $"the middle bins hold {middle} of {balls.Count}: {String.Join(",", counts)}")
        Dim outer = counts.Take(third \ 2).Sum() + counts.Skip(n - third \ 2).Sum()
        Assert.True(outer < 0.15 * balls.Count, $"the outermost bins hold {outer}: {String.Join(",", counts)}")
    End Sub

    <Fact>
    Public Sub IdealGas_KeepsItsKineticEnergy()
        Dim w = SceneFile.LoadFile(Path.Combine(TestRepo.Root(), "scenes", "ideal-gas.json"))
        Assert.Equal(1000, w.Movables.Count)
        Assert.Equal(1.0, w.Restitution)
        Dim before = w.Movables.Sum(Function(b) b.KineticEnergy)
        w.Solver = SolverFactory.Create("event")
        w.Advance(2.0)
        Assert.True(w.CollisionCount > 1000, $"{w.CollisionCount} collisions")
        Assert.Equal(before, w.Movables.Sum(Function(b) b.KineticEnergy), 9)
    End Sub

    <Fact>
    Public Sub SettlingPile_ComesToRestInsideItsBox()
        Dim w = Run("settling-pile.json", 8.0)
        Assert.True(w.Restitution < 1)
        Dim ke = w.Movables.Sum(Function(b) b.KineticEnergy)
        Assert.True(ke < 1.0E-6, $"kinetic energy {ke} J after 8 s")
        Assert.Null(Placement.FindProblem(w))
    End Sub
End Class
