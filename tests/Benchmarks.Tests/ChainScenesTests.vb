Option Strict On
Imports PhysicsEngine
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>
''' The benchmark's rope and cradle-on-strings scenes: they build the lessons they describe, the event solver
''' keeps the rope's energy and sends exactly one ball out of the cradle at the striker's speed, and a
''' position-based stepper at a coarse step spreads the cradle's momentum over two balls.
''' </summary>
Public Class ChainScenesTests
    Private Shared ReadOnly QuickRun As String() = {"--quick"}

    <Fact>
    Public Sub RopeScene_IsTheRopeLesson_TenBallsOnRodsAndThreeFreeBalls()
        Dim w = SceneCatalog.Create("rope", BenchmarkOptions.Parse(QuickRun)).Build()
        Assert.Equal(13, w.Circles.Count)
        Assert.Equal(10, w.Links.Count)
        Assert.All(w.Links, Sub(l)
                                Assert.Equal(LinkKind.Rod, l.Kind)
                                Assert.Equal(l.Length, l.Distance, 12)
                            End Sub)
        Assert.Equal(1.0, w.Restitution)
    End Sub

    <Fact>
    Public Sub CradleStringsScene_StrikesAtTheSpeedEnergyGives()
        Dim w = SceneCatalog.Create("cradle-strings", BenchmarkOptions.Parse(QuickRun)).Build()
        Dim striker = w.Circles(0)
        ' Released 30° out on a 1 m string: it is 1 − cos 30° above the others.
        Assert.Equal(1 - Math.Cos(Math.PI / 6), striker.Position.Y - w.Circles(1).Position.Y, 12)
        Assert.All(w.Links, Sub(l) Assert.Equal(LinkKind.String, l.Kind))
    End Sub

    <Theory>
    <InlineData("rope")>
    <InlineData("cradle-strings")>
    Public Sub EventSolver_IsExactToRounding(name As String)
        Dim r = SceneRunner.Run(SceneCatalog.Create(name, BenchmarkOptions.Parse(QuickRun)), "event", Nothing, 1, 120)
        Assert.True(r.Available, r.Note)
        Assert.InRange(r.Error, 0.0, 0.000000001)
    End Sub

    <Fact>
    Public Sub Verlet_AtACoarseStep_SpreadsTheCradlesMomentum()
        Dim r = SceneRunner.Run(SceneCatalog.Create("cradle-strings", BenchmarkOptions.Parse(QuickRun)), "verlet", 1 / 250.0, 1, 60)
        Assert.True(r.Available, r.Note)
        Assert.True(r.Error > 0.01, $"Verlet at 1/250 s: {r.Error} ({r.Note})")
        Assert.Contains("2 ball(s) moving", r.Note)
    End Sub
End Class
