Option Strict On

''' <summary>
''' A slider's integer positions and the value each stands for: <see cref="Steps"/> equal steps
''' from <see cref="Minimum"/> to <see cref="Maximum"/>. The window sets its slider from these and
''' reports positions back; the presenter turns them into values, so no scaling lives in the window.
''' </summary>
Public NotInheritable Class SliderScale
    ''' <param name="minimum">value at position 0</param>
    ''' <param name="maximum">value at the last position</param>
    ''' <param name="steps">number of steps between them</param>
    Public Sub New(minimum As Double, maximum As Double, steps As Integer)
        If steps < 1 Then Throw New ArgumentOutOfRangeException(NameOf(steps))
        If Not (maximum > minimum) Then Throw New ArgumentOutOfRangeException(NameOf(maximum))
        Me.Minimum = minimum
        Me.Maximum = maximum
        Me.Steps = steps
    End Sub

    ''' <summary>The value at position 0.</summary>
    Public ReadOnly Property Minimum As Double
    ''' <summary>The value at the last position.</summary>
    Public ReadOnly Property Maximum As Double
    ''' <summary>Steps between the ends; positions run from 0 to this.</summary>
    Public ReadOnly Property Steps As Integer

    ''' <summary>The value a position stands for (positions outside 0 to Steps are brought to the ends).</summary>
    Public Function ValueAt(position As Integer) As Double
        Dim p = Math.Max(0, Math.Min(Steps, position))
        Return Minimum + (Maximum - Minimum) * p / Steps
    End Function

    ''' <summary>The position nearest a value.</summary>
    Public Function PositionOf(value As Double) As Integer
        If Double.IsNaN(value) Then Return 0
        Dim p = Math.Round((value - Minimum) / (Maximum - Minimum) * Steps)
        Return CInt(Math.Max(0, Math.Min(Steps, p)))
    End Function
End Class
