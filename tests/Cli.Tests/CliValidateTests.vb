Option Strict On
Imports System.IO
Imports Xunit

''' <summary>validate SCENE, as a person at a terminal would run it.</summary>
Public Class CliValidateTests
    Public Shared ReadOnly Property ExampleScenes As TheoryData(Of String)
        Get
            Return New TheoryData(Of String)(Directory.GetFiles(Path.Combine(RepoRoot, "scenes"), "*.json").Select(Function(f) Path.GetFileName(f)))
        End Get
    End Property

    <Theory>
    <MemberData(NameOf(ExampleScenes))>
    Public Sub ExampleScene_PrintsOk_AndExits0(name As String)
        Dim r = RunCli("validate", Path.Combine("scenes", name))
        Assert.True(r.ExitCode = 0, r.ToString())
        Assert.Equal("ok", r.StdOut.Trim())
        Assert.Equal("", r.StdErr)
    End Sub

    <Fact>
    Public Sub InvalidScene_NamesFilePlaceAndProblem_OnOneLine_AndExits2()
        Using t As New TempFolder()
            Dim scene = t.Write("scene.json", Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[" &
                "{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1},{'type':'circle','x':2,'y':1,'radius':0.1,'mass':1}," &
                "{'type':'circle','x':3,'y':1,'radius':0.1,'mass':1},{'type':'circle','x':4,'y':1,'radius':0,'mass':1}]}"))
            Dim r = RunCli("validate", scene)
            Assert.True(r.ExitCode = 2, r.ToString())
            Assert.Equal(scene & ": bodies[3].radius: must be greater than 0" & vbLf, r.StdErr.Replace(vbCr, ""))
            Assert.Equal("", r.StdOut)
        End Using
    End Sub

    <Theory>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1},{'type':'circle','x':1.1,'y':1,'radius':0.1,'mass':1}]}", "bodies[1]: overlaps bodies[0] by 0.1 m")>
    <InlineData("{'format':'physics-scene/2','world':{'width':8,'height':5},'bodies':[]}", "format: must be ""physics-scene/1"", not ""physics-scene/2""")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5,'restitution':1.5},'bodies':[]}", "world.restitution: must be between 0 and 1")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[{'id':'a','type':'circle','x':1,'y':1,'radius':0.1,'mass':1},{'id':'a','type':'rectangle','x':3,'y':0,'width':1,'height':1}]}", "bodies[1].id: ""a"" is already the id of bodies[0]")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1e400}]}", "bodies[0].mass: must be a finite number (1e400 is too large)")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[{'id':'peg','type':'circle','x':4,'y':4,'radius':0.1,'fixed':true}],'links':[{'type':'string','a':'peg','at':[4,4.5]}]}", "links[0]: both ends are fixed (body ""peg"" and the point (x = 4, y = 4.5)), so it could never move anything")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[{'id':'bob','type':'circle','x':1,'y':1,'radius':0.1,'mass':1}],'links':[{'type':'spring','a':'bob','at':[1,3]}]}", "links[0].stiffness: is required")>
    Public Sub InvalidScenes_AreNamed(json As String, expected As String)
        Using t As New TempFolder()
            Dim scene = t.Write("s.json", Q(json))
            Dim r = RunCli("validate", scene)
            Assert.True(r.ExitCode = 2, r.ToString())
            Assert.Equal(scene & ": " & expected, r.StdErr.TrimEnd())
        End Using
    End Sub

    <Fact>
    Public Sub ASceneWithLinks_PrintsOk()
        Using t As New TempFolder()
            Dim scene = t.Write("links.json", Q("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[" &
                "{'id':'bob','type':'circle','x':2,'y':1.5,'radius':0.1,'mass':1},{'id':'left','type':'circle','x':4,'y':1,'radius':0.1,'mass':1}," &
                "{'id':'right','type':'circle','x':4.7,'y':1,'radius':0.1,'mass':1}]," &
                "'links':[{'type':'string','a':'bob','at':[2.0,3.0],'length':1.5},{'type':'spring','a':'left','b':'right','stiffness':40,'rest_length':0.5},{'type':'rod','a':'left','at':[4,3]}]}"))
            Dim r = RunCli("validate", scene)
            Assert.True(r.ExitCode = 0, r.ToString())
            Assert.Equal("ok", r.StdOut.Trim())
        End Using
    End Sub

    <Fact>
    Public Sub NotJson_Exits2_WithOneLine()
        Using t As New TempFolder()
            Dim scene = t.Write("s.json", "{""format"": ""physics-scene/1"", ""world"": {""width"": 8,")
            Dim r = RunCli("validate", scene)
            Assert.True(r.ExitCode = 2, r.ToString())
            Assert.StartsWith(scene & ": document: is not valid JSON", r.StdErr)
            Assert.Single(r.StdErr.TrimEnd().Split(ChrW(10)))
        End Using
    End Sub

    <Fact>
    Public Sub MissingFile_Exits2_NamingIt()
        Dim r = RunCli("validate", "no-such-scene.json")
        Assert.True(r.ExitCode = 2, r.ToString())
        Assert.Equal("no-such-scene.json: file not found", r.StdErr.TrimEnd())
    End Sub

    <Fact>
    Public Sub AFolderInsteadOfAFile_Exits2()
        Dim r = RunCli("validate", "scenes")
        Assert.True(r.ExitCode = 2, r.ToString())
        Assert.Equal("scenes: is a folder, not a scene file", r.StdErr.TrimEnd())
    End Sub

    <Theory>
    <InlineData("validate: no scene file given")>
    <InlineData("validate: unexpected argument 'extra'", "scenes/demo.json", "extra")>
    <InlineData("validate: unknown option '--fast'", "scenes/demo.json", "--fast")>
    Public Sub BadArguments_Exit2(expectedStart As String, ParamArray args As String())
        Dim all As New List(Of String) From {"validate"}
        all.AddRange(args)
        Dim r = RunCli(all.ToArray())
        Assert.True(r.ExitCode = 2, r.ToString())
        Assert.StartsWith(expectedStart, r.StdErr)
        Assert.Single(r.StdErr.TrimEnd().Split(ChrW(10)))
    End Sub
End Class
