Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' A blow that presses a body B into the fixed frictionless face it slides on (<see cref="Impulse.ResolveOnFace"/>):
''' the face takes the part across it, B moves only along the face's tangent t.
''' </summary>
Public Class FaceImpulseTests
    ''' <summary>A random face (level to 60° either way), a normal n from B towards A that presses B into it, masses and velocities.</summary>
    Private Shared Function RandomBlow(rng As Random, ByRef t As Vector, ByRef n As Vector, ByRef ma As Double, ByRef mb As Double,
                                       ByRef va As Vector, ByRef vb As Vector) As Boolean
        Dim tilt = (rng.NextDouble() * 2 - 1) * Math.PI / 3
        t = New Vector(Math.Cos(tilt), Math.Sin(tilt))
        Dim s = t.Perpendicular() ' the face's normal, pointing up
        ' n within 85° of the face's normal: the blow on B (along −n) presses it into the face.
        Dim angle = (rng.NextDouble() * 2 - 1) * 85 * Math.PI / 180
        n = s * Math.Cos(angle) + t * Math.Sin(angle)
        ma = 0.1 + 10 * rng.NextDouble()
        mb = 0.1 + 10 * rng.NextDouble()
        va = New Vector(rng.NextDouble() * 4 - 2, rng.NextDouble() * 4 - 2)
        vb = t * (rng.NextDouble() * 4 - 2) ' B slides along its face
        Return Vector.Dot(va - vb, n) < 0
    End Function

    <Theory>
    <InlineData(0.0)>
    <InlineData(0.5)>
    <InlineData(1.0)>
    Public Sub AnObliqueBlow_KeepsMomentumAlongTheFace_TheRestitutionLaw_AndNeverRaisesTheEnergy(e As Double)
        Dim rng As New Random(27)
        Dim tried = 0
        For trial = 1 To 500
            Dim t, n, va, vb As Vector
            Dim ma, mb As Double
            If Not RandomBlow(rng, t, n, ma, mb, va, vb) Then Continue For
            tried += 1
            Dim r = Impulse.ResolveOnFace(va, 1 / ma, vb, 1 / mb, n, t, e)
            ' Along the face nothing else acts: momentum along t is kept.
            Assert.Equal(Vector.Dot(va * ma + vb * mb, t), Vector.Dot(r.A * ma + r.B * mb, t), 9)
            ' The face holds B: its velocity changes only along t.
            Assert.True(Math.Abs(Vector.Cross(r.B - vb, t)) <= 1.0E-12 * (1 + (r.B - vb).Length), $"trial {trial}: B's change {r.B - vb} is not along {t}")
            ' Newton's law of restitution along the normal.
            Assert.Equal(-e * Vector.Dot(va - vb, n), Vector.Dot(r.A - r.B, n), 9)
            ' The face does no work: the energy never rises, and with e = 1 it is kept.
            Dim before = 0.5 * ma * va.LengthSquared + 0.5 * mb * vb.LengthSquared
            Dim after = 0.5 * ma * r.A.LengthSquared + 0.5 * mb * r.B.LengthSquared
            Assert.True(after <= before * (1 + 1.0E-12), $"trial {trial}: energy {before} J → {after} J")
            If e = 1 Then Assert.True(Math.Abs(after - before) <= 1.0E-12 * before, $"trial {trial}: energy {before} J → {after} J at e = 1")
        Next
        Assert.True(tried > 100, $"only {tried} approaching blows")
    End Sub

    <Fact>
    Public Sub OnALevelFace_ItIsTheLevelGroundImpulse()
        Dim n = New Vector(0.6, 0.8)
        Dim va = New Vector(0.5, -3), vb = New Vector(0.25, 0)
        Dim onFace = Impulse.ResolveOnFace(va, 0.5, vb, 2.0, n, New Vector(1, 0), 0.3)
        Dim onGround = Impulse.ResolveOnLevelGround(va, 0.5, vb, 2.0, n, 0.3)
        Assert.Equal(onGround.A.X, onFace.A.X, 14)
        Assert.Equal(onGround.A.Y, onFace.A.Y, 14)
        Assert.Equal(onGround.B.X, onFace.B.X, 14)
        Assert.Equal(onGround.B.Y, onFace.B.Y, 14)
    End Sub

    <Fact>
    Public Sub TheClosedForm_ForABlowAcrossA30DegreeFace()
        ' t at 30° below level, n along the face's normal: (n·t) = 0, so B takes none of the blow and A
        ' bounces as off the face itself; n at 45° to the normal: B takes it with inverse mass ½/m_B.
        Dim t = New Vector(Math.Cos(Math.PI / 6), -Math.Sin(Math.PI / 6))
        Dim s = New Vector(Math.Sin(Math.PI / 6), Math.Cos(Math.PI / 6))
        Dim va = s * -2.0, vb = t * 1.0
        Dim square = Impulse.ResolveOnFace(va, 1.0, vb, 1.0, s, t, 0.5)
        Assert.Equal(vb, square.B)
        Assert.Equal(1.0, Vector.Dot(square.A, s), 12)
        Dim n = (s + t) * (1 / Math.Sqrt(2))
        Dim r = Impulse.ResolveOnFace(va, 1.0, vb, 1.0, n, t, 0.0)
        ' j = −(1 + e) (v_rel · n) / (1/m_A + (n·t)²/m_B), v_rel · n = (−2 s − t) · n = −3/√2.
        Dim j = (3 / Math.Sqrt(2)) / 1.5
        Assert.Equal(1.0 - j / Math.Sqrt(2), Vector.Dot(r.B, t), 12)
        Assert.Equal(0.0, Vector.Dot(r.A - r.B, n), 12)
    End Sub

    <Fact>
    Public Sub ASeparatingPair_IsLeftAlone()
        Dim r = Impulse.ResolveOnFace(New Vector(0, 2), 1.0, Vector.Zero, 1.0, New Vector(0.6, 0.8), New Vector(1, 0), 0.5)
        Assert.Equal(New Vector(0, 2), r.A)
        Assert.Equal(Vector.Zero, r.B)
    End Sub
End Class
