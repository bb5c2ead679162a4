Option Strict On

''' <summary>An off-centre elastic hit between equal balls: exit velocities against the closed form.</summary>
Friend NotInheritable Class ObliqueHitScene
    Implements IBenchScene

    Private Const Speed As Double = 2.0
    Private Const ImpactParameter As Double = 0.1
    Private Const Radius As Double = 0.1

    Public ReadOnly Property Name As String = "oblique-hit" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Oblique two-circle hit: exit velocities" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "Scenarios.ObliqueHit(v0 = 2 m/s, b = 0.1 m, r = 0.1 m): equal masses, e = 1, g = 0. Closed form: sin φ = b/(2r) = 0.5; " &
        "the struck ball leaves along the line of centres at v0 cos φ = 1.732 m/s, the striker at right angles with v0 sin φ = 1 m/s. " &
        "Error = the larger of the two |v − v_exact| (m/s) at t = 1 s (impact at 0.413 s)." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "exit-velocity error (m/s)" Implements IBenchScene.ErrorMetric
    Public ReadOnly Property SimulatedSeconds As Double = 1.0 Implements IBenchScene.SimulatedSeconds

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.ObliqueHit(Speed, ImpactParameter, Radius)
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        Dim striker = DirectCast(world.Find("a"), Circle)
        Dim target = DirectCast(world.Find("b"), Circle)
        If Not Sampling.Advance(world, SimulatedSeconds, sampleStep, budget) Then Return SceneMeasurement.Stopped(world, budget)
        Dim exact = ClosedForms.ObliqueExitVelocities(Speed, ImpactParameter, Radius)
        Dim err = Math.Max((striker.Velocity - exact.Striker).Length, (target.Velocity - exact.Target).Length)
        Return New SceneMeasurement(err)
    End Function
End Class
