Option Strict On
Imports PhysicsEngine
Imports PhysicsEngine.Benchmarks
Imports Xunit

''' <summary>The closed forms the benchmark measures against, checked by hand and by conservation laws.</summary>
Public Class ClosedFormsTests
    <Fact>
    Public Sub BounceApex_IsESquaredToTheNTimesTheDropHeight()
        Assert.Equal(0.81, ClosedForms.BounceApex(1.0, 0.9, 1), 12)
        Assert.Equal(Math.Pow(0.5, 6) * 2.0, ClosedForms.BounceApex(2.0, 0.5, 3), 12)
    End Sub

    <Fact>
    Public Sub BounceRestTime_IsT0TimesOnePlusEOverOneMinusE()
        Dim t0 = Math.Sqrt(2 * 1.0 / 9.81)
        Assert.Equal(t0 * 19, ClosedForms.BounceRestTime(1.0, 0.9, 9.81), 12)
        Assert.Equal(8.579, ClosedForms.BounceRestTime(1.0, 0.9, 9.81), 3)
        Assert.True(Double.IsPositiveInfinity(ClosedForms.BounceRestTime(1.0, 1.0, 9.81)))
    End Sub

    <Fact>
    Public Sub BounceImpactTimes_AddUpToTheRestTime()
        Dim t0 = Math.Sqrt(2 / 9.81)
        Assert.Equal(t0, ClosedForms.BounceImpactTime(1.0, 0.9, 9.81, 1), 12)
        Assert.Equal(t0 + 2 * t0 * 0.9, ClosedForms.BounceImpactTime(1.0, 0.9, 9.81, 2), 12)
        Assert.Equal(ClosedForms.BounceRestTime(1.0, 0.9, 9.81), ClosedForms.BounceImpactTime(1.0, 0.9, 9.81, 2000), 9)
    End Sub

    <Fact>
    Public Sub Projectile_LandsAtTheRangeFormula()
        Dim t = ClosedForms.ProjectileFlightTime(10, Math.PI / 4, 9.81)
        Dim p = ClosedForms.ProjectilePosition(New Vector(1, 0.05), New Vector(10 * Math.Cos(Math.PI / 4), 10 * Math.Sin(Math.PI / 4)), 9.81, t)
        Assert.Equal(1 + 100 / 9.81, p.X, 9) ' R = v² sin 2θ / g
        Assert.Equal(0.05, p.Y, 12)
    End Sub

    <Fact>
    Public Sub ObliqueExit_SpeedsAreV0CosPhiAndV0SinPhi_AtRightAngles_ConservingMomentumAndEnergy()
        Dim v = ClosedForms.ObliqueExitVelocities(2.0, 0.1, 0.1) ' sin φ = 0.5
        Assert.Equal(2 * Math.Cos(Math.PI / 6), v.Target.Length, 12)
        Assert.Equal(2 * Math.Sin(Math.PI / 6), v.Striker.Length, 12)
        Assert.Equal(0.0, Vector.Dot(v.Striker, v.Target), 12)
        Assert.Equal(2.0, (v.Striker + v.Target).X, 12)
        Assert.Equal(0.0, (v.Striker + v.Target).Y, 12)
        Assert.Equal(4.0, v.Striker.LengthSquared + v.Target.LengthSquared, 12)
        Assert.True(v.Target.Y < 0, "the target sits below the striker's line, so it is pushed down")
    End Sub
End Class
