Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Links
    ''' <summary>The dumbbell in closed form against a computation by hand and its conservation laws.</summary>
    Public Class DumbbellTests
        Private Const G As Double = 9.81

        <Fact>
        Public Sub AtFiveSeconds_MatchesTheHandComputation()
            ' m₁ = 1 kg at (0, 10) moving (1, −2); m₂ = 3 kg at (2, 10) moving (1, 2); L = 2 m.
            ' Centre of mass (1.5, 10), velocity ((1 + 3)/4, (−2 + 6)/4) = (1, 1).
            ' Relative velocity (0, 4) across the rod (1, 0): ω = 4 / 2 = 2 rad/s.
            ' At t = 5 s: centre (6.5, 10 + 5 − ½ 9.81 · 25) = (6.5, −107.625); the rod has turned 10 rad.
            Dim d As New Dumbbell(1, New Vector(0, 10), New Vector(1, -2), 3, New Vector(2, 10), New Vector(1, 2), 2, G)
            Assert.Equal(2.0, d.AngularVelocity, 0.000000000000001)
            Dim p1 As Vector, v1 As Vector, p2 As Vector, v2 As Vector
            d.StateAt(5, p1, v1, p2, v2)
            Dim centre As New Vector(6.5, -107.625)
            Dim r As New Vector(2 * Math.Cos(10), 2 * Math.Sin(10))
            Assert.True(LinkTestKit.Distance(centre - 0.75 * r, p1) < 0.000000001, p1.ToString())
            Assert.True(LinkTestKit.Distance(centre + 0.25 * r, p2) < 0.000000001, p2.ToString())
            ' Velocities: centre (1, 1 − 9.81·5) plus the turning part ω r⊥ shared 3:1.
            Dim turning As New Vector(-2 * 2 * Math.Sin(10), 2 * 2 * Math.Cos(10))
            Dim centreVelocity As New Vector(1, 1 - G * 5)
            Assert.True(LinkTestKit.Distance(centreVelocity - 0.75 * turning, v1) < 0.000000001)
            Assert.True(LinkTestKit.Distance(centreVelocity + 0.25 * turning, v2) < 0.000000001)
            ' Tension μω²L = (3/4)·4·2 = 6 N.
            Assert.Equal(6.0, d.Tension, 0.000000000001)
        End Sub

        <Fact>
        Public Sub RandomStarts_KeepLengthMomentumAndAngularMomentum()
            Dim rng As New Random(8)
            For trial = 1 To 100
                Dim m1 = 0.1 + rng.NextDouble() * 5, m2 = 0.1 + rng.NextDouble() * 5
                Dim length = 0.2 + rng.NextDouble() * 3
                Dim angle = rng.NextDouble() * 2 * Math.PI
                Dim p1 As New Vector(rng.NextDouble() * 4, rng.NextDouble() * 4)
                Dim dir As New Vector(Math.Cos(angle), Math.Sin(angle))
                Dim p2 = p1 + length * dir
                Dim v1 As New Vector(rng.NextDouble() * 6 - 3, rng.NextDouble() * 6 - 3)
                ' The relative velocity across the rod only (its part along the rod removed).
                Dim v2 = v1 + (rng.NextDouble() * 10 - 5) * dir.Perpendicular()
                Dim d As New Dumbbell(m1, p1, v1, m2, p2, v2, length, G)
                Dim total = m1 + m2
                Dim spin0 = AngularMomentumAboutCentre(m1, p1, v1, m2, p2, v2)
                For Each t In {0.3, 1.0, 7.7}
                    Dim q1 As Vector, u1 As Vector, q2 As Vector, u2 As Vector
                    d.StateAt(t, q1, u1, q2, u2)
                    Assert.Equal(length, (q2 - q1).Length, 0.000000000001 * length)
                    Dim momentum = (m1 * u1 + m2 * u2) - total * New Vector(0, -G * t)
                    Assert.True(LinkTestKit.Distance(m1 * v1 + m2 * v2, momentum) < 0.000000001)
                    Assert.Equal(spin0, AngularMomentumAboutCentre(m1, q1, u1, m2, q2, u2), 0.000000001 * (1 + Math.Abs(spin0)))
                    ' Relative velocity stays across the rod.
                    Assert.Equal(0.0, Vector.Dot(q2 - q1, u2 - u1), 0.000000001)
                Next
            Next
        End Sub

        Private Shared Function AngularMomentumAboutCentre(m1 As Double, p1 As Vector, v1 As Vector, m2 As Double, p2 As Vector, v2 As Vector) As Double
            Dim total = m1 + m2
            Dim c = (m1 * p1 + m2 * p2) / total
            Dim vc = (m1 * v1 + m2 * v2) / total
            Return m1 * Vector.Cross(p1 - c, v1 - vc) + m2 * Vector.Cross(p2 - c, v2 - vc)
        End Function
    End Class
End Namespace
