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
    Public Sub Resize_BringsCirclesBackInside()
        Dim w As New World(10, 10, 0)
        Dim c As New Circle(New Vector(9, 9), 0.5, 1.0)
        w.Add(c)
        w.Resize(4, 3)
        Assert.Equal(New Vector(3.5, 2.5), c.Position)
    End Sub

    <Fact>
    Public Sub Projectile_FallsAsSuvat()
        Dim w = Scenarios.Projectile(speed:=10, angle:=Math.PI / 4)
        w.Solver = SolverFactory.Create("euler", 0.0001)
        Dim ball = w.Circles(0)
        Dim p0 = ball.Position, v0 = ball.Velocity
        w.Advance(1.0)
        ' s = ut + ½at²: semi-implicit Euler is first order, so allow its O(dt) error.
        Assert.Equal(p0.X + v0.X, ball.Position.X, 9)
        Assert.Equal(p0.Y + v0.Y - 0.5 * 9.81, ball.Position.Y, 3)
    End Sub
End Class
