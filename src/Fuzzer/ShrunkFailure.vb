Option Strict On
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Fuzzing.Shrinking

''' <summary>A failure after shrinking: which scene and invariant, the shrunk result, and the file it was written to.</summary>
Friend NotInheritable Class ShrunkFailure
    Friend Sub New(outcome As SceneOutcome, original As Violation, result As ShrinkResult, path As String)
        Me.Outcome = outcome
        Me.Original = original
        Me.Result = result
        Me.Path = path
    End Sub

    Friend ReadOnly Property Outcome As SceneOutcome
    ''' <summary>The violation as the full scene showed it.</summary>
    Friend ReadOnly Property Original As Violation
    Friend ReadOnly Property Result As ShrinkResult
    ''' <summary>The scene file written.</summary>
    Friend ReadOnly Property Path As String
End Class
