Option Strict On

''' <summary>
''' One body's current burst of collisions, as the sleeping rule counts it (<see cref="RestRules"/>):
''' read only when gravity can hold a body, so apart from the hits every collision counts
''' (<see cref="BodyInfo"/>).
''' </summary>
Friend Structure BurstHistory
    ''' <summary>Start of the body's current burst of collisions, s.</summary>
    Friend Start As Double
    ''' <summary>Collisions in the current burst.</summary>
    Friend Count As Integer

    ''' <summary>No collisions yet.</summary>
    Friend Shared ReadOnly Property Fresh As New BurstHistory() With {.Start = Double.NegativeInfinity}
End Structure
