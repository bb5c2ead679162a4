Option Strict On
Imports System.IO
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>Files on disk: atomic saving, clear errors for missing files, the example scenes.</summary>
Public Class SceneFileIoTests
    Inherits TempFolderTests

    Public Sub New()
        MyBase.New("scene-tests-")
    End Sub

    <Fact>
    Public Sub SaveFile_ThenLoadFile_GivesTheSameScene_AndLeavesNoTemporaryFile()
        Dim target = Path.Combine(Folder, "demo.json")
        SceneFile.SaveFile(Scenarios.Demo(), target)
        SceneRoundTripTests.AssertSameScene(Scenarios.Demo(), SceneFile.LoadFile(target), "demo")
        Assert.Equal("demo.json", Path.GetFileName(Assert.Single(Directory.GetFiles(Folder))))
        Assert.Equal(SceneFile.Save(Scenarios.Demo()), File.ReadAllText(target))
    End Sub

    <Fact>
    Public Sub SaveFile_ReplacesAnExistingFile()
        Dim target = Path.Combine(Folder, "scene.json")
        File.WriteAllText(target, "old and much longer text than the new scene could ever be ......................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................................")
        SceneFile.SaveFile(Scenarios.BouncingBall(), target)
        SceneRoundTripTests.AssertSameScene(Scenarios.BouncingBall(), SceneFile.LoadFile(target), "ball")
        Assert.Single(Directory.GetFiles(Folder))
    End Sub

    <Fact>
    Public Sub SaveFile_IntoAMissingFolder_Throws_AndWritesNothing()
        Dim target = Path.Combine(Folder, "no-such-folder", "scene.json")
        Dim ex = Assert.Throws(Of IOException)(Sub() SceneFile.SaveFile(Scenarios.Demo(), target))
        Assert.Contains(Path.Combine(Folder, "no-such-folder"), ex.Message, StringComparison.Ordinal)
        Assert.Contains("nothing was written", ex.Message, StringComparison.Ordinal)
        Assert.Empty(Directory.GetFileSystemEntries(Folder))
    End Sub

    <Fact>
    Public Sub LoadFile_OfAMissingFile_NamesThePath()
        Dim missing = Path.Combine(Folder, "nope.json")
        Dim ex = Assert.Throws(Of SceneFormatException)(Function() SceneFile.LoadFile(missing))
        Assert.Equal(missing & ": file not found", ex.Message)
        Assert.Equal(missing, ex.Place)
    End Sub

    <Fact>
    Public Sub LoadFile_OfABadFile_SaysPlaceAndProblem()
        Dim target = Path.Combine(Folder, "bad.json")
        File.WriteAllText(target, "{""format"":""physics-scene/1"",""world"":{""width"":8,""height"":5},""bodies"":[{""type"":""circle"",""x"":1,""y"":1,""radius"":-1,""mass"":1}]}")
        Dim ex = Assert.Throws(Of SceneFormatException)(Function() SceneFile.LoadFile(target))
        Assert.Equal("bodies[0].radius: must be greater than 0", ex.Message)
    End Sub

    Public Shared ReadOnly Property ExampleScenes As TheoryData(Of String)
        Get
            Return New TheoryData(Of String)(Directory.GetFiles(Path.Combine(TestRepo.Root(), "scenes"), "*.json").Select(Function(f) Path.GetFileName(f)))
        End Get
    End Property

    <Theory>
    <MemberData(NameOf(ExampleScenes))>
    Public Sub ExampleScenes_AreValid_AndSurviveARoundTrip(name As String)
        Dim w = SceneFile.LoadFile(Path.Combine(TestRepo.Root(), "scenes", name))
        Assert.NotEmpty(w.Bodies)
        SceneRoundTripTests.AssertSameScene(w, SceneFile.Load(SceneFile.Save(w)), name)
    End Sub

    <Fact>
    Public Sub TheExampleScenesFolder_HoldsTheNamedExamples()
        Dim names = Directory.GetFiles(Path.Combine(TestRepo.Root(), "scenes"), "*.json").Select(Function(f) Path.GetFileName(f)).ToList()
        For Each expected In {"demo.json", "bouncing-ball.json", "newtons-cradle.json", "pool-break.json", "peg-board.json",
                              "head-on.json", "head-on-inelastic.json", "glancing-blow.json", "pi-31.json", "pi-314.json", "pi-3141.json",
                              "ideal-gas.json", "settling-pile.json", "ramp.json", "ball-in-v.json", "boxes-sliding.json", "box-stack.json",
                              "polygons.json", "pendulum.json", "cradle-strings.json", "spring-mass.json", "double-pendulum.json", "rope.json", "galton-board.json"}
            Assert.Contains(expected, names)
        Next
    End Sub
End Class
