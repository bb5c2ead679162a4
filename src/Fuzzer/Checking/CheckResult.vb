Option Strict On

Namespace Checking
    ''' <summary>What checking one scene with one solver found: the broken invariants and how much work it was.</summary>
    Friend NotInheritable Class CheckResult
        ''' <summary>The first violation of each invariant (per sampling interval).</summary>
        Friend ReadOnly Property Violations As New List(Of Violation)
        ''' <summary>Collisions in the first run.</summary>
        Friend Property Collisions As Long
        ''' <summary>Wall-clock time of every run, s.</summary>
        Friend Property WallSeconds As Double

        ''' <summary>Whether an invariant of this name was broken.</summary>
        Friend Function Broke(invariant As String) As Boolean
            Return Violations.Any(Function(v) v.Invariant = invariant)
        End Function
    End Class
End Namespace
