Option Strict On
Imports System.IO
Imports Xunit

''' <summary>
''' Where an output table goes when its path is not a plain file: through a symbolic link (the link
''' stays, its target is replaced whole), into a FIFO or a link to one, as /dev/stdout is (written straight through, since
''' a stream cannot be replaced). These are POSIX file kinds, made here with ln and mkfifo.
''' </summary>
Public Class CliOutputTargetTests
    Private Const StatesHeader As String = "t,id,x,y,vx,vy"

    Private Shared Sub Shell(program As String, ParamArray args As String())
        Dim r = ProcessRunner.Run(program, args, Nothing, TimeSpan.FromSeconds(30))
        Assert.True(r.ExitCode = 0, program & ": " & r.ToString())
    End Sub

    ''' <summary>Every entry of the folder, hidden ones (temporary outputs) included.</summary>
    Private Shared Function AllFiles(folder As String) As String
        Dim options As New EnumerationOptions With {.AttributesToSkip = 0}
        Return String.Join(" ", Directory.GetFileSystemEntries(folder, "*", options).Select(Function(f) Path.GetFileName(f)).OrderBy(Function(f) f, StringComparer.Ordinal))
    End Function

    ''' <summary>
    ''' Runs the scene for 0.2 s with its states table going to <paramref name="statesPath"/> while
    ''' a reader opens <paramref name="fifo"/> and reads until the writer closes it; returns what it read.
    ''' </summary>
    Private Shared Function RunReadingFifo(scene As String, statesPath As String, fifo As String) As String
        Dim reader = Threading.Tasks.Task.Run(Function() File.ReadAllText(fifo))
        Dim r = RunCli("run", scene, "--time", "0.2", "--sample", "0.1", "--states", statesPath)
        Assert.True(r.ExitCode = 0, r.ToString())
        Assert.True(reader.Wait(TimeSpan.FromSeconds(30)), "the reader never saw the end of the table")
        Return reader.Result
    End Function

    <Fact>
    Public Sub SymbolicLink_IsKept_AndItsTargetReplacedWhole()
        If OperatingSystem.IsWindows() Then Return ' links need extra rights there
        Using t As New TempFolder()
            Dim scene = t.Write("head-on.json", HeadOn)
            Directory.CreateDirectory(t.File("real"))
            File.WriteAllText(t.File(Path.Combine("real", "states.csv")), "old")
            Shell("ln", "-s", Path.Combine("real", "states.csv"), t.File("link.csv"))
            Dim r = RunCli("run", scene, "--time", "0.2", "--sample", "0.1", "--states", t.File("link.csv"))
            Assert.True(r.ExitCode = 0, r.ToString())
            Assert.NotNull(New FileInfo(t.File("link.csv")).LinkTarget)
            Dim text = File.ReadAllText(t.File(Path.Combine("real", "states.csv")))
            Assert.StartsWith(StatesHeader & vbLf, text)
            Assert.Equal(7, text.TrimEnd(ChrW(10)).Split(ChrW(10)).Length) ' header + 3 samples × 2 circles
            Assert.Equal("head-on.json link.csv real", AllFiles(t.Path))
            Assert.Equal("states.csv", AllFiles(t.File("real")))
        End Using
    End Sub

    <Fact>
    Public Sub Fifo_IsWrittenThrough_AndStaysAFifo()
        If OperatingSystem.IsWindows() Then Return ' no FIFOs there
        Using t As New TempFolder()
            Dim scene = t.Write("head-on.json", HeadOn)
            Dim fifo = t.File("states.fifo")
            Shell("mkfifo", fifo)
            Dim text = RunReadingFifo(scene, fifo, fifo)
            Assert.StartsWith(StatesHeader & vbLf, text)
            Assert.Equal(7, text.TrimEnd(ChrW(10)).Split(ChrW(10)).Length)
            Assert.Equal("head-on.json states.fifo", AllFiles(t.Path))
            Assert.Equal(0L, New FileInfo(fifo).Length) ' still the FIFO, not a file put in its place
        End Using
    End Sub

    ''' <summary>
    ''' What /dev/stdout is when the output goes to a pipe: a link to a stream. Made here in the test's
    ''' own folder, so a regression replaces a link of the test's, not the machine's /dev/stdout.
    ''' </summary>
    <Fact>
    Public Sub LinkToAFifo_LikeDevStdout_IsWrittenThrough()
        If OperatingSystem.IsWindows() Then Return ' no FIFOs there
        Using t As New TempFolder()
            Dim scene = t.Write("head-on.json", HeadOn)
            Dim fifo = t.File("pipe")
            Shell("mkfifo", fifo)
            Shell("ln", "-s", fifo, t.File("stdout"))
            Assert.StartsWith(StatesHeader & vbLf, RunReadingFifo(scene, t.File("stdout"), fifo))
            Assert.NotNull(New FileInfo(t.File("stdout")).LinkTarget)
            Assert.Equal("head-on.json pipe stdout", AllFiles(t.Path))
        End Using
    End Sub
    <Fact>
    Public Sub SeriesIntoAFifo_IsWrittenThrough()
        If OperatingSystem.IsWindows() Then Return ' no FIFOs there
        Using t As New TempFolder()
            Dim scene = t.Write("head-on.json", HeadOn)
            Dim fifo = t.File("series.fifo")
            Shell("mkfifo", fifo)
            Dim reader = Threading.Tasks.Task.Run(Function() File.ReadAllText(fifo))
            Dim r = RunCli("run", scene, "--time", "0.2", "--sample", "0.1", "--series", fifo)
            Assert.True(r.ExitCode = 0, r.ToString())
            Assert.True(reader.Wait(TimeSpan.FromSeconds(30)), "the reader never saw the end of the table")
            Assert.StartsWith("t,ke,pe,energy,px,py,com_x,com_y,dissipated" & vbLf, reader.Result)
            Assert.Equal(4, reader.Result.TrimEnd(ChrW(10)).Split(ChrW(10)).Length) ' header + 3 samples
            Assert.Equal("head-on.json series.fifo", AllFiles(t.Path))
        End Using
    End Sub
End Class
