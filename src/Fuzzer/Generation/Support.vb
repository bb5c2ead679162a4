Option Strict On

Namespace Generation
    ''' <summary>A level surface bodies can rest on: the floor or a rectangle's top, from x = Left to x = Right at height Top, m.</summary>
    Friend Structure Support
        Friend Sub New(top As Double, left As Double, right As Double)
            Me.Top = top
            Me.Left = left
            Me.Right = right
        End Sub

        Friend ReadOnly Property Top As Double
        Friend ReadOnly Property Left As Double
        Friend ReadOnly Property Right As Double
    End Structure
End Namespace
