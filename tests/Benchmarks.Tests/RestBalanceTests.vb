Option Strict On
Imports PhysicsEngine
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>Whether the bodies standing still at the end of a run are held there (<see cref="RestBalance"/>).</summary>
Public Class RestBalanceTests
    ''' <summary>Three balls at rest in a box 26 cm wide, one in the V of the two below, which touch the walls: all held.</summary>
    <Fact>
    Public Sub BallsAsleepInAWalledV_AreAllHeld()
        Dim w As New World(0.26, 1, 9.81, 0.3)
        w.Add(New Circle(New Vector(0.05, 0.05), 0.05, 1, id:="left"))
        w.Add(New Circle(New Vector(0.21, 0.05), 0.05, 1, id:="right"))
        w.Add(New Circle(New Vector(0.13, 0.3), 0.05, 1, id:="top"))
        w.Solver = New EventDrivenSolver()
        w.Advance(5)
        Dim still As Integer, largest As Double
        Assert.Equal(0, RestBalance.Unbalanced(w, still, largest))
        Assert.Equal(3, still)
        Assert.Equal("; all 3 still bodies held", RestBalance.Note(w))
    End Sub

    ''' <summary>
    ''' Two still bodies: one in the air, which nothing holds and which falls at g, and one resting on the floor, held.
    ''' </summary>
    <Fact>
    Public Sub StillBallInTheAir_IsNotHeld_AndItsAccelerationIsG()
        Dim w As New World(1, 1, 9.81, 0.3)
        w.Add(New Circle(New Vector(0.5, 0.5), 0.05, 1, id:="floating"))
        w.Add(New Circle(New Vector(0.2, 0.05), 0.05, 1, id:="resting"))
        w.Solver = New EventDrivenSolver()
        Dim still As Integer, largest As Double
        Assert.Equal(1, RestBalance.Unbalanced(w, still, largest))
        Assert.Equal(2, still)
        Assert.Equal(9.81, largest, 12)
        Assert.Equal("; 1 of 2 still bodies not held (forces give up to 9.81 m/s²)", RestBalance.Note(w))
    End Sub

    ''' <summary>Moving bodies are not asked: with none still there is nothing to say.</summary>
    <Fact>
    Public Sub MovingBodies_AreNotAsked()
        Dim w As New World(1, 1, 9.81, 0.3)
        w.Add(New Circle(New Vector(0.5, 0.5), 0.05, 1, New Vector(0.1, 0), id:="moving"))
        w.Solver = New EventDrivenSolver()
        Dim still As Integer, largest As Double
        Assert.Equal(0, RestBalance.Unbalanced(w, still, largest))
        Assert.Equal(0, still)
        Assert.Equal("", RestBalance.Note(w))
    End Sub

    ''' <summary>A stepping solver's bodies are still only by chance: its runs get no clause.</summary>
    <Fact>
    Public Sub SteppingSolver_GetsNoClause()
        Dim w As New World(1, 1, 9.81, 0.3)
        w.Add(New Circle(New Vector(0.5, 0.5), 0.05, 1, id:="floating"))
        w.Solver = New VerletSolver(0.01)
        Assert.Equal("", RestBalance.Note(w))
    End Sub
End Class
