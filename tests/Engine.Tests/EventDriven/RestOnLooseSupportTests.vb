Option Strict On
Imports PhysicsEngine
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>
''' A ball settling on two balls that stand on a frictionless floor. Its weight pushes them apart along the
''' contact normals; the floor pushes only upwards, so unless something holds them from the side (a wall, a
''' neighbour) they slide apart and the ball drops between them to the floor. Held from the side, the three
''' are at rest and sleep.
''' </summary>
Public Class RestOnLooseSupportTests
    ''' <summary>
    ''' tests/cases/event-ball-asleep-in-loose-vee.json: two 1 kg balls (r = 5 cm) on the floor 3 cm apart, a
    ''' third dropped onto the V between them (e = 0.3). It used to sleep in the V at y = 0.126 m, the two
    ''' below never moving. At 5 s it lies on the floor.
    ''' </summary>
    <Fact>
    Public Sub BallDroppedIntoTheVOfTwoLooseBalls_PushesThemApart_AndReachesTheFloor()
        AssertTopEndsOnTheFloor(SceneFile.LoadFile(TestRepo.CaseFile("event-ball-asleep-in-loose-vee.json")))
    End Sub

    ''' <summary>The same with other restitutions and the drop a little off the V's centre (m).</summary>
    <Theory>
    <InlineData(0.0, 0.0)>
    <InlineData(0.003, 0.3)>
    <InlineData(-0.01, 0.6)>
    Public Sub BallDroppedIntoTheVOfTwoLooseBalls_ReachesTheFloor_WhateverTheOffset(offset As Double, restitution As Double)
        Dim w As New World(1, 1, 9.81, restitution)
        w.Add(New Circle(New Vector(0.435, 0.05), 0.05, 1, id:="left"))
        w.Add(New Circle(New Vector(0.565, 0.05), 0.05, 1, id:="right"))
        w.Add(New Circle(New Vector(0.5 + offset, 0.3), 0.05, 1, id:="top"))
        AssertTopEndsOnTheFloor(w)
    End Sub

    ''' <summary>
    ''' The two below touch the side walls of a box 26 cm wide, so the walls hold them from the side: the ball
    ''' comes to rest in the V where it touches both, (0.13, 0.05 + √(0.1² − 0.08²)) = (0.13, 0.11) m, and the
    ''' three sleep there.
    ''' </summary>
    <Fact>
    Public Sub BallDroppedIntoTheVOfTwoBallsHeldByWalls_SleepsInTheV()
        Dim left As Circle = Nothing, right As Circle = Nothing, top As Circle = Nothing
        Dim w = WalledV(left, right, top)
        Dim solver = EventSolverTestKit.UseEventSolver(w)
        EventSolverTestKit.RunChecked(w, 5, 0.5, EnergyLaw.NeverGained(0.000000001), maxOverlap:=0.000000001)
        Assert.True(solver.IsAsleep(top), "the top ball is still awake at t = 5 s")
        Assert.True(Math.Abs(top.Position.X - 0.13) <= 0.0001 AndAlso Math.Abs(top.Position.Y - 0.11) <= 0.0001,
                    $"the top ball is at {top.Position} m at t = 5 s, not in the V at (0.13, 0.11)")
        Assert.Equal(0.05, left.Position.X, 12)
        Assert.Equal(0.21, right.Position.X, 12)
    End Sub

    ''' <summary>
    ''' The same V held by the walls: asleep, the ball touches both balls below exactly, at (0.13, 0.11) m to 10⁻¹² m,
    ''' so the forces that hold it are there to be found: each ball's free-body diagram balances (its acceleration
    ''' below 10⁻⁹ m/s²). Put to sleep where it merely came within 10⁻³ of its size of them, it was 16 µm off one
    ''' and its diagram showed only its weight and one push, an acceleration of 7.8 m/s² for a ball at rest.
    ''' </summary>
    <Fact>
    Public Sub BallAsleepInTheVOfTwoBallsHeldByWalls_TouchesBothExactly_AndItsForcesBalance()
        Dim left As Circle = Nothing, right As Circle = Nothing, top As Circle = Nothing
        Dim w = WalledV(left, right, top)
        Dim solver = EventSolverTestKit.UseEventSolver(w)
        w.Advance(5)
        Assert.True(solver.IsAsleep(top), "the top ball is still awake at t = 5 s")
        Assert.Equal(0.13, top.Position.X, 12)
        Assert.Equal(0.11, top.Position.Y, 12)
        For Each b In {left, right, top}
            Dim a = BodyForces.Diagram(w, b).Acceleration
            Assert.True(a.Length <= 0.000000001, $"{b.Id}: forces sum to m × {a} m/s² at rest")
        Next
    End Sub

    ''' <summary>
    ''' Two 1 kg balls (r = 5 cm) on the floor of a box 26 cm wide, each touching a wall, and a third dropped from 0.3 m
    ''' onto the V between them (e = 0.3).
    ''' </summary>
    Private Shared Function WalledV(ByRef left As Circle, ByRef right As Circle, ByRef top As Circle) As World
        Dim w As New World(0.26, 1, 9.81, 0.3)
        left = New Circle(New Vector(0.05, 0.05), 0.05, 1, id:="left")
        right = New Circle(New Vector(0.21, 0.05), 0.05, 1, id:="right")
        top = New Circle(New Vector(0.13, 0.3), 0.05, 1, id:="top")
        w.Add(left)
        w.Add(right)
        w.Add(top)
        Return w
    End Function

    ''' <summary>Runs the scene 5 s (energy never gained, no overlap), then asserts that the ball "top" lies on the floor (to 10⁻⁹ m).</summary>
    Private Shared Sub AssertTopEndsOnTheFloor(w As World)
        EventSolverTestKit.RunEventSolverChecked(w, 5, 0.5, EnergyLaw.NeverGained(0.000000001), maxOverlap:=0.000000001)
        Dim top = w.Circles.Single(Function(c) c.Id = "top")
        Assert.True(Math.Abs(top.Position.Y - top.Radius) <= 0.000000001, $"the top ball is at y = {top.Position.Y} m at t = 5 s, not on the floor")
    End Sub
End Class
