Option Strict On
Imports PhysicsEngine
Imports Xunit

''' <summary>
''' A blow on a body B that slides on a fixed, frictionless face with unit tangent t
''' (<see cref="Impulse.ResolveOnFace"/>): the face takes the part of the blow across it, B moves only along t.
''' </summary>
Public Class FaceImpulseTests
    ''' <summary>A random blow from above on a face tilted by up to ±60°, with n and t both drawn at random.</summary>
    Private Shared Function RandomBlow(rng As Random) As (N As Vector, T As Vector, Ma As Double, Mb As Double, E As Double, Va As Vector, Vb As Vector)
        Dim tilt = (rng.NextDouble() * 2 - 1) * Math.PI / 3
        Dim t = New Vector(Math.Cos(tilt), Math.Sin(tilt))
        Dim s = t.Perpendicular()
        If s.Y < 0 Then s = -s
        ' n within 80° of the face's normal, so the blow on B (along −n) presses B into its face.
        Dim turn = (rng.NextDouble() * 2 - 1) * 80 * Math.PI / 180
        Dim n = New Vector(s.X * Math.Cos(turn) - s.Y * Math.Sin(turn), s.X * Math.Sin(turn) + s.Y * Math.Cos(turn))
        Dim vb = t * (rng.NextDouble() * 4 - 2)
        Dim va = vb + New Vector(rng.NextDouble() * 4 - 2, rng.NextDouble() * 4 - 2) - n * (0.1 + 3 * rng.NextDouble())
        Return (n, t, 0.1 + 10 * rng.NextDouble(), 0.1 + 10 * rng.NextDouble(), rng.NextDouble(), va, vb)
    End Function

    <Fact>
    Public Sub ABlowOnASlider_MovesItOnlyAlongItsFace_KeepsMomentumAlongIt_AndTheRestitutionLaw()
        Dim rng As New Random(7)
        Dim tried = 0
        For trial = 1 To 300
            Dim c = RandomBlow(rng)
            If Vector.Dot(c.Va - c.Vb, c.N) >= 0 Then Continue For
            tried += 1
            Dim r = Impulse.ResolveOnFace(c.Va, 1 / c.Ma, c.Vb, 1 / c.Mb, c.N, c.T, c.E)
            ' B stays on its face: its change of velocity has no part across the face.
            Dim dB = r.B - c.Vb
            Assert.True(Math.Abs(dB.X * c.T.Y - dB.Y * c.T.X) <= 1.0E-12 * (1 + dB.Length), $"trial {trial}: B's change {dB} leaves its face")
            ' Along the face nothing else acts: momentum along t is kept.
            Assert.Equal(Vector.Dot(c.Va * c.Ma + c.Vb * c.Mb, c.T), Vector.Dot(r.A * c.Ma + r.B * c.Mb, c.T), 9)
            ' Newton's law of restitution along the normal.
            Assert.Equal(-c.E * Vector.Dot(c.Va - c.Vb, c.N), Vector.Dot(r.A - r.B, c.N), 9)
            ' Kinetic energy never rises.
            Dim before = 0.5 * c.Ma * c.Va.LengthSquared + 0.5 * c.Mb * c.Vb.LengthSquared
            Dim after = 0.5 * c.Ma * r.A.LengthSquared + 0.5 * c.Mb * r.B.LengthSquared
            Assert.True(after <= before * (1 + 1.0E-12), $"trial {trial}: energy rose from {before} J to {after} J")
        Next
        Assert.True(tried > 100, $"only {tried} approaching blows were drawn")
    End Sub

    <Fact>
    Public Sub WithEOfOne_NoEnergyIsLost_OnATiltedFace()
        Dim rng As New Random(3)
        For trial = 1 To 100
            Dim c = RandomBlow(rng)
            If Vector.Dot(c.Va - c.Vb, c.N) >= 0 Then Continue For
            Dim r = Impulse.ResolveOnFace(c.Va, 1 / c.Ma, c.Vb, 1 / c.Mb, c.N, c.T, 1.0)
            Dim before = 0.5 * c.Ma * c.Va.LengthSquared + 0.5 * c.Mb * c.Vb.LengthSquared
            Dim after = 0.5 * c.Ma * r.A.LengthSquared + 0.5 * c.Mb * r.B.LengthSquared
            Assert.Equal(1.0, after / before, 12)
        Next
    End Sub

    <Fact>
    Public Sub OnALevelFace_ItIsTheLevelGroundBlow()
        Dim n = New Vector(0.6, 0.8)
        Dim va = New Vector(0.5, -3), vb = New Vector(0.25, 0)
        Dim onFace = Impulse.ResolveOnFace(va, 0.5, vb, 2.0, n, New Vector(1, 0), 0.4)
        Dim onGround = Impulse.ResolveOnLevelGround(va, 0.5, vb, 2.0, n, 0.4)
        Assert.Equal(onGround.A.X, onFace.A.X, 14)
        Assert.Equal(onGround.A.Y, onFace.A.Y, 14)
        Assert.Equal(onGround.B.X, onFace.B.X, 14)
        Assert.Equal(onGround.B.Y, onFace.B.Y, 14)
    End Sub

    <Fact>
    Public Sub ASeparatingPair_IsLeftAlone()
        Dim va = New Vector(0, 2), vb = New Vector(1, 0)
        Dim r = Impulse.ResolveOnFace(va, 1.0, vb, 1.0, New Vector(0.6, 0.8), New Vector(1, 0), 0.5)
        Assert.Equal(va, r.A)
        Assert.Equal(vb, r.B)
    End Sub
End Class
