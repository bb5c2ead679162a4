Option Strict On
Imports Xunit

''' <summary>The world's friction in the real window: the inclined-plane lesson's μk and μs in their boxes, a bad μs refused, a new pair set, the row whole on the screen.</summary>
<Collection(RealWindow.Name)>
Public Class FrictionGuiTests
    <GuiFact>
    Public Sub TheFrictionBoxes_ShowTheScenesMu_RefuseMuSBelowMuK_AndSetANewPair()
        Using app As New AppDriver(New XSessionOptions(), IO.Path.Combine("scenes", "inclined-plane.json"))
            app.WaitFor("^opened inclined-plane.json: 4 bodies$")
            ' The scene's own μk and μs are in the boxes.
            app.WaitFor("^inputs .*\bFrictionKinetic=\[0\.4\] FrictionStatic=\[0\.5\]")
            For Each name In {"friction-label", "friction", "static-friction-label", "static-friction", "set-friction"}
                Dim c = app.Control(name)
                Assert.True(c.W > 0 AndAlso c.H > 0, name & " is not laid out")
            Next
            Assert.EndsWith(" fits", app.Lines().Last(Function(l) l.StartsWith("control set-friction ", StringComparison.Ordinal)), StringComparison.Ordinal)
            app.ClickAndWait("pause", "^paused t=")
            app.TypeInto("static-friction", "0.2")
            Dim from = app.Mark()
            app.Click("set-friction")
            app.WaitFor("^message: Friction is unchanged: static friction μs \(0\.200\) must be at least friction μk \(0\.400\)", skip:=from)
            app.TypeInto("friction", "0.1")
            from = app.Mark()
            app.Click("set-friction")
            app.WaitFor("^friction 0\.10 static 0\.20$", skip:=from)
            app.WaitFor("^message: Friction μk = 0\.1, μs = 0\.2 on walls, .* Balls take no friction", skip:=from)
            app.X.Shoot("friction-set")
            Assert.True(app.X.AppIsRunning)
        End Using
    End Sub
End Class
