Option Strict On

''' <summary>
''' A rod or a taut string of a chain, as <see cref="ChainConstraints"/> sees it: it holds body slot
''' <see cref="A"/> at <see cref="Length"/> from body slot <see cref="B"/>, or from the fixed point
''' <see cref="Anchor"/> when B is −1. Slots index a state array laid out per body as x, y, vx, vy (m, m/s).
''' </summary>
Friend NotInheritable Class ChainTie
    ''' <summary>A tie from slot a to slot b (−1: the fixed point <paramref name="anchor"/>, m), <paramref name="length"/> m long.</summary>
    Friend Sub New(a As Integer, b As Integer, anchor As Vector, length As Double)
        Me.A = a
        Me.B = b
        Me.Anchor = anchor
        Me.Length = length
    End Sub

    ''' <summary>End A's body slot.</summary>
    Friend ReadOnly Property A As Integer

    ''' <summary>End B's body slot, or −1 for a fixed point.</summary>
    Friend ReadOnly Property B As Integer

    ''' <summary>End B's fixed point (m) when <see cref="B"/> is −1.</summary>
    Friend ReadOnly Property Anchor As Vector

    ''' <summary>The length held, m.</summary>
    Friend ReadOnly Property Length As Double
End Class
