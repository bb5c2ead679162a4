Option Strict On

''' <summary>A rectangle on the canvas, px (x to the right, y down): where a label or an obstacle is.</summary>
Public Structure LabelBox
    Public Sub New(x As Double, y As Double, width As Double, height As Double)
        Me.X = x
        Me.Y = y
        Me.Width = width
        Me.Height = height
    End Sub

    ''' <summary>Left edge, px.</summary>
    Public ReadOnly Property X As Double
    ''' <summary>Top edge, px.</summary>
    Public ReadOnly Property Y As Double
    ''' <summary>px</summary>
    Public ReadOnly Property Width As Double
    ''' <summary>px</summary>
    Public ReadOnly Property Height As Double

    ''' <summary>Right edge, px.</summary>
    Public ReadOnly Property Right As Double
        Get
            Return X + Width
        End Get
    End Property

    ''' <summary>Bottom edge, px.</summary>
    Public ReadOnly Property Bottom As Double
        Get
            Return Y + Height
        End Get
    End Property

    ''' <summary>Whether the two share any area (touching edges do not count).</summary>
    Public Function Overlaps(other As LabelBox) As Boolean
        Return X < other.Right AndAlso other.X < Right AndAlso Y < other.Bottom AndAlso other.Y < Bottom
    End Function

    ''' <summary>Whether this box lies wholly inside <paramref name="outer"/>.</summary>
    Public Function IsInside(outer As LabelBox) As Boolean
        Return X >= outer.X AndAlso Y >= outer.Y AndAlso Right <= outer.Right AndAlso Bottom <= outer.Bottom
    End Function

    ''' <summary>The box of a circle of radius <paramref name="r"/> about (<paramref name="cx"/>, <paramref name="cy"/>).</summary>
    Public Shared Function AroundCircle(cx As Double, cy As Double, r As Double) As LabelBox
        Return New LabelBox(cx - r, cy - r, 2 * r, 2 * r)
    End Function
End Structure
