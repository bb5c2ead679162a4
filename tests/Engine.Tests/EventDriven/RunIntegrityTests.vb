Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' What a run must not depend on: how it is cut into advances (sampling only reads the state), a
''' wall-clock budget that stops an advance early, and the size of the container far from the bodies
''' (tolerances are local to the bodies involved). And what is printed must agree with what the
''' solver knows: a ball is shown at rest only once its series of bounces has really ended.
''' </summary>
Public Class RunIntegrityTests
    ''' <summary>Every collision (time, who, velocities) and the final state, as raw bits.</summary>
    Private Shared Function Fingerprint(w As World, log As List(Of Long)) As List(Of Long)
        Dim result As New List(Of Long)(log)
        For Each c In w.Circles
            result.Add(BitConverter.DoubleToInt64Bits(c.Position.X))
            result.Add(BitConverter.DoubleToInt64Bits(c.Position.Y))
            result.Add(BitConverter.DoubleToInt64Bits(c.Velocity.X))
            result.Add(BitConverter.DoubleToInt64Bits(c.Velocity.Y))
        Next
        Return result
    End Function

    Private Shared Function Logged(w As World) As List(Of Long)
        Dim log As New List(Of Long)
        Dim index = w.Bodies.Select(Function(b, k) (b, k)).ToDictionary(Function(x) x.b, Function(x) x.k)
        w.CollisionListener = Sub(r)
                                  log.Add(BitConverter.DoubleToInt64Bits(r.Time))
                                  log.Add(index(r.A))
                                  log.Add(If(r.B Is Nothing, -CInt(r.Wall), index(r.B)))
                                  log.Add(BitConverter.DoubleToInt64Bits(r.AVelocityAfter.X))
                                  log.Add(BitConverter.DoubleToInt64Bits(r.AVelocityAfter.Y))
                                  log.Add(BitConverter.DoubleToInt64Bits(r.BVelocityAfter.X))
                                  log.Add(BitConverter.DoubleToInt64Bits(r.BVelocityAfter.Y))
                              End Sub
        Return log
    End Function

    ''' <summary>Runs the world to <paramref name="total"/> s, reading the state every <paramref name="sample"/> s as the command line does.</summary>
    Private Shared Function RunSampled(make As Func(Of World), total As Double, sample As Double) As List(Of Long)
        Dim w = make()
        UseEventSolver(w)
        Dim log = Logged(w)
        Dim k = 1
        Do
            Dim t = Math.Min(k * sample, total)
            w.Advance(t - w.Time)
            k += 1
            If t >= total Then Exit Do
        Loop
        Return Fingerprint(w, log)
    End Function

    Public Shared ReadOnly Property Scenes As TheoryData(Of String)
        Get
            Return New TheoryData(Of String)("pile", "mixed", "gas")
        End Get
    End Property

    <Theory>
    <MemberData(NameOf(Scenes))>
    Public Sub Listening_ChangesNothing_AndHearsEveryCollisionCounted(name As String)
        ' Without a listener the solver only counts collisions (it builds no records); with one it
        ' builds a record for each. Neither may change the run, and the count must be the same.
        Dim heard = Make(name)
        UseEventSolver(heard)
        Dim records = 0L
        heard.CollisionListener = Sub(r) records += 1
        heard.Advance(1.0)
        Dim silent = Make(name)
        UseEventSolver(silent)
        silent.Advance(1.0)
        Assert.True(records > 50, $"{records} collisions")
        Assert.Equal(records, heard.CollisionCount)
        Assert.Equal(heard.CollisionCount, silent.CollisionCount)
        Assert.Equal(Fingerprint(heard, New List(Of Long)), Fingerprint(silent, New List(Of Long)))
    End Sub

    Private Shared Function Make(name As String) As World
        Select Case name
            Case "pile" : Return Scenarios.Pile(120, 0.3, seed:=2)
            Case "gas" : Return Scenarios.ElasticGas(400, 0.25, seed:=5)
            Case Else
                Dim w = Scenarios.Demo()
                Dim rng As New Random(4)
                For k = 1 To 40
                    Dim p = New Vector(0.3 + 7.4 * rng.NextDouble(), 2.0 + 2.8 * rng.NextDouble())
                    If w.Circles.Any(Function(c) (c.Position - p).Length < c.Radius + 0.06) Then Continue For
                    w.Add(New Circle(p, 0.05, 0.1 + rng.NextDouble(), New Vector(rng.NextDouble() * 8 - 4, rng.NextDouble() * 8 - 4)))
                Next
                Return w
        End Select
    End Function

    <Theory>
    <MemberData(NameOf(Scenes))>
    Public Sub TwoSamplingIntervals_GiveTheSameRun_ToTheLastBit(scene As String)
        Dim coarse = RunSampled(Function() Make(scene), 3.0, 0.15)
        Dim fine = RunSampled(Function() Make(scene), 3.0, 0.0097)
        Assert.True(coarse.Count > 100, "too few collisions to compare")
        Assert.Equal(coarse, fine)
    End Sub

    <Theory>
    <MemberData(NameOf(Scenes))>
    Public Sub AWallClockBudget_StopsEarly_WithoutChangingTheRun(scene As String)
        Dim plain = RunSampled(Function() Make(scene), 3.0, 3.0)
        ' A zero budget: each advance stops after its first instant that is out of time.
        Dim w = Make(scene)
        UseEventSolver(w)
        Dim log = Logged(w)
        Dim calls = 0
        While w.Time < 3.0
            Dim advanced = w.AdvanceWithin(3.0 - w.Time, 0.0)
            Assert.True(advanced >= 0)
            calls += 1
        End While
        Assert.True(calls >= 3, $"only {calls} advances: the budget did not stop them")
        Assert.Equal(plain, Fingerprint(w, log))
    End Sub

    ''' <summary>
    ''' A row of touching balls struck end on, with a pendulum beside it (links: the general path): the blow passes
    ''' down the row in one event per ball, all at one instant.
    ''' </summary>
    Private Shared Function LinkedCradle() As World
        Dim w As New World(8.0, 5.0, 0.0, 1.0)
        w.Add(New Circle(New Vector(1.0, 2.0), 0.1, 1.0, New Vector(2.0, 0.0)))
        For k = 0 To 7
            w.Add(New Circle(New Vector(3.0 + 0.2 * k, 2.0), 0.1, 1.0))
        Next
        Dim bob As New Circle(New Vector(7.0, 3.0), 0.1, 1.0, New Vector(0.0, 1.0))
        w.Add(bob)
        w.Add(Link.CreateTie(LinkKind.String, bob, New Vector(6.0, 3.0), 1.0))
        Return w
    End Function

    <Fact>
    Public Sub AWallClockBudget_StopsWithinACascade_WithoutChangingTheRun()
        ' A cascade at one instant that runs out of time stops between two of its events: a run stuck at one instant
        ' must not hold a window that waits on the advance.
        Dim plain = LinkedCradle()
        UseEventSolver(plain)
        Dim plainLog = Logged(plain)
        plain.Advance(2.0)
        Dim w = LinkedCradle()
        UseEventSolver(w)
        Dim log = Logged(w)
        Dim withinAnInstant = 0
        Dim calls = 0
        While w.Time < 2.0
            Dim heard = log.Count
            Dim advanced = w.AdvanceWithin(2.0 - w.Time, 0.0)
            calls += 1
            Assert.True(calls < 100000, "the budgeted advances do not get on")
            If advanced = 0 AndAlso log.Count > heard Then withinAnInstant += 1
        End While
        ' The striker and the eight balls of the row: seven blows pass on at the instant of the first.
        Assert.True(withinAnInstant >= 7, $"{withinAnInstant} advances stopped within an instant")
        Assert.Equal(Fingerprint(plain, plainLog), Fingerprint(w, log))
    End Sub

    <Fact>
    Public Sub BouncingBall_IsShownAtRestOnlyOnceItsBouncesHaveEnded()
        Dim w = Scenarios.BouncingBall(1.0, 0.9)
        Dim solver = UseEventSolver(w)
        Dim ball = w.Circles(0)
        Dim shownAtRest = Double.NaN
        For k = 1 To 10000
            w.Advance(0.001)
            Dim still = ball.Velocity.Y = 0 AndAlso ball.Position.Y = ball.Radius
            If still AndAlso Double.IsNaN(shownAtRest) Then shownAtRest = w.Time
            If Not still Then shownAtRest = Double.NaN
        Next
        Dim rest = solver.RestTime(ball)
        Assert.True(rest.HasValue)
        Dim t0 = Math.Sqrt(2 * 1.0 / 9.81)
        Assert.True(Math.Abs(rest.Value - t0 * 1.9 / 0.1) < 1.0E-9, $"rest time {rest.Value}")
        ' Sampled every millisecond: shown at rest at the first sample after the rest time, not before.
        Assert.InRange(shownAtRest, rest.Value - 0.001, rest.Value + 0.001)
    End Sub

    <Theory>
    <InlineData(1000000000.0)>
    <InlineData(1000000000000.0)>
    Public Sub AHugeContainer_DoesNotChangeABounceOnItsFloor(width As Double)
        ' An elastic ball dropped 1.9 m onto the floor of a container 3 m high: it bounces back to
        ' the same height however wide the container is.
        Dim w As New World(width, 3.0, 9.81, 1.0)
        Dim ball As New Circle(New Vector(width / 2, 2.0), 0.1, 1.0)
        w.Add(ball)
        UseEventSolver(w)
        Dim bounces = 0
        w.CollisionListener = Sub(r) bounces += 1
        Dim tFall = Math.Sqrt(2 * 1.9 / 9.81)
        w.Advance(2 * tFall)
        Assert.Equal(1, bounces)
        Assert.True(Math.Abs(ball.Position.Y - 2.0) < 1.0E-9, $"back at {ball.Position.Y} m, not 2 m")
        Assert.True(Math.Abs(ball.Velocity.Y) < 1.0E-8, $"vy {ball.Velocity.Y} at the top")
    End Sub
End Class
