Option Strict On
Imports System.IO
Imports PhysicsEngine
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>
''' Scenes of tests/cases that random scenes caught breaking the event solver, run here on the engine
''' alone (see tests/cases/README.md).
''' </summary>
Public Class CaseSceneTests
    ''' <summary>
    ''' 18 balls (radii 1–2 mm, masses 10⁻⁶ to 6·10⁵ kg) in a 39 × 96 mm box, g = 47.8 m/s², e = 0. At
    ''' t ≈ 0.0398 s ball c27, squeezed at the left wall between c49 (asleep, below it) and the heavy c39,
    ''' is resolved with them as a cluster and left at rest, but for rounding, on c49: the solver did not
    ''' see it fall back onto c49 at once, and it sank into c49 as ½ g t² (1.2 mm by t = 0.05 s).
    ''' </summary>
    <Fact>
    Public Sub BallLeftOnASleeper_FallsOntoIt_NotIntoIt()
        Dim w = SceneFile.LoadFile(Path.Combine(RepoRoot(), "tests", "cases", "event-ball-sinks-into-sleeper.json"))
        EventSolverTestKit.UseEventSolver(w)
        For k = 1 To 50
            w.Advance(0.001)
            Dim depth = EventSolverTestKit.DeepestOverlap(w)
            Assert.True(depth <= 0.000000001, $"at t = {w.Time} s two bodies overlap by {depth} m")
        Next
    End Sub

    Private Shared Function RepoRoot() As String
        For Each a In GetType(CaseSceneTests).Assembly.GetCustomAttributes(GetType(Reflection.AssemblyMetadataAttribute), False).Cast(Of Reflection.AssemblyMetadataAttribute)()
            If a.Key = "RepoRoot" Then Return a.Value
        Next
        Throw New InvalidOperationException("no RepoRoot metadata")
    End Function
End Class
