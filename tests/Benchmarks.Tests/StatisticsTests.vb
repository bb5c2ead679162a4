Option Strict On
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>The median the timings are reported as.</summary>
Public Class StatisticsTests
    <Fact>
    Public Sub Median_OfAnOddCount_IsTheMiddleValue_WhateverTheOrder()
        Assert.Equal(3.0, Statistics.Median(Values(5.0, 1.0, 3.0)))
    End Sub

    <Fact>
    Public Sub Median_OfAnEvenCount_IsTheMeanOfTheTwoMiddleValues()
        Assert.Equal(2.5, Statistics.Median(Values(4.0, 1.0, 2.0, 3.0)))
    End Sub

    <Fact>
    Public Sub Median_IgnoresOneSlowOutlier()
        Assert.Equal(10.0, Statistics.Median(Values(10.0, 9.0, 11.0, 10.0, 500.0)))
    End Sub

    <Fact>
    Public Sub Median_DoesNotReorderTheCallersList()
        Dim list As New List(Of Double) From {3.0, 1.0, 2.0}
        Statistics.Median(list)
        Assert.Equal(Values(3.0, 1.0, 2.0), list)
    End Sub

    <Fact>
    Public Sub Median_OfNothingOrNaN_Throws()
        Assert.Throws(Of ArgumentException)(Function() Statistics.Median(Array.Empty(Of Double)()))
        Assert.Throws(Of ArgumentException)(Function() Statistics.Median(Values(1.0, Double.NaN)))
    End Sub
End Class
