Option Strict On

Namespace Checking
    ''' <summary>What one run of one scene with one solver and one sampling interval left: broken invariants, its collisions and its end state.</summary>
    Friend NotInheritable Class RunOutcome
        ''' <summary>The first violation of each invariant, in the order seen.</summary>
        Friend ReadOnly Property Violations As New List(Of Violation)
        ''' <summary>Every collision (when the run was asked to keep them).</summary>
        Friend Property Log As CollisionLog
        ''' <summary>The state at T; Nothing when the run stopped early.</summary>
        Friend Property Final As FinalState
        Friend Property Collisions As Long
        ''' <summary>Wall-clock time of the simulation, s.</summary>
        Friend Property WallSeconds As Double
        ''' <summary>True when it reached T (it may still have broken invariants on the way).</summary>
        Friend Property Completed As Boolean

        ''' <summary>Whether an invariant of this name was broken.</summary>
        Friend Function Broke(invariant As String) As Boolean
            Return Violations.Any(Function(v) v.Invariant = invariant)
        End Function
    End Class
End Namespace
