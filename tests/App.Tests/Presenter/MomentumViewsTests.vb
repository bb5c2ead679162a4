Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>Seeing momentum: the centre of mass, Σp, the momenta diagram, impulses, traces, and the walls toggle.</summary>
Public Class MomentumViewsTests
    Private Shared ReadOnly RoundMantissas As Double() = {1.0, 2.0, 2.5, 5.0}

    ''' <summary>Three balls of unlike masses and velocities, a fixed peg and a fixed block (which must not count), g = 0.</summary>
    Private Shared Function Mixed() As PresenterHarness
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        h.P.World.Add(New Circle(New Vector(1, 1), 0.2, 1.0, New Vector(2, 0.5), "a"))
        h.P.World.Add(New Circle(New Vector(4, 3), 0.3, 2.5, New Vector(-1, 1), "b"))
        h.P.World.Add(New Circle(New Vector(6, 1.5), 0.25, 0.4, New Vector(0.3, -2), "c"))
        h.P.World.Add(Circle.CreateFixed(New Vector(6, 4), 0.3))
        h.P.World.Add(New Rectangle(New Vector(2, 3.8), 1, 0.5))
        Return h
    End Function

    <Fact>
    Public Sub CentreOfMass_AndTotalMomentum_AreTheMassWeightedSumsOfTheMovableBodies()
        Dim h = Mixed()
        For Each dt In {0.0, 0.4, 0.4, 0.4}
            If dt > 0 Then h.P.Tick(dt)
            ' Worked out here from the bodies, independently of the presenter and the engine's queries.
            Dim m = 0.0, mx = 0.0, my = 0.0, px = 0.0, py = 0.0
            For Each b In h.P.World.Circles
                If b.IsFixed Then Continue For
                m += b.Mass
                mx += b.Mass * b.Position.X
                my += b.Mass * b.Position.Y
                px += b.Mass * b.Velocity.X
                py += b.Mass * b.Velocity.Y
            Next
            Dim s = h.P.Momentum
            Assert.Equal(3.9, s.Mass, 12)
            Assert.Equal(mx / m, s.CentreOfMass.X, 12)
            Assert.Equal(my / m, s.CentreOfMass.Y, 12)
            Assert.Equal(px, s.Momentum.X, 12)
            Assert.Equal(py, s.Momentum.Y, 12)
            Assert.Equal(px / m, s.Velocity.X, 12)
            Assert.Equal(py / m, s.Velocity.Y, 12)
            ' And the engine agrees.
            Assert.Equal(h.P.World.CentreOfMass().X, s.CentreOfMass.X, 12)
            Assert.Equal(h.P.World.Momentum().Y, s.Momentum.Y, 12)
        Next
    End Sub

    <Fact>
    Public Sub CentreOfMass_WithNoMovableBody_IsNotShown()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        h.P.World.Add(Circle.CreateFixed(New Vector(6, 4), 0.3))
        Assert.False(h.P.Momentum.HasBodies)
        Assert.Equal(Vector.Zero, h.P.Momentum.Velocity)
    End Sub

    <Fact>
    Public Sub CentreOfMass_MovesInAStraightLineAtItsVelocity_ThroughBallCollisions()
        ' With no gravity and no walls, no outside force acts: the centre of mass moves at Σp/Σm whatever the balls do.
        Dim w = Scenarios.HeadOn(1.0, 2.0, 3.0, -1.0, 0.6)
        Dim h As New PresenterHarness(w)
        Dim start = h.P.Momentum
        For i = 1 To 60
            h.P.Tick(1.0 / 30)
        Next
        Assert.True(h.P.Log.TotalSeen >= 1, "the balls collided")
        Dim now = h.P.Momentum
        Dim t = h.P.World.Time
        Assert.Equal(start.CentreOfMass.X + start.Velocity.X * t, now.CentreOfMass.X, 9)
        Assert.Equal(start.Momentum.X, now.Momentum.X, 12)
    End Sub

    <Fact>
    Public Sub MomentaDiagram_ChainsEachBodysMomentum_TipToTail_AndEndsAtTheSum()
        Dim h = Mixed()
        Dim d = h.P.Momenta()
        Assert.True(d.ShowsEachBody)
        Assert.Equal(3, d.Count)
        Dim movers = h.P.World.Movables
        Dim tip = Vector.Zero
        For i = 0 To d.Count - 1
            Assert.Equal(tip, d.Tail(i))
            Assert.Equal(movers(i).Mass * movers(i).Velocity, d.Momentum(i))
            Assert.Equal(If(movers(i).Color, ""), d.Colour(i))
            tip += d.Momentum(i)
        Next
        Assert.Equal(tip.X, d.Sum.X, 12)
        Assert.Equal(tip.Y, d.Sum.Y, 12)
        Assert.Equal(h.P.Momentum.Momentum.X, d.Sum.X, 12)
        Assert.True(d.Extent >= d.Sum.Length AndAlso d.Extent >= d.Momentum(0).Length)
    End Sub

    <Fact>
    Public Sub MomentaDiagram_OfAGas_DrawsOnlyTheSum()
        Dim h As New PresenterHarness(Scenarios.ElasticGas(200))
        Dim d = h.P.Momenta()
        Assert.False(d.ShowsEachBody)
        Assert.Equal(0, d.Count)
        Assert.Equal(200, d.BodyCount)
        Assert.Equal(h.P.World.Momentum().X, d.Sum.X, 12)
    End Sub

    <Fact>
    Public Sub MomentumScale_FitsTheLongestArrowInItsRoom_WithARoundKey()
        Dim s As New MomentumScale()
        For Each longest In {0.003, 0.7, 12.0, 4500.0}
            s.Update(longest, 150)
            Assert.True(longest * s.PixelsPerUnit <= 150 * (1 + 1.0E-12), $"{longest} kg·m/s is {longest * s.PixelsPerUnit} px")
            Assert.True(longest * s.PixelsPerUnit >= 15 OrElse s.PixelsPerUnit = MomentumScale.MaxPixelsPerUnit, $"{longest} kg·m/s is only {longest * s.PixelsPerUnit} px")
            Dim key = s.LegendMomentum(90)
            Assert.True(key * s.PixelsPerUnit <= 90 * (1 + 1.0E-12) AndAlso key * s.PixelsPerUnit > 90 / 2.5 - 1.0E-9)
            Dim mantissa = key / Math.Pow(10, Math.Floor(Math.Log10(key)))
            Assert.Contains(Math.Round(mantissa, 9), RoundMantissas)
        Next
    End Sub

    <Theory>
    <InlineData(1.0, 2.0, 3.0, -1.0, 1.0)>
    <InlineData(1.0, 2.0, 3.0, -1.0, 0.5)>
    <InlineData(2.0, 1.5, 0.5, 0.0, 0.0)>
    Public Sub Impulses_AtABallCollision_AreEqualAndOpposite_AndMatchTheClosedForm(m1 As Double, u1 As Double, m2 As Double, u2 As Double, e As Double)
        Dim h As New PresenterHarness(Scenarios.HeadOn(m1, u1, m2, u2, e))
        h.P.SetShowImpulses(True)
        For i = 1 To 200
            h.P.Tick(1.0 / 60)
            If h.P.Impulses.Marks.Count >= 2 Then Exit For
        Next
        Dim marks = h.P.Impulses.Marks
        Assert.Equal(2, marks.Count)
        Dim sum = marks(0).Impulse + marks(1).Impulse
        Assert.True(sum.Length < 1.0E-12, $"Δp1 + Δp2 = {sum}")
        ' 1D collision: v1' = (m1 u1 + m2 u2 + m2 e (u2 − u1)) / (m1 + m2), so Δp1 = m1 m2 (1 + e)(u2 − u1) / (m1 + m2).
        Dim expected = m1 * m2 * (1 + e) * (u2 - u1) / (m1 + m2)
        Dim onFirst = marks.First(Function(k) k.Body.Id = "1")
        Assert.Equal(expected, onFirst.Impulse.X, 12)
        Assert.Equal(0.0, onFirst.Impulse.Y, 12)
        ' Drawn from the point of contact: between the two centres, on ball 1's rim.
        Dim b1 = h.P.World.Find("1"), b2 = h.P.World.Find("2")
        Assert.True(onFirst.IsLocated)
        Assert.InRange(onFirst.At.X, b1.Position.X, b2.Position.X)
    End Sub

    <Fact>
    Public Sub Impulse_AtAWall_IsTheWallsImpulse_TwiceTheMomentumAtE1()
        Dim h As New PresenterHarness(New World(4, 3, 0.0, 1.0))
        Dim ball = h.Ball(3.0, 1.5, 0.2, 1.5)
        h.P.World.SetVelocity(ball, New Vector(3, 0))
        h.P.SetShowImpulses(True)
        For i = 1 To 60
            h.P.Tick(1.0 / 60)
            If h.P.Impulses.Marks.Count >= 1 Then Exit For
        Next
        Dim marks = h.P.Impulses.Marks
        Assert.Single(marks)
        Assert.Null(marks(0).Other)
        Assert.Equal(WallSide.Right, marks(0).Wall)
        ' The wall reverses the ball: Δp = m (−v − v) = −2 m v.
        Assert.Equal(-2 * 1.5 * 3, marks(0).Impulse.X, 12)
        Assert.Equal(-2 * 1.5 * 3, ball.Mass * ball.Velocity.X - 1.5 * 3, 12)
        Assert.Equal(4.0, marks(0).At.X, 12) ' on the right wall
    End Sub

    <Fact>
    Public Sub Impulses_FadeOverOneSecond_AndAreBounded()
        Dim marks As New ImpulseMarks()
        Dim a As New Circle(New Vector(1, 1), 0.1, 2.0, id:="a")
        For i = 1 To 500
            marks.Record(New CollisionRecord(i, a, Nothing, WallSide.Left, CollisionKind.CircleWall, New Vector(-1, 0), New Vector(1, 0), Vector.Zero, Vector.Zero))
        Next
        Assert.Equal(ImpulseMarks.MaxMarks, marks.Marks.Count)
        Assert.Equal(500.0, marks.Marks(marks.Marks.Count - 1).Time) ' the newest kept
        Assert.Equal(New Vector(4, 0), marks.Marks(0).Impulse)
        marks.Age(0.25)
        Assert.Equal(0.75, ImpulseMarks.Opacity(marks.Marks(0)), 12)
        marks.Age(0.8)
        Assert.Empty(marks.Marks)
    End Sub

    <Fact>
    Public Sub Impulses_AreRecordedOnlyWhileShown()
        Dim h As New PresenterHarness(Scenarios.HeadOn(1, 2, 1, -2, 1))
        For i = 1 To 120
            h.P.Tick(1.0 / 60)
        Next
        Assert.True(h.P.Log.TotalSeen >= 1)
        Assert.Empty(h.P.Impulses.Marks)
    End Sub

    <Fact>
    Public Sub Traces_AreBounded_AndEndWhereTheBodyIs()
        Dim h As New PresenterHarness(New World(8, 5, 9.81, 1.0))
        Dim ball = h.Ball(2, 4)
        h.P.World.SetVelocity(ball, New Vector(1.5, 0))
        h.P.SetShowTraces(True)
        Assert.Contains("traces on", h.TraceLines)
        For i = 1 To 600
            h.P.Tick(PathTraces.SampleSeconds)
        Next
        Dim pts = h.P.Traces.Points(ball)
        Assert.Equal(PathTraces.Capacity, pts.Count)
        Assert.Equal(ball.CentreOfMass, pts(pts.Count - 1))
        ' Oldest first: the samples are the last Capacity frames, in order (x only grows between wall hits, so check the clock instead).
        Assert.NotEqual(pts(0), pts(pts.Count - 1))
        h.P.SetShowTraces(False)
        Assert.Equal(0, h.P.Traces.Count(ball))
    End Sub

    <Fact>
    Public Sub Traces_InAGas_FollowOnlyTheFirstBodies()
        Dim h As New PresenterHarness(Scenarios.ElasticGas(100))
        h.P.SetShowTraces(True)
        For i = 1 To 10
            h.P.Tick(1.0 / 60)
        Next
        Assert.Equal(PathTraces.MaxBodies, h.P.Traces.Bodies.Count)
        Assert.Same(h.P.World.Movables(0), h.P.Traces.Bodies(0))
        Assert.Equal(0, h.P.Traces.Count(h.P.World.Movables(PathTraces.MaxBodies)))
    End Sub

    <Fact>
    Public Sub Traces_OfADeletedBody_Go()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim a = h.Ball(2, 2), b = h.Ball(5, 2)
        h.P.SetShowTraces(True)
        h.P.Tick(0.1)
        Assert.True(h.P.Traces.Count(a) > 0)
        h.P.World.Remove(a)
        h.P.Tick(0.1)
        Assert.Equal(0, h.P.Traces.Count(a))
        Assert.True(h.P.Traces.Count(b) > 0)
    End Sub

    <Fact>
    Public Sub Toggles_AreTraced_AndTheCentreOfMassLineGivesItsNumbers()
        Dim h = Mixed()
        h.P.SetShowCentreOfMass(True)
        h.P.SetShowTotalMomentum(True)
        h.P.SetShowMomentaDiagram(True)
        Assert.True(h.P.ShowCentreOfMass AndAlso h.P.ShowTotalMomentum AndAlso h.P.ShowMomentaDiagram)
        Assert.Contains("centre of mass on", h.TraceLines)
        Assert.Contains("total momentum on", h.TraceLines)
        Assert.Contains("momenta diagram on", h.TraceLines)
        Dim s = h.P.Momentum
        Assert.Contains("centre of mass at " & Units.Pair(s.CentreOfMass, 4) & " m v " & Units.Pair(s.Velocity, 4) & " m/s total mass 3.9000 kg Σp " & Units.Pair(s.Momentum, 4) & " kg·m/s", h.TraceLines)
        h.P.SetShowCentreOfMass(False)
        Assert.False(h.P.ShowCentreOfMass)
        Assert.Contains("centre of mass off", h.TraceLines)
    End Sub

    <Fact>
    Public Sub Views_StayOnAcrossANewSceneAndReset_ButTheirHistoryGoes()
        Dim h As New PresenterHarness(Scenarios.HeadOn(1, 2, 1, -2, 1))
        h.P.SetShowTraces(True)
        h.P.SetShowImpulses(True)
        For i = 1 To 120
            h.P.Tick(1.0 / 60)
        Next
        Assert.NotEmpty(h.P.Traces.Bodies)
        h.P.Reset()
        Assert.True(h.P.ShowTraces AndAlso h.P.ShowImpulses)
        Assert.Empty(h.P.Traces.Bodies)
        Assert.Empty(h.P.Impulses.Marks)
    End Sub

    <Fact>
    Public Sub WallsOff_LetsABallLeave_AndRestartBringsBackTheScenesWalls()
        Dim h As New PresenterHarness(New World(4, 3, 0.0, 1.0))
        Dim ball = h.Ball(3.0, 1.5, 0.2, 1.0, "b")
        h.P.World.SetVelocity(ball, New Vector(3, 0))
        h.P.SetWalls(False)
        Assert.False(h.P.World.Walls)
        Assert.False(h.P.HasWalls)
        Assert.Contains("walls off", h.TraceLines)
        For i = 1 To 60
            h.P.Tick(1.0 / 60)
        Next
        ' Straight on through where the wall was: x = 3 + 3 t.
        Assert.Equal(3.0 + 3.0 * h.P.World.Time, h.P.World.Find("b").Position.X, 9)
        Assert.True(h.P.World.Find("b").Position.X > 4.2)
        h.P.Restart()
        Assert.True(h.P.World.Walls)
        Assert.Equal(3.0, h.P.World.Find("b").Position.X, 12)
    End Sub

    <Fact>
    Public Sub WallsOn_BringsABallThatLeftBackInside()
        Dim w As New World(4, 3, 0.0, 1.0, walls:=False)
        w.Add(New Circle(New Vector(6, 1.5), 0.2, 1.0, New Vector(1, 0), "b"))
        Dim h As New PresenterHarness(w)
        h.P.SetWalls(True)
        Assert.True(h.P.World.Walls)
        Dim b = h.P.World.Find("b")
        Assert.InRange(b.Position.X, 0.2, 3.8)
        Assert.Contains("walls on", h.TraceLines)
    End Sub
End Class
