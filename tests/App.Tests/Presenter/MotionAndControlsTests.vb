Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>Objectives 1, 4 and 5: motion, pause, speed, reset and the g and e sliders.</summary>
Public Class MotionAndControlsTests
    <Fact>
    Public Sub Tick_MovableCircleFallsUnderGravity_FixedCircleStays()
        Dim h As New PresenterHarness()
        Dim ball = h.Ball(2, 4)
        Dim peg = Circle.CreateFixed(New Vector(6, 4), 0.2)
        h.P.World.Add(peg)
        h.P.Tick(0.05)
        Assert.True(ball.Position.Y < 4 - 0.005, $"ball at {ball.Position}")
        Assert.Equal(New Vector(6, 4), peg.Position)
    End Sub

    <Fact>
    Public Sub Tick_MovesAtAnyVelocity()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim ball = h.Ball(2, 2)
        h.P.World.SetVelocity(ball, New Vector(3, -1))
        h.P.Tick(0.1)
        Assert.Equal(2.3, ball.Position.X, 3)
        Assert.Equal(1.9, ball.Position.Y, 3)
    End Sub

    <Fact>
    Public Sub Tick_WhilePaused_DoesNothing_AndResumes()
        Dim h As New PresenterHarness()
        h.Ball(2, 4)
        h.P.TogglePause()
        Assert.True(h.P.IsPaused)
        h.P.Tick(0.05)
        Assert.Equal(0.0, h.P.World.Time)
        h.P.TogglePause()
        Assert.False(h.P.IsPaused)
        h.P.Tick(0.05)
        Assert.Equal(0.05, h.P.World.Time, 9)
        Assert.Contains(h.TraceLines, Function(l) l.StartsWith("paused", StringComparison.Ordinal))
        Assert.Contains("resumed", h.TraceLines)
    End Sub

    <Theory>
    <InlineData(0, 0.05)>
    <InlineData(8, 1.0)>
    <InlineData(12, 4.0)>
    Public Sub Speed_ScalesSimulatedTime(index As Integer, factor As Double)
        Dim h As New PresenterHarness()
        h.P.SetSpeedIndex(index)
        h.P.Tick(0.02)
        Assert.Equal(0.02 * factor, h.P.World.Time, 9)
    End Sub

    <Fact>
    Public Sub Speed_RunsFrom20xSlowerTo4xFaster_AndClamps()
        Dim h As New PresenterHarness()
        h.P.SetSpeedIndex(-5)
        Assert.Equal("20× slower", SpeedSteps.Label(h.P.Speed))
        h.P.SetSpeedIndex(99)
        Assert.Equal("4× faster", SpeedSteps.Label(h.P.Speed))
        Assert.Equal("1× (real time)", SpeedSteps.Label(1.0))
    End Sub

    <Fact>
    Public Sub Tick_AfterAStall_AdvancesAtMostATenthOfASecond()
        Dim h As New PresenterHarness()
        h.P.Tick(5.0)
        Assert.Equal(SimulationPresenter.MaxFrameSeconds, h.P.World.Time, 9)
    End Sub

    <Fact>
    Public Sub Gravity_Slider_ClampsTo0To100_AndTraces()
        Dim h As New PresenterHarness()
        h.P.SetGravity(24.79)
        Assert.Equal(24.79, h.P.World.Gravity)
        h.P.SetGravity(500)
        Assert.Equal(100.0, h.P.World.Gravity)
        h.P.SetGravity(-3)
        Assert.Equal(0.0, h.P.World.Gravity)
        Assert.Contains("gravity 24.79", h.TraceLines)
    End Sub

    <Fact>
    Public Sub Gravity_Marks_AreMoonMarsEarthJupiter()
        Assert.Equal("Moon Mars Earth Jupiter", String.Join(" ", GravityMark.All.Select(Function(m) m.Name)))
        Assert.Equal(9.81, GravityMark.All(2).Value)
        Assert.All(GravityMark.All, Sub(m) Assert.InRange(m.Value, GravityMark.Minimum, GravityMark.Maximum))
    End Sub

    <Fact>
    Public Sub Gravity_ChangesLiveWhileRunning()
        Dim h As New PresenterHarness()
        Dim ball = h.Ball(4, 4)
        h.P.SetGravity(0)
        h.P.Tick(0.05)
        Assert.Equal(0.0, ball.Velocity.Y, 9)
        h.P.SetGravity(20)
        h.P.Tick(0.05)
        Assert.Equal(-1.0, ball.Velocity.Y, 2)
    End Sub

    <Fact>
    Public Sub Restitution_Slider_ClampsTo0To1()
        Dim h As New PresenterHarness()
        h.P.SetRestitution(0.35)
        Assert.Equal(0.35, h.P.World.Restitution)
        h.P.SetRestitution(3)
        Assert.Equal(1.0, h.P.World.Restitution)
        h.P.SetRestitution(-1)
        Assert.Equal(0.0, h.P.World.Restitution)
    End Sub

    <Fact>
    Public Sub Reset_RemovesEverything_AndRestoresDefaults()
        Dim h As New PresenterHarness(Scenarios.Demo())
        h.P.SetGravity(50)
        h.P.SetRestitution(0.2)
        h.P.SetSpeedIndex(0)
        h.P.Tick(0.05)
        h.P.Reset()
        Assert.Empty(h.P.World.Bodies)
        Assert.Equal(1.0, h.P.World.Restitution)
        Assert.Equal(9.81, h.P.World.Gravity)
        Assert.Equal(1.0, h.P.Speed)
        Assert.Equal(0, h.P.Log.Count)
        Assert.True(h.View.BodiesShown > 0)
    End Sub

    <Fact>
    Public Sub StartsWithTheDemoScene_UsingTheAutoSolver()
        Dim p As New SimulationPresenter(New RecordingView())
        Assert.True(p.World.Circles.Count >= 3)
        Assert.NotNull(p.World.Solver)
        Assert.All(p.World.Bodies, Sub(b) Assert.False(String.IsNullOrEmpty(b.Color)))
    End Sub

    <Fact>
    Public Sub Container_ResizesFromTheWindow_AndValidates()
        Dim h As New PresenterHarness()
        h.P.ResizeContainer("12", "6.5")
        Assert.Equal(12.0, h.P.World.Width)
        Assert.Equal(6.5, h.P.World.Height)
        h.P.ResizeContainer("", "3")
        Assert.StartsWith(InputLimits.ContainerMessage, h.View.LastMessage, StringComparison.Ordinal)
        Assert.Contains("container width (m) is empty", h.View.LastMessage, StringComparison.Ordinal)
        Assert.Equal(12.0, h.P.World.Width)
        h.P.ResizeContainer("1000", "5")
        Assert.Equal(InputLimits.MaxContainer, h.P.World.Width)
        Assert.Equal("100", h.P.Inputs.ContainerWidthText)
        ' Below the least side it is brought to it, as every other box is.
        h.P.ResizeContainer("0.1", "5")
        Assert.Equal(InputLimits.MinContainer, h.P.World.Width)
    End Sub

    <Fact>
    Public Sub Container_Shrinking_BringsBallsInside()
        Dim h As New PresenterHarness()
        Dim ball = h.Ball(7.5, 4.5)
        h.P.ResizeContainer("4", "3")
        Assert.InRange(ball.Position.X, 0.2, 3.8)
        Assert.InRange(ball.Position.Y, 0.2, 2.8)
    End Sub

    <Fact>
    Public Sub LargeFonts_HighContrast_Arrows_AreViewSettings()
        Dim h As New PresenterHarness()
        h.P.SetLargeFonts(True)
        h.P.SetHighContrast(True)
        h.P.SetShowArrows(False)
        Assert.True(h.P.LargeFonts)
        Assert.Same(Theme.Dark, h.P.Theme)
        Assert.False(h.P.ShowArrows)
        Assert.Equal(3, h.View.ThemesShown)
    End Sub

    <Fact>
    Public Sub Totals_ShowMomentumAndEnergyWithUnits()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim ball = h.Ball(2, 2, mass:=2)
        h.P.World.SetVelocity(ball, New Vector(3, 0))
        h.P.TogglePause() ' a snapshot of the state now
        Dim t = h.P.TotalsText.Replace(Units.Nbsp, " "c)
        Assert.Contains("Σp = (6.00, 0) kg·m/s", t, StringComparison.Ordinal)
        Assert.Contains("ΣKE = 9.00 J", t, StringComparison.Ordinal)
        ' Each item keeps its number and unit together: only the gaps between items may break.
        Assert.All(h.P.Snapshot.Totals, Sub(item) Assert.DoesNotContain(" ", item, StringComparison.Ordinal))
    End Sub
End Class
