Option Strict On
Imports System.IO

''' <summary>A screenshot's pixels, read from the PPM that ImageMagick writes (no imaging library needed).</summary>
Public NotInheritable Class Screenshot
    Public ReadOnly Property Width As Integer
    Public ReadOnly Property Height As Integer
    Private ReadOnly _rgb As Byte()

    Private Sub New(width As Integer, height As Integer, rgb As Byte())
        Me.Width = width
        Me.Height = height
        _rgb = rgb
    End Sub

    ''' <summary>The pixel at (x, y) as &amp;HRRGGBB.</summary>
    Public Function Pixel(x As Integer, y As Integer) As Integer
        Dim i = (y * Width + x) * 3
        Return (CInt(_rgb(i)) << 16) Or (CInt(_rgb(i + 1)) << 8) Or _rgb(i + 2)
    End Function

    ''' <summary>How many different colours the region holds.</summary>
    Public Function DistinctColours(x0 As Integer, y0 As Integer, x1 As Integer, y1 As Integer) As Integer
        Dim seen As New HashSet(Of Integer)
        For y = Math.Max(0, y0) To Math.Min(Height, y1) - 1
            For x = Math.Max(0, x0) To Math.Min(Width, x1) - 1
                seen.Add(Pixel(x, y))
            Next
        Next
        Return seen.Count
    End Function

    ''' <summary>The fraction of the region's pixels for which the test holds.</summary>
    Public Function Fraction(x0 As Integer, y0 As Integer, x1 As Integer, y1 As Integer, test As Func(Of Integer, Boolean)) As Double
        Dim hit = 0, total = 0
        For y = Math.Max(0, y0) To Math.Min(Height, y1) - 1
            For x = Math.Max(0, x0) To Math.Min(Width, x1) - 1
                total += 1
                If test(Pixel(x, y)) Then hit += 1
            Next
        Next
        Return If(total = 0, 0.0, hit / total)
    End Function

    ''' <summary>Reads a binary PPM (P6, maxval 255).</summary>
    Public Shared Function ReadPpm(path As String) As Screenshot
        Dim bytes = File.ReadAllBytes(path)
        Dim pos = 0
        Dim magic = Token(bytes, pos)
        If magic <> "P6" Then Throw New InvalidDataException(path & ": not a binary PPM")
        Dim w = Integer.Parse(Token(bytes, pos), Globalization.CultureInfo.InvariantCulture)
        Dim h = Integer.Parse(Token(bytes, pos), Globalization.CultureInfo.InvariantCulture)
        Dim maxval = Integer.Parse(Token(bytes, pos), Globalization.CultureInfo.InvariantCulture)
        If maxval <> 255 Then Throw New InvalidDataException(path & ": maxval " & maxval)
        pos += 1 ' the single whitespace after maxval
        Dim rgb(w * h * 3 - 1) As Byte
        Array.Copy(bytes, pos, rgb, 0, rgb.Length)
        Return New Screenshot(w, h, rgb)
    End Function

    Private Shared Function Token(bytes As Byte(), ByRef pos As Integer) As String
        Do While pos < bytes.Length
            If bytes(pos) = AscW("#"c) Then
                Do While pos < bytes.Length AndAlso bytes(pos) <> 10
                    pos += 1
                Loop
            ElseIf Char.IsWhiteSpace(ChrW(bytes(pos))) Then
                pos += 1
            Else
                Exit Do
            End If
        Loop
        Dim start = pos
        Do While pos < bytes.Length AndAlso Not Char.IsWhiteSpace(ChrW(bytes(pos)))
            pos += 1
        Loop
        Return Text.Encoding.ASCII.GetString(bytes, start, pos - start)
    End Function
End Class
