Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' The solvers each theory runs for. <see cref="Stepping"/> is for what only a time-stepping solver is
''' asked to do (resting contacts, sub-steps); <see cref="All"/> is for what every solver must do.
''' </summary>
Public NotInheritable Class TestSolvers
    Private Sub New()
    End Sub

    ''' <summary>The time-stepping solvers: semi-implicit Euler and position Verlet.</summary>
    Public Shared ReadOnly Property Stepping As TheoryData(Of String)
        Get
            Return New TheoryData(Of String)("euler", "verlet")
        End Get
    End Property

    ''' <summary>Every solver. The event-driven one joins when it is merged.</summary>
    Public Shared ReadOnly Property All As TheoryData(Of String)
        Get
            Return Stepping
        End Get
    End Property

    ''' <summary>Gives <paramref name="world"/> the named solver (default time step) and returns the world.</summary>
    Public Shared Function Run(world As World, solver As String, Optional timeStep As Double? = Nothing) As World
        world.Solver = SolverFactory.Create(solver, timeStep)
        Return world
    End Function

    ''' <summary>Advances in frames of <paramref name="frame"/> s (like the app does) for <paramref name="total"/> s, calling <paramref name="check"/> after each.</summary>
    Public Shared Sub Frames(world As World, total As Double, frame As Double, Optional check As Action = Nothing)
        Dim n = CInt(Math.Round(total / frame))
        For i = 1 To n
            world.Advance(frame)
            check?.Invoke()
        Next
    End Sub
End Class
