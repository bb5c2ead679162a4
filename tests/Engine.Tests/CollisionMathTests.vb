Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>The response maths against the textbook formulas for a 1D collision.</summary>
Public Class CollisionMathTests
    <Theory>
    <InlineData(1.0, 2.0, 1.0, 0.0, 1.0)>
    <InlineData(2.0, 3.0, 1.0, -1.0, 1.0)>
    <InlineData(1.0, 5.0, 3.0, 0.0, 0.5)>
    <InlineData(1.0, 1.0, 1000000.0, 0.0, 0.0)>
    Public Sub HeadOnImpulse_MatchesTextbookFormula(m1 As Double, u1 As Double, m2 As Double, u2 As Double, e As Double)
        ' Normal from B to A is −x: A is on the left moving right.
        Dim result = Impulse.Resolve(New Vector(u1, 0), 1 / m1, New Vector(u2, 0), 1 / m2, New Vector(-1, 0), e)
        Dim v1 = (m1 * u1 + m2 * u2 + m2 * e * (u2 - u1)) / (m1 + m2)
        Dim v2 = (m1 * u1 + m2 * u2 + m1 * e * (u1 - u2)) / (m1 + m2)
        Assert.Equal(v1, result.A.X, 12)
        Assert.Equal(v2, result.B.X, 12)
        Assert.Equal(m1 * u1 + m2 * u2, m1 * result.A.X + m2 * result.B.X, 9)
    End Sub

    <Fact>
    Public Sub CoincidentCentres_GiveAFiniteNormal()
        Dim c = Collider.CircleCircle(New Vector(1, 1), 0.5, New Vector(1, 1), 0.5)
        Assert.True(c.Normal.IsFinite)
        Assert.Equal(1.0, c.Normal.Length, 12)
        Assert.Equal(1.0, c.Depth, 12)
    End Sub
End Class
