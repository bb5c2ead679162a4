Option Strict On

''' <summary>
''' What the presenter asks of the window (Passive View): the window only shows what it is told and
''' forwards the teacher's actions. Tests implement it with a recorder.
''' </summary>
Public Interface ISimulationView
    ''' <summary>Shows a one-line message to the teacher (an error or a hint); an empty string clears it.</summary>
    Sub ShowMessage(text As String)

    ''' <summary>Gravity, restitution, speed, pause, mode or container size changed: update sliders, labels and buttons.</summary>
    Sub ShowSettings()

    ''' <summary>Bodies were added or removed: update the tables' row counts.</summary>
    Sub ShowBodies()

    ''' <summary>Large fonts or high contrast changed: restyle the window.</summary>
    Sub ShowTheme()
End Interface
