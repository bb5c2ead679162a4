Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' The grid's lanes copy each body's motion for the vectorised pair test. A copy that lags its body
''' would feed wrong predictions without any other sign, so these scenes run with every lane checked
''' against its body after every event: piles that settle and sleep and wake, a ball that slides
''' off a table, a gas crowded enough to overflow the lanes, and every kind of change mid-run. The
''' vectorised and the one-at-a-time pair tests must also agree collision for collision.
''' </summary>
Public Class LaneTests
    Private Shared Function Checked(w As World) As EventDrivenSolver
        Dim s = UseEventSolver(w)
        s.CheckLanesEveryEvent = True
        Return s
    End Function

    <Fact>
    Public Sub Pile_SettlingSleepingAndWaking_KeepsEveryLaneInStep()
        Dim w = Scenarios.Pile(80, 0.3)
        Dim s = Checked(w)
        w.Advance(4.0)
        ' Wake part of it: a fast ball dropped onto the settled pile.
        w.Add(New Circle(New Vector(w.Width / 2, w.Height - 0.1), 0.05, 1.0, New Vector(0.3, -6)))
        w.Advance(1.0)
        Assert.True(s.EventCount > 1000)
        Assert.True(DeepestOverlap(w) <= 1.0E-6)
    End Sub

    <Fact>
    Public Sub BallSlidingOffATable_KeepsEveryLaneInStep()
        Dim w As New World(6, 4, 9.81, 0.5)
        w.Add(New Rectangle(New Vector(0, 0), 2, 1, "table"))
        w.Add(New Circle(New Vector(1.9, 1.05), 0.05, 1.0, New Vector(0.2, 0), "slow"))
        w.Add(New Circle(New Vector(1.0, 1.05), 0.05, 1.0, New Vector(2.0, 0), "fast"))
        w.Add(New Circle(New Vector(3.0, 0.05), 0.05, 1.0, New Vector(-0.5, 0), "floor"))
        Checked(w)
        w.Advance(3.0)
        Assert.True(DeepestOverlap(w) <= 1.0E-9)
    End Sub

    <Fact>
    Public Sub CrowdedCells_OverflowTheLanes_AndKeepEveryLaneInStep()
        ' A gas with a tight cluster of small balls in one corner: that cell holds far more than
        ' its four lanes, and the cluster spreads through its neighbours' overflow as it explodes.
        Dim w As New World(1.0, 1.0, 0.0, 1.0)
        Dim rng As New Random(3)
        For k = 0 To 99
            Dim p = New Vector((k Mod 10 + 0.5) / 10, (k \ 10 + 0.5) / 10)
            w.Add(New Circle(p, 0.012, 1.0, New Vector(rng.NextDouble() * 2 - 1, rng.NextDouble() * 2 - 1)))
        Next
        For k = 0 To 15
            Dim p = New Vector(0.01 + 0.013 * (k Mod 4), 0.01 + 0.013 * (k \ 4))
            w.Add(New Circle(p, 0.006, 1.0, New Vector(rng.NextDouble() * 2 - 1, rng.NextDouble() * 2 - 1)))
        Next
        Dim s = Checked(w)
        w.Advance(0.001)
        Assert.True(s.OverflowCount > 0, "no cell overflowed its lanes")
        Dim e0 = w.KineticEnergy()
        w.Advance(8.0)
        Assert.True(w.CollisionCount > 1000)
        Assert.True(Math.Abs(w.KineticEnergy() - e0) <= 1.0E-9 * e0)
        Assert.True(DeepestOverlap(w) <= 1.0E-9)
    End Sub

    <Fact>
    Public Sub ChangesMidRun_KeepEveryLaneInStep()
        Dim w = Scenarios.ElasticGas(120, 0.2)
        w.Gravity = 3.0
        Checked(w)
        w.Advance(0.5)
        Dim a = DirectCast(w.Circles(5), Circle), b = DirectCast(w.Circles(50), Circle)
        w.ApplyImpulse(a, New Vector(0.02, 0.01))
        w.SetVelocity(b, New Vector(-1, 2))
        w.Advance(0.3)
        w.BeginDrag(a)
        w.DragTo(New Vector(w.Width / 2, w.Height / 2))
        w.Advance(0.3)
        w.EndDrag(Vector.Zero)
        w.Restitution = 0.7
        w.Resize(w.Width * 0.9, w.Height * 0.9)
        w.Add(New Circle(New Vector(0.05, w.Height - 0.05), 0.01, 1.0, New Vector(1, 0)))
        w.Remove(b)
        w.Advance(1.0)
        Assert.True(DeepestOverlap(w) <= 1.0E-9)
    End Sub

    <Theory>
    <InlineData(1, False)>
    <InlineData(2, False)>
    <InlineData(1, True)>
    Public Sub VectorAndScalarPairTests_GiveTheSameCollisions(seed As Integer, pile As Boolean)
        ' A gas (every pair on the hot path), or a pile (resting, sleeping and waking balls too).
        Dim sequences = New List(Of (Double, Integer, Integer))(1) {}
        For pass = 0 To 1
            Dim w = If(pile, Scenarios.Pile(120, 0.3, seed), Scenarios.ElasticGas(300, 0.3, seed:=seed))
            Dim s = UseEventSolver(w)
            s.VectorScan = pass = 0
            s.CellOccupancy = 2.0 ' the same grid for both (each would choose its own)
            Dim index = w.Circles.Select(Function(c, k) (c, k)).ToDictionary(Function(x) x.c, Function(x) x.k)
            Dim seen As New List(Of (Double, Integer, Integer))()
            w.CollisionListener = Sub(r) If seen.Count < 3000 Then seen.Add((r.Time, index(DirectCast(r.A, Circle)), If(r.B Is Nothing, -1, index(DirectCast(r.B, Circle)))))
            While seen.Count < 3000
                w.Advance(0.05)
            End While
            sequences(pass) = seen
        Next
        ' Same arithmetic lane by lane: the same collisions, at the same times to the last digit.
        Assert.Equal(sequences(1), sequences(0))
    End Sub
End Class
