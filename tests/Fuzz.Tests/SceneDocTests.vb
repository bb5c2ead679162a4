Option Strict On
Imports PhysicsEngine.Fuzzing.Generation
Imports PhysicsEngine.Scenes
Imports Xunit

''' <summary>Scenes as pieces of text: written, split, cut down and read back without changing a bit.</summary>
Public Class SceneDocTests
    Private Shared Sub AssertSameWorld(a As World, b As World)
        Assert.Equal(a.Bodies.Count, b.Bodies.Count)
        Assert.Equal(a.Width, b.Width)
        Assert.Equal(a.Gravity, b.Gravity)
        For i = 0 To a.Circles.Count - 1
            Dim x = a.Circles(i), y = b.Circles(i)
            Assert.Equal(x.Id, y.Id)
            Assert.Equal(BitConverter.DoubleToInt64Bits(x.Position.X), BitConverter.DoubleToInt64Bits(y.Position.X))
            Assert.Equal(BitConverter.DoubleToInt64Bits(x.Position.Y), BitConverter.DoubleToInt64Bits(y.Position.Y))
            Assert.Equal(BitConverter.DoubleToInt64Bits(x.Velocity.X), BitConverter.DoubleToInt64Bits(y.Velocity.X))
            Assert.Equal(x.Mass, y.Mass)
        Next
        For i = 0 To a.Rectangles.Count - 1
            Assert.Equal(a.Rectangles(i).Min, b.Rectangles(i).Min)
            Assert.Equal(a.Rectangles(i).Max, b.Rectangles(i).Max)
        Next
    End Sub

    <Fact>
    Public Sub AGeneratedScene_SplitAndWrittenAgain_ReadsTheSame()
        For seed = 1 To 50
            Dim text = SceneGenerator.Generate(seed, BodyKinds.Default, 40).ToText()
            Dim again = SceneDoc.Parse(text).ToText()
            Assert.Equal(text, again)
        Next
    End Sub

    <Fact>
    Public Sub AHandWrittenScene_KeepsItsNumbersAndGetsTheIdsTheReaderGives()
        Dim text = TestPaths.Case_("stepping-centre-inside-rectangle.json")
        Dim original = SceneFile.LoadFile(text)
        AssertSameWorld(original, SceneFile.Load(SceneDoc.Parse(IO.File.ReadAllText(text)).ToText()))
        ' bodies without ids are named by their place, as the reader names them, and keep that name when others go
        Dim bare = "{""format"": ""physics-scene/1"", ""world"": {""width"": 2, ""height"": 2}, ""bodies"": [" &
            "{""type"": ""circle"", ""x"": 0.5, ""y"": 0.5, ""radius"": 0.1, ""mass"": 1}," &
            "{""type"": ""circle"", ""x"": 1.5, ""y"": 0.5, ""radius"": 0.1, ""mass"": 2, ""vx"": 0.1}]}"
        Dim doc = SceneDoc.Parse(bare)
        AssertSameWorld(SceneFile.Load(bare), SceneFile.Load(doc.ToText()))
        Dim second = SceneFile.Load(doc.WithBodies({doc.Bodies(1)}).ToText())
        Assert.Equal("2", second.Circles.Single().Id)
        Assert.Equal(2.0, second.Circles.Single().Mass)
    End Sub

    <Fact>
    Public Sub CuttingBodies_DropsTheLinksThatNeedThem()
        Dim text = "{""format"": ""physics-scene/1"", ""world"": {""width"": 2, ""height"": 2}, ""bodies"": [" &
            "{""id"": ""a"", ""type"": ""circle"", ""x"": 0.5, ""y"": 0.5, ""radius"": 0.1, ""mass"": 1}," &
            "{""id"": ""b"", ""type"": ""circle"", ""x"": 1.5, ""y"": 0.5, ""radius"": 0.1, ""mass"": 1}]," &
            """links"": [{""type"": ""rod"", ""a"": ""a"", ""b"": ""b""}, {""type"": ""string"", ""a"": ""b"", ""at"": [1.5, 1.5]}]}"
        Dim doc = SceneDoc.Parse(text)
        Assert.Equal("link1,link2", String.Join(",", doc.Links.Select(Function(l) l.Id)))
        Dim onlyB = doc.WithBodies(doc.Bodies.Where(Function(b) b.Id = "b"))
        Assert.Equal("link2", String.Join(",", onlyB.Links.Select(Function(l) l.Id)))
        Assert.Contains("""id"": ""link2""", onlyB.ToText(), StringComparison.Ordinal)
        Assert.Empty(doc.WithBodies(doc.Bodies.Where(Function(b) b.Id = "a")).Links)
    End Sub
End Class
