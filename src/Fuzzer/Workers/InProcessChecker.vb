Option Strict On
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Scenes

Namespace Workers
    ''' <summary>
    ''' Checks in this process. A run that never returns hangs the caller: the wall-time cap is only
    ''' checked between samples. For tests of the checks and for debugging; campaigns use workers.
    ''' </summary>
    Friend NotInheritable Class InProcessChecker
        Implements ISceneChecker

        Public Function Check(sceneText As String, solver As String, plan As RunPlan, stopAt As String) As CheckResult Implements ISceneChecker.Check
            Try
                Return SceneCheck.Check(sceneText, solver, plan, stopAt)
            Catch ex As SceneFormatException
                Dim result As New CheckResult()
                result.Violations.Add(New Violation(Invariants.Refused, solver, plan.Sample, 0, ex.Message))
                Return result
            End Try
        End Function
    End Class
End Namespace
