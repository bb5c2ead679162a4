Option Strict On
Imports System.Globalization
Imports PhysicsEngine.Presentation
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>Air resistance from the Forces tab: the air's density (a setting, like friction) and a body's C_d and b (an undoable edit), checked as the scene reader checks them.</summary>
Public Class AirSettingTests
    Private Shared Function Harness() As PresenterHarness
        Dim w As New World(8, 5, 9.81, 0.9)
        w.Add(New Circle(New Vector(2, 2), 0.2, 1.0, New Vector(1.5, 0), "ball"))
        w.Add(Rectangle.CreateMovable(New Vector(5, 0), 0.6, 0.5, 3.0, Vector.Zero, "crate"))
        Return New PresenterHarness(w)
    End Function

    ''' <summary>The world as text with every number to the last bit, and its clock.</summary>
    Private Shared Function State(h As PresenterHarness) As String
        Return SceneFile.Save(h.P.World) & " t=" & h.P.World.Time.ToString("R", CultureInfo.InvariantCulture)
    End Function

    <Fact>
    Public Sub AirOn_SetsTheWorldsDensity_DefaultOnePointTwo_AndOffIsZero()
        Dim h = Harness()
        Assert.Equal(0.0, h.P.AirDensity)
        Assert.Equal("No air (no quadratic drag)", h.P.AirText)
        h.P.SetAir(True, "")
        Assert.Equal(SimulationPresenter.DefaultAirDensity, h.P.World.AirDensity)
        Assert.Equal(1.2, h.P.World.AirDensity)
        Assert.StartsWith("Air ρ = 1.2 kg/m². C_d: quadratic drag", h.P.Message, StringComparison.Ordinal)
        Assert.Contains("air 1.200", h.TraceLines)
        ' A decimal comma as well as a point, whatever the machine's culture.
        h.P.SetAir(True, "1,25")
        Assert.Equal(1.25, h.P.World.AirDensity)
        h.P.SetAir(True, "0.9")
        Assert.Equal(0.9, h.P.World.AirDensity)
        h.P.SetAir(False, "0.9")
        Assert.Equal(0.0, h.P.World.AirDensity)
        Assert.StartsWith("No air", h.P.Message, StringComparison.Ordinal)
        ' Too dense for air: brought to the limit, and said.
        h.P.SetAir(True, "5000")
        Assert.Equal(SimulationPresenter.MaxAirDensity, h.P.World.AirDensity)
        Assert.StartsWith("An air density above 100 kg/m² was brought to it", h.P.Message, StringComparison.Ordinal)
    End Sub

    <Theory>
    <InlineData("-1", "The air is unchanged: air density ρ (kg/m²) must be 0 or more, not -1.")>
    <InlineData("thick", "The air is unchanged: air density ρ (kg/m²) 'thick' is not a number.")>
    Public Sub BadAirDensity_IsRefusedNamingItsBox_AndNothingChanges(text As String, message As String)
        Dim h = Harness()
        h.P.SetAir(True, "1.2")
        h.P.SetAir(True, text)
        Assert.Equal(message, h.P.Message)
        Assert.Equal(1.2, h.P.World.AirDensity)
    End Sub

    <Fact>
    Public Sub TypedDrag_SetsTheBodysCdAndB_AndSaysCdNeedsAir()
        Dim h = Harness()
        Assert.Equal((0.0, 0.0), h.P.DragOf("ball").Value)
        Assert.False(h.P.DragOf("nobody").HasValue)
        h.P.SetDrag("ball", "0,47", "0.5")
        Dim ball = h.P.World.Find("ball")
        Assert.Equal(0.47, ball.DragCoefficient)
        Assert.Equal(0.5, ball.LinearDrag)
        Assert.Equal((0.47, 0.5), h.P.DragOf("ball").Value)
        Assert.Equal("ball: C_d = 0.47, b = 0.5 N·s/m. C_d acts only with air on (and in liquids).", h.P.Message)
        Assert.Contains("drag of ball cd 0.470 b 0.500", h.TraceLines)
        Assert.Contains("edit kept: the drag of ball", h.TraceLines)
        ' The other body is untouched.
        Assert.Equal(0.0, h.P.World.Find("crate").LinearDrag)
    End Sub

    <Theory>
    <InlineData("-0.5", "0", "The drag of ball is unchanged: drag coefficient C_d must be 0 or more, not -0.5.")>
    <InlineData("0.4", "", "The drag of ball is unchanged: linear drag b (N·s/m) is empty.")>
    <InlineData("x", "-2", "The drag of ball is unchanged: drag coefficient C_d 'x' is not a number; linear drag b (N·s/m) must be 0 or more, not -2.")>
    Public Sub BadDrag_IsRefusedNamingItsBox_AndNothingChanges(cd As String, b As String, message As String)
        Dim h = Harness()
        h.P.SetDrag("ball", "0.3", "0.2")
        Dim before = State(h)
        h.P.SetDrag("ball", cd, b)
        Assert.Equal(message, h.P.Message)
        Assert.Equal(before, State(h))
    End Sub

    <Fact>
    Public Sub DragEdit_UndoesAndRedoesToTheLastBit_AndTheAirStaysAsSet()
        Dim h = Harness()
        For k = 1 To 5
            h.P.Tick(1 / 60.0)
        Next
        h.P.TogglePause()
        Dim before = State(h)
        h.P.SetDrag("ball", "0.47", "0.123456789")
        Dim after = State(h)
        Assert.NotEqual(before, after)
        h.P.SetAir(True, "1.2")
        h.P.Undo()
        Assert.Equal(0.0, h.P.World.Find("ball").LinearDrag)
        ' The air is a setting, like friction: Undo leaves it as set.
        Assert.Equal(1.2, h.P.World.AirDensity)
        h.P.SetAir(False, "")
        Assert.Equal(before, State(h))
        h.P.Redo()
        Assert.Equal(0.123456789, h.P.World.Find("ball").LinearDrag)
        Assert.Equal(after, State(h))
    End Sub

    <Fact>
    Public Sub Air_IsKeptThroughRestart_AndResetTakesItAway()
        Dim h = Harness()
        h.P.SetAir(True, "2")
        h.P.Restart()
        Assert.Equal(2.0, h.P.World.AirDensity)
        h.P.Reset()
        Assert.Equal(0.0, h.P.World.AirDensity)
    End Sub

    <Fact>
    Public Sub BallWithLinearDrag_FallsTowardsItsTerminalSpeed_mg_over_b_WithTheEventSolver()
        Dim w As New World(10, 60, 9.81, 1.0)
        w.Add(New Circle(New Vector(5, 58), 0.2, 1.0, Vector.Zero, "ball"))
        Dim h As New PresenterHarness(w)
        h.P.ChooseSolver("event")
        h.P.SetDrag("ball", "0", "2")
        For k = 1 To 5 * 60
            h.P.Tick(1 / 60.0)
        Next
        Dim t = h.P.World.Time
        Assert.True(t > 4.5, $"only {t} s ran")
        Dim ball = h.P.World.Find("ball")
        Dim terminal = 1.0 * 9.81 / 2.0, tau = 1.0 / 2.0
        ' v(t) = −(m g / b)(1 − e^(−t/τ)), τ = m/b: the closed form, and by now within 0.1 % of m g / b.
        Assert.Equal(-terminal * (1 - Math.Exp(-t / tau)), ball.Velocity.Y, 9)
        Assert.Equal(0.0, ball.Velocity.X)
        Assert.True(Math.Abs(-ball.Velocity.Y - terminal) < 0.001 * terminal, $"{-ball.Velocity.Y} m/s is not near m g / b = {terminal} m/s")
    End Sub

    <Fact>
    Public Sub TheHelp_SaysWhereTheAirAndDragAreSet()
        Dim forces = HelpTexts.Maths.Single(Function(t) t.Title.StartsWith("Forces on a body", StringComparison.Ordinal))
        Assert.Contains("""Air"" switches air resistance on or off", forces.Text, StringComparison.Ordinal)
        Assert.Contains("kg/m²", forces.Text, StringComparison.Ordinal)
        Assert.Contains("""Set drag""", forces.Text, StringComparison.Ordinal)
        Dim air = HelpTexts.Maths.Single(Function(t) t.Title.StartsWith("Air resistance", StringComparison.Ordinal))
        Assert.Contains("set in the Forces tab", air.Text, StringComparison.Ordinal)
        Assert.DoesNotContain(HelpTexts.Tutorial.Concat(HelpTexts.Maths), Function(t) t.Text.Contains("set in the scene file only", StringComparison.Ordinal))
    End Sub
End Class
