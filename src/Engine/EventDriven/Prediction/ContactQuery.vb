Option Strict On

''' <summary>
''' One pair's question for a contact rule: body A relative to body B. D is A's reference point
''' minus B's (m), Dv and Da the relative velocity (m/s) and acceleration (m/s²), so relative to B,
''' A's reference point moves on D + Dv t + ½ Da t². Slop (m) is the touching tolerance, SpeedScale
''' (m/s) the size of the bodies' own speeds (rounding errs in proportion to it), Horizon (s) how far
''' ahead a contact is worth finding (+∞ for no limit).
''' </summary>
Friend Structure ContactQuery
    Friend A As Outline
    Friend B As Outline
    Friend D As Vector
    Friend Dv As Vector
    Friend Da As Vector
    Friend Slop As Double
    Friend SpeedScale As Double
    Friend Horizon As Double
    ''' <summary>Where the rules find the pair's Minkowski difference K = B ⊕ (−A).</summary>
    Friend Shapes As ContactShapes

    ''' <summary>The pair's Minkowski difference K = B ⊕ (−A), with radius R_A + R_B.</summary>
    Friend ReadOnly Property K As Outline
        Get
            Return Shapes.Difference(B, A)
        End Get
    End Property
End Structure
