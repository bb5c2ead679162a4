Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>The measuring tools: the tape measure, the protractor on a ramp, the stopwatch on simulated time, and a pendulum's period timed by its passes.</summary>
Public Class MeasuringToolsTests
    <Fact>
    Public Sub TheTape_DraggedBetweenTwoPoints_ReadsTheirDistanceAndAngle_AndStaysUntilEsc()
        Dim h As New PresenterHarness(New World(8, 5, 9.81, 1.0))
        h.P.ToggleTapeMeasure()
        Assert.True(h.P.Tape.IsOn)
        ' A 3-4-5 triangle: 5 m long, tan⁻¹(4/3) = 53.13° from the horizontal.
        h.Drag(PointerButton.Left, 1, 0.5, 4, 4.5)
        Assert.True(h.P.Tape.HasLine)
        Assert.Equal(5.0, h.P.Tape.Length, 9)
        Assert.Equal(Math.Atan2(4, 3) * 180 / Math.PI, h.P.Tape.AngleDegrees, 9)
        Assert.Equal("5.00 m at 53.1°", h.P.TapeLabel)
        Assert.Contains(h.TraceLines, Function(l) l.StartsWith("tape 5 m at 53.130 deg", StringComparison.Ordinal))
        ' The cue aimed at nothing: the drag was the tape's.
        Assert.Null(h.P.AimedBody)
        ' Drawn right to left and downwards, the same line reads the same.
        h.Drag(PointerButton.Left, 4, 4.5, 1, 0.5)
        Assert.Equal(5.0, h.P.Tape.Length, 9)
        Assert.Equal(53.13, h.P.Tape.AngleDegrees, 2)
        h.P.Tick(0.1)
        Assert.True(h.P.Tape.HasLine, "the line stays while time runs")
        h.P.CancelPlacement()
        Assert.False(h.P.Tape.IsOn)
        Assert.False(h.P.Tape.HasLine)
        Assert.Equal("", h.P.TapeLabel)
    End Sub

    <Theory>
    <InlineData(1.23456, 0.01, 2)>
    <InlineData(1.23456, 0.0001, 4)>
    <InlineData(123.456, 0.05, 2)>
    <InlineData(123.456, 1.0, 0)>
    <InlineData(0.0123, 0.01, 4)>
    Public Sub TheTapesDecimals_AreThreeFiguresOrWhatAPixelResolves(length As Double, metresPerPixel As Double, decimals As Integer)
        Assert.Equal(decimals, TapeMeasure.Decimals(length, metresPerPixel))
    End Sub

    <Fact>
    Public Sub TheProtractor_OnA30DegreeRamp_Reads30Degrees_AtItsLowerEnd()
        Dim w As New World(8, 5, 9.81, 1.0)
        Dim a As New Vector(1, 1), b = a + 3 * New Vector(Math.Cos(Math.PI / 6), Math.Sin(Math.PI / 6))
        w.Add(New Segment(b, a))
        Dim h As New PresenterHarness(w)
        Dim mid = h.Px(0.5 * (a.X + b.X), 0.5 * (a.Y + b.Y))
        h.P.PointerMove(mid.X, mid.Y + 3)
        Assert.NotNull(h.P.Protractor)
        Assert.Equal(30.0, h.P.Protractor.Degrees, 9)
        Assert.Equal("30.0°", h.P.Protractor.Label)
        Assert.Equal(a, h.P.Protractor.Lower)
        Assert.True(h.P.Protractor.RisesRight)
        ' Far from the ramp there is nothing to read.
        Dim away = h.Px(6, 4)
        h.P.PointerMove(away.X, away.Y)
        Assert.Null(h.P.Protractor)
    End Sub

    <Fact>
    Public Sub TheProtractor_ReadsAPolygonsFace()
        Dim w As New World(8, 5, 9.81, 1.0)
        ' A wedge whose long face rises at tan⁻¹(1/2) = 26.57°.
        w.Add(Polygon.CreateFixed({New Vector(2, 1), New Vector(6, 1), New Vector(6, 3)}))
        Dim h As New PresenterHarness(w)
        Dim onFace = h.Px(4, 2)
        h.P.PointerMove(onFace.X, onFace.Y)
        Assert.Equal(Math.Atan(0.5) * 180 / Math.PI, h.P.Protractor.Degrees, 9)
        Assert.Equal(New Vector(2, 1), h.P.Protractor.Lower)
    End Sub

    <Fact>
    Public Sub TheStopwatch_CountsSimulatedTime_StandsStillWhenPaused_AndFollowsTheSpeedSlider()
        Dim h As New PresenterHarness()
        h.P.StopwatchStartStop()
        Assert.True(h.P.LabStopwatch.IsRunning)
        For k = 1 To 30
            h.P.Tick(0.02)
        Next
        Assert.Equal(0.6, h.P.LabStopwatch.Reading, 9)
        h.P.StopwatchLap()
        ' Paused, real time passes but the stopwatch does not move.
        h.P.TogglePause()
        h.P.Tick(0.05)
        Assert.Equal(0.6, h.P.LabStopwatch.Reading, 9)
        h.P.TogglePause()
        ' 4× faster: 0.1 s of real time is 0.4 s on the stopwatch.
        h.P.SetSpeedIndex(12)
        For k = 1 To 5
            h.P.Tick(0.02)
        Next
        Assert.Equal(1.0, h.P.LabStopwatch.Reading, 9)
        h.P.StopwatchStartStop()
        h.P.Tick(0.05)
        Assert.False(h.P.LabStopwatch.IsRunning)
        Assert.Equal(1.0, h.P.LabStopwatch.Reading, 9)
        Assert.Single(h.P.LabStopwatch.Laps)
        Assert.Equal(0.6, h.P.LabStopwatch.Laps(0), 9)
        Assert.Equal("Stopwatch 1.000 s (lap 1: 0.600 s) (stopped)", h.P.StopwatchText)
        h.P.StopwatchReset()
        Assert.Equal(0.0, h.P.LabStopwatch.Reading)
        Assert.Empty(h.P.LabStopwatch.Laps)
        Assert.Equal("", h.P.StopwatchText)
    End Sub

    <Fact>
    Public Sub TheStopwatch_GoesBackWithTheRun_ButNotBelowWhereItStarted()
        Dim h As New PresenterHarness()
        For k = 1 To 10
            h.P.Tick(0.05)
        Next
        h.P.StopwatchStartStop()
        For k = 1 To 20
            h.P.Tick(0.05)
        Next
        Assert.Equal(1.0, h.P.LabStopwatch.Reading, 9)
        h.P.RewindTo(1.0)
        Assert.Equal(0.5, h.P.LabStopwatch.Reading, 9)
        h.P.RewindTo(0.2)
        Assert.Equal(0.0, h.P.LabStopwatch.Reading)
    End Sub

    ''' <summary>
    ''' A pendulum released from θ0 = 0.05 rad: its period is 2π√(L/g)·(1 + θ0²/16 + …), 1.6 parts in 10⁴
    ''' above the small-swing value; timed by the passes of its bob through the vertical line under the pivot.
    ''' </summary>
    <Theory>
    <InlineData(1.0)>
    <InlineData(1.5)>
    Public Sub APendulumsPeriod_TimedByItsPasses_Is2PiRootLOverG(length As Double)
        Const theta0 As Double = 0.05
        Dim h As New PresenterHarness(Scenarios.Pendulum(length, theta0, kind:=LinkKind.Rod))
        Dim bob = h.P.World.Find("bob")
        h.P.SetPassLine(bob, New Vector(2.0, 3.5), New Vector(0, 1))
        Dim small = 2 * Math.PI * Math.Sqrt(length / 9.81)
        Do While h.P.PassTimer.Passes.Count < 4
            h.P.Tick(1 / 60.0)
            Assert.True(h.P.World.Time < 5 * small, "the bob passes the line once a period")
        Loop
        Dim passes = h.P.PassTimer.Passes
        Dim expected = small * (1 + theta0 * theta0 / 16 + 11 * theta0 ^ 4 / 3072)
        For i = 1 To passes.Count - 1
            Dim period = passes(i) - passes(i - 1)
            Assert.True(Math.Abs(period / small - 1) < 0.0003, $"period {period} s against 2π√(L/g) = {small} s")
            Assert.True(Math.Abs(period / expected - 1) < 0.000001, $"period {period} s against {expected} s for θ0 = {theta0}")
        Next
        ' Its first pass is a quarter period after release, going one way only.
        Assert.Equal(expected / 4, passes(0), 3)
        Assert.Contains(h.TraceLines, Function(l) l.StartsWith("pass bob 2 t=", StringComparison.Ordinal) AndAlso l.Contains(" period "))
        Assert.Contains("Passes of bob: 4", h.P.StopwatchText)
    End Sub

    <Fact>
    Public Sub StepByStep_ThePassesComeAtTheSameTimes_AndGoingBackForgetsThoseAfter()
        Dim h As New PresenterHarness(Scenarios.Pendulum(1.0, 0.05, kind:=LinkKind.Rod))
        h.P.SetPassLine(h.P.World.Find("bob"), New Vector(2.0, 3.5), New Vector(0, 1))
        Do While h.P.PassTimer.Passes.Count < 2
            h.P.StepFrame()
            Assert.True(h.P.World.Time < 10, "the bob passes the line once a period")
        Loop
        Dim small = 2 * Math.PI * Math.Sqrt(1.0 / 9.81)
        Assert.Equal(small * (1 + 0.05 * 0.05 / 16), h.P.PassTimer.Period, 5)
        Dim first = h.P.PassTimer.Passes(0)
        h.P.RewindTo(first + 0.1)
        Assert.Single(h.P.PassTimer.Passes)
        Assert.Equal(first, h.P.PassTimer.Passes(0))
    End Sub

    <Fact>
    Public Sub ThePassLine_ChosenByAClick_UsesTheTapesLine()
        Dim h As New PresenterHarness(Scenarios.Pendulum(1.0, 0.3, kind:=LinkKind.Rod))
        h.P.ToggleTapeMeasure()
        h.Drag(PointerButton.Left, 2.0, 1.0, 2.0, 3.0)
        h.P.BeginPassLine()
        Dim bob = h.P.World.Find("bob")
        h.LeftClick(bob.CentreOfMass.X, bob.CentreOfMass.Y)
        Assert.NotNull(h.P.PassTimer)
        Assert.Equal("bob", h.P.PassTimer.BodyId)
        Assert.Equal(New Vector(2.0, 1.0), h.P.PassTimer.Through)
        Assert.Null(h.P.AimedBody)
    End Sub

    <Fact>
    Public Sub APassBetweenTwoFrames_IsTimedOnTheCubicThroughThem()
        ' s(t) = t³ − 0.001 crosses at t = 0.1: positions and rates at 0 and 0.2 s give it exactly.
        Dim t = PassTimer.CrossingTime(0, -0.001, 0, 0.2, 0.007, 0.12)
        Assert.Equal(0.1, t, 12)
        ' A straight line between the two frames alone would say 0.025 s.
        Assert.NotEqual(0.025, Math.Round(t, 3))
    End Sub
End Class
