Option Strict On
Imports System.Globalization

''' <summary>How numbers are written on screen and in the trace: invariant culture, fixed decimals, SI units.</summary>
Public Module Units
    ''' <summary>A number with <paramref name="decimals"/> decimals, invariant culture.</summary>
    Public Function Num(value As Double, Optional decimals As Integer = 2) As String
        If Double.IsInfinity(value) Then Return If(value > 0, "∞", "-∞")
        Return value.ToString("F" & decimals.ToString(CultureInfo.InvariantCulture), CultureInfo.InvariantCulture)
    End Function

    ''' <summary>"(x, y)" with <paramref name="decimals"/> decimals.</summary>
    Public Function Pair(v As Vector, Optional decimals As Integer = 2) As String
        Return "(" & Num(v.X, decimals) & ", " & Num(v.Y, decimals) & ")"
    End Function
End Module
