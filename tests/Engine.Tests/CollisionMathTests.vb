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

    <Fact>
    Public Sub CircleOverATopFace_GetsTheFaceNormal()
        ' Rectangle [0, 2] × [0, 1]; circle of radius 0.5 centred 0.4 above the top face.
        Dim c = Collider.CircleRectangle(New Vector(1, 1.4), 0.5, New Vector(0, 0), New Vector(2, 1))
        Assert.Equal(New Vector(0, 1), c.Normal)
        Assert.Equal(0.1, c.Depth, 12)
    End Sub

    <Fact>
    Public Sub CircleBesideASideFace_GetsTheFaceNormal()
        Dim c = Collider.CircleRectangle(New Vector(-0.3, 0.5), 0.5, New Vector(0, 0), New Vector(2, 1))
        Assert.Equal(New Vector(-1, 0), c.Normal)
        Assert.Equal(0.2, c.Depth, 12)
    End Sub

    <Fact>
    Public Sub CircleNearACorner_GetsTheCornerNormal_AndReflectsAboutIt()
        ' Centre at 45° from the top-right corner (2, 1), 0.3 away; radius 0.5.
        Dim d = 0.3 / Math.Sqrt(2)
        Dim c = Collider.CircleRectangle(New Vector(2 + d, 1 + d), 0.5, New Vector(0, 0), New Vector(2, 1))
        Assert.Equal(1 / Math.Sqrt(2), c.Normal.X, 12)
        Assert.Equal(1 / Math.Sqrt(2), c.Normal.Y, 12)
        Assert.Equal(0.2, c.Depth, 12)
        ' Coming straight down onto the corner with e = 1: reflected about the corner normal, so it leaves along +x.
        Dim v = Impulse.Resolve(New Vector(0, -1), 1.0, Vector.Zero, 0.0, c.Normal, 1.0).A
        Assert.Equal(1.0, v.X, 12)
        Assert.Equal(0.0, v.Y, 12)
    End Sub

    <Fact>
    Public Sub CircleCentreInsideARectangle_LeavesThroughTheNearestFace()
        ' Centre 0.1 below the top face and far from the others.
        Dim c = Collider.CircleRectangle(New Vector(1, 0.9), 0.2, New Vector(0, 0), New Vector(2, 1))
        Assert.Equal(New Vector(0, 1), c.Normal)
        Assert.Equal(0.3, c.Depth, 12) ' out by 0.1 to the face, plus the radius
        Dim right = Collider.CircleRectangle(New Vector(1.95, 0.5), 0.2, New Vector(0, 0), New Vector(2, 1))
        Assert.Equal(New Vector(1, 0), right.Normal)
        Assert.Equal(0.25, right.Depth, 12)
    End Sub

    <Fact>
    Public Sub Walls_PointIntoTheContainer()
        Assert.Equal(New Vector(1, 0), Collider.CircleWall(New Vector(0.05, 1), 0.1, WallSide.Left, 4, 2).Normal)
        Assert.Equal(0.05, Collider.CircleWall(New Vector(0.05, 1), 0.1, WallSide.Left, 4, 2).Depth, 12)
        Assert.Equal(New Vector(0, -1), Collider.CircleWall(New Vector(1, 1.95), 0.1, WallSide.Top, 4, 2).Normal)
        Assert.Equal(0.05, Collider.CircleWall(New Vector(1, 1.95), 0.1, WallSide.Top, 4, 2).Depth, 12)
        Assert.True(Collider.CircleWall(New Vector(1, 1), 0.1, WallSide.Right, 4, 2).Depth < 0)
    End Sub

    <Fact>
    Public Sub ImpulseAgainstAFixedBody_ReversesOnlyTheNormalPart()
        ' Oblique hit on a floor with e = 0.5: tangential velocity kept (no friction), normal part × −e.
        Dim v = Impulse.Resolve(New Vector(3, -2), 1.0, Vector.Zero, 0.0, New Vector(0, 1), 0.5).A
        Assert.Equal(New Vector(3, 1), v)
    End Sub

    <Fact>
    Public Sub SeparatingPair_IsLeftAlone()
        Dim r = Impulse.Resolve(New Vector(1, 0), 1.0, New Vector(-1, 0), 1.0, New Vector(1, 0), 1.0)
        Assert.Equal(New Vector(1, 0), r.A)
        Assert.Equal(New Vector(-1, 0), r.B)
    End Sub
End Class
