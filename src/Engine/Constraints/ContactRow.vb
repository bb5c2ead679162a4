Option Strict On

''' <summary>
''' One row of a <see cref="ContactSolve"/> problem: its value is u·(x_A − x_B) + c, where x is what is solved for
''' (each body's velocity, m/s, or acceleration, m/s²), and its force λ (N·s or N) acts +λu on body A and −λu on
''' body B. A pushing row (a contact, a string seen from its ends) keeps its value ≥ 0 with λ ≥ 0, and λ &gt; 0 only
''' where the value is 0; a holding row (a rod) keeps its value at 0 with λ of either sign.
''' </summary>
Friend Structure ContactRow
    ''' <summary>No body: a wall, a fixed body or a fixed point, which nothing moves.</summary>
    Friend Const None As Integer = -1

    ''' <summary>A row on bodies <paramref name="a"/> and <paramref name="b"/> (or <see cref="None"/>) along the unit <paramref name="direction"/>.</summary>
    Friend Sub New(a As Integer, b As Integer, direction As Vector, offset As Double, holds As Boolean)
        Me.A = a
        Me.B = b
        Me.Direction = direction
        Me.Offset = offset
        Me.Holds = holds
    End Sub

    ''' <summary>Body A's index.</summary>
    Friend ReadOnly Property A As Integer
    ''' <summary>Body B's index, or <see cref="None"/>.</summary>
    Friend ReadOnly Property B As Integer
    ''' <summary>The unit direction u.</summary>
    Friend ReadOnly Property Direction As Vector
    ''' <summary>The constant part c of the value (m/s or m/s²).</summary>
    Friend ReadOnly Property Offset As Double
    ''' <summary>A holding row (value = 0, force of either sign) rather than a pushing one.</summary>
    Friend ReadOnly Property Holds As Boolean
End Structure
