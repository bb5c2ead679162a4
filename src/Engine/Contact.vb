Option Strict On

''' <summary>
''' Where two shapes touch or overlap: the unit normal pointing from the other body towards the
''' circle, and the overlap depth in m (negative when apart).
''' </summary>
Public Structure Contact
    ''' <summary>Unit vector from the other body towards the circle.</summary>
    Public ReadOnly Property Normal As Vector
    ''' <summary>Overlap in m: positive when overlapping, 0 when touching, negative when apart.</summary>
    Public ReadOnly Property Depth As Double

    Public Sub New(normal As Vector, depth As Double)
        Me.Normal = normal
        Me.Depth = depth
    End Sub
End Structure
