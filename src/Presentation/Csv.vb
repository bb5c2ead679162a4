Option Strict On
Imports System.Globalization
Imports System.Text

''' <summary>
''' CSV a spreadsheet opens as it is: RFC 4180 (fields separated by commas, lines ended by CR LF,
''' a field holding a comma, a quote or a line break put in quotes with its quotes doubled),
''' numbers in the invariant culture with "." as the decimal point and enough digits to read back
''' the same double, and UTF-8 with a byte-order mark so that Excel reads "Σ", "·" and "²".
''' </summary>
Public NotInheritable Class Csv
    Private Sub New()
    End Sub

    ''' <summary>UTF-8 with a byte-order mark.</summary>
    Public Shared ReadOnly Property Encoding As Encoding = New UTF8Encoding(True)

    ''' <summary>A field: quoted only when it holds a comma, a quote or a line break.</summary>
    Public Shared Function Field(text As String) As String
        If text Is Nothing Then Return ""
        If text.IndexOfAny({","c, """"c, ChrW(13), ChrW(10)}) < 0 Then Return text
        Return """" & text.Replace("""", """""") & """"
    End Function

    ''' <summary>A number in round-trip form ("R"), "." as the decimal point; empty for NaN and ±∞ (a blank cell, not text).</summary>
    Public Shared Function Number(value As Double) As String
        If Double.IsNaN(value) OrElse Double.IsInfinity(value) Then Return ""
        Return value.ToString("R", CultureInfo.InvariantCulture)
    End Function

    ''' <summary>One line (without its CR LF) of already-spelled cells, each quoted as it needs.</summary>
    Public Shared Function Line(cells As IEnumerable(Of String)) As String
        If cells Is Nothing Then Throw New ArgumentNullException(NameOf(cells))
        Return String.Join(",", cells.Select(AddressOf Field))
    End Function

    ''' <summary>A whole document: the header, then the rows, each line ended by CR LF.</summary>
    Public Shared Function Document(header As IEnumerable(Of String), rows As IEnumerable(Of IEnumerable(Of String))) As String
        If rows Is Nothing Then Throw New ArgumentNullException(NameOf(rows))
        Dim sb As New StringBuilder()
        sb.Append(Line(header)).Append(ChrW(13)).Append(ChrW(10))
        For Each r In rows
            sb.Append(Line(r)).Append(ChrW(13)).Append(ChrW(10))
        Next
        Return sb.ToString()
    End Function

    ''' <summary>The document's bytes as written to a file: the byte-order mark, then UTF-8.</summary>
    Public Shared Function Bytes(document As String) As Byte()
        Dim preamble = Encoding.GetPreamble()
        Dim body = Encoding.GetBytes(If(document, ""))
        Dim all(preamble.Length + body.Length - 1) As Byte
        preamble.CopyTo(all, 0)
        body.CopyTo(all, preamble.Length)
        Return all
    End Function

    ''' <summary>
    ''' Reads a document back into rows of fields (RFC 4180: quoted fields may hold commas, doubled
    ''' quotes and line breaks). A leading byte-order mark is skipped.
    ''' </summary>
    Public Shared Function Parse(text As String) As List(Of List(Of String))
        Dim rows As New List(Of List(Of String))
        If String.IsNullOrEmpty(text) Then Return rows
        Dim i = If(text(0) = ChrW(&HFEFF), 1, 0)
        Dim row As New List(Of String)
        Dim cell As New StringBuilder()
        Dim quoted = False
        While i < text.Length
            Dim c = text(i)
            If quoted Then
                If c = """"c Then
                    If i + 1 < text.Length AndAlso text(i + 1) = """"c Then
                        cell.Append(""""c)
                        i += 1
                    Else
                        quoted = False
                    End If
                Else
                    cell.Append(c)
                End If
            ElseIf c = """"c Then
                quoted = True
            ElseIf c = ","c Then
                row.Add(cell.ToString())
                cell.Clear()
            ElseIf c = ChrW(13) OrElse c = ChrW(10) Then
                If c = ChrW(13) AndAlso i + 1 < text.Length AndAlso text(i + 1) = ChrW(10) Then i += 1
                row.Add(cell.ToString())
                cell.Clear()
                rows.Add(row)
                row = New List(Of String)
            Else
                cell.Append(c)
            End If
            i += 1
        End While
        If cell.Length > 0 OrElse row.Count > 0 Then
            row.Add(cell.ToString())
            rows.Add(row)
        End If
        Return rows
    End Function
End Class
