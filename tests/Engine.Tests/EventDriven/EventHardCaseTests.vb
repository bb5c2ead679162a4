Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>The shared hard cases: coincident centres, spawn overlaps, mixed sizes, extreme gravity.</summary>
Public Class EventHardCaseTests
    ''' <summary>
    ''' Walls are only tested from the cells along them: a ball starting in the middle of a gridded
    ''' box must pick the wall up when it crosses into the last cell, and bounce.
    ''' </summary>
    <Theory>
    <InlineData(-2.0, 0.0)>
    <InlineData(2.0, 0.0)>
    <InlineData(0.0, -2.0)>
    <InlineData(0.0, 2.0)>
    Public Sub BallFromTheMiddle_BouncesOffEachWall(vx As Double, vy As Double)
        Dim w As New World(1.0, 1.0, 0.0, 1.0)
        ' Still balls on a lattice, clear of the middle row and column, so the grid has many cells.
        For i = 1 To 9
            For j = 1 To 9
                If i <> 5 AndAlso j <> 5 Then w.Add(New Circle(New Vector(i / 10, j / 10), 0.01, 1.0, Vector.Zero))
            Next
        Next
        Dim ball = New Circle(New Vector(0.5, 0.5), 0.01, 1.0, New Vector(vx, vy))
        w.Add(ball)
        UseEventSolver(w)
        w.Advance(0.3)
        ' It reaches the wall (0.49 m away) at 0.245 s and comes 0.055 s × 2 m/s back.
        Dim along = If(vx <> 0, ball.Position.X, ball.Position.Y)
        Dim expected = If(vx + vy < 0, 0.01 + 0.11, 0.99 - 0.11)
        Assert.Equal(expected, along, 9)
        Assert.Equal(-vx, ball.Velocity.X, 12)
        Assert.Equal(-vy, ball.Velocity.Y, 12)
    End Sub

    ''' <summary>
    ''' A centre a hair on the wrong side of its cell's boundary: with 12 columns over 1 m,
    ''' 0.49999999999999994 / (1/12) rounds to 6, so the ball is put in column 6, which starts at 0.5.
    ''' Moving left, it must still leave that cell (at once), or its searches stay centred on
    ''' column 6 and it passes through a ball two columns away.
    ''' </summary>
    <Fact>
    Public Sub BallRegisteredAHairBeyondItsCell_StillCrossesAndHitsWhatIsAhead()
        Dim w As New World(1.0, 1.0, 0.0, 1.0)
        Dim mover = New Circle(New Vector(0.49999999999999994, 0.5), 0.01, 1.0, New Vector(-1, 0))
        Dim target = New Circle(New Vector(0.2, 0.5), 0.01, 1.0, Vector.Zero)
        w.Add(mover)
        w.Add(target)
        Dim s = UseEventSolver(w)
        s.CellOccupancy = 0.0128 ' cells of 0.08 m: 12 columns of 1/12 m
        w.Advance(0.3)
        ' Equal masses, e = 1, head on: they exchange velocities at 0.28 s.
        Assert.Equal(1, w.CollisionCount)
        Assert.Equal(0.0, mover.Velocity.X, 12)
        Assert.Equal(-1.0, target.Velocity.X, 12)
    End Sub

    <Fact>
    Public Sub CoincidentCentres_ArePushedApart_WithoutNaN()
        Dim w As New World(4, 4, 9.81, 0.8)
        For k = 1 To 3
            w.Add(New Circle(New Vector(2, 2), 0.2, 1.0))
        Next
        UseEventSolver(w)
        w.Advance(2.0)
        For Each c In w.Circles
            Assert.True(c.Position.IsFinite AndAlso c.Velocity.IsFinite)
        Next
        Assert.True(DeepestOverlap(w) <= 1.0E-9)
    End Sub

    <Fact>
    Public Sub SpawnOverlap_WithARectangleAndACircle_IsResolved()
        Dim w As New World(4, 4, 9.81, 0.5)
        w.Add(New Rectangle(New Vector(1, 0), 2, 1))
        w.Add(New Circle(New Vector(2, 0.95), 0.2, 1.0))
        w.Add(New Circle(New Vector(2.1, 1.1), 0.2, 1.0))
        UseEventSolver(w)
        w.Advance(3.0)
        Assert.True(DeepestOverlap(w) <= 1.0E-9)
    End Sub

    <Theory>
    <InlineData(0.0)>
    <InlineData(100.0)>
    Public Sub TinyAndHugeCircles_InOneScene_NeverOverlap(g As Double)
        Dim w As New World(10, 10, g, 0.9)
        w.Add(New Circle(New Vector(5, 5), 2.0, 100.0, New Vector(1, 0.5), "big"))
        Dim rng As New Random(11)
        For k = 1 To 60
            w.Add(New Circle(New Vector(0.5 + rng.NextDouble() * 9, 0.5 + rng.NextDouble() * 2), 0.001, 0.001,
                             New Vector(rng.NextDouble() * 4 - 2, rng.NextDouble() * 4 - 2)))
        Next
        w.Add(Circle.CreateFixed(New Vector(8, 8), 0.5))
        Dim solver = UseEventSolver(w)
        solver.MaxEventsPerAdvance = 2000000
        RunChecked(w, 3, 0.3, maxOverlap:=1.0E-9)
        For Each c In w.Circles
            Assert.True(c.Position.IsFinite AndAlso c.Velocity.IsFinite)
        Next
    End Sub

    <Fact>
    Public Sub Demo_RunsWithoutOverlap()
        RunEventSolverChecked(Scenarios.Demo(), 10, 0.5, maxOverlap:=1.0E-9)
    End Sub
End Class
