Option Strict On
Imports System.IO
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>
''' The scenes of tests/cases that random scenes with links (<c>--kinds all</c>) caught breaking the event
''' solver; each test checks that its defect is gone (see tests/cases/README.md).
''' </summary>
<Collection(FuzzRuns.Name)>
Public Class LinkedRegressionSceneTests
    Private Const SamplingWall As String = "event-linked-sampling-wall.json"
    Private Const BallOnPeg As String = "event-linked-ball-on-peg.json"
    ''' <summary>These runs are known to end quickly; the cap only stops a runaway, s.</summary>
    Private Const GenerousCap As Double = 300

    <Fact>
    Public Sub SamplingWall_TwoSamplingIntervals_GiveTheSameCollisionsAndEndState()
        ' c35 flies into the left wall beside c34 on a string: sampled every 0.05 s and every 0.013 s, the
        ' collision came an ulp apart (t = 0.1346559591951048 s and 0.13465595919510476 s), because each
        ' advance searched again from its own start.
        Dim text = File.ReadAllText(TestPaths.Case_(SamplingWall))
        Dim result = SceneCheck.Check(text, "event", New RunPlan(0.15, 0.05, 0.013, GenerousCap))
        Assert.True(result.Violations.Count = 0, String.Join("; ", result.Violations))
    End Sub

    <Theory>
    <InlineData(0.05)>
    <InlineData(0.1)>
    Public Sub BallOnPeg_NeverSinksIntoPegF0_NorPassesThroughIt(advance As Double)
        ' c0 sits exactly on top of the 1.25 mm peg f0, moving sideways at 1.7 cm/s, g = 56 m/s², beside a ball
        ' on a string. It used to bounce on f0 a nanometre deeper each time (2.25 μm deep by t = 0.05 s), and with
        ' an advance of 0.1 s it fell right through f0 (4 cm) without touching it. Now it slides round the peg,
        ' held on it until it leaves, however the run is cut into advances.
        Dim world = SceneFile.LoadFile(TestPaths.Case_(BallOnPeg))
        world.Solver = SolverFactory.Create("event")
        Dim ball = world.Find("c0")
        Dim peg = world.Find("f0")
        Do While world.Time < 1 - 0.000000001
            world.Advance(advance)
            Assert.Null(StateChecks.Overlap(world))
        Loop
        ' Off the peg to one side, not through it.
        Assert.True(Math.Abs(ball.Position.X - peg.Position.X) > 0.001, $"c0 at {ball.Position}, f0 at {peg.Position}")
    End Sub
End Class
