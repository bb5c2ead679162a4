Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>
''' A body the exact solver holds asleep where the forces of its free-body diagram do not balance: choosing it in the
''' Forces view says why it does not move. A true rest, or a body that is not asleep, adds nothing.
''' </summary>
Public Class ForcesRestNoteTests
    ''' <summary>
    ''' A ball (r = 5 cm, 1 kg) dropped into the V of two balls 3 cm apart on a frictionless floor (e = 0.3), with
    ''' <paramref name="others"/> more balls resting on the floor far off; with the two below against the walls of a box
    ''' 26 cm wide when <paramref name="walled"/>. Run 5 s.
    ''' </summary>
    Private Shared Function BallInAV(others As Integer, walled As Boolean, Optional beforeRun As Action(Of PresenterHarness) = Nothing) As PresenterHarness
        Dim w As New World(If(walled, 0.26, 4.0), 1, 9.81, 0.3)
        Dim x0 = If(walled, 0.05, 0.435), x1 = If(walled, 0.21, 0.565)
        w.Add(New Circle(New Vector(x0, 0.05), 0.05, 1, id:="left"))
        w.Add(New Circle(New Vector(x1, 0.05), 0.05, 1, id:="right"))
        w.Add(New Circle(New Vector((x0 + x1) / 2, 0.3), 0.05, 1, id:="top"))
        For k = 0 To others - 1
            w.Add(New Circle(New Vector(1.0 + 0.2 * k, 0.05), 0.05, 1, id:="o" & k.ToString(Globalization.CultureInfo.InvariantCulture)))
        Next
        Dim h As New PresenterHarness(w)
        beforeRun?.Invoke(h)
        For k = 1 To 300
            h.P.Tick(1 / 60.0)
        Next
        Return h
    End Function

    ''' <summary>Chooses the top ball in the Forces view and draws its forces on the canvas.</summary>
    Private Shared Sub DrawTopForces(h As PresenterHarness)
        h.P.ChooseForcesBody("top")
        h.P.SetShowForces(True)
    End Sub

    ''' <summary>How the message begins when it explains the top ball's rest.</summary>
    Private Const TopExplained As String = "top is at rest, but the forces shown do not balance (ΣF = "

    ''' <summary>
    ''' With 17 movable bodies the solver lets the ball sleep in the V (it asks whether the two below are held only in a
    ''' world of at most 16): its diagram has its weight and two pushes that point apart, and the message says why it
    ''' stays.
    ''' </summary>
    <Fact>
    Public Sub BallAsleepInAVNothingHoldsApart_IsExplained()
        Dim h = BallInAV(14, walled:=False)
        Assert.True(h.P.World.Time >= 4.99, $"ran only to {h.P.World.Time} s")
        h.P.ChooseForcesBody("top")
        Assert.StartsWith(TopExplained, h.P.Message, StringComparison.Ordinal)
        Assert.EndsWith("holding the bodies around it as fixed. With no friction they would move, and so would it.", h.P.Message, StringComparison.Ordinal)
    End Sub

    ''' <summary>
    ''' Chosen before the run with the forces drawn on the canvas: the message says why once the ball falls asleep in the
    ''' V, with no new choice.
    ''' </summary>
    <Fact>
    Public Sub BallChosenBeforeTheRun_ForcesDrawn_IsExplainedWhenItFallsAsleep()
        Dim h = BallInAV(14, walled:=False, beforeRun:=AddressOf DrawTopForces)
        Assert.True(h.P.World.Time >= 4.99, $"ran only to {h.P.World.Time} s")
        Assert.StartsWith(TopExplained, h.P.Message, StringComparison.Ordinal)
    End Sub

    ''' <summary>
    ''' Chosen before the run, the forces not drawn: nothing is said during the run; the Forces tab coming into view
    ''' (<see cref="SimulationPresenter.ExplainForces"/>) says it.
    ''' </summary>
    <Fact>
    Public Sub BallChosenBeforeTheRun_ForcesTabOpenedAfter_IsExplained()
        Dim h = BallInAV(14, walled:=False, beforeRun:=Sub(x) x.P.ChooseForcesBody("top"))
        Assert.DoesNotContain("do not balance", h.P.Message, StringComparison.Ordinal)
        h.P.ExplainForces()
        Assert.StartsWith(TopExplained, h.P.Message, StringComparison.Ordinal)
    End Sub

    ''' <summary>Held by the walls, the same ball's forces balance: nothing to explain. Nor for a ball on the floor alone.</summary>
    <Fact>
    Public Sub TrueRest_AddsNothing()
        Dim h = BallInAV(0, walled:=True)
        h.P.ChooseForcesBody("top")
        Assert.DoesNotContain("do not balance", h.P.Message, StringComparison.Ordinal)
        Dim crowd = BallInAV(14, walled:=False)
        crowd.P.ChooseForcesBody("o3")
        Assert.DoesNotContain("do not balance", crowd.P.Message, StringComparison.Ordinal)
        ' Drawn on the canvas through the run: nothing either.
        Dim drawn = BallInAV(0, walled:=True, beforeRun:=AddressOf DrawTopForces)
        Assert.DoesNotContain("do not balance", drawn.P.Message, StringComparison.Ordinal)
        drawn.P.ExplainForces()
        Assert.DoesNotContain("do not balance", drawn.P.Message, StringComparison.Ordinal)
    End Sub

    ''' <summary>Before the run, a ball in the air has only its weight, but it is not asleep: nothing to explain.</summary>
    <Fact>
    Public Sub BallNotAsleep_AddsNothing()
        Dim w As New World(4, 1, 9.81, 0.3)
        w.Add(New Circle(New Vector(2, 0.5), 0.05, 1, id:="ball"))
        Dim h As New PresenterHarness(w)
        h.P.SetShowForces(True)
        h.P.ChooseForcesBody("ball")
        Assert.DoesNotContain("do not balance", h.P.Message, StringComparison.Ordinal)
    End Sub
End Class
