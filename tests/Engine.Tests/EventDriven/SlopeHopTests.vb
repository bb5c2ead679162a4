Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' How a slow body leaves a slope (<see cref="SlopeHop"/>): at least the minimum normal speed, and never
''' more kinetic energy than it came with plus what it lost in height.
''' </summary>
Public Class SlopeHopTests
    Private Const G As Double = 9.81
    ''' <summary>The minimum normal speed, m/s.</summary>
    Private Const U As Double = 0.002
    ''' <summary>A slope of 30°: its normal, and its tangent pointing downhill (towards +x).</summary>
    Private Shared ReadOnly Normal As New Vector(Math.Sin(Math.PI / 6), Math.Cos(Math.PI / 6))
    Private Shared ReadOnly Downhill As New Vector(Math.Cos(Math.PI / 6), -Math.Sin(Math.PI / 6))

    <Fact>
    Public Sub AlreadyFastEnough_LeavesAsItIs()
        Dim after = Normal * (2 * U) + Downhill * 0.3
        Dim shift As Vector
        Assert.Equal(after, SlopeHop.Depart(-Normal * (3 * U) + Downhill * 0.3, after, Normal, U, G, 1, shift))
        Assert.Equal(Vector.Zero, shift)
    End Sub

    <Fact>
    Public Sub LandingAtTheMinimum_LeavesAtItAgain_WithItsSpeedAlongTheSlope()
        ' A hop that lands at u on a flat slope leaves at u (as sliding would lose nothing), whatever e took.
        Dim before = -Normal * U + Downhill * 0.3
        Dim after = Normal * (0.1 * U) + Downhill * 0.3
        Dim shift As Vector
        Dim v = SlopeHop.Depart(before, after, Normal, U, G, 1, shift)
        Assert.Equal(U, Vector.Dot(v, Normal), 15)
        Assert.Equal(0.3, Vector.Dot(v, Downhill), 15)
        Assert.Equal(Vector.Zero, shift)
    End Sub

    <Fact>
    Public Sub LandingSlower_PaysTheDifferenceFromItsSpeedAlongTheSlope()
        ' The slope curved away beneath it: it landed at 0.8 u. Its energy stays what it came with.
        Dim before = -Normal * (0.8 * U) + Downhill * 0.01
        Dim after = Normal * (0.8 * U) + Downhill * 0.01
        Dim shift As Vector
        Dim v = SlopeHop.Depart(before, after, Normal, U, G, 1, shift)
        Assert.Equal(U, Vector.Dot(v, Normal), 15)
        Assert.True(Vector.Dot(v, Downhill) < 0.01 AndAlso Vector.Dot(v, Downhill) > 0, $"along the slope {Vector.Dot(v, Downhill)} m/s")
        Assert.Equal(before.LengthSquared, v.LengthSquared, 1.0E-12 * before.LengthSquared)
        Assert.Equal(Vector.Zero, shift)
    End Sub

    <Fact>
    Public Sub AtRest_MovesDownTheTangent_ByTheHeightThatPaysForTheHop()
        Dim shift As Vector
        Dim v = SlopeHop.Depart(Vector.Zero, Vector.Zero, Normal, U, G, 1, shift)
        Assert.Equal(U, Vector.Dot(v, Normal), 15)
        Assert.Equal(0.0, Vector.Dot(shift, Normal), 1.0E-12 * shift.Length) ' along the tangent: never into the support
        Assert.True(shift.Y < 0, $"moved to {shift}")
        ' ½ u² = g h
        Assert.Equal(0.5 * U * U, G * -shift.Y, 1.0E-12 * U * U)
    End Sub

    <Fact>
    Public Sub AtRestNearTheTop_MovesNoFurtherThanAllowed_AndHopsLower()
        ' 10⁻⁴ rad from the top the full height would take a move of 2 mm; it may move 10 µm.
        Dim n = New Vector(Math.Sin(0.0001), Math.Cos(0.0001))
        Dim shift As Vector
        Dim v = SlopeHop.Depart(Vector.Zero, Vector.Zero, n, U, G, 0.00001, shift)
        Assert.Equal(0.00001, shift.Length, 1.0E-17)
        Assert.True(Vector.Dot(v, n) < U AndAlso Vector.Dot(v, n) > 0, $"normal speed {Vector.Dot(v, n)} m/s")
        Assert.Equal(0.5 * v.LengthSquared, G * -shift.Y, 1.0E-12 * v.LengthSquared)
    End Sub

    <Fact>
    Public Sub AtRest_NotAllowedToMove_GainsNothing()
        Dim shift As Vector
        Dim v = SlopeHop.Depart(Vector.Zero, Vector.Zero, Normal, U, G, 0, shift)
        Assert.Equal(Vector.Zero, v)
        Assert.Equal(Vector.Zero, shift)
    End Sub
End Class
