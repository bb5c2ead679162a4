Option Strict On

''' <summary>The graphs the Graphs tab can show.</summary>
Public Enum GraphKind
    ''' <summary>Kinetic, potential and total energy against time, J.</summary>
    Energy
    ''' <summary>The components px and py of the total momentum against time, kg·m/s.</summary>
    Momentum
    ''' <summary>How many bodies have each speed now, with the 2D Maxwell–Boltzmann curve.</summary>
    SpeedHistogram
    ''' <summary>The pressure on the walls from their impulses, against time, beside N·k·T/A, N/m.</summary>
    Pressure
End Enum
