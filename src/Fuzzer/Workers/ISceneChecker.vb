Option Strict On
Imports PhysicsEngine.Fuzzing.Checking

Namespace Workers
    ''' <summary>Checks scene text with one solver, somewhere: in a worker process (a campaign) or in this process (tests, debugging).</summary>
    Friend Interface ISceneChecker
        ''' <summary>As <see cref="SceneCheck.Check"/>; a scene the reader refuses is a violation of <see cref="Invariants.Refused"/>.</summary>
        Function Check(sceneText As String, solver As String, plan As RunPlan, stopAt As String) As CheckResult
    End Interface
End Namespace
