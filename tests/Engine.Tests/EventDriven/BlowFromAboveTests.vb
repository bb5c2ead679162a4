Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' A ball dropped onto a ball resting alone on level ground, with the event solver: the ground takes
''' the vertical part of the blow and the resting ball the horizontal part, so it is knocked sideways
''' and momentum along the ground is kept (a resting ball in a pile still takes a blow from above as the
''' ground does, which keeps a settled pile still).
''' </summary>
Public Class BlowFromAboveTests
    Private Const G As Double = 9.81

    <Theory>
    <InlineData(0.0, 0.8)>
    <InlineData(0.0, 1.0)>
    <InlineData(1.2, 0.5)>
    Public Sub ABallDroppedOffCentre_KnocksTheRestingBallSideways(groundHeight As Double, e As Double)
        ' groundHeight 0: the floor; otherwise the level top of a fixed rectangle.
        Dim w As New World(4, 3, G, e)
        If groundHeight > 0 Then w.Add(New Rectangle(New Vector(1, 0), 2, groundHeight, id:="table"))
        Const R = 0.1, Ma = 1.0, Mb = 2.5
        Dim b As New Circle(New Vector(2, groundHeight + R), R, Mb, id:="B")
        Dim a As New Circle(New Vector(2.08, groundHeight + 1.5), R, Ma, id:="A")
        w.Add(b)
        w.Add(a)
        UseEventSolver(w)
        Dim hit As CollisionRecord? = Nothing
        w.CollisionListener = Sub(rec)
                                  If hit Is Nothing AndAlso rec.B IsNot Nothing AndAlso rec.B.Kind = ShapeKind.Circle Then hit = rec
                              End Sub
        w.Advance(0.6)
        Assert.True(hit.HasValue, "A never hit B")
        Dim h = hit.Value
        Dim aBefore = If(h.A Is a, h.AVelocityBefore, h.BVelocityBefore), aAfter = If(h.A Is a, h.AVelocityAfter, h.BVelocityAfter)
        Dim bAfter = If(h.A Is a, h.BVelocityAfter, h.AVelocityAfter)
        ' Free fall from rest through the gap: contact when the centres are 2R apart, 0.08 m sideways.
        Dim drop = 1.5 - R - Math.Sqrt(4 * R * R - 0.08 * 0.08)
        Dim u = Math.Sqrt(2 * G * drop)
        Assert.Equal(-u, aBefore.Y, 9)
        Dim n = New Vector(0.08, Math.Sqrt(4 * R * R - 0.08 * 0.08)) / (2 * R)
        Dim j = (1 + e) * u * n.Y / (1 / Ma + n.X * n.X / Mb)
        Assert.Equal(-j * n.X / Mb, bAfter.X, 9)
        Assert.Equal(0.0, bAfter.Y)
        Assert.Equal(j * n.X / Ma, aAfter.X, 9)
        Assert.Equal(-u + j * n.Y / Ma, aAfter.Y, 9)
        ' Along the ground nothing else pushes: momentum in x stays zero until a wall.
        Assert.Equal(0.0, Ma * a.Velocity.X + Mb * b.Velocity.X, 9)
        ' B slides along the ground, never sinking into it.
        For k = 1 To 10
            w.Advance(0.02)
            Assert.True(Math.Abs(b.Position.Y - (groundHeight + R)) <= 1.0E-9, $"B at height {b.Position.Y}")
            Assert.True(b.Velocity.X < 0, $"B's velocity {b.Velocity}")
        Next
    End Sub

    <Fact>
    Public Sub ABallDroppedOnABallInARow_LeavesTheRowStill()
        ' The resting ball touches a neighbour: the pile rule holds, and the row does not move.
        Dim w As New World(4, 3, G, 0.5)
        Const R = 0.1
        Dim row = {New Circle(New Vector(1.8, R), R, 1.0, id:="L"), New Circle(New Vector(2.0, R), R, 1.0, id:="B"),
                   New Circle(New Vector(2.2, R), R, 1.0, id:="Rt")}
        For Each c In row
            w.Add(c)
        Next
        w.Add(New Circle(New Vector(2.05, 1.2), R, 1.0, id:="A"))
        UseEventSolver(w)
        w.Advance(0.45)
        Assert.True(w.CollisionCount > 0)
        For Each c In row
            Assert.Equal(Vector.Zero, c.Velocity)
        Next
    End Sub
End Class
