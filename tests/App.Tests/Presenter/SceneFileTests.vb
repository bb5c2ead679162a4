Option Strict On
Imports PhysicsEngine.Presentation
Imports Xunit

''' <summary>Open and Save through the scene store; every problem is a message.</summary>
Public Class SceneFileTests
    Private NotInheritable Class FakeStore
        Implements ISceneStore
        Public Property ToLoad As World
        Public Property Failure As Exception
        Public Property Saved As World
        Public Property SavedPath As String

        Public Function Load(path As String) As World Implements ISceneStore.Load
            If Failure IsNot Nothing Then Throw Failure
            Return ToLoad
        End Function

        Public Sub Save(world As World, path As String) Implements ISceneStore.Save
            If Failure IsNot Nothing Then Throw Failure
            Saved = world
            SavedPath = path
        End Sub
    End Class

    <Fact>
    Public Sub WithoutAStore_OpenAndSave_SayWhy()
        Dim h As New PresenterHarness()
        Assert.False(h.P.CanOpenAndSave)
        h.P.OpenScene("x.json")
        Assert.Contains("not available", h.View.LastMessage, StringComparison.Ordinal)
        h.P.SaveScene("x.json")
        Assert.Contains("not available", h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub Open_ReplacesTheWorld_WithSolverColoursAndLog()
        Dim store As New FakeStore With {.ToLoad = Scenarios.NewtonsCradle()}
        Dim h As New PresenterHarness(store:=store)
        h.P.OpenScene("/tmp/cradle.json")
        Assert.Same(store.ToLoad, h.P.World)
        Assert.NotNull(h.P.World.Solver)
        Assert.All(h.P.World.Bodies, Sub(b) Assert.False(String.IsNullOrEmpty(b.Color)))
        Assert.Equal("10", h.P.Inputs.ContainerWidthText)
        For k = 1 To 180
            h.P.Tick(1 / 60.0)
        Next
        Assert.True(h.P.Log.Count > 0, "the log listens to the new world")
        Assert.Contains("opened cradle.json: 6 bodies", h.TraceLines)
    End Sub

    ''' <summary>
    ''' A file whose rod has its ends moving apart along it: the window puts it right as it opens the scene, as the command
    ''' line does, and says what changed (the rod keeps its length; the kinetic energy before and after).
    ''' </summary>
    <Fact>
    Public Sub Open_ARodWhoseEndsMoveApart_IsPutRight_AndTheMessageSaysSo()
        Dim w As New World(10, 10)
        Dim bob As New Circle(New Vector(5, 4), 0.1, 2, New Vector(1, -0.5)) With {.Id = "bob"}
        w.Add(bob)
        w.Add(Link.CreateTie(LinkKind.Rod, bob, New Vector(5, 5), 1, "arm"))
        Dim h As New PresenterHarness(store:=New FakeStore With {.ToLoad = w})
        h.P.OpenScene("/tmp/rod.json")
        Assert.Same(w, h.P.World)
        Assert.Equal(New Vector(1, 0), bob.Velocity)
        Assert.Contains("Put right: links[0] ('arm', a rod): its ends moved apart along it; they now keep its length (kinetic energy 1.25 J before, 1 J after).",
                        h.View.LastMessage, StringComparison.Ordinal)
    End Sub

    <Fact>
    Public Sub Open_ASceneTooFastToShow_IsRefusedWithThePlace_AndTheSceneIsKept()
        Dim fast As New World(10, 10)
        fast.Add(New Circle(New Vector(5, 5), 0.5, 1.0, New Vector(1.0E+300, 0)) With {.Id = "fast"})
        Dim h As New PresenterHarness(store:=New FakeStore With {.ToLoad = fast})
        Dim before = h.P.World
        h.P.OpenScene("/tmp/fast.json")
        Assert.Same(before, h.P.World)
        Assert.Equal("Could not open fast.json: bodies[0] speed: 1.00×10³⁰⁰ m/s is beyond the largest this app shows, 1.00×10⁶ m/s. The scene on screen is kept.",
                     h.View.LastMessage)
    End Sub

    <Fact>
    Public Sub Open_BadFile_ShowsTheOneLineMessage_AndKeepsTheScene()
        Dim store As New FakeStore With {.Failure = New FormatException("bodies[3].radius: must be greater than 0")}
        Dim h As New PresenterHarness(store:=store)
        Dim before = h.P.World
        h.P.OpenScene("/tmp/bad.json")
        Assert.Same(before, h.P.World)
        Assert.Equal("Could not open bad.json: bodies[3].radius: must be greater than 0", h.View.LastMessage)
    End Sub

    <Fact>
    Public Sub Save_WritesTheWorld_OrSaysWhyNot()
        Dim store As New FakeStore()
        Dim h As New PresenterHarness(store:=store)
        h.P.SaveScene("/tmp/a.json")
        Assert.Same(h.P.World, store.Saved)
        store.Failure = New IO.IOException("disk full")
        h.P.SaveScene("/tmp/b.json")
        Assert.Equal("Could not save b.json: disk full", h.View.LastMessage)
    End Sub
End Class

''' <summary>Open and Save with the real scene files on disk.</summary>
Public Class SceneFileStoreTests
    <Fact>
    Public Sub SaveThenOpen_RoundTripsTheScene()
        Dim path = IO.Path.Combine(IO.Path.GetTempPath(), "app-roundtrip-" & Guid.NewGuid().ToString("N") & ".json")
        Try
            Dim h As New PresenterHarness(Scenarios.Demo(), New SceneFileStore())
            h.P.SetGravity(3.71)
            h.P.SaveScene(path)
            Assert.True(IO.File.Exists(path), h.View.LastMessage)
            Dim other As New PresenterHarness(store:=New SceneFileStore())
            other.P.OpenScene(path)
            Assert.Equal(3.71, other.P.World.Gravity)
            Assert.Equal(h.P.World.Bodies.Select(Function(b) b.Id), other.P.World.Bodies.Select(Function(b) b.Id))
            Assert.Equal("#e53935", other.P.World.Find("red").Color)
        Finally
            IO.File.Delete(path)
        End Try
    End Sub

    <Fact>
    Public Sub Open_InvalidScene_ShowsTheFieldAndKeepsTheScene()
        Dim path = IO.Path.Combine(IO.Path.GetTempPath(), "app-bad-" & Guid.NewGuid().ToString("N") & ".json")
        Try
            IO.File.WriteAllText(path, "{""format"":""physics-scene/1"",""world"":{""width"":4,""height"":3},""bodies"":[{""type"":""circle"",""x"":1,""y"":1,""radius"":0,""mass"":1}]}")
            Dim h As New PresenterHarness(store:=New SceneFileStore())
            Dim before = h.P.World
            h.P.OpenScene(path)
            Assert.Same(before, h.P.World)
            Assert.Equal("Could not open " & IO.Path.GetFileName(path) & ": bodies[0].radius: must be greater than 0", h.View.LastMessage)
        Finally
            IO.File.Delete(path)
        End Try
    End Sub

    <Fact>
    Public Sub Open_MissingFile_IsAMessage()
        Dim h As New PresenterHarness(store:=New SceneFileStore())
        h.P.OpenScene("/no/such/folder/scene.json")
        Assert.Equal("Could not open scene.json: file not found", h.View.LastMessage)
    End Sub
End Class
