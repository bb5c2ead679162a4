Option Strict On

''' <summary>
''' Round numbers for a graph's axis: ticks a step of 1, 2 or 5 × 10ⁿ apart, few enough to label
''' in large type, covering the data's range.
''' </summary>
Public NotInheritable Class AxisTicks
    Private Sub New()
    End Sub

    ''' <summary>The round step (1, 2 or 5 × 10ⁿ) that divides <paramref name="span"/> into at most <paramref name="maxTicks"/> − 1 parts.</summary>
    Public Shared Function NiceStep(span As Double, maxTicks As Integer) As Double
        If Not (span > 0) OrElse Double.IsInfinity(span) Then Return 1
        Dim parts = Math.Max(1, maxTicks - 1)
        Dim raw = span / parts
        Dim power = Math.Pow(10, Math.Floor(Math.Log10(raw)))
        For Each m In {1.0, 2.0, 5.0, 10.0}
            If m * power >= raw * (1 - 1.0E-12) Then Return m * power
        Next
        Return 10 * power
    End Function

    ''' <summary>
    ''' Ticks from a multiple of the step at or below <paramref name="low"/> to one at or above
    ''' <paramref name="high"/>, at most <paramref name="maxTicks"/> of them (an empty or flat range is
    ''' widened around its value).
    ''' </summary>
    Public Shared Function Ticks(low As Double, high As Double, maxTicks As Integer) As IReadOnlyList(Of Double)
        If Double.IsNaN(low) OrElse Double.IsNaN(high) OrElse Double.IsInfinity(low) OrElse Double.IsInfinity(high) Then
            low = 0
            high = 1
        End If
        If high < low Then
            Dim t = low
            low = high
            high = t
        End If
        If high - low <= Math.Max(Math.Abs(high), Math.Abs(low)) * 1.0E-9 Then
            Dim pad = If(high = 0, 1.0, Math.Abs(high) * 0.1)
            low -= pad
            high += pad
        End If
        Dim count = Math.Max(2, maxTicks)
        Dim stepSize = NiceStep(high - low, count)
        Dim first = Math.Floor(low / stepSize + 1.0E-9) * stepSize
        Dim last = Math.Ceiling(high / stepSize - 1.0E-9) * stepSize
        ' Rounding both ends outwards can add a part: widen the step until they fit.
        While (last - first) / stepSize > count - 1 + 1.0E-9
            stepSize = NiceStep(stepSize * 1.01 * (count - 1), count)
            first = Math.Floor(low / stepSize + 1.0E-9) * stepSize
            last = Math.Ceiling(high / stepSize - 1.0E-9) * stepSize
        End While
        Dim result As New List(Of Double)
        Dim n = CInt(Math.Round((last - first) / stepSize))
        For i = 0 To n
            Dim v = first + i * stepSize
            ' −0.0000000001 prints as 0.
            If Math.Abs(v) < stepSize * 1.0E-9 Then v = 0
            result.Add(v)
        Next
        Return result
    End Function

    ''' <summary>The smallest 1, 2 or 5 × 10ⁿ at or above <paramref name="value"/> (&gt; 0).</summary>
    Public Shared Function RoundUp(value As Double) As Double
        If Not (value > 0) OrElse Double.IsInfinity(value) Then Return 1
        Dim power = Math.Pow(10, Math.Floor(Math.Log10(value)))
        For Each m In {1.0, 2.0, 5.0, 10.0}
            If m * power >= value * (1 - 1.0E-12) Then Return m * power
        Next
        Return 10 * power
    End Function
End Class
