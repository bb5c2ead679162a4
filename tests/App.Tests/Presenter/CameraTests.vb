Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>Zoom about the cursor, pan with the middle button, follow a body.</summary>
Public Class CameraTests
    Private Shared Function Near(a As Vector, b As Vector, tolerance As Double) As Boolean
        Return (a - b).Length <= tolerance
    End Function

    <Fact>
    Public Sub TheWheel_ZoomsAboutTheCursor_ThePointUnderItStaysUnderIt()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim fitted = h.P.View.Scale
        Dim under = h.P.View.ToWorld(600, 150)
        h.P.ZoomAt(3, 600, 150)
        Assert.Equal(Math.Pow(1.25, 3), h.P.Zoom, 12)
        Assert.Equal(fitted * Math.Pow(1.25, 3), h.P.View.Scale, 9)
        Assert.True(Near(under, h.P.View.ToWorld(600, 150), 0.000001), "the point under the cursor moved")
        ' Out again, past the fitted view: the whole container, as it was.
        h.P.ZoomAt(-10, 100, 100)
        Assert.Equal(1.0, h.P.Zoom)
        Assert.Equal(fitted, h.P.View.Scale)
        ' No closer than 20 times.
        h.P.ZoomAt(100, 400, 250)
        Assert.Equal(20.0, h.P.Zoom)
    End Sub

    <Fact>
    Public Sub ADragWithTheMiddleButton_PansTheScene_AndTheWholeBoxDoesNotPan()
        Dim h As New PresenterHarness(New World(8, 5, 0.0, 1.0))
        Dim origin = h.P.View.ToScreen(Vector.Zero)
        h.P.PointerDown(PointerButton.Middle, 400, 250)
        h.P.PointerMove(300, 200)
        h.P.PointerUp(PointerButton.Middle, 300, 200)
        Assert.Equal(origin, h.P.View.ToScreen(Vector.Zero))
        h.P.ZoomAt(4, 400, 250)
        Dim p = h.P.View.ToWorld(400, 250)
        h.P.PointerDown(PointerButton.Middle, 400, 250)
        h.P.PointerMove(350, 260)
        h.P.PointerMove(300, 270)
        h.P.PointerUp(PointerButton.Middle, 300, 270)
        ' The scene moved with the cursor: the point that was under it is under it still.
        Assert.True(Near(p, h.P.View.ToWorld(300, 270), 0.000001))
        Assert.Null(h.P.FollowedBody)
    End Sub

    <Fact>
    Public Sub AMiddleClickOnABody_FollowsIt_AndTheViewKeepsItInTheMiddle()
        Dim h As New PresenterHarness(New World(40, 5, 0.0, 1.0))
        Dim ball = New Circle(New Vector(5, 2.5), 0.3, 1.0, New Vector(6, 0), "runner")
        h.P.World.Add(ball)
        Dim s = h.Px(5, 2.5)
        h.P.PointerDown(PointerButton.Middle, s.X, s.Y)
        h.P.PointerUp(PointerButton.Middle, s.X, s.Y)
        Assert.Same(ball, h.P.FollowedBody)
        Assert.Equal(3.0, h.P.Zoom)
        Assert.StartsWith("The view follows runner.", h.P.Message, StringComparison.Ordinal)
        Dim middle = h.P.View.ToScreen(ball.CentreOfMass)
        For k = 1 To 60
            h.P.Tick(1 / 60.0)
        Next
        Assert.True(ball.Position.X > 10)
        ' A second later it is still in the middle of the view.
        Assert.True(Near(middle, h.P.View.ToScreen(ball.CentreOfMass), 0.5))
        ' A click on an empty place stops following; Ctrl+0 shows the whole box.
        h.P.PointerDown(PointerButton.Middle, 20, 20)
        h.P.PointerUp(PointerButton.Middle, 20, 20)
        Assert.Null(h.P.FollowedBody)
        Assert.Equal("", h.P.Message)
        h.P.ResetView()
        Assert.Equal(1.0, h.P.Zoom)
    End Sub
End Class
