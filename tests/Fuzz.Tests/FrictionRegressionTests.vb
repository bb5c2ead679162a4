Option Strict On
Imports PhysicsEngine.Fuzzing.Checking
Imports Xunit

''' <summary>
''' Random scenes with friction (the fuzzer's --rough scenes, tests/cases/README.md) that the event solver's friction
''' once got wrong: checked with every invariant of a fuzz run, sampled two ways.
''' </summary>
<Collection(FuzzRuns.Name)>
Public Class FrictionRegressionTests
    ''' <summary>These runs are known to end in seconds; the cap only stops a runaway, s.</summary>
    Private Const GenerousCap As Double = 300

    <Fact>
    Public Sub BallPressedOnBrakingBox_BreaksNoInvariant()
        AssertNoViolation("event-rough-ball-pressed-on-braking-box.json")
    End Sub

    <Fact>
    Public Sub BallOnSlidingBox_BreaksNoInvariant()
        AssertNoViolation("event-rough-ball-on-sliding-box.json")
    End Sub

    <Fact>
    Public Sub BallOnPolygonCorner_GetsPastTheCorner_AndBreaksNoInvariant()
        ' An exception ("could not get past t = 0.854 s") is reported as a violation, as is any overlap.
        AssertNoViolation("event-rough-ball-on-polygon-corner.json")
    End Sub

    Private Shared Sub AssertNoViolation(name As String)
        Dim text = IO.File.ReadAllText(TestPaths.Case_(name))
        Dim result = SceneCheck.Check(text, "event", New RunPlan(1.0, 0.05, 0.013, GenerousCap))
        Assert.True(result.Violations.Count = 0, String.Join("; ", result.Violations))
    End Sub
End Class
