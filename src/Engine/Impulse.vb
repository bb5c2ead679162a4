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
End Module
