Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace EventDriven
    ''' <summary>
    ''' The quintic of an integrated step (<see cref="QuinticSteps"/>): it matches position, velocity and acceleration at both
    ''' ends, and between them reads the motion without losing it to the rounding of where the body is.
    ''' </summary>
    Public Class QuinticStepsTests
        ''' <summary>
        ''' A body 3.5 m from the origin at 22.7 m/s, stepping a microsecond with a small steady acceleration: its speed read
        ''' halfway is the exact one to 5·10⁻¹² (the rounding of p1 itself). Built from 10 p0 and 10 p1 (each rounded at 35 m), it read 10⁻⁸ m/s off, and
        ''' a 56 t ball showed 0.04 J of energy that was never there.
        ''' </summary>
        <Fact>
        Public Sub FarFromTheOriginInAShortStep_TheSpeedReadBetweenIsExact()
            Const h = 0.000001, p0 = 3.477891732808174, v0 = 22.741022221734084, a = 0.0125
            Dim p1 = p0 + v0 * h + 0.5 * a * h * h
            Dim v1 = v0 + a * h
            Dim c = QuinticSteps.Coefficients(p0, v0 * h, a * h * h, p1, v1 * h, a * h * h)
            For Each s In {0.25, 0.5, 0.75}
                Dim slope = c(1) + s * (2 * c(2) + s * (3 * c(3) + s * (4 * c(4) + s * 5 * c(5))))
                Dim exact = v0 + a * s * h
                Assert.True(Math.Abs(slope / h - exact) <= 0.000000000005 * exact, $"at s = {s}: {slope / h} m/s against {exact} m/s")
            Next
        End Sub

        ''' <summary>The quintic meets its six conditions: position, velocity and acceleration at s = 0 and s = 1.</summary>
        <Fact>
        Public Sub MatchesPositionVelocityAndAccelerationAtBothEnds()
            Dim c = QuinticSteps.Coefficients(1.5, 0.25, -0.125, 2.0, 0.5, 0.375)
            Dim at = Function(s As Double) c(0) + s * (c(1) + s * (c(2) + s * (c(3) + s * (c(4) + s * c(5)))))
            Dim slope = Function(s As Double) c(1) + s * (2 * c(2) + s * (3 * c(3) + s * (4 * c(4) + s * 5 * c(5))))
            Dim curve = Function(s As Double) 2 * c(2) + s * (6 * c(3) + s * (12 * c(4) + s * 20 * c(5)))
            Assert.Equal(1.5, at(0), 14)
            Assert.Equal(0.25, slope(0), 14)
            Assert.Equal(-0.125, curve(0), 14)
            Assert.Equal(2.0, at(1), 14)
            Assert.Equal(0.5, slope(1), 14)
            Assert.Equal(0.375, curve(1), 14)
        End Sub
    End Class
End Namespace
