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

    ''' <summary>
    ''' The same collision when B slides on a fixed frictionless face (the floor, a rectangle's top, a tilted
    ''' face) with unit tangent t, and the blow presses it into that face (the face's normal s has s·n ≥ 0).
    ''' The face takes the part of the impulse on B across it, so B's velocity changes only along t: along n
    ''' it has the inverse mass (n·t)²/m_B. The impulse j = −(1 + e)(v_rel · n) / (1/m_A + (n·t)²/m_B) acts on A
    ''' as +j n and on B as −j (n·t) t: momentum along t is conserved exactly, B stays on its face, and the
    ''' normal relative velocity becomes −e times what it was. The face's push does no work on a body it keeps
    ''' on the face, so with e = 1 no energy is lost and with e &lt; 1 it never rises. With t = (1, 0) this is
    ''' <see cref="ResolveOnLevelGround"/>. A pair that is already separating is left alone.
    ''' </summary>
    Public Function ResolveOnFace(va As Vector, inverseMassA As Double, vb As Vector, inverseMassB As Double,
                                  normal As Vector, tangent As Vector, restitution As Double) As (A As Vector, B As Vector)
        Dim approach = Vector.Dot(va - vb, normal)
        Dim along = Vector.Dot(normal, tangent)
        Dim sumInv = inverseMassA + inverseMassB * along * along
        If approach >= 0 OrElse sumInv = 0 Then Return (va, vb)
        Dim j = -(1 + restitution) * approach / sumInv
        Return (va + normal * (j * inverseMassA), vb - tangent * (j * inverseMassB * along))
    End Function
End Module
