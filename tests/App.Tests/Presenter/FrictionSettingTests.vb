Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>The world's friction in the side panel: μk and μs typed, checked as the scene reader checks them, saved, kept like gravity.</summary>
Public Class FrictionSettingTests
    Private Shared Function Harness(Optional store As ISceneStore = Nothing) As PresenterHarness
        Dim w As New World(8, 5, 9.81, 0.9)
        w.Add(Rectangle.CreateMovable(New Vector(2, 0), 0.6, 0.5, 3.0, New Vector(2, 0), "crate"))
        Return New PresenterHarness(w, store)
    End Function

    <Fact>
    Public Sub TypedMu_SetsTheWorldsFriction_AndTheMessageSaysBallsTakeNone()
        Dim h = Harness()
        Assert.Equal("0", h.P.Inputs(InputField.FrictionKinetic))
        Assert.Equal("", h.P.Inputs(InputField.FrictionStatic))
        Assert.Equal("No friction (every surface is ice)", h.P.FrictionText)
        h.P.SetFriction("0.3", "0,5")
        Assert.Equal(0.3, h.P.World.Friction)
        Assert.Equal(0.5, h.P.World.StaticFriction)
        Assert.Equal("Friction μk = 0.3, μs = 0.5", h.P.FrictionText)
        Assert.Contains(SimulationPresenter.FrictionBallsNote, h.P.Message, StringComparison.Ordinal)
        Assert.StartsWith("Friction μk = 0.3, μs = 0.5 on walls", h.P.Message, StringComparison.Ordinal)
        Assert.Contains("friction 0.30 static 0.50", h.TraceLines)
        ' An empty μs is μk, as in a scene file without static_friction.
        h.P.SetFriction("0.2", " ")
        Assert.Equal(0.2, h.P.World.Friction)
        Assert.Null(h.P.World.StaticFriction)
        Assert.Equal("Friction μk = 0.2", h.P.FrictionText)
        ' A μk above the old μs is not refused on the way to a new pair.
        h.P.SetFriction("0.2", "0.25")
        h.P.SetFriction("0.6", "0.8")
        Assert.Equal(0.6, h.P.World.Friction)
        Assert.Equal(0.8, h.P.World.StaticFriction)
    End Sub

    <Theory>
    <InlineData("-0.1", "", "Friction is unchanged: friction μk must be 0 or more, not -0.1.")>
    <InlineData("0.3", "-1", "Friction is unchanged: static friction μs must be 0 or more, not -1.")>
    <InlineData("", "0.4", "Friction is unchanged: friction μk is empty.")>
    <InlineData("rough", "0.4", "Friction is unchanged: friction μk 'rough' is not a number.")>
    <InlineData("0.5", "0.3", "Friction is unchanged: static friction μs (0.300) must be at least friction μk (0.500): a surface grips at least as hard before it slides as while it slides.")>
    Public Sub BadMu_IsRefusedNamingItsBox_AndNothingChanges(kinetic As String, [static] As String, message As String)
        Dim h = Harness()
        h.P.SetFriction("0.1", "0.2")
        h.P.SetFriction(kinetic, [static])
        Assert.Equal(message, h.P.Message)
        Assert.Equal(0.1, h.P.World.Friction)
        Assert.Equal(0.2, h.P.World.StaticFriction)
        ' What was typed stays in the boxes, to be put right.
        Assert.Equal(kinetic, h.P.Inputs(InputField.FrictionKinetic))
        Assert.Equal([static], h.P.Inputs(InputField.FrictionStatic))
    End Sub

    <Fact>
    Public Sub MuAboveTheLimit_IsBroughtToIt_AndSaid()
        Dim h = Harness()
        h.P.SetFriction("50", "")
        Assert.Equal(10.0, h.P.World.Friction)
        Assert.Equal("10", h.P.Inputs(InputField.FrictionKinetic))
        Assert.StartsWith("μ above 10 was brought to 10. Friction μk = 10 on walls", h.P.Message, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub Friction_IsSavedAndOpenedWithTheScene_AndTheBoxesShowTheOpenedScenes()
        Dim path = IO.Path.Combine(IO.Path.GetTempPath(), "app-friction-" & Guid.NewGuid().ToString("N") & ".json")
        Try
            Dim h = Harness(New SceneFileStore())
            h.P.SetFriction("0.25", "0.4")
            h.P.SaveScene(path)
            Dim text = IO.File.ReadAllText(path)
            Assert.Contains("""friction"": 0.25", text, StringComparison.Ordinal)
            Assert.Contains("""static_friction"": 0.4", text, StringComparison.Ordinal)
            Dim other As New PresenterHarness(store:=New SceneFileStore())
            other.P.OpenScene(path)
            Assert.Equal(0.25, other.P.World.Friction)
            Assert.Equal(0.4, other.P.World.StaticFriction)
            Assert.Equal("0.25", other.P.Inputs(InputField.FrictionKinetic))
            Assert.Equal("0.4", other.P.Inputs(InputField.FrictionStatic))
        Finally
            IO.File.Delete(path)
        End Try
    End Sub

    <Fact>
    Public Sub Friction_IsASettingLikeGravity_UndoAndRestartKeepIt_ResetClearsIt()
        Dim h = Harness(New SceneFileStore())
        h.P.BeginAddCircle("0.2", "0.5", False)
        h.LeftClick(5, 3)
        Assert.True(h.P.CanUndo)
        h.P.SetFriction("0.3", "0.5")
        h.P.Undo()
        Assert.Equal(0.3, h.P.World.Friction)
        Assert.Equal(0.5, h.P.World.StaticFriction)
        h.P.Restart()
        Assert.Equal(0.3, h.P.World.Friction)
        Assert.Equal(0.5, h.P.World.StaticFriction)
        Assert.Equal("0.3", h.P.Inputs(InputField.FrictionKinetic))
        h.P.Reset()
        Assert.Equal(0.0, h.P.World.Friction)
        Assert.Null(h.P.World.StaticFriction)
        Assert.Equal("0", h.P.Inputs(InputField.FrictionKinetic))
        Assert.Equal("", h.P.Inputs(InputField.FrictionStatic))
        ' Undoing Reset brings its settings back, friction with them.
        h.P.Undo()
        Assert.Equal(0.3, h.P.World.Friction)
        Assert.Equal("0.5", h.P.Inputs(InputField.FrictionStatic))
    End Sub

    <Fact>
    Public Sub FrictionSet_SlowsASlidingBox_AndItStops()
        Dim h = Harness()
        h.P.SetFriction("0.5", "")
        Dim x0 = h.P.World.Find("crate").CentreOfMass.X
        For k = 1 To 120
            h.P.Tick(1 / 60.0)
        Next
        ' v = 2 m/s stops after v²/(2 μk g) = 0.408 m.
        Dim crate = h.P.World.Find("crate")
        Assert.Equal(0.0, crate.Velocity.X, 9)
        Assert.Equal(x0 + 4.0 / (2 * 0.5 * 9.81), crate.CentreOfMass.X, 6)
    End Sub
End Class

''' <summary>Going back in time to before friction was set shows that moment's friction, in the world and in the boxes.</summary>
Public Class FrictionTimeTravelTests
    <Fact>
    Public Sub SteppingBackBeforeFrictionWasSet_BringsBackTheFrictionOfThatMoment()
        Dim w As New World(8, 5, 9.81, 0.9)
        w.Add(Rectangle.CreateMovable(New Vector(2, 0), 0.6, 0.5, 3.0, New Vector(2, 0), "crate"))
        Dim h As New PresenterHarness(w)
        For k = 1 To 6
            h.P.Tick(1 / 60.0)
        Next
        h.P.TogglePause()
        h.P.SetFriction("0.3", "0.5")
        h.P.StepFrame()
        h.P.StepFrame()
        Assert.Equal(0.3, h.P.World.Friction)
        ' Back past the moment friction was set: the scene is ice again, and the boxes say so.
        For k = 1 To 4
            h.P.StepBackFrame()
        Next
        Assert.Equal(0.0, h.P.World.Friction)
        Assert.Equal("0", h.P.Inputs(InputField.FrictionKinetic))
        Assert.Equal("", h.P.Inputs(InputField.FrictionStatic))
    End Sub
End Class
