Option Strict On
Imports System.Globalization
Imports System.IO
Imports System.Text.Json
Imports System.Text.RegularExpressions
Imports System.Xml.Linq
Imports Xunit

''' <summary>
''' The benchmark run as a real process on a tiny configuration, the way scripts/bench.sh runs it:
''' child processes, files written, JSON readable. Nothing here depends on how fast it ran.
''' </summary>
Public Class BenchmarkProcessTests
    Private Shared ReadOnly Property BenchmarkDll As String
        Get
            Return Path.Combine(ProcessRunner.RepoRoot, "src", "Benchmarks", "bin", ProcessRunner.Configuration, "net10.0", "Benchmarks.dll")
        End Get
    End Property

    Private Shared Function RunBenchmark(ParamArray args As String()) As ProcessResult
        Dim all As New List(Of String) From {BenchmarkDll}
        all.AddRange(args)
        Return ProcessRunner.Run("dotnet", all, Nothing, TimeSpan.FromMinutes(3))
    End Function

    <Fact>
    Public Sub TinyRun_WritesTheReportThePlotAndTheJson_AndListsAnUnknownSolverAsNotAvailable()
        Dim dir = Path.Combine(Path.GetTempPath(), "bench-smoke-" & Guid.NewGuid().ToString("N"))
        Try
            Dim json = Path.Combine(dir, "out", "results.json")
            Dim r = RunBenchmark("--quick", "--scenes", "projectile,gas-scaling", "--solvers", "euler,event,no-such-solver", "--dts", "1/60",
                                 "--gas-sizes", "60,50", "--gas-rounds", "2", "--repeats", "1", "--out", dir, "--json", json)
            Assert.True(r.ExitCode = 0, r.ToString())
            ' A round takes the sizes in turn, smallest first, and every solver at a size one after the
            ' other, so the event solver and the textbook baseline beside it meet the same spell.
            Dim firstRound = r.StdOut.Substring(0, r.StdOut.IndexOf("gas scaling, round 2", StringComparison.Ordinal))
            Dim order = Values("gas-scaling euler dt=1/1000 N=50:", "gas-scaling event dt=— N=50:", "gas-scaling textbook dt=— N=50:",
                               "gas-scaling euler dt=1/1000 N=60:", "gas-scaling event dt=— N=60:", "gas-scaling textbook dt=— N=60:").
                Select(Function(line) firstRound.IndexOf(line, StringComparison.Ordinal)).ToList()
            Assert.DoesNotContain(-1, order)
            Assert.Equal(order.OrderBy(Function(k) k), order)

            Dim md = File.ReadAllText(Path.Combine(dir, "benchmarks.md"))
            Assert.Contains("## Headline", md)
            Assert.Contains("## Projectile: position at landing", md)
            Assert.Contains("| euler | 1/60 |", md)
            Assert.Contains("| no-such-solver | — | — | — | — | not available in this build", md)
            Assert.Contains("## Scaling: elastic gas at packing fraction 0.1", md)
            Assert.Contains("## Recording for rewind (the app)", md)
            Assert.False(File.Exists(Path.Combine(dir, "benchmarks.md.tmp")), "no temporary file is left behind")

            Dim svg = XDocument.Load(Path.Combine(dir, "benchmark-projectile.svg"))
            Assert.Equal("svg", svg.Root.Name.LocalName)

            Using doc = JsonDocument.Parse(File.ReadAllText(json))
                Dim results = doc.RootElement.GetProperty("results").EnumerateArray().ToList()
                Dim projectile = results.Single(Function(e) e.GetProperty("scene").GetString() = "projectile" AndAlso e.GetProperty("solver").GetString() = "euler")
                Assert.True(projectile.GetProperty("available").GetBoolean())
                Assert.Equal(1 / 60.0, projectile.GetProperty("dt").GetDouble(), 12)
                Assert.True(projectile.GetProperty("error").GetDouble() > 0)
                Assert.True(projectile.GetProperty("msPerSimulatedSecond").GetDouble() > 0)
                Dim gas = results.First(Function(e) e.GetProperty("scene").GetString() = "gas-scaling" AndAlso e.GetProperty("solver").GetString() = "euler")
                Assert.Equal(50, gas.GetProperty("n").GetInt32())
                Assert.True(gas.GetProperty("peakMB").GetDouble() > 0, "peak memory comes from the child process")
                Assert.Contains(results, Function(e) e.GetProperty("solver").GetString() = "no-such-solver" AndAlso Not e.GetProperty("available").GetBoolean())
                ' The event solver's work counts behind its time: events per collision, cells searched per event.
                Dim exact = results.First(Function(e) e.GetProperty("scene").GetString() = "gas-scaling" AndAlso e.GetProperty("solver").GetString() = "event")
                Dim counts = Regex.Match(exact.GetProperty("note").GetString(), "; (\d+\.\d\d) events per collision, (\d+\.\d\d) cells searched per event$")
                ' Each size ran twice (--gas-rounds 2): the row is the slower run, and says so.
                Assert.Equal(2, exact.GetProperty("rounds").GetInt32())
                Assert.StartsWith("median of 2 runs, ", exact.GetProperty("note").GetString(), StringComparison.Ordinal)
                Assert.Equal(exact.GetProperty("slowestCollisionsPerSecond").GetDouble(), exact.GetProperty("collisionsPerSecond").GetDouble())
                Assert.True(counts.Success, exact.GetProperty("note").GetString())
                ' The gas children run with .NET's default tiered compilation, unlike the other scenes.
                Assert.DoesNotContain("tiered compilation off", exact.GetProperty("note").GetString(), StringComparison.Ordinal)
                Assert.InRange(Double.Parse(counts.Groups(1).Value, CultureInfo.InvariantCulture), 1.0, 5.0)
                Assert.InRange(Double.Parse(counts.Groups(2).Value, CultureInfo.InvariantCulture), 1.0, 18.0)
                ' The textbook baseline runs beside the event solver, in rounds as well, and says what it is.
                Dim baseline = results.First(Function(e) e.GetProperty("scene").GetString() = "gas-scaling" AndAlso e.GetProperty("solver").GetString() = "textbook")
                Assert.True(baseline.GetProperty("available").GetBoolean(), baseline.GetProperty("note").GetString())
                Assert.Equal(50, baseline.GetProperty("n").GetInt32())
                Assert.Equal(2, baseline.GetProperty("rounds").GetInt32())
                Assert.True(baseline.GetProperty("collisionsPerSecond").GetDouble() > 0)
                Assert.Matches("events per collision; the textbook baseline, not the engine", baseline.GetProperty("note").GetString())
            End Using
        Finally
            If Directory.Exists(dir) Then Directory.Delete(dir, True)
        End Try
    End Sub

    <Fact>
    Public Sub BadOption_ExitsWith2AndOneLineOnStandardError()
        Dim r = RunBenchmark("--dts", "fast")
        Assert.Equal(2, r.ExitCode)
        Assert.Equal("benchmarks: --dts: 'fast' is not a time step greater than 0 (write 1/60 or 0.001)", r.StdErr.Trim())
    End Sub
End Class
