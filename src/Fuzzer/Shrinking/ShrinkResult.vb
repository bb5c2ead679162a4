Option Strict On
Imports PhysicsEngine.Fuzzing.Checking

Namespace Shrinking
    ''' <summary>A shrunk failure: the smallest scene and shortest run found that still fail, and what they show.</summary>
    Friend NotInheritable Class ShrinkResult
        Friend Sub New(doc As SceneDoc, plan As RunPlan, violation As Violation, probes As Integer, reproduced As Boolean)
            Me.Doc = doc
            Me.Plan = plan
            Me.Violation = violation
            Me.Probes = probes
            Me.Reproduced = reproduced
        End Sub

        Friend ReadOnly Property Doc As SceneDoc
        Friend ReadOnly Property Plan As RunPlan
        ''' <summary>The violation the shrunk scene shows (the original one when it did not reproduce).</summary>
        Friend ReadOnly Property Violation As Violation
        ''' <summary>Runs it took.</summary>
        Friend ReadOnly Property Probes As Integer
        ''' <summary>False when the original scene did not fail again when probed (a fluke, such as a cap on a busy machine): then nothing was shrunk.</summary>
        Friend ReadOnly Property Reproduced As Boolean
    End Class
End Namespace
