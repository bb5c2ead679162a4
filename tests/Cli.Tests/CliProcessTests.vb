Option Strict On
Imports Xunit

''' <summary>The real SimulatorCli process: verbs, exit codes, messages.</summary>
Public Class CliProcessTests
    <Fact>
    Public Sub NoArguments_PrintsUsageToStdErr_AndExits2()
        Dim r = RunCli()
        Assert.True(r.ExitCode = 2, r.ToString())
        Assert.Contains("usage:", r.StdErr)
        Assert.Single(r.StdErr.TrimEnd().Split(ChrW(10)))
    End Sub

    <Fact>
    Public Sub UnknownVerb_SaysWhich_AndExits2()
        Dim r = RunCli("fly")
        Assert.True(r.ExitCode = 2, r.ToString())
        Assert.Contains("unknown verb 'fly'", r.StdErr)
    End Sub
End Class
