Option Strict On
Imports System.Globalization

''' <summary>How the CSV outputs spell values: invariant culture, round-trip precision, RFC 4180 quoting.</summary>
Friend Module CsvText
    ''' <summary>Round-trip ("R"), "." as the decimal point.</summary>
    Friend Function Number(value As Double) As String
        Return value.ToString("R", CultureInfo.InvariantCulture)
    End Function

    ''' <summary>An id as a field: quoted only when it holds a comma, a quote or a line break.</summary>
    Friend Function Field(text As String) As String
        If text.IndexOfAny({","c, """"c, ChrW(13), ChrW(10)}) < 0 Then Return text
        Return """" & text.Replace("""", """""") & """"
    End Function
End Module
