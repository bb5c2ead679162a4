Option Strict On
Imports System.Globalization
Imports System.Text

''' <summary>
''' One JSON object on one line, written member by member: numbers in the shortest text that reads
''' back as the same double (as the engine's scene writer does), strings escaped per RFC 8259.
''' </summary>
Friend NotInheritable Class JsonText
    Private ReadOnly _text As New StringBuilder("{")
    Private _count As Integer

    ''' <summary>Adds a number member; the value must be finite.</summary>
    Friend Function Add(name As String, value As Double) As JsonText
        Return Raw(name, Number(value))
    End Function

    ''' <summary>Adds a string member.</summary>
    Friend Function Add(name As String, value As String) As JsonText
        Return Raw(name, Quote(value))
    End Function

    ''' <summary>Adds a true/false member.</summary>
    Friend Function Add(name As String, value As Boolean) As JsonText
        Return Raw(name, If(value, "true", "false"))
    End Function

    ''' <summary>Adds a member whose value is already JSON text.</summary>
    Friend Function Raw(name As String, json As String) As JsonText
        If _count > 0 Then _text.Append(", ")
        _text.Append(Quote(name)).Append(": ").Append(json)
        _count += 1
        Return Me
    End Function

    ''' <summary>The object's text.</summary>
    Public Overrides Function ToString() As String
        Return _text.ToString() & "}"
    End Function

    ''' <summary>The shortest text that reads back as exactly <paramref name="value"/> ("R", checked; G17 otherwise).</summary>
    Friend Shared Function Number(value As Double) As String
        If Double.IsNaN(value) OrElse Double.IsInfinity(value) Then Throw New ArgumentOutOfRangeException(NameOf(value), "a scene file holds only finite numbers")
        Dim text = value.ToString("R", CultureInfo.InvariantCulture)
        If Double.Parse(text, NumberStyles.Float, CultureInfo.InvariantCulture) <> value Then text = value.ToString("G17", CultureInfo.InvariantCulture)
        Return text
    End Function

    ''' <summary>A point as a JSON array [x, y].</summary>
    Friend Shared Function Point(p As Vector) As String
        Return "[" & Number(p.X) & ", " & Number(p.Y) & "]"
    End Function

    ''' <summary>A JSON string literal.</summary>
    Friend Shared Function Quote(value As String) As String
        If value Is Nothing Then Throw New ArgumentNullException(NameOf(value))
        Dim b As New StringBuilder("""")
        For Each ch In value
            Select Case ch
                Case """"c : b.Append("\""")
                Case "\"c : b.Append("\\")
                Case ChrW(10) : b.Append("\n")
                Case ChrW(13) : b.Append("\r")
                Case ChrW(9) : b.Append("\t")
                Case Else
                    If AscW(ch) < 32 Then
                        b.Append("\u").Append(AscW(ch).ToString("x4", CultureInfo.InvariantCulture))
                    Else
                        b.Append(ch)
                    End If
            End Select
        Next
        Return b.Append(""""c).ToString()
    End Function
End Class
