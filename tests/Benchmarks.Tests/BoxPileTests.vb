Option Strict On
Imports System.Globalization
Imports PhysicsEngine
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>
''' The box piles: the scene itself, what the event solver leaves at the end of it, and the Box2D
''' reference's input, output and place in the report. No timings: those are the benchmark's.
''' </summary>
Public Class BoxPileTests
    Private Shared ReadOnly QuickRun As String() = {"--quick"}

    Private Shared Function Pile(name As String) As BoxPileScene
        Return DirectCast(SceneCatalog.Create(name, BenchmarkOptions.Parse(QuickRun)), BoxPileScene)
    End Function

    <Fact>
    Public Sub Scene_Has200MovableBoxesOfMixedSizes_ApartAndInsideTheContainer_TheSameEveryTime()
        Dim world = Pile(BoxPileScene.WideName).Build()
        Dim again = Pile(BoxPileScene.WideName).Build()
        Assert.Equal(200, world.Rectangles.Count)
        Assert.All(world.Rectangles, Sub(b)
                                         Assert.False(b.IsFixed)
                                         Assert.InRange(b.Width, 0.2, 0.5)
                                         Assert.InRange(b.Height, 0.2, 0.5)
                                         Assert.Equal(10.0, b.Density, 9)
                                     End Sub)
        ' Mixed: the sizes spread over most of the range.
        Assert.True(world.Rectangles.Max(Function(b) b.Width) - world.Rectangles.Min(Function(b) b.Width) > 0.25)
        Assert.Equal(0.0, Overlap.DeepestBetweenBoxes(world))
        Dim closest = Double.PositiveInfinity
        For i = 0 To world.Rectangles.Count - 1
            For j = i + 1 To world.Rectangles.Count - 1
                Dim a = world.Rectangles(i), b = world.Rectangles(j)
                closest = Math.Min(closest, -Collider.BoxBoxDepth(a.Min, a.Max, b.Min, b.Max))
            Next
        Next
        Assert.True(closest >= 0.1, $"two boxes start {closest} m apart")
        For k = 0 To world.Rectangles.Count - 1
            Assert.Equal(world.Rectangles(k).Position, again.Rectangles(k).Position)
            Assert.Equal(world.Rectangles(k).Width, again.Rectangles(k).Width)
        Next
    End Sub

    <Fact>
    Public Sub DeepScene_StacksTenAndMoreBoxesDeep()
        ' 200 boxes of mean area 0.35² m² over 3 m hold a heap at least 10 mean heights (0.35 m) tall.
        Dim world = Pile(BoxPileScene.DeepName).Build()
        Dim area = world.Rectangles.Sum(Function(b) b.Width * b.Height)
        Assert.True(area / world.Width / 0.35 >= 10, $"the heap is only {area / world.Width / 0.35} boxes deep")
    End Sub

    <Theory>
    <InlineData(BoxPileScene.WideName)>
    <InlineData(BoxPileScene.DeepName)>
    Public Sub EventSolver_BringsThePileToRest_WithNoOverlap_AndNoEnergyGained(name As String)
        Dim scene = Pile(name)
        Dim world = scene.Build()
        world.Solver = New EventDrivenSolver()
        Dim startEnergy = world.KineticEnergy() + world.PotentialEnergy()
        Dim rest = scene.RunToRest(world, New RunBudget(120))
        Assert.False(Double.IsNaN(rest), $"{name}: not at rest after {scene.SimulatedSeconds} s")
        ' At rest means at rest: asleep or standing still, every box, and so it stays.
        Dim solver = DirectCast(world.Solver, EventDrivenSolver)
        Assert.All(world.Rectangles, Sub(b) Assert.True(solver.IsAsleep(b) OrElse b.Velocity.Length = 0, $"{b.Id} moves at {b.Velocity.Length} m/s"))
        Dim heights = world.Rectangles.Select(Function(b) b.Position).ToList()
        world.Advance(0.5)
        Assert.Equal(heights, world.Rectangles.Select(Function(b) b.Position).ToList())
        Assert.InRange(Overlap.DeepestBetweenBoxes(world), 0.0, 1.0E-9)
        ' The energy books: what the collisions took plus what is left is what there was; it never grows.
        Dim ledger = world.KineticEnergy() + world.PotentialEnergy() + world.Dissipated
        Assert.True(ledger <= startEnergy * (1 + 1.0E-9), $"{name}: energy rose from {startEnergy} J to {ledger} J")
        Assert.True(ledger >= startEnergy * (1 - 1.0E-9), $"{name}: {startEnergy - ledger} J left without being counted as dissipated")
        Assert.True(world.Dissipated > 0.5 * (startEnergy - world.PotentialEnergy()))
    End Sub

    <Theory>
    <InlineData(BoxPileScene.WideName)>
    <InlineData(BoxPileScene.DeepName)>
    Public Sub EventSolver_LeavesNoBoxAsleepInTheAir(name As String)
        ' Frictionless boxes that cannot turn are held up only by something under them: the floor, or the
        ' top of a box with some width in common (a corner on a corner holds a box that cannot turn).
        Dim scene = Pile(name)
        Dim world = scene.Build()
        world.Solver = New EventDrivenSolver()
        Assert.False(Double.IsNaN(scene.RunToRest(world, New RunBudget(120))))
        Assert.Equal(0, BoxPileScene.Unsupported(world, BoxPileScene.SupportGap))
    End Sub

    <Fact>
    Public Sub Measure_NotesRestAndTheEnergyBooks_AndGivesTheOverlapAsTheError()
        Dim scene = Pile(BoxPileScene.WideName)
        Dim world = scene.Build()
        world.Solver = New EventDrivenSolver()
        Dim m = scene.Measure(world, SceneRunner.EventSampleStep, New RunBudget(120))
        Assert.True(m.Completed)
        Assert.InRange(m.Error, 0.0, 1.0E-9)
        Assert.Contains("all 200 at rest from", m.Note, StringComparison.Ordinal)
        Assert.Contains("KE + PE + dissipated − E0", m.Note, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub Unsupported_CountsABoxWithNothingUnderIt_NotOneOnTheFloorOrOnABox()
        Dim w As New World(4, 4, 9.81, 0.3)
        w.Add(Rectangle.CreateMovable(New Vector(0.5, 0), 0.4, 0.4, 1, Vector.Zero, "floor"))
        w.Add(Rectangle.CreateMovable(New Vector(0.7, 0.4), 0.4, 0.4, 1, Vector.Zero, "on a box"))
        w.Add(Rectangle.CreateMovable(New Vector(2.0, 0.3), 0.4, 0.4, 1, Vector.Zero, "in the air"))
        w.Add(Rectangle.CreateMovable(New Vector(0.9, 0.801), 0.4, 0.4, 1, Vector.Zero, "a mm above"))
        w.Add(Rectangle.CreateMovable(New Vector(0.1, 0.4), 0.4, 0.4, 1, Vector.Zero, "corner on corner"))
        w.Add(Rectangle.CreateMovable(New Vector(3.0, 1.0), 0.4, 0.4, 1, Vector.Zero, "beside, not on"))
        w.Add(Rectangle.CreateMovable(New Vector(3.4, 0.8), 0.4, 0.4, 1, Vector.Zero, "beside it, lower"))
        Assert.Equal(4, BoxPileScene.Unsupported(w, 1.0E-9))
        Assert.Equal(3, BoxPileScene.Unsupported(w, 0.002))
    End Sub

    <Fact>
    Public Sub SceneText_GivesTheWorldAndEveryBox_SoThatTheyReadBackExactly()
        Dim world = Pile(BoxPileScene.WideName).Build()
        Dim lines = Box2dReference.SceneText(world).Split(ControlChars.Lf).Where(Function(l) l.Length > 0 AndAlso Not l.StartsWith("#"c)).ToList()
        Assert.Equal(201, lines.Count)
        Dim head = lines(0).Split(" "c)
        Assert.Equal("world", head(0))
        Assert.Equal({world.Width, world.Height, world.Gravity, world.Restitution}, head.Skip(1).Select(Function(x) Double.Parse(x, CultureInfo.InvariantCulture)).ToArray())
        For k = 0 To world.Rectangles.Count - 1
            Dim f = lines(k + 1).Split(" "c)
            Dim b = world.Rectangles(k)
            Assert.Equal("box", f(0))
            Assert.Equal({b.Min.X, b.Min.Y, b.Width, b.Height, b.Mass}, f.Skip(1).Select(Function(x) Double.Parse(x, CultureInfo.InvariantCulture)).ToArray())
        Next
    End Sub

    <Fact>
    Public Sub SceneText_RefusesWhatTheReferenceCannotBuild()
        Dim w = Scenarios.BoxDrop()
        w.Add(New Circle(New Vector(0.5, 0.5), 0.1, 1.0))
        Assert.Throws(Of ArgumentException)(Function() Box2dReference.SceneText(w))
    End Sub

    <Fact>
    Public Sub ParseRunLine_ReadsEveryField_AndRejectsALineWithOneMissing()
        Dim r = Box2dReference.ParseRunLine("run 2 steps=210 simulated_s=3.500000 wall_ms=61.2500 max_overlap_m=1.1e-02 asleep=200 bodies=200")
        Assert.True(r.HasValue)
        Assert.Equal(210, r.Value.Steps)
        Assert.Equal(3.5, r.Value.SimulatedSeconds)
        Assert.Equal(61.25, r.Value.WallMs)
        Assert.Equal(0.011, r.Value.MaxOverlap, 12)
        Assert.Equal(200, r.Value.Asleep)
        Assert.Null(Box2dReference.ParseRunLine("run 2 steps=210 simulated_s=3.5 wall_ms=61.25 asleep=200 bodies=200"))
        Assert.Null(Box2dReference.ParseRunLine("run 2 steps=x simulated_s=3.5 wall_ms=61.25 max_overlap_m=0 asleep=200 bodies=200"))
        Assert.Null(Box2dReference.ParseRunLine("box2d: something else"))
    End Sub

    <Fact>
    Public Sub Summarise_TakesTheMedianWall_AndGivesNoRestTimeWhenBodiesWereAwake()
        Dim run = Function(wall As Double, asleep As Integer) New Box2dReference.RunLine With {
            .Steps = 210, .SimulatedSeconds = 3.5, .WallMs = wall, .MaxOverlap = -0.001, .Asleep = asleep, .Bodies = 200}
        Dim r = Box2dReference.Summarise("box-pile", "m", {run(70, 200), run(50, 200), run(60, 200)})
        Assert.True(r.Available)
        Assert.Equal(60.0, r.RestWallMs)
        Assert.Equal(3.5, r.RestSeconds)
        Assert.Equal(0.0, r.Error)
        Dim awake = Box2dReference.Summarise("box-pile", "m", {run(70, 198)})
        Assert.True(Double.IsNaN(awake.RestWallMs))
        Assert.Contains("198 of 200 asleep", awake.Note, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub Run_WithoutTheProgram_IsARowSayingSo_NotAnError()
        Dim r = Box2dReference.Run("/nonexistent/box_pile", Pile(BoxPileScene.WideName), 1, TimeSpan.FromSeconds(10))
        Assert.False(r.Available)
        Assert.Equal(Box2dReference.SolverName, r.Solver)
        Assert.Contains("missing", r.Note, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub Report_PutsBox2dBesideOurs_WithTheRatio_OrSaysWhyItDidNotRun()
        Dim scene = Pile(BoxPileScene.WideName)
        Dim ours = New BenchResult With {.Scene = scene.Name, .Solver = "event", .Error = 0, .ErrorMetric = scene.ErrorMetric, .MsPerSimulatedSecond = 30,
                                         .RestSeconds = 1.411, .RestWallMs = 45.0, .Runs = 3, .Note = "all 200 at rest"}
        Dim theirs = New BenchResult With {.Scene = scene.Name, .Solver = Box2dReference.SolverName, .TimeStep = 1 / 60.0, .Error = 0.011,
                                           .ErrorMetric = scene.ErrorMetric, .MsPerSimulatedSecond = 20, .RestSeconds = 3.5, .RestWallMs = 90.0, .Note = "all 200 asleep"}
        Dim md = MarkdownReport.Render(SampleResults.Machine(), "quick", 3, {scene}, {ours, theirs}, New FrameResult With {.Note = "skipped"})
        Assert.Contains("| event | — | 1.411 | 45.00 | **0.50** | 0 |", md, StringComparison.Ordinal)
        Assert.Contains("| Box2D 2.4.1 | 1/60 | 3.500 | 90.00 | 1 |", md, StringComparison.Ordinal)
        Assert.Contains("**0.50× Box2D's time**", md, StringComparison.Ordinal)
        ' Not in the first table, nor taken for the best stepping run.
        Assert.DoesNotContain("| box2d |", md, StringComparison.Ordinal)
        Assert.DoesNotContain("(box2d,", md, StringComparison.Ordinal)

        Dim missing = Box2dReference.NotRun(scene.Name, scene.ErrorMetric, "not run: libbox2d-dev (Box2D 2.4.1) is not installed.")
        md = MarkdownReport.Render(SampleResults.Machine(), "quick", 3, {scene}, {ours, missing}, New FrameResult With {.Note = "skipped"})
        Assert.Contains("| Box2D 2.4.1 | 1/60 | — | — | — | — | not run: libbox2d-dev (Box2D 2.4.1) is not installed. |", md, StringComparison.Ordinal)
        Assert.Contains("| event | — | 1.411 | 45.00 | — |", md, StringComparison.Ordinal)
    End Sub
End Class
