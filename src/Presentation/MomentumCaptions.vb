Option Strict On

''' <summary>The words on the momentum views' check boxes (and the walls toggle), as the window and the tutorial give them.</summary>
Public Module MomentumCaptions
    Public Const CentreOfMass As String = "Centre of mass"
    Public Const TotalMomentum As String = "Σp arrow"
    Public Const MomentaDiagram As String = "Momenta"
    Public Const Impulses As String = "Impulses Δp"
    Public Const Traces As String = "Traces"
    Public Const Walls As String = "Walls"

    ''' <summary>Every caption of the block.</summary>
    Public ReadOnly Property All As IReadOnlyList(Of String) = {CentreOfMass, TotalMomentum, MomentaDiagram, Impulses, Traces, Walls}
End Module
