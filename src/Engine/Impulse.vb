Option Strict On

''' <summary>
''' Collision response as a pure function: the velocities after an impulse along the contact normal.
''' </summary>
Public Module Impulse
    ''' <summary>
    ''' Velocities of A and B after a collision along unit normal n (from B towards A) with restitution e.
    ''' The impulse j = −(1 + e)(v_rel · n) / (1/m_A + 1/m_B) acts on A as +j n and on B as −j n, so
    ''' momentum is conserved exactly and the normal relative velocity becomes −e times what it was.
    ''' Inverse masses of 0 stand for fixed bodies (or a dragged one). A pair that is already separating
    ''' is left alone.
    ''' </summary>
    Public Function Resolve(va As Vector, inverseMassA As Double, vb As Vector, inverseMassB As Double,
                            normal As Vector, restitution As Double) As (A As Vector, B As Vector)
        Dim approach = Vector.Dot(va - vb, normal)
        Dim sumInv = inverseMassA + inverseMassB
        If approach >= 0 OrElse sumInv = 0 Then Return (va, vb)
        Dim j = -(1 + restitution) * approach / sumInv
        Return (va + normal * (j * inverseMassA), vb - normal * (j * inverseMassB))
    End Function

    ''' <summary>
    ''' The same collision when B lies on level ground that can only push up (a frictionless floor, or
    ''' the level top of a fixed body) and the blow presses it down (n points up from B towards A). The
    ''' ground takes the vertical part of the impulse on B, so B moves only sideways: along n it has the
    ''' inverse mass n_x²/m_B. The impulse j = −(1 + e)(v_rel · n) / (1/m_A + n_x²/m_B) acts on A as
    ''' +j n and on B as −j n_x along the ground: momentum along the ground is conserved exactly, B's
    ''' vertical velocity is unchanged, and the normal relative velocity becomes −e times what it was.
    ''' With e = 1 no energy is lost, since the ground does no work on a body it keeps from moving
    ''' vertically. A blow straight down (n_x = 0) leaves B where it is, as the ground itself would.
    ''' </summary>
    Public Function ResolveOnLevelGround(va As Vector, inverseMassA As Double, vb As Vector, inverseMassB As Double,
                                         normal As Vector, restitution As Double) As (A As Vector, B As Vector)
        Dim approach = Vector.Dot(va - vb, normal)
        Dim sideways = inverseMassB * normal.X * normal.X
        Dim sumInv = inverseMassA + sideways
        If approach >= 0 OrElse sumInv = 0 Then Return (va, vb)
        Dim j = -(1 + restitution) * approach / sumInv
        Return (va + normal * (j * inverseMassA), New Vector(vb.X - j * inverseMassB * normal.X, vb.Y))
    End Function
End Module
