Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' The stability limit of the stepping solvers on a spring, ω h &lt; 2: the fuzzer uses it to tell a stepping run
''' that blows up on a stiff spring (the method's limit, noted as unstable) from one that blows up for any other
''' reason (a failure), and the CLI and the app to warn before such a run.
''' </summary>
Public Class StepStabilityTests
    ''' <summary>No gravity, no walls; a 1 kg ball 0.1 m from a point on a spring of rest length 0 and stiffness ω² N/m.</summary>
    Private Shared Function Oscillator(omega As Double, solver As String, ByRef ball As Circle) As World
        Dim w As New World(10, 10, 0, 1.0, False)
        w.Solver = SolverFactory.Create(solver, 0.001)
        ball = New Circle(New Vector(5.1, 5), 0.01, 1.0, Vector.Zero, "ball")
        w.Add(ball)
        w.Add(Link.CreateSpring(ball, New Vector(5, 5), omega * omega, 0, id:="s"))
        Return w
    End Function

    <Fact>
    Public Sub BeyondLimit_NamesASpringAtOrPastOmegaHOf2_AndNoneBelow()
        Dim ball As Circle = Nothing
        Assert.Null(StepStability.BeyondLimit(Oscillator(1999, "euler", ball), 0.001))
        Dim message = StepStability.BeyondLimit(Oscillator(2001, "euler", ball), 0.001)
        Assert.Contains("spring s has ω h = 2.001", message, StringComparison.Ordinal)
        ' Between two movable bodies both inverse masses count: ω² = k (1/m_A + 1/m_B).
        Dim w As New World(10, 10, 0, 1.0, False)
        Dim a As New Circle(New Vector(4, 5), 0.01, 1.0, id:="a")
        Dim b As New Circle(New Vector(6, 5), 0.01, 1.0, id:="b")
        w.Add(a)
        w.Add(b)
        w.Add(Link.CreateSpring(a, b, 1999 * 1999 / 2.0 * 1.002, 2, id:="ab"))
        Assert.NotNull(StepStability.BeyondLimit(w, 0.001))
    End Sub

    <Theory>
    <InlineData("euler")>
    <InlineData("verlet")>
    Public Sub TheLimitIsTheSolversOwn_BoundedJustBelow_GrowingJustAbove(solver As String)
        ' 0.2 s of steps of 1 ms: at ω h = 1.9 the ball stays within a few times its 0.1 m start; at ω h = 2.1
        ' each step multiplies the swing by |λ| = (ω²h² − 2 + √((ω²h² − 2)² − 4)) / 2 ≈ 1.88, and 200 steps make it enormous.
        Dim ball As Circle = Nothing
        Dim below = Oscillator(1900, solver, ball)
        below.Advance(0.2)
        Assert.True((ball.Position - New Vector(5, 5)).Length < 1.0, $"at ω h = 1.9 the ball is at {ball.Position}")
        Dim above = Oscillator(2100, solver, ball)
        Dim grew = False
        Try
            above.Advance(0.2)
            grew = Not ball.Position.IsFinite OrElse (ball.Position - New Vector(5, 5)).Length > 1000000.0
        Catch ex As ArithmeticException
            grew = True
        Catch ex As SpeedLimitException
            grew = True
        End Try
        Assert.True(grew, $"at ω h = 2.1 the ball is still at {ball.Position}")
    End Sub
End Class
