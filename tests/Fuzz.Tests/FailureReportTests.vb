Option Strict On
Imports System.IO
Imports PhysicsEngine.Fuzzing
Imports PhysicsEngine.Fuzzing.Checking
Imports PhysicsEngine.Fuzzing.Generation
Imports PhysicsEngine.Fuzzing.Shrinking
Imports Xunit

''' <summary>Failing scenes are written as &lt;invariant&gt;-&lt;seed&gt;.json with one README line holding the command that shows them.</summary>
Public Class FailureReportTests
    Private Shared ReadOnly EventOnly As String() = {"event"}

    <Fact>
    Public Sub TheCommand_RunsTheFileWithTheFailingRunsSettings()
        Dim plan As New RunPlan(0.35, 0.05, 0.013, 10)
        Dim overlap As New Violation(Invariants.Overlap, "event", 0.013, 0.2, "a and b overlap")
        Dim path = IO.Path.Combine(Directory.GetCurrentDirectory(), "out", "overlap-7.json")
        Assert.Equal("dotnet run -c Release --project src/SimulatorCli -- run out/overlap-7.json --time 0.35 --solver event --sample 0.013 --states s.csv",
                     FailureReport.Command(path, overlap, plan))
        Dim sampling As New Violation(Invariants.Sampling, "event", 0.05, 0.2, "collision #3 differs")
        Assert.Equal("dotnet run -c Release --project src/SimulatorCli -- run out/overlap-7.json --time 0.35 --solver event --sample 0.05 --states s.csv --events a.csv && " &
                     "dotnet run -c Release --project src/SimulatorCli -- run out/overlap-7.json --time 0.35 --solver event --sample 0.013 --states s.csv --events b.csv && diff a.csv b.csv",
                     FailureReport.Command(path, sampling, plan))
    End Sub

    <Fact>
    Public Sub WritingTwice_KeepsOneLinePerFile()
        Dim folder = Path.Combine(Path.GetTempPath(), "fuzz-report-" & Guid.NewGuid().ToString("N"))
        Try
            Dim doc = SceneGenerator.Generate(9, BodyKinds.Default, 40).ToDoc()
            Dim plan As New RunPlan(1, 0.05, 0.013, 10)
            Dim outcome As New SceneOutcome("9", 9, doc, plan)
            Dim v As New Violation(Invariants.Energy, "event", 0.05, 0.1, "energy grew")
            Dim small = doc.WithBodies(doc.Bodies.Take(2))
            Dim shrunk As New ShrinkResult(small, plan.WithTime(0.1), v, 12, True)
            Dim file = FailureReport.Write(folder, outcome, v, shrunk, EventOnly)
            FailureReport.Write(folder, outcome, v, shrunk, EventOnly)
            Assert.Equal("energy-9.json", Path.GetFileName(file))
            Assert.Equal(small.ToText(), IO.File.ReadAllText(file))
            Dim lines = IO.File.ReadAllLines(Path.Combine(folder, "README.md")).Where(Function(l) l.StartsWith("- ", StringComparison.Ordinal)).ToList()
            Dim line = Assert.Single(lines)
            Assert.Contains("2 of " & doc.Bodies.Count & " bodies", line, StringComparison.Ordinal)
            Assert.Contains("--time 0.1 --solver event --sample 0.05", line, StringComparison.Ordinal)
        Finally
            If Directory.Exists(folder) Then Directory.Delete(folder, recursive:=True)
        End Try
    End Sub
End Class
