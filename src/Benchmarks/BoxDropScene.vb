Option Strict On
Imports System.Globalization

''' <summary>A box dropped on the floor (h0 = 1 m, e = 0.5): when it stops bouncing, against t0 (1 + e) / (1 − e).</summary>
Friend NotInheritable Class BoxDropScene
    Implements IBenchScene

    Private Const DropHeight As Double = 1.0
    Private Const Restitution As Double = 0.5
    Private Const Gravity As Double = 9.81

    Public ReadOnly Property Name As String = "box-drop" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Box dropped on the floor: time to rest" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "Scenarios.BoxDrop(h0 = 1 m, e = 0.5): a movable 0.2 m square box falls flat onto the floor. As for a ball, the bounces " &
        "form a geometric series ending at T = t0 (1 + e) / (1 − e), t0 = √(2 h0 / g) (T = 1.354 s). Error = |rest time − T| " &
        "for the event solver (its own recorded rest time), |last reported floor bounce − T| for a stepping solver; the note " &
        "gives the lowest the box's bottom went (m; below 0 is through the floor)." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "rest-time error (s)" Implements IBenchScene.ErrorMetric

    Private Shared ReadOnly RestTime As Double = ClosedForms.BounceRestTime(DropHeight, Restitution, Gravity)

    Public ReadOnly Property SimulatedSeconds As Double = 1.25 * RestTime Implements IBenchScene.SimulatedSeconds

    Public Function Build() As World Implements IBenchScene.Build
        Return Scenarios.BoxDrop(DropHeight, Restitution, Gravity)
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim box = world.Rectangles(0)
        Dim lastBounce = Double.NaN
        Dim bounces = 0
        world.CollisionListener = Sub(r)
                                      If r.Wall = WallSide.Bottom Then
                                          lastBounce = r.Time
                                          bounces += 1
                                      End If
                                  End Sub
        Dim lowest = Double.PositiveInfinity
        Dim finished = Sampling.Run(world, SimulatedSeconds, Sampling.SliceOf(sampleStep, 0.01),
                                    Function(t)
                                        lowest = Math.Min(lowest, box.Min.Y)
                                        Return True
                                    End Function, budget)
        world.CollisionListener = Nothing
        If Not finished Then Return SceneMeasurement.Stopped(world, budget)
        Dim note = bounces.ToString(CultureInfo.InvariantCulture) & " bounces; lowest bottom " & lowest.ToString("0.0e+0", CultureInfo.InvariantCulture) & " m"
        Dim eventSolver = TryCast(world.Solver, EventDrivenSolver)
        Dim rest = If(eventSolver Is Nothing, Nothing, eventSolver.RestTime(box))
        If rest.HasValue Then Return New SceneMeasurement(Math.Abs(rest.Value - RestTime), note & "; at rest from " & rest.Value.ToString("0.000000", CultureInfo.InvariantCulture) & " s")
        If bounces = 0 Then Return New SceneMeasurement(RestTime, "no bounce reported")
        Return New SceneMeasurement(Math.Abs(lastBounce - RestTime), note & "; last at " & lastBounce.ToString("0.000", CultureInfo.InvariantCulture) & " s")
    End Function
End Class
