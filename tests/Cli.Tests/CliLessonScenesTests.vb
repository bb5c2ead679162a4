Option Strict On
Imports System.IO
Imports System.Text.Json
Imports Xunit

''' <summary>The lesson scenes run from the command line give the numbers their lessons promise.</summary>
Public Class CliLessonScenesTests
    ''' <summary>
    ''' π from collisions: a block of mass m between a wall and a block of mass M, e = 1. In the
    ''' coordinates (√m·v, √M·V) each collision is a reflection, and the two lines of reflection meet
    ''' at θ = atan √(m/M), so the blocks collide ⌈π/θ⌉ − 1 times in all (the wall hits included):
    ''' 31, 314 and 3141 for M/m = 10², 10⁴ and 10⁶.
    ''' </summary>
    <Theory>
    <InlineData("pi-31.json", 31)>
    <InlineData("pi-314.json", 314)>
    <InlineData("pi-3141.json", 3141)>
    Public Sub PiScene_CollidesAsOftenAsTheDigitsOfPi(name As String, digits As Integer)
        Dim file = Path.Combine(RepoRoot, "scenes", name)
        Dim m As Double, big As Double
        Using doc = JsonDocument.Parse(IO.File.ReadAllText(file))
            For Each b In doc.RootElement.GetProperty("bodies").EnumerateArray()
                Dim id = b.GetProperty("id").GetString()
                If id = "small" Then m = b.GetProperty("mass").GetDouble()
                If id = "big" Then big = b.GetProperty("mass").GetDouble()
            Next
        End Using
        Dim expected = CLng(Math.Ceiling(Math.PI / Math.Atan(Math.Sqrt(m / big)))) - 1
        Assert.Equal(CLng(digits), expected)

        ' Long enough for the big block to turn round and leave: no collision comes after.
        For Each seconds In {"30", "120"}
            Dim r = RunCli("run", Path.Combine("scenes", name), "--time", seconds, "--solver", "event", "--json")
            Assert.True(r.ExitCode = 0, r.ToString())
            Using doc = JsonDocument.Parse(r.StdOut)
                Dim s = doc.RootElement
                Assert.Equal(expected, s.GetProperty("collisions").GetInt64())
                ' e = 1: the big block's kinetic energy, ½ M (1 m/s)², is all still there.
                Assert.Equal(0.5 * big, s.GetProperty("kinetic_energy").GetDouble(), 0.5 * big * 1.0E-9)
            End Using
        Next
    End Sub
End Class
