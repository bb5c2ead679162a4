Option Strict On

''' <summary>The part of a body inside a liquid's rectangle: its area and the first moment of that area about y = 0.</summary>
Public Structure Submerged
    ''' <param name="area">A_sub, m²</param>
    ''' <param name="momentY">∫ y dA over that part, m³ (absolute y)</param>
    Public Sub New(area As Double, momentY As Double)
        Me.Area = area
        Me.MomentY = momentY
    End Sub

    ''' <summary>A_sub, m².</summary>
    Public ReadOnly Property Area As Double

    ''' <summary>∫ y dA over the part inside, m³: its area times the height of its centroid.</summary>
    Public ReadOnly Property MomentY As Double
End Structure
