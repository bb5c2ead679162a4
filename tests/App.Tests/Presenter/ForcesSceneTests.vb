Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>
''' A scene file's air resistance and liquid act in the app as the file says, though the window has no
''' controls for them yet (what docs/app.md and the tutorial's limits tell the teacher).
''' </summary>
Public Class ForcesSceneTests
    Private Shared Function OpenText(json As String) As PresenterHarness
        Dim path = IO.Path.Combine(IO.Path.GetTempPath(), "app-forces-" & Guid.NewGuid().ToString("N") & ".json")
        Try
            IO.File.WriteAllText(path, json)
            Dim h As New PresenterHarness(store:=New SceneFileStore())
            h.P.OpenScene(path)
            Assert.StartsWith("Opened", h.View.LastMessage, StringComparison.Ordinal)
            Return h
        Finally
            IO.File.Delete(path)
        End Try
    End Function

    <Fact>
    Public Sub ABallWithLinearDrag_FallsAtItsTerminalVelocity()
        ' m g / b = 1 × 9.81 / 2 = 4.905 m/s, approached as e^(−t/τ), τ = m/b = 0.5 s.
        Dim h = OpenText("{""format"":""physics-scene/1"",""world"":{""width"":4,""height"":60,""gravity"":9.81,""restitution"":0.5}," &
                         """bodies"":[{""id"":""ball"",""type"":""circle"",""x"":2,""y"":58,""radius"":0.2,""mass"":1,""linear_drag"":2}]}")
        For k = 1 To 240
            h.P.Tick(1 / 60.0)
        Next
        Dim t = h.P.World.Time
        Assert.Equal(-4.905 * (1 - Math.Exp(-t / 0.5)), h.P.World.Find("ball").Velocity.Y, 6)
    End Sub

    <Fact>
    Public Sub ABoxLighterThanItsLiquid_Floats_ADenserOneSinks()
        Dim h = OpenText("{""format"":""physics-scene/1"",""world"":{""width"":6,""height"":4,""gravity"":9.81,""restitution"":0.2}," &
                         """bodies"":[{""id"":""light"",""type"":""rectangle"",""x"":1,""y"":2.5,""width"":0.5,""height"":0.5,""fixed"":false,""mass"":0.125}," &
                         "{""id"":""heavy"",""type"":""rectangle"",""x"":4,""y"":2.5,""width"":0.5,""height"":0.5,""fixed"":false,""mass"":0.5}," &
                         "{""id"":""water"",""type"":""liquid"",""x"":0,""y"":0,""width"":6,""height"":2,""density"":1,""linear_drag"":2}]}")
        For k = 1 To 1200
            h.P.Tick(1 / 60.0)
        Next
        ' Floating: m = ρ w d, so d = 0.125 / (1 × 0.5) = 0.25 m below the surface at y = 2 (its bottom at 1.75 m).
        Dim light = h.P.World.Find("light")
        Assert.Equal(2.0, light.CentreOfMass.Y, 2)
        Assert.Equal(0.25, h.P.World.Find("heavy").CentreOfMass.Y, 6)
    End Sub
End Class
