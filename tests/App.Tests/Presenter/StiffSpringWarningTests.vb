Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>
''' A stepping solver chosen for a scene with a spring too stiff for its step (ω h ≥ 2, where each step makes
''' the swing larger) is told in plain words in the message, with the exact solver as the way out; so is a
''' Restart with it. The exact solver, or a spring the step can follow, adds nothing.
''' </summary>
Public Class StiffSpringWarningTests
    ''' <summary>A 1 kg ball 0.1 m below a point on a spring "s" of stiffness <paramref name="stiffness"/> N/m (ω = √k rad/s).</summary>
    Private Shared Function BallOnSpring(stiffness As Double) As PresenterHarness
        Dim w As New World(8, 5, 9.81, 0.9)
        Dim ball As New Circle(New Vector(4, 3), 0.1, 1.0, id:="ball")
        w.Add(ball)
        w.Add(Link.CreateSpring(ball, New Vector(4, 3.1), stiffness, 0.1, id:="s"))
        Return New PresenterHarness(w)
    End Function

    <Fact>
    Public Sub ChoosingAStepSolver_ForASpringTooStiffForItsStep_SaysSo_AndRestartSaysItAgain()
        ' 9 × 10⁶ N/m on 1 kg: ω = 3000 rad/s, ω h = 3 at Verlet's step of 1 ms.
        Dim h = BallOnSpring(9000000.0)
        h.P.ChooseSolver("verlet")
        Assert.StartsWith("Verlet (fixed step) from now: small steps: for links, piles, springs.", h.P.Message, StringComparison.Ordinal)
        Assert.Contains("Spring s is too stiff for this step: ω h = 3.0 (how fast it swings, ω = 3000" & Units.Nbsp & "rad/s, times the step h = 1.00" & Units.Nbsp & "ms)," &
                        " and a step method is stable only below 2, so its swing will grow without bound. The exact solver follows it.", h.P.Message, StringComparison.Ordinal)
        h.P.Restart()
        Assert.Equal("verlet", h.P.SolverInUse)
        Assert.StartsWith("Restarted: every body is back where the scene started, and the clock at 0. Spring s is too stiff for this step", h.P.Message, StringComparison.Ordinal)
        h.P.ChooseSolver("euler")
        Assert.Contains("Spring s is too stiff for this step", h.P.Message, StringComparison.Ordinal)
        ' The exact solver follows the spring: nothing to say.
        h.P.ChooseSolver("event")
        Assert.DoesNotContain("too stiff", h.P.Message, StringComparison.Ordinal)
        h.P.Restart()
        Assert.DoesNotContain("too stiff", h.P.Message, StringComparison.Ordinal)
    End Sub

    ''' <summary>
    ''' Two balls of 0.1 g (lighter than the app makes; a scene file may have them) with Verlet chosen: a spring of
    ''' 10⁴ N/m added between them with the link tool swings at ω = √(k (1/m + 1/m)) ≈ 14 000 rad/s, ω h ≈ 14. The
    ''' message says so as the spring is added; a 1 N/m spring (ω h ≈ 0.14) adds nothing.
    ''' </summary>
    <Theory>
    <InlineData("10000", True)>
    <InlineData("1", False)>
    Public Sub ASpringAddedWithTheLinkTool_TooStiffForTheStep_IsToldAtOnce(stiffness As String, tooStiff As Boolean)
        Dim w As New World(8, 5, 0, 1)
        w.Add(New Circle(New Vector(2, 2), 0.1, 0.0001, id:="a"))
        w.Add(New Circle(New Vector(4, 2), 0.1, 0.0001, id:="b"))
        Dim h As New PresenterHarness(w)
        h.P.ChooseSolver("verlet")
        h.P.BeginAddLink(LinkKind.Spring, stiffness)
        h.LeftClick(2, 2)
        h.LeftClick(4, 2)
        Dim l = Assert.Single(h.P.World.Links)
        If tooStiff Then
            Assert.StartsWith("Spring " & l.Id & " is too stiff for this step: ω h = 14 ", h.P.Message, StringComparison.Ordinal)
        Else
            Assert.Equal("", h.P.Message)
        End If
    End Sub

    <Fact>
    Public Sub ASpringTheStepFollows_AddsNothingToTheMessage()
        ' 40 N/m on 1 kg: ω h = 0.0063.
        Dim h = BallOnSpring(40)
        h.P.ChooseSolver("verlet")
        Assert.DoesNotContain("too stiff", h.P.Message, StringComparison.Ordinal)
        h.P.Restart()
        Assert.Equal("Restarted: every body is back where the scene started, and the clock at 0.", h.P.Message)
    End Sub
End Class
