Option Strict On
Imports System.Globalization

''' <summary>
''' Random body colours that always show: picked in HSV (any hue, strong saturation) and kept only
''' when their contrast ratio is at least 3:1 against both the light and the dark (high-contrast)
''' canvas, so no body ever fades into the background (it was planned from the start). Colours are
''' "#rrggbb", as scene files write them.
''' </summary>
Public NotInheritable Class BodyColours
    ''' <summary>Least contrast ratio (WCAG) against either background.</summary>
    Public Const MinContrast As Double = 3.0

    Private ReadOnly _random As Random

    ''' <param name="seed">the same seed gives the same colours (tests)</param>
    Public Sub New(Optional seed As Integer = 12345)
        _random = New Random(seed)
    End Sub

    ''' <summary>A new random colour, "#rrggbb", that shows on both canvases.</summary>
    Public Function NextColour() As String
        Return Pick(_random)
    End Function

    ''' <summary>
    ''' The colour of a body that has none in its file: the same for the same id every time the file
    ''' is opened, on every machine (a hash of the id, not .NET's string hash, which changes from run
    ''' to run), and one that shows on both canvases.
    ''' </summary>
    Public Shared Function ForId(id As String) As String
        ' FNV-1a over the UTF-16 code units, kept to 32 bits (a ULong holds the product without overflow).
        Dim h As ULong = 2166136261UL
        For Each ch In If(id, "")
            h = ((h Xor CULng(AscW(ch))) * 16777619UL) And &HFFFFFFFFUL
        Next
        Return Pick(New Random(CInt(h And &H7FFFFFFFUL)))
    End Function

    Private Shared Function Pick(random As Random) As String
        For attempt = 1 To 1000
            Dim h = random.NextDouble() * 360.0
            Dim s = 0.65 + 0.35 * random.NextDouble()
            Dim v = 0.45 + 0.5 * random.NextDouble()
            Dim rgb = FromHsv(h, s, v)
            If ShowsOnBothCanvases(rgb) Then Return ToHex(rgb)
        Next
        Return "#1e88e5" ' a blue that passes; reached only if the random source is broken
    End Function

    ''' <summary>True when <paramref name="rgb"/> (&amp;HRRGGBB) has the contrast it needs against both canvases.</summary>
    Public Shared Function ShowsOnBothCanvases(rgb As Integer) As Boolean
        Return ContrastRatio(rgb, Theme.Light.Background) >= MinContrast AndAlso ContrastRatio(rgb, Theme.Dark.Background) >= MinContrast
    End Function

    ''' <summary>HSV (h in degrees, s and v in [0, 1]) to &amp;HRRGGBB.</summary>
    Public Shared Function FromHsv(h As Double, s As Double, v As Double) As Integer
        Dim c = v * s
        Dim hh = (h Mod 360.0) / 60.0
        Dim x = c * (1 - Math.Abs(hh Mod 2.0 - 1))
        Dim r1, g1, b1 As Double
        Select Case CInt(Math.Floor(hh))
            Case 0 : r1 = c : g1 = x : b1 = 0
            Case 1 : r1 = x : g1 = c : b1 = 0
            Case 2 : r1 = 0 : g1 = c : b1 = x
            Case 3 : r1 = 0 : g1 = x : b1 = c
            Case 4 : r1 = x : g1 = 0 : b1 = c
            Case Else : r1 = c : g1 = 0 : b1 = x
        End Select
        Dim m = v - c
        Return (Channel(r1 + m) << 16) Or (Channel(g1 + m) << 8) Or Channel(b1 + m)
    End Function

    Private Shared Function Channel(f As Double) As Integer
        Return Math.Max(0, Math.Min(255, CInt(Math.Round(f * 255))))
    End Function

    ''' <summary>WCAG relative luminance of &amp;HRRGGBB, 0 (black) to 1 (white).</summary>
    Public Shared Function Luminance(rgb As Integer) As Double
        Return 0.2126 * Linear((rgb >> 16) And 255) + 0.7152 * Linear((rgb >> 8) And 255) + 0.0722 * Linear(rgb And 255)
    End Function

    Private Shared Function Linear(channel8 As Integer) As Double
        Dim c = channel8 / 255.0
        Return If(c <= 0.03928, c / 12.92, Math.Pow((c + 0.055) / 1.055, 2.4))
    End Function

    ''' <summary>WCAG contrast ratio of two colours, 1 (none) to 21 (black on white).</summary>
    Public Shared Function ContrastRatio(rgb1 As Integer, rgb2 As Integer) As Double
        Dim l1 = Luminance(rgb1), l2 = Luminance(rgb2)
        Return (Math.Max(l1, l2) + 0.05) / (Math.Min(l1, l2) + 0.05)
    End Function

    ''' <summary>&amp;HRRGGBB to "#rrggbb".</summary>
    Public Shared Function ToHex(rgb As Integer) As String
        Return "#" & (rgb And &HFFFFFF).ToString("x6", CultureInfo.InvariantCulture)
    End Function

    ''' <summary>"#rrggbb" to &amp;HRRGGBB, or <paramref name="fallback"/> when the text is not a colour.</summary>
    Public Shared Function Parse(hex As String, fallback As Integer) As Integer
        If hex Is Nothing OrElse hex.Length <> 7 OrElse hex(0) <> "#"c Then Return fallback
        Dim v = 0
        For i = 1 To 6
            Dim d = "0123456789abcdef".IndexOf(Char.ToLowerInvariant(hex(i)))
            If d < 0 Then Return fallback
            v = v * 16 + d
        Next
        Return v
    End Function
End Class
