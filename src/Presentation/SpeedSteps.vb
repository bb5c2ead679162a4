Option Strict On

''' <summary>
''' The speed slider's positions: from 20× slower (the original classroom range) through real time up to 4×
''' faster (safe now that nothing tunnels). Speed is simulated seconds per real second.
''' </summary>
Public Module SpeedSteps
    ''' <summary>Every position's speed, slowest first.</summary>
    Public ReadOnly Property Values As IReadOnlyList(Of Double) = {1 / 20, 1 / 15, 1 / 10, 1 / 8, 1 / 5, 1 / 4, 1 / 3, 1 / 2, 1.0, 1.5, 2.0, 3.0, 4.0}

    ''' <summary>The position of real time (1×).</summary>
    Public ReadOnly Property RealTimeIndex As Integer = 8

    ''' <summary>The label for a speed: "5× slower", "1× (real time)", "2× faster".</summary>
    Public Function Label(speed As Double) As String
        If Math.Abs(speed - 1.0) < 0.000001 Then Return "1× (real time)"
        If speed > 1 Then Return Trimmed(speed) & "× faster"
        Return Trimmed(1 / speed) & "× slower"
    End Function

    Private Function Trimmed(x As Double) As String
        Return Math.Round(x, 1).ToString("0.#", Globalization.CultureInfo.InvariantCulture)
    End Function
End Module
