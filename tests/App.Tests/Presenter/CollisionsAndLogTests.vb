Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>Objectives 2 and 8: collisions through the presenter, the tables and the collision log.</summary>
Public Class CollisionsAndLogTests
    Private Shared Function HeadOnHarness(e As Double) As PresenterHarness
        Dim h As New PresenterHarness(Scenarios.HeadOn(1.0, 2.0, 3.0, -1.0, e))
        For k = 1 To 200
            h.P.Tick(1 / 60.0)
        Next
        Return h
    End Function

    <Fact>
    Public Sub HeadOn_Elastic_LogShowsMomentumAndEnergyConserved()
        Dim h = HeadOnHarness(1.0)
        Dim entry = Enumerable.Range(0, h.P.Log.Count).Select(Function(i) h.P.Log(i)).First(Function(x) x.IsPair)
        Assert.Equal(entry.MomentumBefore.X, entry.MomentumAfter.X, 6)
        Assert.Equal(-1.0, entry.MomentumBefore.X, 6)
        Assert.Equal(entry.EnergyBefore, entry.EnergyAfter, 6)
        Dim cells = entry.Cells()
        Assert.Equal(CollisionLogEntry.Headers.Count, cells.Length)
        Assert.Equal("3.50 → 3.50", cells(3))
        Assert.Equal("0%", cells(4))
        Assert.Equal("(−1.00, 0) → (−1.00, 0)", cells(5))
        Assert.Equal("1 ↔ 2", cells(1))
        Assert.Equal(-1.0, h.P.World.Momentum().X, 6)
    End Sub

    <Fact>
    Public Sub HeadOn_Inelastic_LogShowsEnergyLost_MomentumKept()
        Dim h = HeadOnHarness(0.5)
        Dim entry = Enumerable.Range(0, h.P.Log.Count).Select(Function(i) h.P.Log(i)).First(Function(x) x.IsPair)
        Assert.Equal(entry.MomentumBefore.X, entry.MomentumAfter.X, 6)
        ' The pair loses ½ μ (1 − e²) u² with μ = m1 m2 / (m1 + m2) = 0.75 kg and closing speed u = 3 m/s:
        ' 2.53125 J of its 3.5 J, leaving 0.96875 J.
        Assert.Equal(3.5, entry.EnergyBefore, 6)
        Assert.Equal(0.96875, entry.EnergyAfter, 4)
        Assert.Equal("72%", entry.Cells()(4))
    End Sub

    <Fact>
    Public Sub Log_WallHits_SayMomentumIsNotConserved()
        Dim h As New PresenterHarness(New World(2, 2, 0.0, 1.0))
        Dim ball = h.Ball(1, 1)
        h.P.World.SetVelocity(ball, New Vector(5, 0))
        For k = 1 To 30
            h.P.Tick(1 / 60.0)
        Next
        Assert.True(h.P.Log.Count > 0)
        Dim entry = h.P.Log(h.P.Log.Count - 1)
        Assert.Equal("wall:right", entry.BName)
        Assert.False(entry.IsPair)
        Assert.Contains("p not conserved", entry.Text, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub Balls_NeverLeaveTheContainer()
        Dim h As New PresenterHarness(Scenarios.ElasticGas(40, 0.2, 0.05))
        For k = 1 To 120
            h.P.Tick(1 / 60.0)
        Next
        For Each c In h.P.World.Circles
            Assert.InRange(c.Position.X, c.Radius - 0.001, h.P.World.Width - c.Radius + 0.001)
            Assert.InRange(c.Position.Y, c.Radius - 0.001, h.P.World.Height - c.Radius + 0.001)
        Next
    End Sub

    <Fact>
    Public Sub Log_StaysBounded_AndSummarisesBusyFrames()
        Dim h As New PresenterHarness(Scenarios.ElasticGas(150, 0.4, 0.05))
        ' A hot gas: five times the scenario's speeds, so that many collisions fall in each frame whatever the solver.
        For Each c In h.P.World.Circles
            h.P.World.SetVelocity(c, c.Velocity * 5)
        Next
        For k = 1 To 60
            h.P.Tick(1 / 60.0)
        Next
        Assert.True(h.P.Log.TotalSeen > CollisionLog.Capacity, $"only {h.P.Log.TotalSeen} collisions")
        Assert.True(h.P.Log.Count <= CollisionLog.Capacity)
        Assert.Contains(Enumerable.Range(0, h.P.Log.Count).Select(Function(i) h.P.Log(i)), Function(x) x.SkippedCount > 0)
    End Sub

    <Fact>
    Public Sub Log_NewestFirst()
        Dim log As New CollisionLog()
        Dim a As New Circle(New Vector(0, 0), 0.1, 1)
        For k = 1 To 5
            Dim other As New Circle(New Vector(1, 0), 0.1, 1, id:="o" & k)
            log.Record(New CollisionRecord(k, a, other, WallSide.Left, CollisionKind.CircleCircle, New Vector(-1, 0), New Vector(1, 0), Vector.Zero, Vector.Zero), Nothing)
            log.EndFrame()
        Next
        Assert.Equal(5.0, log(0).Time)
        Assert.Equal(1.0, log(4).Time)
        Dim v0 = log.Version
        log.Clear()
        Assert.Equal(0, log.Count)
        Assert.True(log.Version > v0)
    End Sub

    <Fact>
    Public Sub Tables_ShowEveryColumnWithUnits_InSignificantFigures()
        Assert.Contains("|v| (m/s)", BodyTable.Circles.Headers)
        Assert.Contains("ρ (kg/m²)", BodyTable.Circles.Headers)
        Dim c As New Circle(New Vector(1, 2), 0.5, 2, New Vector(3, 4), "b1") With {.Color = "#123456"}
        Dim row = BodyTable.Circles.Cells(BodyRow.Capture(c))
        Assert.Equal("b1|#123456|1.00|2.00|3.00|4.00|5.00|2.00|0.500|2.55", String.Join("|", row))
        Dim r = BodyTable.Rectangles.Cells(BodyRow.Capture(New Rectangle(New Vector(1, 0), 2, 0.5, "t")))
        Assert.Equal("2.00 × 0.500", r(8))
        Assert.Equal("fixed", r(7))
        Assert.Equal(BodyTable.Rectangles.Headers.Count, r.Length)
        Assert.True(BodyTable.Circles.Lists(c))
        Assert.False(BodyTable.Rectangles.Lists(c))
    End Sub
End Class
