Option Strict On
Imports System.Globalization
Imports System.IO
Imports System.Runtime.InteropServices
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' The event solver's two pair tests, and its two builds, give the same run to the last bit: the
''' same collisions at the same times with the same velocities, and the same final state. The
''' net10.0 build is run here with the vectorised and the one-at-a-time pair test; the netstandard2.0
''' build (the app's) is run by the engine's test program for it, under Mono (directly on Windows).
''' No tolerance is needed: Math.Cos, Sin and Acos (slides round a corner) come from the C library
''' in both runtimes, Math.Sqrt is the processor's, and neither JIT fuses a·b + c into one rounding,
''' so every scene agrees to the last bit.
''' </summary>
Public Class BuildAgreementTests
    Public Shared ReadOnly Property Scenes As TheoryData(Of String)
        Get
            Return New TheoryData(Of String)(CollisionLog.SceneNames)
        End Get
    End Property

    <Theory>
    <MemberData(NameOf(Scenes))>
    Public Sub VectorAndScalarPairTests_GiveTheSameRun_BitForBit(scene As String)
        Dim scalar = CollisionLog.Record(scene, vectorScan:=False)
        Dim vector = CollisionLog.Record(scene, vectorScan:=True)
        AssertRich(scene, scalar)
        AssertSameRun(scalar, vector, "one at a time", "vectorised")
    End Sub

    <Theory>
    <MemberData(NameOf(Scenes))>
    Public Sub NetStandardBuild_GivesTheSameRun_BitForBit(scene As String)
        Dim reference = CollisionLog.Record(scene, vectorScan:=False)
        Dim result = RunNetStandardBuild(scene)
        Assert.True(result.ExitCode = 0, result.ToString())
        Dim other = result.StdOut.Split({vbLf}, StringSplitOptions.RemoveEmptyEntries).Select(Function(l) l.TrimEnd(ChrW(13))).ToList()
        AssertSameRun(reference, other, "net10.0", "netstandard2.0")
    End Sub

    ''' <summary>
    ''' The scene exercises what it is there for, so that agreeing means something: the fewest
    ''' collisions of each kind it must have (its run has several times as many).
    ''' </summary>
    Private Shared Sub AssertRich(scene As String, log As List(Of String))
        Dim kinds = log.Where(Function(l) l.StartsWith("collision ", StringComparison.Ordinal)).
                        GroupBy(Function(l) l.Split(" "c)(4)).ToDictionary(Function(g) g.Key, Function(g) g.Count())
        Dim least As New Dictionary(Of String, Integer) From {{"circle-circle", 1000}, {"circle-wall", 50}}
        Select Case scene
            Case "mixed"
                least("circle-rectangle") = 50
                least("circle-fixed") = 10
            Case "tables"
                least("circle-circle") = 100
                least("circle-rectangle") = 100
        End Select
        For Each kv In least
            Dim seen = 0
            kinds.TryGetValue(kv.Key, seen)
            Assert.True(seen >= kv.Value, $"{scene}: {seen} {kv.Key} collisions, fewer than {kv.Value}")
        Next
    End Sub

    ''' <summary>Equal line for line; else the first line that differs, with the numbers in decimal and how many units in the last place apart.</summary>
    Private Shared Sub AssertSameRun(expected As List(Of String), actual As List(Of String), expectedName As String, actualName As String)
        Dim n = Math.Min(expected.Count, actual.Count)
        For k = 0 To n - 1
            If expected(k) <> actual(k) Then
                Assert.Fail($"line {k} of {expected.Count} differs:{vbLf}{expectedName}: {Readable(expected(k))}{vbLf}{actualName}: {Readable(actual(k))}{vbLf}{Ulps(expected(k), actual(k))}")
            End If
        Next
        Assert.True(expected.Count = actual.Count, $"{expectedName} has {expected.Count} lines, {actualName} {actual.Count}")
    End Sub

    ''' <summary>A record line with its doubles in decimal.</summary>
    Private Shared Function Readable(line As String) As String
        Return String.Join(" ", line.Split(" "c).Select(Function(f) If(f.Length = 16, CollisionLog.FromBits(f).ToString("R", CultureInfo.InvariantCulture), f)))
    End Function

    ''' <summary>Field by field, how many units in the last place two record lines are apart (in decimal: two bit patterns of opposite sign overflow a Long).</summary>
    Private Shared Function Ulps(a As String, b As String) As String
        Dim fa = a.Split(" "c), fb = b.Split(" "c)
        If fa.Length <> fb.Length Then Return "(different kinds of line)"
        Return "ulps apart: " & String.Join(" ", fa.Zip(fb, Function(x, y) If(x.Length = 16 AndAlso y.Length = 16,
            Math.Abs(CDec(Long.Parse(x, NumberStyles.HexNumber, CultureInfo.InvariantCulture)) - CDec(Long.Parse(y, NumberStyles.HexNumber, CultureInfo.InvariantCulture))).ToString(CultureInfo.InvariantCulture),
            If(x = y, "=", "≠"))))
    End Function

    ''' <summary>The engine's test program for its netstandard2.0 build, asked for one scene's record.</summary>
    Private Shared Function RunNetStandardBuild(scene As String) As ProcessResult
        Dim exe = Path.Combine(RepoRoot, "tests", "Engine.Tests.Mono", "bin", Configuration, "net48", "Engine.Tests.exe")
        Assert.True(File.Exists(exe), exe & " is not built")
        If RuntimeInformation.IsOSPlatform(OSPlatform.Windows) Then
            Return ProcessRunner.Run(exe, {"--collision-log", scene}, Nothing, TimeSpan.FromMinutes(5))
        End If
        Return ProcessRunner.Run("mono", {exe, "--collision-log", scene}, Nothing, TimeSpan.FromMinutes(5))
    End Function
End Class
