Option Strict On
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>How the apex of a flight is read from samples.</summary>
Public Class SamplingTests
    <Theory>
    <InlineData(0.0)>
    <InlineData(0.3)>
    <InlineData(0.77)>
    Public Sub ParabolaPeak_FindsTheExactApex_WhateverTheSamplingPhase(phase As Double)
        ' y = 2 − 4.905 (t − 0.5)², sampled every 0.01 s starting at a phase of the step.
        Dim y = Function(t As Double) 2 - 4.905 * (t - 0.5) * (t - 0.5)
        Dim h = 0.01
        Dim t1 = 0.5 + (phase - 0.5) * h
        Assert.Equal(2.0, Sampling.ParabolaPeak(y(t1 - h), y(t1), y(t1 + h)), 12)
    End Sub

    <Fact>
    Public Sub ParabolaPeak_OfAFlatTriple_IsTheMiddleValue()
        Assert.Equal(1.0, Sampling.ParabolaPeak(1.0, 1.0, 1.0))
    End Sub
End Class
