Option Strict On

''' <summary>One point of a plot, with an optional short label drawn beside it (e.g. "1/60").</summary>
Friend Structure PlotPoint
    Public ReadOnly Property X As Double
    Public ReadOnly Property Y As Double
    Public ReadOnly Property Label As String

    Public Sub New(x As Double, y As Double, Optional label As String = "")
        Me.X = x
        Me.Y = y
        Me.Label = If(label, "")
    End Sub
End Structure
