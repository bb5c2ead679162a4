Option Strict On
Imports PhysicsEngine.Presentation

''' <summary>A view that shows nothing: the frame benchmark drives the presenter without a window.</summary>
Friend NotInheritable Class QuietView
    Implements ISimulationView

    Public Sub ShowMessage(text As String) Implements ISimulationView.ShowMessage
    End Sub

    Public Sub ShowSettings() Implements ISimulationView.ShowSettings
    End Sub

    Public Sub ShowInputs() Implements ISimulationView.ShowInputs
    End Sub

    Public Sub ShowState() Implements ISimulationView.ShowState
    End Sub

    Public Sub ShowTheme() Implements ISimulationView.ShowTheme
    End Sub
End Class
