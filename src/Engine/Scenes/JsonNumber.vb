Option Strict On
Imports System.Globalization
Imports System.Text.RegularExpressions

Namespace Scenes
    ''' <summary>
    ''' Numbers as scene files spell them. The BCL's JSON reader passes any number-like token through
    ''' (NaN, Infinity, 0x10, 1.), so the JSON grammar is checked here before parsing.
    ''' </summary>
    Friend Module JsonNumber
        Private ReadOnly Grammar As New Regex("^-?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?$", RegexOptions.CultureInvariant Or RegexOptions.Compiled)

        ''' <summary>Parses a JSON number token; Nothing when it is not a finite JSON number (<paramref name="problem"/> says why).</summary>
        Friend Function TryParse(token As String, ByRef problem As String) As Double?
            If token = "NaN" OrElse token = "Infinity" OrElse token = "-Infinity" Then
                problem = "must be a finite number, not " & token
                Return Nothing
            End If
            If Not Grammar.IsMatch(token) Then
                problem = "is not a valid JSON number: " & token
                Return Nothing
            End If
            Dim value As Double
            Try
                value = Double.Parse(token, NumberStyles.Float, CultureInfo.InvariantCulture)
            Catch ex As OverflowException
                ' .NET Framework throws where .NET Core returns ±Infinity; both mean "too large".
                value = Double.PositiveInfinity
            End Try
            If Double.IsNaN(value) OrElse Double.IsInfinity(value) Then
                problem = "must be a finite number (" & token & " is too large)"
                Return Nothing
            End If
            ' .NET Framework and Mono read "-0" (and a negative number too small to hold) as +0, .NET
            ' Core as −0: the sign is restored so that a zero velocity reads back bit for bit.
            If value = 0 AndAlso token(0) = "-"c Then value = -Math.Abs(value)
            problem = Nothing
            Return value
        End Function

        ''' <summary>
        ''' The shortest text that reads back as exactly <paramref name="value"/>. "R" is checked because
        ''' on .NET Framework it can lose the last bit; G17 always round-trips. Zero keeps its sign,
        ''' which .NET Framework and Mono drop ("0" for −0).
        ''' </summary>
        Friend Function Format(value As Double) As String
            If Double.IsNaN(value) OrElse Double.IsInfinity(value) Then Throw New ArgumentOutOfRangeException(NameOf(value), "a scene file holds only finite numbers")
            If value = 0 Then Return If(BitConverter.DoubleToInt64Bits(value) < 0, "-0", "0")
            Dim text = value.ToString("R", CultureInfo.InvariantCulture)
            If Double.Parse(text, NumberStyles.Float, CultureInfo.InvariantCulture) <> value Then text = value.ToString("G17", CultureInfo.InvariantCulture)
            Return text
        End Function
    End Module
End Namespace
