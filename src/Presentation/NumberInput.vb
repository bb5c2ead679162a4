Option Strict On
Imports System.Globalization

''' <summary>The outcome of reading one number that the teacher typed.</summary>
Public Structure NumberInput
    ''' <summary>True when the text held a usable number (possibly clamped).</summary>
    Public ReadOnly Property IsValid As Boolean
    ''' <summary>The value to use, clamped to the bound; 0 when not valid.</summary>
    Public ReadOnly Property Value As Double
    ''' <summary>True when the typed value was beyond a bound and was brought to it.</summary>
    Public ReadOnly Property WasClamped As Boolean
    ''' <summary>True when it was brought up to the lower bound (False: down to the upper one, or not at all).</summary>
    Public ReadOnly Property WasRaised As Boolean
    ''' <summary>Why the text was refused, naming the field, or "" when valid.</summary>
    Public ReadOnly Property Problem As String

    Private Sub New(isValid As Boolean, value As Double, wasClamped As Boolean, problem As String, Optional wasRaised As Boolean = False)
        Me.IsValid = isValid
        Me.Value = value
        Me.WasClamped = wasClamped
        Me.WasRaised = wasRaised
        Me.Problem = problem
    End Sub

    ''' <summary>
    ''' Reads a number that must be greater than 0: empty, non-numeric, zero or negative text is
    ''' refused; a value above <paramref name="maximum"/> or below <paramref name="minimum"/> is
    ''' brought to that bound. Accepts a decimal point (0.5), the machine's own separator, and a
    ''' decimal comma (0,5) on any machine (see <see cref="TryParse"/>).
    ''' </summary>
    ''' <param name="text">what was typed</param>
    ''' <param name="label">the field's name with its unit, for the message, e.g. "radius (m)"</param>
    ''' <param name="maximum">upper bound, in the field's unit</param>
    ''' <param name="minimum">lower bound, in the field's unit (0: none beyond "greater than 0")</param>
    Public Shared Function ReadPositive(text As String, label As String, maximum As Double, Optional minimum As Double = 0) As NumberInput
        Dim t = If(text, "").Trim()
        If t.Length = 0 Then Return Refuse(label & " is empty")
        Dim v As Double
        If t.Length > 40 Then Return Refuse(label & " is too long to be a number")
        If Not TryParse(t, v) Then Return Refuse(NotANumber(label, t))
        If Double.IsNaN(v) OrElse Double.IsInfinity(v) Then Return Refuse(label & " '" & t & "' is not a finite number")
        If v <= 0 Then Return Refuse(label & " must be greater than 0, not " & t)
        If v > maximum Then Return New NumberInput(True, maximum, True, "")
        If v < minimum Then Return New NumberInput(True, minimum, True, "", wasRaised:=True)
        Return New NumberInput(True, v, False, "")
    End Function

    ''' <summary>
    ''' Reads any finite number (zero and negative too, as an angle may be): empty or non-numeric
    ''' text is refused; a value beyond ±<paramref name="limit"/> is brought to it.
    ''' </summary>
    Public Shared Function ReadFinite(text As String, label As String, limit As Double) As NumberInput
        Dim t = If(text, "").Trim()
        If t.Length = 0 Then Return Refuse(label & " is empty")
        Dim v As Double
        If t.Length > 40 Then Return Refuse(label & " is too long to be a number")
        If Not TryParse(t, v) Then Return Refuse(NotANumber(label, t))
        If Double.IsNaN(v) OrElse Double.IsInfinity(v) Then Return Refuse(label & " '" & t & "' is not a finite number")
        If v > limit Then Return New NumberInput(True, limit, True, "")
        If v < -limit Then Return New NumberInput(True, -limit, True, "", wasRaised:=True)
        Return New NumberInput(True, v, False, "")
    End Function

    ''' <summary>
    ''' Reads a coefficient or density that may be 0 but never negative (μ, ρ, C_d, b): as <see cref="ReadFinite"/>,
    ''' a value above <paramref name="limit"/> brought to it, and a negative one refused; what is wrong, if
    ''' anything, is added to <paramref name="problems"/> (a row of boxes reports them all at once).
    ''' </summary>
    Public Shared Function ReadNonNegative(text As String, label As String, limit As Double, problems As List(Of String)) As NumberInput
        If problems Is Nothing Then Throw New ArgumentNullException(NameOf(problems))
        Dim read = ReadFinite(text, label, limit)
        If Not read.IsValid Then
            problems.Add(read.Problem)
        ElseIf read.Value < 0 Then
            problems.Add(label & " must be 0 or more, not " & If(text, "").Trim())
        End If
        Return read
    End Function

    ''' <summary>
    ''' Reads a whole number from <paramref name="minimum"/> to <paramref name="maximum"/>: empty,
    ''' non-numeric or fractional text is refused; a value beyond a bound is brought to it.
    ''' </summary>
    Public Shared Function ReadWhole(text As String, label As String, minimum As Integer, maximum As Integer) As NumberInput
        Dim read = ReadFinite(text, label, Double.MaxValue)
        If Not read.IsValid Then Return read
        Dim v = read.Value
        If v <> Math.Floor(v) Then Return Refuse(label & " must be a whole number, not " & If(text, "").Trim())
        If v > maximum Then Return New NumberInput(True, maximum, True, "")
        If v < minimum Then Return New NumberInput(True, minimum, True, "", wasRaised:=True)
        Return New NumberInput(True, v, False, "")
    End Function

    Private Shared Function Refuse(problem As String) As NumberInput
        Return New NumberInput(False, 0, False, problem)
    End Function

    ''' <summary>
    ''' Parses a number typed with a decimal point (what the app itself writes) or with the machine's
    ''' own decimal separator, and a decimal comma on any machine: "0,25" is 0.25 in every class. No
    ''' thousands separators are read, so where the machine's separator is a point, "1,000" (which a
    ''' reader could take for a thousand) is refused rather than read as 1.
    ''' </summary>
    Public Shared Function TryParse(text As String, ByRef value As Double) As Boolean
        Const styles = NumberStyles.Float
        If text Is Nothing Then Return False
        If Double.TryParse(text, styles, CultureInfo.InvariantCulture, value) Then Return True
        If Double.TryParse(text, styles, CultureInfo.CurrentCulture, value) Then Return True
        Dim comma = text.IndexOf(","c)
        If comma < 0 OrElse text.IndexOf(","c, comma + 1) >= 0 OrElse text.Contains("."c) OrElse LooksLikeThousands(text, comma) Then Return False
        Return Double.TryParse(text.Replace(","c, "."c), styles, CultureInfo.InvariantCulture, value)
    End Function

    ''' <summary>"1,000" or "-12,500": a comma after one to three digits and before exactly three, as a thousands separator would stand.</summary>
    Private Shared Function LooksLikeThousands(text As String, comma As Integer) As Boolean
        Dim before = text.Substring(0, comma).Trim().TrimStart("-"c, "+"c)
        Dim after = text.Substring(comma + 1).Trim()
        Return before.Length >= 1 AndAlso before.Length <= 3 AndAlso before.All(AddressOf Char.IsDigit) AndAlso before <> "0" AndAlso
               after.Length = 3 AndAlso after.All(AddressOf Char.IsDigit)
    End Function

    ''' <summary>"'1,000' is not a number", with a hint on how to write a decimal when the text has a comma.</summary>
    Private Shared Function NotANumber(label As String, t As String) As String
        Dim hint = If(t.Contains(","c), " (write a decimal as 0.25 or 0,25, with no separator between thousands)", "")
        Return label & " '" & t & "' is not a number" & hint
    End Function
End Structure
