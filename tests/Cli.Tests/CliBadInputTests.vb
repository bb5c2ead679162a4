Option Strict On
Imports System.IO
Imports Xunit

''' <summary>
''' Bad input: exit 2, one line on standard error saying what and where, and no output file created
''' or changed. Every case also names a states and an events file in a folder that exists. A valid
''' scene that no solver can run fails the same way, with exit 1 (cli.md: any other failure).
''' </summary>
Public Class CliBadInputTests
    Private Const Scene As String = "{scene}"
    Private Const States As String = "{states}"
    Private Const Events As String = "{events}"

    <Theory>
    <InlineData("run: no scene file given", "--time", "1", "--states", States, "--events", Events)>
    <InlineData("run: --time T is required", Scene, "--states", States, "--events", Events)>
    <InlineData("--time: must be greater than 0, not 0", Scene, "--time", "0", "--states", States, "--events", Events)>
    <InlineData("--time: must be greater than 0, not -1", Scene, "--time", "-1", "--states", States, "--events", Events)>
    <InlineData("--time: 'abc' is not a number", Scene, "--time", "abc", "--states", States, "--events", Events)>
    <InlineData("--time: '1,5' is not a number", Scene, "--time", "1,5", "--states", States, "--events", Events)>
    <InlineData("--time: 'NaN' is not a finite number", Scene, "--time", "NaN", "--states", States, "--events", Events)>
    <InlineData("--time: '1e400' is not a finite number", Scene, "--time", "1e400", "--states", States, "--events", Events)>
    <InlineData("--time: missing value", Scene, "--states", States, "--events", Events, "--time")>
    <InlineData("--time: missing value", Scene, "--time", "--json", "--states", States, "--events", Events)>
    <InlineData("--time: given more than once", Scene, "--time", "1", "--time", "2", "--states", States, "--events", Events)>
    <InlineData("--sample: must be greater than 0, not 0", Scene, "--time", "1", "--sample", "0", "--states", States, "--events", Events)>
    <InlineData("--dt: must be greater than 0, not -0.001", Scene, "--time", "1", "--dt", "-0.001", "--states", States, "--events", Events)>
    <InlineData("--dt: 'fast' is not a number", Scene, "--time", "1", "--dt", "fast", "--states", States, "--events", Events)>
    <InlineData("--solver: unknown solver 'rk4'", Scene, "--time", "1", "--solver", "rk4", "--states", States, "--events", Events)>
    <InlineData("--solver: missing value", Scene, "--time", "1", "--states", States, "--events", Events, "--solver")>
    <InlineData("--states: missing value", Scene, "--time", "1", "--events", Events, "--states")>
    <InlineData("run: unknown option '--speed'", Scene, "--time", "1", "--speed", "2", "--states", States, "--events", Events)>
    <InlineData("run: unknown option '-t'", Scene, "-t", "1", "--states", States, "--events", Events)>
    <InlineData("run: unexpected argument 'extra.json'", Scene, "extra.json", "--time", "1", "--states", States, "--events", Events)>
    <InlineData("--json: takes no value", Scene, "--time", "1", "--json=yes", "--states", States, "--events", Events)>
    <InlineData("--events: '", Scene, "--time", "1", "--states", States, "--events", States)>
    <InlineData("--series: missing value", Scene, "--time", "1", "--states", States, "--events", Events, "--series")>
    <InlineData("--series: '", Scene, "--time", "1", "--states", States, "--events", Events, "--series", States)>
    <InlineData("--series: '", Scene, "--time", "1", "--states", States, "--events", Events, "--series", Events)>
    <InlineData("--sample: 1E-300 s would take more than 10,000,000 samples", Scene, "--time", "1e300", "--sample", "1e-300", "--states", States, "--events", Events)>
    Public Sub BadArguments_Exit2_WithOneLine_AndWriteNothing(expectedStart As String, ParamArray args As String())
        Using t As New TempFolder()
            Dim scenePath = t.Write("scene.json", HeadOn)
            Dim r = Run(t, scenePath, args)
            Assert.True(r.ExitCode = 2, r.ToString())
            Assert.StartsWith(expectedStart, r.StdErr)
            AssertOneLineAndNothingWritten(t, r)
        End Using
    End Sub

    <Theory>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[{'type':'circle','x':1,'y':1,'radius':0,'mass':1}]}", "bodies[0].radius: must be greater than 0")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1},{'type':'circle','x':1.05,'y':1,'radius':0.1,'mass':1}]}", "bodies[1]: overlaps bodies[0] by 0.15 m")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[{'type':'circle','x':1,'y':1,'radius':0.1,'mass':1}", "document: is not valid JSON")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[{'id':'ball1','type':'circle','x':1,'y':1,'radius':0.1,'mass':1},{'id':'ball2','type':'circle','x':2,'y':1,'radius':0.1,'mass':1}]," &
                "'links':[{'type':'rod','a':'ball1','b':'ball2'},{'type':'string','a':'ball1','at':[1,3]},{'type':'spring','a':'ball1','b':'bal2','stiffness':40}]}", "links[2].b: no body ""bal2""")>
    <InlineData("{'format':'physics-scene/1','world':{'width':8,'height':5},'bodies':[{'id':'bob','type':'circle','x':1,'y':1,'radius':0.1,'mass':1}],'links':[{'type':'rod','a':'bob','at':[1,3],'length':1.5}]}",
                "links[0].length: a rod's length must be the distance between its ends in the file, 2 m, not 1.5 m")>
    Public Sub InvalidScene_Exits2_NamingFileAndPlace_AndWritesNothing(json As String, expected As String)
        Using t As New TempFolder()
            Dim scenePath = t.Write("scene.json", Q(json))
            Dim r = Run(t, scenePath, {Scene, "--time", "1", "--states", States, "--events", Events, "--json"})
            Assert.True(r.ExitCode = 2, r.ToString())
            Assert.StartsWith(scenePath & ": " & expected, r.StdErr)
            Assert.Equal("", r.StdOut)
            AssertOneLineAndNothingWritten(t, r)
        End Using
    End Sub

    <Fact>
    Public Sub ASceneTooFastToSimulate_IsValid_ButTheRunFails_Exit1_AndWritesNothing()
        Using t As New TempFolder()
            Dim scenePath = t.Write("scene.json", Q("{'format':'physics-scene/1','world':{'width':10,'height':10}," &
                                                    "'bodies':[{'id':'fast','type':'circle','x':5,'y':5,'radius':0.5,'mass':1,'vx':1e300}]}"))
            Assert.Equal(0, RunCli("validate", scenePath).ExitCode)
            Dim r = Run(t, scenePath, {Scene, "--time", "1", "--states", States, "--events", Events})
            Assert.True(r.ExitCode = 1, r.ToString())
            Assert.StartsWith("run: circle 'fast' moves at 1E+300 m/s, faster than the 1E+150 m/s the simulation can handle", r.StdErr)
            AssertOneLineAndNothingWritten(t, r)
        End Using
    End Sub

    <Fact>
    Public Sub MissingSceneFile_Exits2()
        Using t As New TempFolder()
            t.Write("scene.json", HeadOn)
            Dim missing = t.File("missing.json")
            Dim r = Run(t, missing, {Scene, "--time", "1", "--states", States, "--events", Events})
            Assert.True(r.ExitCode = 2, r.ToString())
            Assert.Equal(missing & ": file not found", r.StdErr.TrimEnd())
            AssertOneLineAndNothingWritten(t, r)
        End Using
    End Sub

    <Theory>
    <InlineData("--states")>
    <InlineData("--events")>
    <InlineData("--series")>
    Public Sub MissingOutputFolder_Exits2_AndWritesNothing(optionName As String)
        Using t As New TempFolder()
            Dim scenePath = t.Write("scene.json", HeadOn)
            Dim bad = Path.Combine(t.Path, "no-such-folder", "out.csv")
            Dim other = If(optionName = "--states", "--events", "--states")
            Dim r = RunCli("run", scenePath, "--time", "1", optionName, bad, other, t.File("other.csv"))
            Assert.True(r.ExitCode = 2, r.ToString())
            Assert.Equal(optionName & ": folder '" & Path.GetDirectoryName(bad) & "' does not exist", r.StdErr.TrimEnd())
            Assert.Equal("scene.json", String.Join("|", t.Files()))
        End Using
    End Sub

    <Theory>
    <InlineData("--states")>
    <InlineData("--series")>
    Public Sub OutputThatIsAFolder_Exits2(optionName As String)
        Using t As New TempFolder()
            Dim scenePath = t.Write("scene.json", HeadOn)
            Directory.CreateDirectory(t.File("out"))
            Dim r = RunCli("run", scenePath, "--time", "1", optionName, t.File("out"))
            Assert.True(r.ExitCode = 2, r.ToString())
            Assert.Equal(optionName & ": '" & t.File("out") & "' is a folder, not a file", r.StdErr.TrimEnd())
        End Using
    End Sub

    <Theory>
    <InlineData("--states")>
    <InlineData("--events")>
    <InlineData("--series")>
    Public Sub AnOutputOnTopOfTheScene_IsBadInput_AndTheSceneSurvives(optionName As String)
        Using t As New TempFolder()
            Dim scenePath = t.Write("scene.json", HeadOn)
            Dim r = RunCli("run", scenePath, "--time", "1", optionName, scenePath)
            Assert.True(r.ExitCode = 2, r.ToString())
            Assert.Equal(optionName & ": '" & scenePath & "' is the scene file itself", r.StdErr.TrimEnd())
            Assert.Equal(HeadOn, File.ReadAllText(scenePath))
        End Using
    End Sub

    <Theory>
    <InlineData("--states")>
    <InlineData("--series")>
    Public Sub BadInput_LeavesAnExistingOutputFileUntouched(optionName As String)
        Using t As New TempFolder()
            Dim scenePath = t.Write("scene.json", HeadOn)
            Dim output = t.Write("out.csv", "precious")
            Dim r = RunCli("run", scenePath, "--time", "-5", optionName, output)
            Assert.True(r.ExitCode = 2, r.ToString())
            Assert.Equal("precious", File.ReadAllText(output))
            Assert.Equal("out.csv|scene.json", String.Join("|", t.Files()))
        End Using
    End Sub

    <Fact>
    Public Sub RunHelp_PrintsUsage_AndExits0()
        Dim r = RunCli("run", "--help")
        Assert.True(r.ExitCode = 0, r.ToString())
        Assert.Contains("run SCENE --time T", r.StdOut)
    End Sub

    ''' <summary>Runs "run" with {scene}, {states} and {events} replaced by paths in the folder.</summary>
    Private Shared Function Run(t As TempFolder, scenePath As String, args As String()) As ProcessResult
        Dim all As New List(Of String) From {"run"}
        For Each a In args
            all.Add(a.Replace(Scene, scenePath).Replace(States, t.File("states.csv")).Replace(Events, t.File("events.csv")))
        Next
        Return RunCli(all.ToArray())
    End Function

    Private Shared Sub AssertOneLineAndNothingWritten(t As TempFolder, r As ProcessResult)
        Dim errLines = r.StdErr.TrimEnd().Split(ChrW(10))
        Assert.True(errLines.Length = 1 AndAlso errLines(0).Length > 0, r.ToString())
        Assert.Equal("scene.json", String.Join("|", t.Files()))
    End Sub
End Class
