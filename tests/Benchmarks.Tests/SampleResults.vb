Option Strict On
Imports PhysicsEngine.Benchmarks

''' <summary>Made-up results for the writer tests: they test the writing, not the physics.</summary>
Friend Module SampleResults
    Public Function Machine() As MachineInfo
        Return New MachineInfo With {.Date = "2026-01-02 03:04 UTC", .CpuModel = "Test CPU 3000", .Cores = 2, .MemoryGigabytes = 23.5,
                                     .OperatingSystem = "TestOS 1", .DotNet = ".NET 10.0.0"}
    End Function

    Public Function Scenes() As IReadOnlyList(Of IBenchScene)
        Return {New ProjectileScene()}
    End Function

    Public Function Results() As List(Of BenchResult)
        Return New List(Of BenchResult) From {
            New BenchResult With {.Scene = "projectile", .Solver = "event", .Error = 0.0, .ErrorMetric = "position error at landing (m)",
                                  .MsPerSimulatedSecond = 0.02, .CollisionsPerSecond = 50, .BodyCount = 1, .Runs = 5},
            New BenchResult With {.Scene = "projectile", .Solver = "euler", .TimeStep = 1 / 60.0, .Error = 0.05, .ErrorMetric = "position error at landing (m)",
                                  .MsPerSimulatedSecond = 0.1, .CollisionsPerSecond = 10, .BodyCount = 1, .Runs = 5},
            New BenchResult With {.Scene = "projectile", .Solver = "euler", .TimeStep = 1 / 1000.0, .Error = 0.003, .ErrorMetric = "position error at landing (m)",
                                  .MsPerSimulatedSecond = 2.5, .CollisionsPerSecond = 1, .BodyCount = 1, .Runs = 5},
            New BenchResult With {.Scene = "projectile", .Solver = "verlet", .Available = False, .Note = "not available in this build"},
            New BenchResult With {.Scene = "gas-scaling", .Solver = "event", .BodyCount = 1000, .MsPerSimulatedSecond = 40,
                                  .CollisionsPerSecond = 1234567, .MicrosecondsPerCollision = 0.81, .PeakMegabytes = 40.5, .Runs = 5},
            New BenchResult With {.Scene = "gas-scaling", .Solver = "event", .BodyCount = 10000, .MsPerSimulatedSecond = 450,
                                  .CollisionsPerSecond = 987654, .MicrosecondsPerCollision = 1.01, .PeakMegabytes = 60.25, .Runs = 5}}
    End Function
End Module
