Option Strict On
Imports System.Globalization

''' <summary>Time steps as people write them: "1/60" (s) rather than 0.0166….</summary>
Friend Module TimeStepText
    ''' <summary>"1/60" for 1/60 s when the reciprocal is a whole number, else the seconds in invariant form; "—" for Nothing.</summary>
    Public Function Format(timeStep As Double?) As String
        If Not timeStep.HasValue Then Return "—"
        Dim inverse = 1.0 / timeStep.Value
        Dim rounded = Math.Round(inverse)
        If rounded >= 1 AndAlso Math.Abs(inverse - rounded) < 1.0E-6 * rounded Then
            Return "1/" & rounded.ToString("0", CultureInfo.InvariantCulture)
        End If
        Return timeStep.Value.ToString("R", CultureInfo.InvariantCulture)
    End Function

    ''' <summary>
    ''' Reads "1/60" or "0.001" as seconds. Returns False for anything that is not a finite number
    ''' greater than 0.
    ''' </summary>
    Public Function TryParse(text As String, ByRef seconds As Double) As Boolean
        seconds = 0
        If String.IsNullOrWhiteSpace(text) Then Return False
        Dim slash = text.IndexOf("/"c)
        Dim value As Double
        If slash >= 0 Then
            Dim num As Double, den As Double
            If Not Double.TryParse(text.AsSpan(0, slash), NumberStyles.Float, CultureInfo.InvariantCulture, num) Then Return False
            If Not Double.TryParse(text.AsSpan(slash + 1), NumberStyles.Float, CultureInfo.InvariantCulture, den) Then Return False
            If den = 0 Then Return False
            value = num / den
        ElseIf Not Double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, value) Then
            Return False
        End If
        If Not (value > 0) OrElse Double.IsInfinity(value) Then Return False
        seconds = value
        Return True
    End Function
End Module
