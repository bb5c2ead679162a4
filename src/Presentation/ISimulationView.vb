Option Strict On

''' <summary>
''' What the presenter asks of the window (Passive View): the window only shows what it is told and
''' forwards the teacher's actions. Tests implement it with a recorder.
''' </summary>
Public Interface ISimulationView
    ''' <summary>Shows a message to the teacher (an error or a hint), whole, however long; an empty string clears it.</summary>
    Sub ShowMessage(text As String)

    ''' <summary>Gravity, restitution, speed, pause, mode, the Fixed box or the container changed: update sliders, labels and buttons.</summary>
    Sub ShowSettings()

    ''' <summary>The presenter changed what an input box should hold (a value brought to a limit, a scene's container): show <see cref="SimulationPresenter.Inputs"/>.</summary>
    Sub ShowInputs()

    ''' <summary>A new snapshot of the tables and totals is ready (bodies added, removed, moved, pushed, or time went on).</summary>
    Sub ShowState()

    ''' <summary>Large fonts or high contrast changed: restyle the window.</summary>
    Sub ShowTheme()
End Interface
