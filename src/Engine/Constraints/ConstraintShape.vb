Option Strict On

''' <summary>The geometry of a <see cref="Constraint"/>: what it holds at zero.</summary>
Friend Enum ConstraintShape
    ''' <summary>A rod or a taut string: ψ = L − |c_B − c_A| (m), c_B a body's centre or a fixed point.</summary>
    Tie
    ''' <summary>A contact on a flat face (a wall, an edge of a pair shape): ψ = n·d − h (m).</summary>
    Plane
    ''' <summary>A contact on a round part (two balls, a ball on a corner or a peg): ψ = |d − c| − R (m).</summary>
    Round
End Enum
