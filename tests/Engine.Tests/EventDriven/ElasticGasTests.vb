Option Strict On
Imports PhysicsEngine
Imports Xunit
Imports Xunit.Abstractions

''' <summary>Invariants of a long elastic-gas run: energy and momentum books balance, nothing overlaps.</summary>
Public Class ElasticGasTests
    Private ReadOnly _output As ITestOutputHelper

    Public Sub New(output As ITestOutputHelper)
        _output = output
    End Sub

    <Fact>
    Public Sub ElasticGas_AMillionCollisions_ConservesEnergy_AndNeverOverlaps()
        Dim w = Scenarios.ElasticGas(1000)
        UseEventSolver(w)
        Dim e0 = w.KineticEnergy()
        Dim worst = 0.0
        Dim watch = Diagnostics.Stopwatch.StartNew()
        Dim slices = 0
        While w.CollisionCount < 1000000 AndAlso slices < 100000
            w.Advance(0.5)
            slices += 1
            If slices Mod 20 = 0 Then worst = Math.Max(worst, DeepestOverlap(w))
        End While
        watch.Stop()
        worst = Math.Max(worst, DeepestOverlap(w))
        _output.WriteLine($"{w.CollisionCount} collisions in {watch.Elapsed.TotalSeconds:F2} s of wall time ({w.CollisionCount / watch.Elapsed.TotalSeconds:F0}/s, this build), simulated {w.Time} s")
        Assert.True(w.CollisionCount >= 1000000)
        Assert.True(Relative(w.KineticEnergy(), e0) < 1.0E-9, $"energy drift {Relative(w.KineticEnergy(), e0)}")
        Assert.True(worst <= 1.0E-9, $"overlap {worst} m")
        For Each c In w.Circles
            Assert.True(c.Position.IsFinite AndAlso c.Velocity.IsFinite)
        Next
    End Sub
End Class
