Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' Where a sleeping body touches two supports exactly (<see cref="RestSupport.Touching"/>): lines n · p = h and
''' circles |p − c| = R, two at a time, the crossing nearest the body's position.
''' </summary>
Public Class RestSupportTests
    Private Shared Sub AssertAt(expected As Vector, actual As Vector?, digits As Integer)
        Assert.True(actual.HasValue, $"no crossing, expected {expected}")
        Assert.Equal(expected.X, actual.Value.X, digits)
        Assert.Equal(expected.Y, actual.Value.Y, digits)
    End Sub

    ''' <summary>
    ''' A ball (r = 5 cm) in the V of two balls of the same size on the floor 16 cm apart: the pair shapes are circles of
    ''' R = 0.1 m about their centres, and the ball touches both at (0.13, 0.05 + √(0.1² − 0.08²)) = (0.13, 0.11) m.
    ''' From a point a few micrometres off, the upper crossing; from below the centres, the lower one.
    ''' </summary>
    <Fact>
    Public Sub BallInTheHollowOfTwoBalls_TouchesBothAtTheCrossingNearIt()
        Dim left = RestSupport.Round(New Vector(0.05, 0.05), 0.1)
        Dim right = RestSupport.Round(New Vector(0.21, 0.05), 0.1)
        AssertAt(New Vector(0.13, 0.11), RestSupport.Touching(New Vector(0.129989704987789, 0.1100137242301), left, right), 15)
        AssertAt(New Vector(0.13, 0.11), RestSupport.Touching(New Vector(0.13, 0.11), right, left), 15)
        AssertAt(New Vector(0.13, -0.01), RestSupport.Touching(New Vector(0.13, 0.0), left, right), 15)
    End Sub

    ''' <summary>
    ''' A ball (r = 5 cm) on the floor (its centre's line y = 0.05 m) against a neighbour of r = 3 cm on the floor at
    ''' x = 0.3 m (centre (0.3, 0.03), R = 0.08 m): δ = 0.02 m, so it touches both at x = 0.3 − √(0.08² − 0.02²).
    ''' </summary>
    <Fact>
    Public Sub BallOnTheFloorAgainstASmallerNeighbour_TouchesBoth()
        Dim floor = RestSupport.Flat(New Vector(0, 1), 0.05)
        Dim neighbour = RestSupport.Round(New Vector(0.3, 0.03), 0.08)
        Dim expected = New Vector(0.3 - Math.Sqrt(0.08 * 0.08 - 0.02 * 0.02), 0.05)
        AssertAt(expected, RestSupport.Touching(New Vector(0.2225, 0.05004), floor, neighbour), 15)
        AssertAt(expected, RestSupport.Touching(New Vector(0.2225, 0.05004), neighbour, floor), 15)
    End Sub

    ''' <summary>Two flat faces: the point where they cross, as for a ball in a V of two slopes.</summary>
    <Fact>
    Public Sub TwoSlopes_CrossAtOnePoint()
        Dim s = Math.Sqrt(0.5)
        Dim a = RestSupport.Flat(New Vector(s, s), s * 1.0)   ' x + y = 1
        Dim b = RestSupport.Flat(New Vector(-s, s), 0)        ' y = x
        AssertAt(New Vector(0.5, 0.5), RestSupport.Touching(New Vector(0.49, 0.52), a, b), 15)
    End Sub

    ''' <summary>
    ''' No single point: circles too far apart, one inside the other, concentric; a line that misses a circle or only
    ''' grazes it (the two normals there less than 0.08° apart); parallel faces.
    ''' </summary>
    <Fact>
    Public Sub SupportsWithoutOneCommonPoint_GiveNone()
        Dim p = New Vector(0, 0)
        Assert.False(RestSupport.Touching(p, RestSupport.Round(New Vector(0, 0), 1), RestSupport.Round(New Vector(3, 0), 1)).HasValue)
        Assert.False(RestSupport.Touching(p, RestSupport.Round(New Vector(0, 0), 3), RestSupport.Round(New Vector(0.5, 0), 1)).HasValue)
        Assert.False(RestSupport.Touching(p, RestSupport.Round(New Vector(0, 0), 1), RestSupport.Round(New Vector(0, 0), 1)).HasValue)
        Dim floor = RestSupport.Flat(New Vector(0, 1), 0)
        Assert.False(RestSupport.Touching(p, floor, RestSupport.Round(New Vector(0, -2), 1)).HasValue)
        Assert.False(RestSupport.Touching(p, floor, RestSupport.Round(New Vector(0, -0.9999995), 1)).HasValue)
        Assert.True(RestSupport.Touching(p, floor, RestSupport.Round(New Vector(0, -0.99999), 1)).HasValue)
        Assert.False(RestSupport.Touching(p, floor, RestSupport.Flat(New Vector(0, 1), 1)).HasValue)
    End Sub

    ''' <summary>One support alone: a point goes straight out onto a circle, or along the normal onto a line.</summary>
    <Fact>
    Public Sub NearestPointOfOneSupport_IsAlongItsNormal()
        Dim ball = RestSupport.Round(New Vector(1, 1), 0.5)
        Dim p = New Vector(1.3, 1.4 + 0.001)
        Dim n = ball.NormalAt(p)
        Assert.Equal(1.0, n.Length, 15)
        Dim q = ball.Nearest(p)
        Assert.Equal(0.5, (q - New Vector(1, 1)).Length, 15)
        Assert.Equal(0.0, (q - New Vector(1, 1)).X * n.Y - (q - New Vector(1, 1)).Y * n.X, 15)
        Dim floor = RestSupport.Flat(New Vector(0, 1), 0.05)
        Assert.Equal(New Vector(0.2, 0.05), floor.Nearest(New Vector(0.2, 0.0500123)))
    End Sub
End Class
