Option Strict On
Imports System.Globalization

''' <summary>The rope lesson: ten balls joined by rods, hanging from a point, released level; its energy after 5 s against its energy at the start.</summary>
Friend NotInheritable Class RopeScene
    Implements IBenchScene

    Private Const Count As Integer = 10
    Private Const Spacing As Double = 0.2
    Private Const Mass As Double = 0.2
    Private Const Gravity As Double = 9.81

    Public ReadOnly Property Name As String = "rope" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Rope of ten balls on rods: energy" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "The rope lesson (scenes/rope.json) with e = 1: ten 0.2 kg balls joined by 0.2 m rods, the first on a rod to a fixed point, " &
        "released level beside three free balls in a 5 m box (g = 9.81). No force does work but gravity and the walls' and balls' " &
        "elastic blows, so the energy ½mv² + mgy is constant. Error = |E(5 s) − E(0)| ÷ (M g L), M g L = 39.24 J (the rope's " &
        "weight times its length); the note gives the largest rod-length error then (m)." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "energy error after 5 s (of M g L)" Implements IBenchScene.ErrorMetric
    Public ReadOnly Property SimulatedSeconds As Double = 5.0 Implements IBenchScene.SimulatedSeconds

    ''' <summary>The world of scenes/rope.json, with e = 1.</summary>
    Public Function Build() As World Implements IBenchScene.Build
        Dim w As New World(5, 5, Gravity, 1.0)
        Dim pivot As New Vector(1.0, 4.0)
        Dim previous As Circle = Nothing
        For k = 1 To Count
            Dim id = "rope" & k.ToString(CultureInfo.InvariantCulture)
            Dim ball As New Circle(pivot + New Vector(k * Spacing, 0), 0.06, Mass, id:=id)
            w.Add(ball)
            If previous Is Nothing Then
                w.Add(Link.CreateTie(LinkKind.Rod, ball, pivot, Spacing, "rod1"))
            Else
                w.Add(Link.CreateTie(LinkKind.Rod, ball, previous, Spacing, "rod" & k.ToString(CultureInfo.InvariantCulture)))
            End If
            previous = ball
        Next
        For k = 1 To 3
            w.Add(New Circle(New Vector(0.6 + 0.35 * (k - 1), 0.15), 0.15, 1.0, id:="free" & k.ToString(CultureInfo.InvariantCulture)))
        Next
        Return w
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim e0 = Energy(world)
        If Not Sampling.Advance(world, SimulatedSeconds, sampleStep, budget) Then Return SceneMeasurement.Stopped(world, budget)
        Dim lengths = world.Links.Max(Function(l) Math.Abs(l.Distance - l.Length))
        Return New SceneMeasurement(Math.Abs(Energy(world) - e0) / (Count * Mass * Gravity * Count * Spacing),
                                    "rod lengths off by " & lengths.ToString("0.0E+0", CultureInfo.InvariantCulture) & " m")
    End Function

    Private Shared Function Energy(world As World) As Double
        Return world.Circles.Sum(Function(c) 0.5 * c.Mass * c.Velocity.LengthSquared + c.Mass * world.Gravity * c.Position.Y)
    End Function
End Class
