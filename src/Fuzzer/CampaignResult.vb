Option Strict On
Imports PhysicsEngine.Fuzzing.Checking

''' <summary>Everything a campaign checked and found.</summary>
Friend NotInheritable Class CampaignResult
    ''' <summary>Every scene, in seed order.</summary>
    Friend ReadOnly Property Outcomes As New List(Of SceneOutcome)
    ''' <summary>Every shrunk failure written out (none when shrinking was off).</summary>
    Friend ReadOnly Property Shrunk As New List(Of ShrunkFailure)
    Friend Property ElapsedSeconds As Double

    ''' <summary>One entry per scene and invariant that failed.</summary>
    Friend Function Failures() As List(Of (Outcome As SceneOutcome, Violation As Violation))
        Return Outcomes.SelectMany(Function(o) o.Failures().Select(Function(v) (o, v))).ToList()
    End Function
End Class
