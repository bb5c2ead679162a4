Option Strict On

''' <summary>
''' Sits between the window and the engine: the form forwards its events here and draws what this
''' exposes. Everything a teacher can do is a method here, so tests drive it without a window.
''' </summary>
Public NotInheritable Class SimulationPresenter
    ''' <summary>Starts with the demo scene.</summary>
    Public Sub New()
        World = Scenarios.Demo()
        World.Solver = SolverFactory.Create("auto")
    End Sub

    ''' <summary>The world being shown.</summary>
    Public ReadOnly Property World As World

    ''' <summary>True while paused.</summary>
    Public Property IsPaused As Boolean

    ''' <summary>Simulated seconds per real second (1 = real time).</summary>
    Public Property Speed As Double = 1.0

    ''' <summary>Called once per frame with the real time since the last frame, s.</summary>
    Public Sub Tick(realSeconds As Double)
        If IsPaused Then Return
        World.Advance(Math.Min(realSeconds, 0.1) * Speed)
    End Sub
End Class
