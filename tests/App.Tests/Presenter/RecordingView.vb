Option Strict On
Imports PhysicsEngine.Presentation

''' <summary>A view for tests: remembers what the presenter asked it to show.</summary>
Public NotInheritable Class RecordingView
    Implements ISimulationView

    Public ReadOnly Property Messages As New List(Of String)
    Public Property SettingsShown As Integer
    Public Property BodiesShown As Integer
    Public Property InputsShown As Integer
    Public Property ThemesShown As Integer

    Public ReadOnly Property LastMessage As String
        Get
            Return If(Messages.Count = 0, "", Messages(Messages.Count - 1))
        End Get
    End Property

    Public Sub ShowMessage(text As String) Implements ISimulationView.ShowMessage
        Messages.Add(text)
    End Sub

    Public Sub ShowSettings() Implements ISimulationView.ShowSettings
        SettingsShown += 1
    End Sub

    Public Sub ShowState() Implements ISimulationView.ShowState
        BodiesShown += 1
    End Sub

    Public Sub ShowInputs() Implements ISimulationView.ShowInputs
        InputsShown += 1
    End Sub

    Public Sub ShowTheme() Implements ISimulationView.ShowTheme
        ThemesShown += 1
    End Sub
End Class
