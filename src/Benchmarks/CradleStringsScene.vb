Option Strict On
Imports System.Globalization

''' <summary>Newton's cradle on strings: one ball swings in from 30°, one ball swings out with its speed, the rest stay still.</summary>
Friend NotInheritable Class CradleStringsScene
    Implements IBenchScene

    Private Const Count As Integer = 5
    Private Const Length As Double = 1.0
    Private Const Angle As Double = Math.PI / 6
    Private Const Gravity As Double = 9.81
    Private Const Radius As Double = 0.1

    Public ReadOnly Property Name As String = "cradle-strings" Implements IBenchScene.Name
    Public ReadOnly Property Title As String = "Newton's cradle on strings" Implements IBenchScene.Title
    Public ReadOnly Property Description As String =
        "The cradle lesson (scenes/cradle-strings.json): five 1 kg balls of radius 0.1 m on 1 m strings, touching, e = 1; the first " &
        "is released at rest from 30° and strikes at u = √(2gL(1 − cos 30°)) = 1.621 m/s. Closed form: exactly one ball, the last, " &
        "leaves at u and the others stay at rest. Each ball's speed is read from its energy as the speed it has (or had) at the " &
        "bottom, √(v² + 2g(y − y_bottom)), at half a period, when the last ball is at the top of its swing. Error = the largest " &
        "such speed of balls 1–4 + |speed of ball 5 − u| (m/s)." Implements IBenchScene.Description
    Public ReadOnly Property ErrorMetric As String = "speed spread to the wrong balls (m/s)" Implements IBenchScene.ErrorMetric

    Private Shared ReadOnly Period As Double = ClosedForms.PendulumPeriod(Length, Angle, Gravity)

    Public ReadOnly Property SimulatedSeconds As Double = Period / 2 Implements IBenchScene.SimulatedSeconds

    ''' <summary>The world of scenes/cradle-strings.json.</summary>
    Public Function Build() As World Implements IBenchScene.Build
        Dim w As New World(4, 3, Gravity, 1.0)
        For k = 1 To Count
            Dim pivot As New Vector(1.6 + 2 * Radius * (k - 1), 2.5)
            Dim theta = If(k = 1, -Angle, 0)
            Dim ball As New Circle(pivot + New Vector(Length * Math.Sin(theta), -Length * Math.Cos(theta)), Radius, 1.0, id:="b" & k.ToString(CultureInfo.InvariantCulture))
            w.Add(ball)
            w.Add(Link.CreateTie(LinkKind.String, ball, pivot, Length, "s" & k.ToString(CultureInfo.InvariantCulture)))
        Next
        Return w
    End Function

    Public Function Measure(world As World, sampleStep As Double, budget As RunBudget) As SceneMeasurement Implements IBenchScene.Measure
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim bottom = 2.5 - Length
        Dim u = Math.Sqrt(2 * Gravity * Length * (1 - Math.Cos(Angle)))
        If Not Sampling.Advance(world, SimulatedSeconds, sampleStep, budget) Then Return SceneMeasurement.Stopped(world, budget)
        Dim stray = 0.0, moving = 0
        Dim leaving = 0.0
        For k = 1 To Count
            Dim c = DirectCast(world.Find("b" & k.ToString(CultureInfo.InvariantCulture)), Circle)
            Dim speed = Math.Sqrt(c.Velocity.LengthSquared + 2 * Gravity * Math.Max(c.Position.Y - bottom, 0))
            If speed > 0.01 * u Then moving += 1
            If k = Count Then leaving = speed Else stray = Math.Max(stray, speed)
        Next
        Return New SceneMeasurement(stray + Math.Abs(leaving - u),
                                    moving.ToString(CultureInfo.InvariantCulture) & " ball(s) moving; the last at " &
                                    leaving.ToString("0.000000", CultureInfo.InvariantCulture) & " m/s (u = " & u.ToString("0.000000", CultureInfo.InvariantCulture) & ")")
    End Function
End Class
