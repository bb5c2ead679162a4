Option Strict On
Imports PhysicsEngine.Fuzzing
Imports PhysicsEngine.Fuzzing.Generation
Imports Xunit

''' <summary>How long a generated scene runs: as asked, or shorter for a fast scene; and the options the command line reads.</summary>
Public Class CampaignPlanTests
    <Fact>
    Public Sub AFastScene_RunsUntilItsFastestBallHasCrossedTheContainerAThousandTimes()
        Dim options As New FuzzOptions()
        For seed = 1 To 300
            Dim draft = SceneGenerator.Generate(seed, BodyKinds.Default, 40)
            Dim plan = Campaign.PlanFor(draft, options)
            Dim crossings = 1000 * Math.Min(draft.World.Width, draft.World.Height) / draft.TopSpeed()
            If crossings >= 1 Then
                Assert.Equal(1.0, plan.Time)
                Assert.Equal(0.05, plan.Sample)
                Assert.Equal(0.013, plan.SecondSample)
            Else
                Assert.True(plan.Time <= Math.Max(crossings, 0.01) AndAlso plan.Time > crossings / 2.5 OrElse plan.Time = 0.01, $"seed {seed}: T = {plan.Time} s for {crossings} s")
                Assert.True(plan.Sample <= plan.Time / 10 + 0.000000000001, $"seed {seed}: S = {plan.Sample} s for T = {plan.Time} s")
                Assert.Equal(0.26, plan.SecondSample / plan.Sample, 12)
            End If
        Next
    End Sub

    <Fact>
    Public Sub Options_ReadTheCommandLine()
        Dim o = FuzzOptions.Parse(Words("--scenes 20 --seed 500 --solvers event,verlet --kinds all --cap 3 --no-shrink --time 0.5"))
        Assert.Equal(20, o.Scenes)
        Assert.Equal(500L, o.Seed)
        Assert.Equal("event,verlet", String.Join(",", o.Solvers))
        Assert.Equal(BodyKinds.All, o.Kinds)
        Assert.Equal(3.0, o.Cap)
        Assert.False(o.Shrink)
        Assert.Equal(0.5, o.Time)
        Assert.Throws(Of ArgumentException)(Function() FuzzOptions.Parse(Words("--solvers rk4")))
        Assert.Throws(Of ArgumentException)(Function() FuzzOptions.Parse(Words("--scenes 0")))
        Assert.Throws(Of ArgumentException)(Function() FuzzOptions.Parse(Words("--bogus 1")))
    End Sub

    Private Shared Function Words(line As String) As String()
        Return line.Split(" "c)
    End Function
End Class
