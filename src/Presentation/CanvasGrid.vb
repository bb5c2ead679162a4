Option Strict On

''' <summary>
''' The grid a teacher can switch on under the bodies, to read positions and lengths off the canvas:
''' a line every metre and, where they are far enough apart to tell, a fainter one every 10 cm. Only
''' the lines inside the container and on the canvas are listed, so a zoomed-in view of a large box
''' draws a few dozen lines, not thousands.
''' </summary>
Public Module CanvasGrid
    ''' <summary>The major lines' spacing, m.</summary>
    Public Const MajorStep As Double = 1.0
    ''' <summary>The minor lines' spacing, m.</summary>
    Public Const MinorStep As Double = 0.1
    ''' <summary>Closest the metre lines may be, px at 96 dpi: closer, they would fill the canvas with grey.</summary>
    Public Const MinMajorPixels As Double = 4
    ''' <summary>Closest the 10 cm lines may be, px at 96 dpi: closer, they are left out and the metre lines remain.</summary>
    Public Const MinMinorPixels As Double = 6

    ''' <summary>
    ''' The grid's lines for a container <paramref name="width"/> × <paramref name="height"/> m seen
    ''' through <paramref name="view"/> on a canvas <paramref name="canvasWidth"/> × <paramref name="canvasHeight"/> px
    ''' (<paramref name="screenScale"/> px per 96-dpi px): the metre lines, and the 10 cm lines when they are at
    ''' least <see cref="MinMinorPixels"/> apart. Each line runs across the whole container (clipped to the canvas).
    ''' </summary>
    Public Function Lines(width As Double, height As Double, view As ViewTransform, canvasWidth As Integer, canvasHeight As Integer,
                          Optional screenScale As Double = 1.0) As IReadOnlyList(Of GridLine)
        If view Is Nothing Then Throw New ArgumentNullException(NameOf(view))
        Dim result As New List(Of GridLine)
        If Not (width > 0 AndAlso height > 0) Then Return result
        Dim k = Math.Max(screenScale, 0.000001)
        If view.ToPixels(MajorStep) < MinMajorPixels * k Then Return result
        Dim minor = view.ToPixels(MinorStep) >= MinMinorPixels * k
        ' The part of the container on the canvas, m.
        Dim a = view.ToWorld(0, canvasHeight), b = view.ToWorld(canvasWidth, 0)
        Dim x0 = Math.Max(0.0, Math.Min(a.X, b.X)), x1 = Math.Min(width, Math.Max(a.X, b.X))
        Dim y0 = Math.Max(0.0, Math.Min(a.Y, b.Y)), y1 = Math.Min(height, Math.Max(a.Y, b.Y))
        If x1 < x0 OrElse y1 < y0 Then Return result
        Dim stepSize = If(minor, MinorStep, MajorStep)
        AddLines(result, True, x0, x1, y0, y1, stepSize)
        AddLines(result, False, y0, y1, x0, x1, stepSize)
        Return result
    End Function

    ''' <summary>Lines across, at every multiple of <paramref name="stepSize"/> from <paramref name="from"/> to <paramref name="upTo"/> m; every tenth (a whole metre) is major.</summary>
    Private Sub AddLines(result As List(Of GridLine), vertical As Boolean, from As Double, upTo As Double, acrossFrom As Double, acrossTo As Double, stepSize As Double)
        ' Counted in whole steps, so 0.3 m is the third line, not 0.30000000000000004 compared with 0.3.
        Dim first = CLng(Math.Ceiling(from / stepSize - 0.000000001)), last = CLng(Math.Floor(upTo / stepSize + 0.000000001))
        Dim perMetre = CLng(Math.Round(MajorStep / stepSize))
        For i = first To last
            Dim at = i * stepSize
            Dim major = i Mod perMetre = 0
            If vertical Then
                result.Add(New GridLine(New Vector(at, acrossFrom), New Vector(at, acrossTo), major))
            Else
                result.Add(New GridLine(New Vector(acrossFrom, at), New Vector(acrossTo, at), major))
            End If
        Next
    End Sub
End Module
