Option Strict On

''' <summary>One reading of the wall pressure: over the interval ending at <see cref="Time"/>.</summary>
Public Structure PressureReading
    Public Sub New(time As Double, measured As Double, ideal As Double)
        Me.Time = time
        Me.Measured = measured
        Me.Ideal = ideal
    End Sub

    ''' <summary>End of the interval, s.</summary>
    Public ReadOnly Property Time As Double
    ''' <summary>Σ |Δp| / (perimeter × interval), N/m.</summary>
    Public ReadOnly Property Measured As Double
    ''' <summary>N k T / A at the end of the interval, N/m.</summary>
    Public ReadOnly Property Ideal As Double
End Structure
