Option Strict On
Imports Xunit

''' <summary>Coulomb's law as impulses: sticking within μs j_n, sliding with μk j_n, never reversing the slip.</summary>
Public Class ContactFrictionTests
    <Fact>
    Public Sub Sticks_WhenStoppingTakesAtMostMuSTimesTheNormalImpulse()
        ' m_eff 2 kg, slip 0.1 m/s: stopping takes 0.2 N·s; μs j_n = 0.5 × 0.5.
        Assert.Equal(0.2, ContactFriction.TangentialImpulse(0.1, 2, 0.5, 0.5, 0.3), 15)
    End Sub

    <Fact>
    Public Sub Slides_WithMuKTimesTheNormalImpulse_OtherwiseNeverReversing()
        Assert.Equal(0.3 * 0.5, ContactFriction.TangentialImpulse(1.0, 2, 0.5, 0.5, 0.3), 15)
        Assert.Equal(0.15, ContactFriction.TangentialImpulse(0.1, 2, 0.5, 0.3, 0.3), 15)
        ' Even a kinetic coefficient that could more than stop the slip only stops it: friction never reverses it.
        Assert.Equal(0.2, ContactFriction.TangentialImpulse(0.1, 2, 0.5, 0.1, 0.9), 15)
        Assert.Equal(0.0, ContactFriction.TangentialImpulse(0, 2, 0.5, 0.5, 0.3))
        Assert.Equal(0.0, ContactFriction.TangentialImpulse(1, 2, 0, 0.5, 0.3))
    End Sub

    <Fact>
    Public Sub TheTextbookResults()
        Assert.Equal(Math.Sqrt(0.2 * 0.8), ContactFriction.Mean(0.2, 0.8), 15)
        Assert.Equal(0.0, ContactFriction.Mean(0, 0.8))
        Assert.True(ContactFriction.HoldsOnSlope(Math.Atan(0.5) - 0.000001, 0.5))
        Assert.False(ContactFriction.HoldsOnSlope(Math.Atan(0.5) + 0.000001, 0.5))
        Assert.Equal(9.81 * (0.5 - 0.2 * Math.Sqrt(0.75)), ContactFriction.SlidingAcceleration(Math.PI / 6, 9.81, 0.2), 14)
        Assert.Equal(4.0 / (2 * 0.4 * 9.81), ContactFriction.StoppingDistance(2, 9.81, 0.4), 15)
    End Sub
End Class
