Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>Choosing the solver in the window, each with a line on what it is for, and the same start run with another to compare.</summary>
Public Class SolverChoiceTests
    Private Shared Function Drop() As PresenterHarness
        Dim w As New World(8, 5, 9.81, 0.9)
        w.Add(New Circle(New Vector(2, 3), 0.3, 1.0, New Vector(1.5, 0), "ball"))
        Dim h As New PresenterHarness(w)
        ' A stepping solver keeps to a frame's budget by the real clock: a loaded machine must not cut its frames short here.
        h.P.FrameBudgetSeconds = 1000
        Return h
    End Function

    <Fact>
    Public Sub EverySolverOffered_HasATitle_ALineOnWhatItIsFor_AndAShortMenuLine()
        Assert.Equal("event verlet euler", String.Join(" ", SolverChoice.Names))
        For Each name In SolverChoice.Names
            Assert.False(String.IsNullOrEmpty(SolverChoice.Title(name)))
            Assert.True(SolverChoice.Purpose(name).Length > 40, name)
            Assert.True(SolverChoice.MenuLine(name).Length <= 62, SolverChoice.MenuLine(name))
            ' The engine makes each one by that name.
            Assert.Equal(name, SolverFactory.Create(name).Name)
        Next
    End Sub

    <Fact>
    Public Sub AChosenSolver_MovesTheSceneFromNow_AndRestartRunsTheSameStartWithIt()
        Dim h = Drop()
        Assert.Equal("event", h.P.SolverInUse)
        Assert.Equal("Solver: exact ▾", h.P.SolverText)
        For k = 1 To 30
            h.P.Tick(1 / 60.0)
        Next
        Dim exactY = h.P.World.Movables(0).Position.Y
        h.P.ChooseSolver("verlet")
        Assert.Equal("verlet", h.P.SolverInUse)
        Assert.StartsWith("Verlet (fixed step) from now: small steps: for links, piles, springs.", h.P.Message, StringComparison.Ordinal)
        Assert.Contains("runs the same start with it, to compare", h.P.Message, StringComparison.Ordinal)
        ' The same start again, with the solver chosen: after the same half second the ball is where
        ' the exact solver put it, to within what the fixed steps allow, and not to the last bit.
        h.P.Restart()
        Assert.Equal("verlet", h.P.SolverInUse)
        For k = 1 To 30
            h.P.Tick(1 / 60.0)
        Next
        Dim verletY = h.P.World.Movables(0).Position.Y
        Assert.InRange(verletY, exactY - 0.01, exactY + 0.01)
        Assert.NotEqual(exactY, verletY)
        h.P.ChooseSolver("euler")
        Assert.Equal("euler", h.P.SolverInUse)
        Assert.Equal("Solver: Euler ▾", h.P.SolverText)
    End Sub

    <Fact>
    Public Sub ANameThatIsNoSolver_IsRefusedWithTheChoices()
        Dim h = Drop()
        h.P.ChooseSolver("runge-kutta")
        Assert.Equal("event", h.P.SolverInUse)
        Assert.StartsWith("There is no solver called 'runge-kutta': choose one of Event-driven (exact), Verlet (fixed step), Euler (fixed step).", h.P.Message, StringComparison.Ordinal)
    End Sub
End Class
