Option Strict On
Imports System.Globalization

''' <summary>
''' How numbers are written. On screen (<see cref="Sig"/>, <see cref="Quantity"/>): three significant
''' figures, with a power of ten beyond the range a reader takes in at a glance, so 1e-300 reads
''' "1.00×10⁻³⁰⁰" rather than "0.00" and 1e300 is not 300 digits long. In the trace, for tests
''' (<see cref="Num"/>, <see cref="Pair"/>): fixed decimals, invariant culture, machine-readable.
''' </summary>
Public Module Units
    ''' <summary>No-break space: a number and its unit never part at the end of a line.</summary>
    Public Const Nbsp As Char = ChrW(&HA0)

    ''' <summary>Values at or above this (in size) are written with a power of ten.</summary>
    Private Const LargeFrom As Double = 100000.0
    ''' <summary>Values below this (in size, other than 0) are written with a power of ten.</summary>
    Private Const SmallBelow As Double = 0.001

    Private ReadOnly Superscripts As String = "⁰¹²³⁴⁵⁶⁷⁸⁹"

    ''' <summary>
    ''' Below this fraction of the quantities it was worked out from, a value is rounding noise: a
    ''' link's extension of 4.44×10⁻¹⁶ m beside its 2 m length, a momentum of 10⁻¹⁷ kg·m/s where every
    ''' body moves at metres a second. Doubles carry about 16 figures and a step loses a few; a
    ''' billionth is far below both that noise's reach into a real value and the 3 figures shown.
    ''' </summary>
    Public Const NoiseFraction As Double = 0.000000001

    ''' <summary>0 when <paramref name="value"/> is rounding noise beside <paramref name="scale"/> (see <see cref="NoiseFraction"/>), else the value.</summary>
    Public Function AtNoise(value As Double, scale As Double) As Double
        If Math.Abs(value) <= NoiseFraction * Math.Abs(scale) Then Return 0
        Return value
    End Function

    ''' <summary>A value as it goes back into a text box: enough figures to read back the same size.</summary>
    Public Function Input(value As Double) As String
        ' Four significant figures, not fixed decimals: 0.0004 m must not come back as "0".
        Return value.ToString("G4", CultureInfo.InvariantCulture)
    End Function

    ''' <summary>For the trace: the value with <paramref name="decimals"/> decimals, invariant culture; ∞ for infinity.</summary>
    Public Function Num(value As Double, Optional decimals As Integer = 2) As String
        If Double.IsInfinity(value) Then Return If(value > 0, "∞", "-∞")
        Return value.ToString("F" & decimals.ToString(CultureInfo.InvariantCulture), CultureInfo.InvariantCulture)
    End Function

    ''' <summary>For the trace: "(x, y)" with <paramref name="decimals"/> decimals.</summary>
    Public Function Pair(v As Vector, Optional decimals As Integer = 2) As String
        Return "(" & Num(v.X, decimals) & ", " & Num(v.Y, decimals) & ")"
    End Function

    ''' <summary>
    ''' For the screen: <paramref name="figures"/> significant figures ("3.02", "−0.350", "1234",
    ''' "0.0123"), a power of ten outside 0.001 to 100 000 ("1.23×10⁵"), "0" for zero, "−" as the
    ''' minus sign. A value that is not a finite number reads "∞" or "not a number" (never "NaN").
    ''' </summary>
    Public Function Sig(value As Double, Optional figures As Integer = 3) As String
        If Double.IsNaN(value) Then Return "not a number"
        If Double.IsInfinity(value) Then Return If(value > 0, "∞", "−∞")
        If value = 0 Then Return "0"
        figures = Math.Max(1, Math.Min(15, figures))
        Dim size = Math.Abs(value)
        Dim sign = If(value < 0, "−", "")
        Dim exponent = CInt(Math.Floor(Math.Log10(size)))
        If size >= LargeFrom OrElse size < SmallBelow Then
            Dim mantissa = size / Math.Pow(10, exponent)
            Dim rounded = Math.Round(mantissa, figures - 1)
            If rounded >= 10 Then
                rounded /= 10
                exponent += 1
            End If
            Return sign & rounded.ToString("F" & (figures - 1).ToString(CultureInfo.InvariantCulture), CultureInfo.InvariantCulture) & "×10" & Superscript(exponent)
        End If
        Dim decimals = Math.Max(0, figures - 1 - exponent)
        Dim text = size.ToString("F" & decimals.ToString(CultureInfo.InvariantCulture), CultureInfo.InvariantCulture)
        ' Rounding can carry into a new digit (0.09996 → "0.100"): write it again with one decimal fewer.
        If decimals > 0 AndAlso Math.Round(size, decimals) >= Math.Pow(10, exponent + 1) Then
            text = size.ToString("F" & (decimals - 1).ToString(CultureInfo.InvariantCulture), CultureInfo.InvariantCulture)
        End If
        If text.Trim("0"c, "."c).Length = 0 Then Return "0"
        Return sign & text
    End Function

    ''' <summary>
    ''' <paramref name="value"/> with as many significant figures as it takes to tell it from
    ''' <paramref name="other"/> (at least <paramref name="figures"/>, at most 15): the times of two
    ''' collisions 10⁻⁶ s apart read differently. Equal values are written with <paramref name="figures"/>.
    ''' </summary>
    Public Function SigApart(value As Double, other As Double?, Optional figures As Integer = 4) As String
        If Not other.HasValue OrElse other.Value = value Then Return Sig(value, figures)
        For f = figures To 15
            Dim text = Sig(value, f)
            If text <> Sig(other.Value, f) Then Return text
        Next
        Return Sig(value, 15)
    End Function

    ''' <summary>A value and its unit, joined so that they never part: "18.6 J", "−3.00 kg·m/s".</summary>
    Public Function Quantity(value As Double, unit As String, Optional figures As Integer = 3) As String
        Return Sig(value, figures) & Nbsp & unit
    End Function

    ''' <summary>For the screen: "(x, y)" with significant figures.</summary>
    Public Function SigPair(v As Vector, Optional figures As Integer = 3) As String
        Return "(" & Sig(v.X, figures) & ", " & Sig(v.Y, figures) & ")"
    End Function

    Private Function Superscript(exponent As Integer) As String
        Dim digits = Math.Abs(exponent).ToString(CultureInfo.InvariantCulture)
        Dim chars = digits.Select(Function(d) Superscripts(AscW(d) - AscW("0"c))).ToArray()
        Return If(exponent < 0, "⁻", "") & New String(chars)
    End Function
End Module
