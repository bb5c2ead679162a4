Option Strict On
Imports System.Globalization

''' <summary>Numbers as the report prints them: readable, invariant, and "—" for what was not measured.</summary>
Friend Module NumberText
    ''' <summary>An error value: "0" when exact, else two significant figures in e-notation, "1.2e-5".</summary>
    Public Function Sci(value As Double) As String
        If Double.IsNaN(value) OrElse Double.IsInfinity(value) Then Return "—"
        If value = 0 Then Return "0"
        Return value.ToString("0.0e+0", CultureInfo.InvariantCulture)
    End Function

    ''' <summary>A cost in ms: more decimals for small numbers, thousands separators for large ones.</summary>
    Public Function Ms(value As Double) As String
        If Double.IsNaN(value) OrElse Double.IsInfinity(value) Then Return "—"
        If value >= 100 Then Return value.ToString("#,0", CultureInfo.InvariantCulture)
        If value >= 1 Then Return value.ToString("0.0", CultureInfo.InvariantCulture)
        Return value.ToString("0.000", CultureInfo.InvariantCulture)
    End Function

    ''' <summary>A rate or count, whole, with thousands separators: "1,234,567".</summary>
    Public Function Whole(value As Double) As String
        If Double.IsNaN(value) OrElse Double.IsInfinity(value) Then Return "—"
        Return value.ToString("#,0", CultureInfo.InvariantCulture)
    End Function

    ''' <summary>Two decimals ("1.25"), for µs per collision and MB.</summary>
    Public Function Fixed2(value As Double) As String
        If Double.IsNaN(value) OrElse Double.IsInfinity(value) Then Return "—"
        Return value.ToString("0.00", CultureInfo.InvariantCulture)
    End Function
End Module
