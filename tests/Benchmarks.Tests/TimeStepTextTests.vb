Option Strict On
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>Time steps written as people write them.</summary>
Public Class TimeStepTextTests
    <Theory>
    <InlineData(60.0, "1/60")>
    <InlineData(4000.0, "1/4000")>
    <InlineData(30.0, "1/30")>
    Public Sub Format_WritesAWholeReciprocalAsAFraction(perSecond As Double, expected As String)
        Assert.Equal(expected, TimeStepText.Format(1 / perSecond))
    End Sub

    <Fact>
    Public Sub Format_WritesOtherStepsAsSeconds_AndNothingAsADash()
        Assert.Equal("0.0015", TimeStepText.Format(0.0015))
        Assert.Equal("—", TimeStepText.Format(Nothing))
    End Sub

    <Theory>
    <InlineData("1/60", 1 / 60.0)>
    <InlineData("0.001", 0.001)>
    <InlineData("1e-3", 0.001)>
    Public Sub TryParse_ReadsFractionsAndDecimals(text As String, expected As Double)
        Dim seconds As Double
        Assert.True(TimeStepText.TryParse(text, seconds))
        Assert.Equal(expected, seconds, 15)
    End Sub

    <Theory>
    <InlineData("1/0")>
    <InlineData("0")>
    <InlineData("-0.01")>
    <InlineData("abc")>
    <InlineData("1/")>
    <InlineData("")>
    Public Sub TryParse_RejectsWhatIsNotAPositiveStep(text As String)
        Dim seconds As Double
        Assert.False(TimeStepText.TryParse(text, seconds))
    End Sub
End Class
