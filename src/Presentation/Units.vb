Option Strict On
Imports System.Globalization

''' <summary>How numbers are written on screen and in the trace: invariant culture, fixed decimals, SI units.</summary>
Public Module Units
    ''' <summary>A value as it goes back into a text box: enough figures to read back the same size.</summary>
    Public Function Input(value As Double) As String
        ' Four significant figures, not fixed decimals: 0.0004 m must not come back as "0".
        Return value.ToString("G4", CultureInfo.InvariantCulture)
    End Function

    ''' <summary>The value with <paramref name="decimals"/> decimals, invariant culture; ∞ for infinity.</summary>
    Public Function Num(value As Double, Optional decimals As Integer = 2) As String
        If Double.IsInfinity(value) Then Return If(value > 0, "∞", "-∞")
        Return value.ToString("F" & decimals.ToString(CultureInfo.InvariantCulture), CultureInfo.InvariantCulture)
    End Function

    ''' <summary>"(x, y)" with <paramref name="decimals"/> decimals.</summary>
    Public Function Pair(v As Vector, Optional decimals As Integer = 2) As String
        Return "(" & Num(v.X, decimals) & ", " & Num(v.Y, decimals) & ")"
    End Function
End Module
