Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' A blow from above on a body lying on level, frictionless ground (<see cref="Impulse.ResolveOnLevelGround"/>):
''' the ground takes the vertical part, the body the horizontal part.
''' </summary>
Public Class LevelGroundImpulseTests
    <Fact>
    Public Sub AnObliqueBlow_KeepsMomentumAlongTheGround_AndTheRestitutionLaw()
        Dim rng As New Random(11)
        For trial = 1 To 200
            Dim angle = (0.05 + 0.9 * rng.NextDouble()) * Math.PI ' n points upwards, from B towards A
            Dim n = New Vector(Math.Cos(angle), Math.Sin(angle))
            Dim ma = 0.1 + 10 * rng.NextDouble(), mb = 0.1 + 10 * rng.NextDouble()
            Dim e = rng.NextDouble()
            Dim va = New Vector(rng.NextDouble() * 4 - 2, -1 - 5 * rng.NextDouble())
            Dim vb = New Vector(rng.NextDouble() * 2 - 1, 0)
            If Vector.Dot(va - vb, n) >= 0 Then Continue For
            Dim r = Impulse.ResolveOnLevelGround(va, 1 / ma, vb, 1 / mb, n, e)
            ' Along the ground nothing else acts: momentum in x is kept.
            Assert.Equal(ma * va.X + mb * vb.X, ma * r.A.X + mb * r.B.X, 9)
            ' The ground holds B: its vertical velocity is what it was.
            Assert.Equal(vb.Y, r.B.Y)
            ' Newton's law of restitution along the normal.
            Assert.Equal(-e * Vector.Dot(va - vb, n), Vector.Dot(r.A - r.B, n), 9)
            ' The impulse on A is along n.
            Dim dA = r.A - va
            Assert.True(Math.Abs(dA.X * n.Y - dA.Y * n.X) <= 1.0E-12 * (1 + dA.Length), $"trial {trial}: A's change {dA} is not along {n}")
        Next
    End Sub

    <Fact>
    Public Sub WithEOfOne_NoEnergyIsLost()
        Dim n = New Vector(0.6, 0.8)
        Dim va = New Vector(0.5, -3), vb = New Vector(0, 0)
        Const Ma = 2.0, Mb = 0.5
        Dim r = Impulse.ResolveOnLevelGround(va, 1 / Ma, vb, 1 / Mb, n, 1.0)
        Dim before = 0.5 * Ma * va.LengthSquared + 0.5 * Mb * vb.LengthSquared
        Dim after = 0.5 * Ma * r.A.LengthSquared + 0.5 * Mb * r.B.LengthSquared
        Assert.Equal(before, after, 12)
    End Sub

    <Fact>
    Public Sub TheClosedForm_ForEqualBallsStruckAt60Degrees()
        ' n = (cos 60°, sin 60°): B takes the blow with inverse mass n_x²/m = 1/4 along n, so
        ' j = (1 + e) u sin 60° / (1 + 1/4) for A falling at u; B moves off at −j cos 60°.
        Dim n = New Vector(0.5, Math.Sqrt(3) / 2)
        Const U = 4.0, E = 0.5
        Dim r = Impulse.ResolveOnLevelGround(New Vector(0, -U), 1.0, Vector.Zero, 1.0, n, E)
        Dim j = (1 + E) * U * n.Y / 1.25
        Assert.Equal(-j * 0.5, r.B.X, 12)
        Assert.Equal(0.0, r.B.Y)
        Assert.Equal(j * n.X, r.A.X, 12)
        Assert.Equal(-U + j * n.Y, r.A.Y, 12)
    End Sub

    <Fact>
    Public Sub AStraightDownBlow_LeavesTheBodyWhereItIs_AndASeparatingPairAlone()
        Dim r = Impulse.ResolveOnLevelGround(New Vector(0, -2), 1.0, Vector.Zero, 1.0, New Vector(0, 1), 0.5)
        Assert.Equal(Vector.Zero, r.B)
        Assert.Equal(New Vector(0, 1), r.A)
        Dim apart = Impulse.ResolveOnLevelGround(New Vector(0, 2), 1.0, Vector.Zero, 1.0, New Vector(0.6, 0.8), 0.5)
        Assert.Equal(New Vector(0, 2), apart.A)
        Assert.Equal(Vector.Zero, apart.B)
    End Sub
End Class
