Option Strict On
Imports System.Globalization
Imports System.Threading
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>CSV as a spreadsheet reads it (files written whole or not at all are the engine's WholeFile, tested there).</summary>
Public Class CsvExportTests
    Private Shared ReadOnly Headers As String() = {"h1", "h2", "h3", "h4", "h5", "h6"}

    <Fact>
    Public Sub Fields_AreQuotedAsRfc4180Says_AndReadBack()
        Assert.Equal("plain", Csv.Field("plain"))
        Assert.Equal("""a,b""", Csv.Field("a,b"))
        Assert.Equal("""say """"hi""""""", Csv.Field("say ""hi"""))
        Assert.Equal("""two" & vbLf & "lines""", Csv.Field("two" & vbLf & "lines"))
        Dim rows = {New String() {"x", "a,b", "say ""hi""", "two" & vbCrLf & "lines", "Σ·²", ""}}
        Dim doc = Csv.Document(Headers, rows)
        Assert.EndsWith(vbCrLf, doc, StringComparison.Ordinal)
        Dim back = Csv.Parse(doc)
        Assert.Equal(2, back.Count)
        Assert.Equal(rows(0), back(1).ToArray())
    End Sub

    <Fact>
    Public Sub Numbers_UseAPoint_WhateverTheCulture_AndReadBackExactly()
        Dim saved = CultureInfo.CurrentCulture
        Try
            CultureInfo.CurrentCulture = New CultureInfo("fr-FR")
            For Each v In {0.1, -1234567.891, 1.0E-300, Math.PI, 6.02214076E+23}
                Dim text = Csv.Number(v)
                Assert.DoesNotContain(",", text, StringComparison.Ordinal)
                Assert.Equal(v, Double.Parse(text, CultureInfo.InvariantCulture))
            Next
            Assert.Equal("", Csv.Number(Double.NaN))
        Finally
            CultureInfo.CurrentCulture = saved
        End Try
    End Sub

    <Fact>
    Public Sub Bytes_StartWithTheUtf8ByteOrderMark()
        Dim b = Csv.Bytes("Σp (kg·m/s)")
        Assert.Equal({CByte(&HEF), CByte(&HBB), CByte(&HBF)}, b.Take(3).ToArray())
        Assert.Equal("Σp (kg·m/s)", New Text.UTF8Encoding(False).GetString(b, 3, b.Length - 3))
    End Sub
End Class
