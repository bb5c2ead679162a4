Option Strict On
Imports PhysicsEngine
Imports PhysicsEngine.Scenes
Imports Xunit

Namespace EventDriven
    ''' <summary>
    ''' Two rods or taut strings from fixed points to one body, in line (docs/links.md, "Two ties in line"): where no
    ''' small move across them keeps both, the body is held where it is, whatever pulls it across; where one does,
    ''' it swings.
    ''' </summary>
    Public Class TiesInLineTests
        ''' <summary>
        ''' A 3.9 mg ball on the floor with two rods straight up to points 0.89 m and 0.15 m above it, and a stiff spring
        ''' (4.4 kN/m) pulling it up and a little sideways (random scene seed 22007, cut to the ball). The two rods' rows
        ''' were one row twice: the ball swung on the long rod, the short one was watched, stretched past a nanometre
        ''' 19 µm across, was struck, and again, 60 000 times a second at up to 4 m/s; 18 s of CPU per simulated second,
        ''' and the energy of the full scene rose by 5·10⁻⁴ of itself. The ball is held: it stays where it is, its
        ''' sideways start speed taken away at once and counted as dissipated.
        ''' </summary>
        <Fact>
        Public Sub BallOnTwoRodsInLine_PulledSideways_StaysWhereItIs()
            Dim w = SceneFile.LoadFile(TestRepo.CaseFile("event-linked-ball-locked-by-two-rods-in-line.json"))
            Dim ball = w.Bodies.First(Function(b) b.Id = "c0")
            Dim start = ball.Position
            EventSolverTestKit.RunEventSolverChecked(w, 2, 0.05, EnergyLaw.PlusDissipatedKept(0.000000001), maxOverlap:=0.000000001)
            Assert.Equal(2.0, w.Time, 12)
            Assert.True((ball.Position - start).Length <= 0.000000000001, $"the ball moved {(ball.Position - start).Length} m")
            Assert.Equal(Vector.Zero, ball.Velocity)
        End Sub

        ''' <summary>
        ''' A 1 kg ball held level between two rods to points 1 m to its left and right (anchors on opposite sides), g
        ''' = 9.81, e = 1. Any fall stretches both rods: it hangs there, its energy exactly kept.
        ''' </summary>
        <Theory>
        <InlineData("rod", "rod")>
        <InlineData("rod", "string")>
        <InlineData("string", "string")>
        Public Sub BallBetweenTwoTiesToEitherSide_DoesNotFall(left As String, right As String)
            Dim w = LinkedWorlds.NewWorld("event", 1)
            Dim ball As New Circle(New Vector(5, 5), 0.05, 1, Vector.Zero, "ball")
            w.Add(ball)
            w.Add(Link.CreateTie(KindOf(left), ball, New Vector(4, 5), 1))
            w.Add(Link.CreateTie(KindOf(right), ball, New Vector(6, 5), 1))
            EventSolverTestKit.RunEventSolverChecked(w, 1, 0.05, EnergyLaw.Kept(0.000000001))
            Assert.Equal(5.0, ball.Position.Y, 12)
            Assert.Equal(5.0, ball.Position.X, 12)
        End Sub

        ''' <summary>
        ''' The ball held level between two rods (as above), struck from above by a ball falling from 1 m (e = 1): it
        ''' takes the blow as a fixed body would, and the falling ball bounces back up with its energy, all of it kept.
        ''' </summary>
        <Fact>
        Public Sub BallHeldBetweenTwoRods_StruckFromAbove_BouncesTheOtherBackAsAFixedBodyWould()
            Dim w = LinkedWorlds.NewWorld("event", 1)
            Dim ball As New Circle(New Vector(5, 5), 0.05, 1, Vector.Zero, "ball")
            Dim falling As New Circle(New Vector(5, 6.1), 0.05, 0.5, Vector.Zero, "falling")
            w.Add(ball)
            w.Add(falling)
            w.Add(Link.CreateTie(LinkKind.Rod, ball, New Vector(4, 5), 1))
            w.Add(Link.CreateTie(LinkKind.Rod, ball, New Vector(6, 5), 1))
            ' It falls 1 m in 0.4515 s and is back at the top at 0.903 s.
            EventSolverTestKit.RunEventSolverChecked(w, 0.9, 0.05, EnergyLaw.Kept(0.000000001))
            Assert.True(w.CollisionCount >= 1, "the falling ball never struck")
            Assert.True(falling.Position.Y > 6.09, $"the falling ball is back up only to {falling.Position.Y} m")
            Assert.Equal(New Vector(5, 5), ball.Position)
            Assert.Equal(Vector.Zero, ball.Velocity)
        End Sub

        ''' <summary>
        ''' A ball on a 0.5 m rod with a 1 m string in line above it, struck sideways at 1 m/s (e = 1): the rod is the
        ''' shorter, so it swings on the rod and the string goes slack. It is not held, and its energy is kept.
        ''' </summary>
        <Fact>
        Public Sub BallOnTheShorterRod_WithALongerStringInLine_Swings()
            Dim w = LinkedWorlds.NewWorld("event", 1)
            Dim ball As New Circle(New Vector(5, 5), 0.05, 1, New Vector(1, 0), "ball")
            w.Add(ball)
            w.Add(Link.CreateTie(LinkKind.Rod, ball, New Vector(5, 5.5), 0.5))
            w.Add(Link.CreateTie(LinkKind.String, ball, New Vector(5, 6), 1))
            EventSolverTestKit.RunEventSolverChecked(w, 0.2, 0.05, EnergyLaw.Kept(0.000000001))
            Assert.True(ball.Position.X - 5 > 0.1, $"the ball is at x = {ball.Position.X} m")
            Assert.Equal(0.5, (ball.Position - New Vector(5, 5.5)).Length, 12)
        End Sub

        Private Shared Function KindOf(name As String) As LinkKind
            Return If(name = "rod", LinkKind.Rod, LinkKind.String)
        End Function
    End Class
End Namespace
