Option Strict On

''' <summary>
''' The tape measure: while it is on, a left drag on the canvas lays a line between two points and
''' reads its length (m) and its angle to the horizontal (°). The line stays until the next drag
''' replaces it or the tool is switched off (Esc, or its menu entry again).
''' </summary>
Public NotInheritable Class TapeMeasure
    ''' <summary>The fewest significant figures a length is shown with.</summary>
    Public Const MinFigures As Integer = 3
    ''' <summary>The most decimals a length is shown with, however far the view is zoomed in.</summary>
    Public Const MaxDecimals As Integer = 6

    ''' <summary>Whether a left drag on the canvas measures (rather than aiming the cue).</summary>
    Public ReadOnly Property IsOn As Boolean
    ''' <summary>Whether the button is down and the far end follows the cursor.</summary>
    Public ReadOnly Property IsDragging As Boolean
    ''' <summary>Where the line starts, m (Nothing before the first drag).</summary>
    Public ReadOnly Property Start As Vector?
    ''' <summary>Where the line ends, m (Nothing before the first drag).</summary>
    Public ReadOnly Property Finish As Vector?

    ''' <summary>Whether there is a line to show.</summary>
    Public ReadOnly Property HasLine As Boolean
        Get
            Return _Start.HasValue AndAlso _Finish.HasValue
        End Get
    End Property

    ''' <summary>The line's length, m (0 without a line).</summary>
    Public ReadOnly Property Length As Double
        Get
            Return If(HasLine, (_Finish.Value - _Start.Value).Length, 0.0)
        End Get
    End Property

    ''' <summary>The line's angle to the horizontal, 0° to 90° (0 without a line).</summary>
    Public ReadOnly Property AngleDegrees As Double
        Get
            Return If(HasLine, AngleToHorizontal(_Start.Value, _Finish.Value), 0.0)
        End Get
    End Property

    ''' <summary>Switches the tool on, with no line yet.</summary>
    Public Sub TurnOn()
        _IsOn = True
        _IsDragging = False
        _Start = Nothing
        _Finish = Nothing
    End Sub

    ''' <summary>Switches the tool off and takes its line away.</summary>
    Public Sub Clear()
        _IsOn = False
        _IsDragging = False
        _Start = Nothing
        _Finish = Nothing
    End Sub

    ''' <summary>The left button went down at <paramref name="p"/> (m): a new line starts there.</summary>
    Public Sub Press(p As Vector)
        If Not _IsOn Then Return
        _Start = p
        _Finish = p
        _IsDragging = True
    End Sub

    ''' <summary>The cursor moved to <paramref name="p"/> (m): the far end follows it while dragging.</summary>
    Public Sub MoveTo(p As Vector)
        If _IsDragging Then _Finish = p
    End Sub

    ''' <summary>The left button came up at <paramref name="p"/> (m): the line ends there and stays.</summary>
    Public Sub Release(p As Vector)
        If Not _IsDragging Then Return
        _Finish = p
        _IsDragging = False
    End Sub

    ''' <summary>
    ''' The acute angle between the line through <paramref name="a"/> and <paramref name="b"/> (m) and
    ''' the horizontal, 0° to 90°: the way the line was drawn does not matter.
    ''' </summary>
    Public Shared Function AngleToHorizontal(a As Vector, b As Vector) As Double
        Dim d = b - a
        If d.X = 0 AndAlso d.Y = 0 Then Return 0
        Return Math.Atan2(Math.Abs(d.Y), Math.Abs(d.X)) * 180.0 / Math.PI
    End Function

    ''' <summary>
    ''' The decimals a length (m) is shown with: at least <see cref="MinFigures"/> significant figures,
    ''' and more when one canvas pixel (<paramref name="metresPerPixel"/>) is finer than that.
    ''' </summary>
    Public Shared Function Decimals(length As Double, metresPerPixel As Double) As Integer
        Dim bySize = If(length > 0, MinFigures - 1 - CInt(Math.Floor(Math.Log10(length))), MinFigures - 1)
        Dim byPixel = If(metresPerPixel > 0, CInt(Math.Ceiling(-Math.Log10(metresPerPixel))), 0)
        Return Math.Max(0, Math.Min(MaxDecimals, Math.Max(bySize, byPixel)))
    End Function

    ''' <summary>"1.23 m at 30.0°": the line's reading, with as many decimals as the zoom warrants.</summary>
    Public Function Label(metresPerPixel As Double) As String
        If Not HasLine Then Return ""
        Return Units.Num(Length, Decimals(Length, metresPerPixel)) & " m at " & Units.Num(AngleDegrees, 1) & "°"
    End Function
End Class
