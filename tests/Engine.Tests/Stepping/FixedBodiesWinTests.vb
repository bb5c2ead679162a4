Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' A stepping solver may let bodies overlap a little within a step, but a fixed body always wins:
''' no centre ends a step inside one, and a circle pushed into one leaves by the side it came in by,
''' never through to the far side (a heavy neighbour pushing a light ball, a fast ball in one step).
''' </summary>
Public Class FixedBodiesWinTests
    <Fact>
    Public Sub CentreInsideARectangle_LeavesByTheFaceItsPathCameIn_NotTheNearest()
        ' A 0.1 m thick plate; the centre came in from above and ended 0.08 m down, nearer the bottom face.
        Dim min = New Vector(0, 0), max = New Vector(2, 0.1)
        Dim p = New Vector(1, 0.02)
        Dim nearest = Collider.CircleRectangle(p, 0.05, min, max)
        Assert.Equal(New Vector(0, -1), nearest.Normal)
        Dim fromAbove = Collider.CircleRectangleFrom(p, 0.05, min, max, New Vector(1, 0.3))
        Assert.Equal(New Vector(0, 1), fromAbove.Normal)
        Assert.Equal(0.05 + 0.08, fromAbove.Depth, 12)
        ' Coming in through the left face.
        Dim fromLeft = Collider.CircleRectangleFrom(New Vector(0.03, 0.05), 0.05, min, max, New Vector(-0.2, 0.05))
        Assert.Equal(New Vector(-1, 0), fromLeft.Normal)
        Assert.Equal(0.05 + 0.03, fromLeft.Depth, 12)
        ' Outside: the ordinary closest-point contact.
        Dim outside = Collider.CircleRectangleFrom(New Vector(1, 0.13), 0.05, min, max, New Vector(1, 0.5))
        Assert.Equal(New Vector(0, 1), outside.Normal)
        Assert.Equal(0.02, outside.Depth, 12)
    End Sub

    <Fact>
    Public Sub CentreInsideAFixedCircle_LeavesByTheSideItsPathCameIn()
        ' Its centre crossed the fixed circle's centre: pushed out along the line to it, it would go
        ' through; it leaves where its path entered (the top).
        Dim c = Collider.CircleCircleFrom(New Vector(0, -0.2), 0.1, Vector.Zero, 0.5, New Vector(0, 1))
        Assert.Equal(0.0, c.Normal.X, 12)
        Assert.Equal(1.0, c.Normal.Y, 12)
        Assert.Equal(0.1 + 0.5 + 0.2, c.Depth, 12)
        Dim plain = Collider.CircleCircle(New Vector(0, -0.2), 0.1, Vector.Zero, 0.5)
        Assert.Equal(-1.0, plain.Normal.Y, 12)
    End Sub

    <Theory>
    <MemberData(NameOf(TestSolvers.Stepping), MemberType:=GetType(TestSolvers))>
    Public Sub HeavyBallDrivingALightOne_IntoAThinPlate_NeverPushesItThrough(solver As String)
        ' A 10⁶ kg ball at 30 m/s drives a 1 g ball down onto a 2 cm plate: the light ball is squeezed
        ' between them, but stays above the plate, and no centre is ever inside it.
        Dim w As New World(4, 4, 9.81, 1.0)
        Dim plate As New Rectangle(New Vector(0.5, 1.0), 3.0, 0.02, "plate")
        w.Add(plate)
        Dim light As New Circle(New Vector(2.0, 1.07), 0.05, 0.001, id:="light")
        Dim heavy As New Circle(New Vector(2.0, 1.6), 0.3, 1000000.0, New Vector(0, -30), "heavy")
        w.Add(light)
        w.Add(heavy)
        TestSolvers.Run(w, solver)
        For k = 1 To 300
            w.Advance(0.001)
            For Each c In {light, heavy}
                Dim p = c.Position
                Dim inside = p.X > plate.Min.X AndAlso p.X < plate.Max.X AndAlso p.Y > plate.Min.Y AndAlso p.Y < plate.Max.Y
                Assert.False(inside, $"{c.Id}'s centre is inside the plate at t = {w.Time}")
                If p.X > plate.Min.X AndAlso p.X < plate.Max.X Then
                    Assert.True(p.Y > plate.Max.Y, $"{c.Id} went through the plate: y = {p.Y} at t = {w.Time}")
                End If
            Next
        Next
    End Sub
End Class
