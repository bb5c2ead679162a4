Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>The world's own rules: ids, density, impulses, resizing.</summary>
Public Class WorldTests
    <Fact>
    Public Sub Density_IsMassOverArea()
        Dim c As New Circle(New Vector(1, 1), 0.5, 2.0)
        Assert.Equal(2.0 / (Math.PI * 0.25), c.Density, 12)
    End Sub

    <Fact>
    Public Sub Add_GivesEmptyIdsTheNextNumber_AndRejectsARepeatedId()
        Dim w As New World(4, 4)
        w.Add(New Circle(New Vector(1, 1), 0.1, 1.0))
        w.Add(New Circle(New Vector(2, 1), 0.1, 1.0, id:="b"))
        Assert.Equal("1", w.Bodies(0).Id)
        Assert.Throws(Of ArgumentException)(Sub() w.Add(New Circle(New Vector(3, 1), 0.1, 1.0, id:="b")))
        Assert.Equal(2, w.Bodies.Count)
    End Sub

    <Fact>
    Public Sub Replace_PutsTheNewBodyInTheOldOnesPlace_AndRefusesAMismatch()
        Dim w As New World(10, 10, 9.81, 0.5) With {.Solver = New EventDrivenSolver()}
        Dim table = New Rectangle(New Vector(2, 1), 2, 1, "table")
        Dim peg = Circle.CreateFixed(New Vector(5, 5), 0.2, "peg")
        Dim ball = New Circle(New Vector(7, 7), 0.3, 1.0)
        w.Add(table)
        w.Add(peg)
        w.Add(ball)
        Dim moved = Circle.CreateFixed(New Vector(6, 2), 0.2, "peg")
        w.Replace(peg, moved)
        Assert.Equal({"table", "peg", ball.Id}, w.Bodies.Select(Function(b) b.Id).ToArray())
        Assert.Same(moved, w.Circles(0))
        Assert.Same(moved, w.Bodies(1))
        Dim slid = New Rectangle(New Vector(3, 1), 2, 1, "table")
        w.Replace(table, slid)
        Assert.Same(slid, w.Rectangles(0))
        Assert.Same(slid, w.Bodies(0))
        ' The engine still runs with the moved bodies (a fixed body's change rebuilds the solver).
        w.Advance(0.1)
        Assert.Equal(6.0, moved.Position.X)
        Assert.Throws(Of ArgumentException)(Sub() w.Replace(peg, Circle.CreateFixed(New Vector(1, 1), 0.2, "peg")))
        Assert.Throws(Of ArgumentException)(Sub() w.Replace(moved, New Rectangle(New Vector(6, 2), 1, 1, "peg")))
        Assert.Throws(Of ArgumentException)(Sub() w.Replace(moved, Circle.CreateFixed(New Vector(6, 2), 0.2, "other")))
        Assert.Throws(Of ArgumentException)(Sub() w.Replace(moved, ball))
    End Sub

    <Fact>
    Public Sub ApplyImpulse_MovesAHeavyBallLess()
        Dim w As New World(10, 10, 0)
        Dim light As New Circle(New Vector(2, 2), 0.1, 1.0)
        Dim heavy As New Circle(New Vector(5, 5), 0.1, 4.0)
        w.Add(light)
        w.Add(heavy)
        w.ApplyImpulse(light, New Vector(2, 0))
        w.ApplyImpulse(heavy, New Vector(2, 0))
        Assert.Equal(2.0, light.Velocity.X, 15)
        Assert.Equal(0.5, heavy.Velocity.X, 15)
    End Sub

    <Fact>
    Public Sub Resize_FoldsCirclesBackInside_AsFarInAsTheyWereOut()
        Dim w As New World(10, 10, 0)
        Dim nearWall As New Circle(New Vector(4.2, 2.8), 0.5, 1.0)
        Dim farOut As New Circle(New Vector(9, 9), 0.5, 1.0)
        w.Add(nearWall)
        w.Add(farOut)
        w.Resize(4, 3)
        ' Centres may range over 0.5 … 3.5 m across and 0.5 … 2.5 m up: 0.7 m beyond the right
        ' limit comes back 0.7 m inside it, 0.3 m above the top limit 0.3 m below it.
        Assert.Equal(2.8, nearWall.Position.X, 12)
        Assert.Equal(2.2, nearWall.Position.Y, 12)
        Assert.InRange(farOut.Position.X, 0.5, 3.5)
        Assert.InRange(farOut.Position.Y, 0.5, 2.5)
    End Sub

    <Fact>
    Public Sub Resize_AStripOfCirclesBeyondTheNewWall_CanBeSeparated()
        ' 60 circles 4 cm wide in the strip x = 1.2 … 1.9 m: clamped onto the new wall they would
        ' need a 2.4 m line in a 1 m high box, and no pushing along that line could part them.
        Dim w As New World(2, 1, 0)
        For k = 0 To 59
            w.Add(New Circle(New Vector(1.2 + 0.7 * (k Mod 6) / 5, 0.05 + 0.09 * (k \ 6)), 0.02, 1.0))
        Next
        w.Resize(1.0, 1.0)
        Assert.True(OverlapResolver.Resolve(w) <= 1.0E-12)
        For Each c In w.Circles
            Assert.InRange(c.Position.X, 0.02, 0.98)
        Next
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
    Public Sub Drag_PushesTheBallItTouches_AndIsNotPushedBack(solver As String)
        Dim w As New World(4.0, 2.0, 9.81, 0.5)
        Dim hand As New Circle(New Vector(1.0, 0.2), 0.2, 1.0, id:="hand")
        Dim heavy As New Circle(New Vector(1.5, 0.2), 0.2, 1000.0, id:="heavy")
        w.Add(hand)
        w.Add(heavy)
        TestSolvers.Run(w, solver)
        w.BeginDrag(hand)
        For i = 1 To 30
            w.DragTo(New Vector(1.0 + 0.05 * i, 0.2))
            w.Advance(1.0 / 60)
            ' Infinite mass: the dragged circle is exactly where it was led, however heavy the ball it pushes.
            Assert.Equal(1.0 + 0.05 * i, hand.Position.X, 12)
            Assert.Equal(0.2, hand.Position.Y, 12)
            Assert.True(SceneChecks.AllFinite(w))
        Next
        Assert.True(heavy.Position.X >= hand.Position.X + 0.4 - 1.0E-9, $"the pushed ball is at {heavy.Position.X}, inside the hand at {hand.Position.X}")
        Assert.True(heavy.Velocity.X > 0)
        Assert.Equal(0.2, hand.Position.Y, 12) ' no gravity while dragged

        ' Released, it drops back into the simulation: gravity acts on it again.
        w.DragTo(New Vector(2.5, 1.5))
        w.Advance(0.1)
        w.EndDrag(Vector.Zero)
        w.Advance(0.2)
        Assert.Equal(1.5 - 0.5 * 9.81 * 0.2 * 0.2, hand.Position.Y, 2)
        Assert.True(hand.Velocity.Y < -1.9)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
    Public Sub SameImpulse_MovesTheHeavierBallLess(solver As String)
        Dim w As New World(10, 10, 0)
        Dim light As New Circle(New Vector(2, 2), 0.1, 1.0)
        Dim heavy As New Circle(New Vector(2, 5), 0.1, 4.0)
        w.Add(light)
        w.Add(heavy)
        TestSolvers.Run(w, solver)
        w.Advance(0.1)
        w.ApplyImpulse(light, New Vector(2, 0))
        w.ApplyImpulse(heavy, New Vector(2, 0))
        w.Advance(1.0)
        ' F = ma over the push: Δv = J/m, so in 1 s the 1 kg ball goes 2 m and the 4 kg ball 0.5 m.
        Assert.Equal(4.0, light.Position.X, 9)
        Assert.Equal(2.5, heavy.Position.X, 9)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
    Public Sub ChangingGravityWhileRunning_TakesEffectAtOnce(solver As String)
        Dim w As New World(20, 20, 9.81)
        Dim ball As New Circle(New Vector(10, 15), 0.1, 1.0, New Vector(1, 0))
        w.Add(ball)
        TestSolvers.Run(w, solver)
        w.Advance(0.5)
        Dim v = ball.Velocity, p = ball.Position
        w.Gravity = 0
        w.Advance(0.5)
        ' No gravity: straight on at the velocity it had (a stale Verlet history would still pull it down).
        Assert.Equal(v.Y, ball.Velocity.Y, 9)
        Assert.Equal(p.Y + 0.5 * v.Y, ball.Position.Y, 9)
        w.Gravity = 100
        w.Advance(0.1)
        Assert.Equal(v.Y - 10.0, ball.Velocity.Y, 9)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
    Public Sub ChangingRestitutionWhileRunning_AppliesToTheNextBounce(solver As String)
        Dim w As New World(4.0, 2.0, 0.0, 1.0)
        Dim ball As New Circle(New Vector(2.0, 1.0), 0.1, 1.0, New Vector(2.0, 0.0))
        w.Add(ball)
        TestSolvers.Run(w, solver)
        w.Advance(1.0) ' bounces off the right wall with e = 1
        Assert.Equal(-2.0, ball.Velocity.X, 9)
        w.Restitution = 0.25
        w.Advance(2.0) ' and off the left wall with e = 0.25
        Assert.Equal(0.5, ball.Velocity.X, 9)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
    Public Sub SetVelocityAndSetPosition_WhileRunning_TakeEffectExactly(solver As String)
        Dim w As New World(20, 20, 0.0)
        Dim ball As New Circle(New Vector(5, 5), 0.1, 1.0, New Vector(1, 1))
        w.Add(ball)
        TestSolvers.Run(w, solver)
        w.Advance(0.3)
        w.SetVelocity(ball, New Vector(-2, 0))
        w.Advance(0.5)
        Assert.Equal(New Vector(5.3 - 1.0, 5.3), New Vector(Math.Round(ball.Position.X, 9), Math.Round(ball.Position.Y, 9)))
        ' A jump must not be read as a velocity (x − x_prev would be huge for Verlet).
        w.SetPosition(ball, New Vector(10, 10))
        w.Advance(0.5)
        Assert.Equal(-2.0, ball.Velocity.X, 9)
        Assert.Equal(0.0, ball.Velocity.Y, 9)
        Assert.Equal(9.0, ball.Position.X, 9)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
    Public Sub AddingAndRemovingBodiesWhileRunning_Works(solver As String)
        Const g = 9.81
        Dim w As New World(20, 20, g, 0.5)
        Dim first As New Circle(New Vector(5, 15), 0.1, 1.0, id:="first")
        w.Add(first)
        TestSolvers.Run(w, solver)
        w.Advance(0.25)
        Dim added As New Circle(New Vector(10, 15), 0.1, 2.0, New Vector(1, 2), "added")
        w.Add(added)
        w.Advance(0.5)
        ' The newcomer flies as s = ut + ½at² from the moment it was added (Euler within its O(dt) error).
        Dim tolerance = If(solver = "euler", g * w.Solver.TimeStep.Value, 1.0E-9)
        Assert.Equal(10.5, added.Position.X, 9)
        Assert.InRange(added.Position.Y - (15 + 2 * 0.5 - 0.5 * g * 0.25), -tolerance, tolerance)
        Assert.Equal(2 - g * 0.5, added.Velocity.Y, 9)
        Assert.True(w.Remove(first))
        Dim frozen = first.Position
        w.Advance(0.25)
        Assert.Equal(frozen, first.Position)
        Assert.Single(w.Circles)
        Assert.Equal(2 - g * 0.75, added.Velocity.Y, 9)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.All), MemberType:=GetType(TestSolvers))>
    Public Sub ShrinkingTheContainerWhileRunning_BringsCirclesIn_AndKeepsThemIn(solver As String)
        Dim w = RandomScenesForWorld(solver)
        w.Advance(0.2)
        w.Resize(2.0, 1.5)
        For Each c In w.Circles
            If c.IsFixed Then Continue For
            Assert.InRange(c.Position.X, c.Radius, 2.0 - c.Radius)
            Assert.InRange(c.Position.Y, c.Radius, 1.5 - c.Radius)
        Next
        TestSolvers.Frames(w, 1.0, 1.0 / 60, Sub()
                                                  Assert.True(SceneChecks.AllFinite(w))
                                                  For Each c In w.Circles
                                                      If c.IsFixed Then Continue For
                                                      Assert.InRange(c.Position.X, c.Radius - 1.0E-9, 2.0 - c.Radius + 1.0E-9)
                                                      Assert.InRange(c.Position.Y, c.Radius - 1.0E-9, 1.5 - c.Radius + 1.0E-9)
                                                  Next
                                              End Sub)
        ' Growing it again lets them spread out.
        w.Resize(4.0, 3.0)
        TestSolvers.Frames(w, 1.0, 1.0 / 60)
        Assert.Contains(w.Circles, Function(c) Not c.IsFixed AndAlso c.Position.X > 2.0)
    End Sub

    Private Shared Function RandomScenesForWorld(solver As String) As World
        Return TestSolvers.Run(RandomScenes.Build(11, 30, 9.81, 0.8), solver)
    End Function
End Class
