Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Links
    ''' <summary>Elliptic integrals and Jacobi functions against quadrature, known values and their identities.</summary>
    Public Class EllipticFunctionTests
        <Fact>
        Public Sub CompleteIntegral_MatchesKnownValues()
            ' K(0) = π/2; K(1/√2) = Γ(1/4)² / (4√π) (the lemniscatic case).
            Assert.Equal(Math.PI / 2, EllipticIntegral.CompleteFirstKind(1), 1.0E-15)
            Assert.Equal(1.8540746773013719, EllipticIntegral.CompleteFirstKind(Math.Sqrt(0.5)), 1.0E-14)
            ' K(k) → ln(4/k′) as k′ → 0: at k′ = 1e-8 the correction is O(k′² ln k′), below 1e-14.
            Dim kc = 0.00000001
            Assert.Equal(Math.Log(4 / kc), EllipticIntegral.CompleteFirstKind(kc), 1.0E-12)
            Assert.Equal(Double.PositiveInfinity, EllipticIntegral.CompleteFirstKind(0))
        End Sub

        <Theory>
        <InlineData(0.1)>
        <InlineData(0.5)>
        <InlineData(0.9)>
        <InlineData(0.999)>
        Public Sub IncompleteIntegral_MatchesQuadrature(k As Double)
            Dim kc = EllipticIntegral.Complement(k)
            For Each phi In {0.1, 0.7, 1.2, 1.5, Math.PI / 2, 2.0, 3.0, -1.1, 5.0, -7.5}
                Dim expected = LinkTestKit.EllipticFByQuadrature(phi, k)
                Assert.Equal(expected, EllipticIntegral.IncompleteFirstKind(phi, kc), 1.0E-11)
                Dim principal = phi - 2 * Math.PI * Math.Round(phi / (2 * Math.PI))
                If Math.Abs(principal) <= Math.PI Then
                    Dim byPair = EllipticIntegral.IncompleteFirstKind(Math.Sin(phi), Math.Cos(phi), kc)
                    Assert.Equal(LinkTestKit.EllipticFByQuadrature(principal, k), byPair, 1.0E-11)
                End If
            Next
            Assert.Equal(LinkTestKit.EllipticFByQuadrature(Math.PI / 2, k), EllipticIntegral.CompleteFirstKind(kc), 1.0E-11)
        End Sub

        <Theory>
        <InlineData(0.0)>
        <InlineData(0.3)>
        <InlineData(0.8)>
        <InlineData(0.99999)>
        Public Sub Jacobi_InvertsTheIntegral(k As Double)
            ' am(F(φ)) = φ, so sn = sin φ, cn = cos φ, dn = √(1 − k² sin² φ) at u = F(φ) (F checked by quadrature above).
            Dim kc = EllipticIntegral.Complement(k)
            Dim jacobi As New JacobiElliptic(kc)
            For Each phi In {0.0, 0.2, 1.0, 1.5, 1.5707, 2.5, 3.1, -0.4, -2.9, 4.0, 9.0, -20.0}
                Dim u = EllipticIntegral.IncompleteFirstKind(phi, kc)
                Dim sn As Double, cn As Double, dn As Double
                jacobi.Evaluate(u, sn, cn, dn)
                Assert.Equal(Math.Sin(phi), sn, 1.0E-13)
                Assert.Equal(Math.Cos(phi), cn, 1.0E-13)
                Assert.Equal(Math.Sqrt(1 - k * k * Math.Sin(phi) * Math.Sin(phi)), dn, 1.0E-13)
                Assert.Equal(phi, jacobi.Amplitude(u), 1.0E-12)
            Next
        End Sub

        <Fact>
        Public Sub Jacobi_SatisfiesIdentitiesAndPeriods()
            Dim rng As New Random(5)
            For trial = 1 To 200
                Dim k = rng.NextDouble()
                Dim jacobi As New JacobiElliptic(EllipticIntegral.Complement(k))
                Dim quarter = jacobi.QuarterPeriod
                Dim u = (rng.NextDouble() - 0.5) * 40
                Dim sn As Double, cn As Double, dn As Double
                jacobi.Evaluate(u, sn, cn, dn)
                Assert.Equal(1.0, sn * sn + cn * cn, 1.0E-14)
                Assert.Equal(1.0, dn * dn + k * k * sn * sn, 1.0E-14)
                ' sn(u + 2K) = −sn(u), cn(u + 2K) = −cn(u), dn(u + 2K) = dn(u).
                Dim s2 As Double, c2 As Double, d2 As Double
                jacobi.Evaluate(u + 2 * quarter, s2, c2, d2)
                Assert.Equal(-sn, s2, 1.0E-12)
                Assert.Equal(-cn, c2, 1.0E-12)
                Assert.Equal(dn, d2, 1.0E-12)
                ' d sn/du = cn dn, by a centred difference of step 1e-5 (error ~1e-10).
                Dim h = 0.00001
                Dim slope = (jacobi.Sn(u + h) - jacobi.Sn(u - h)) / (2 * h)
                Assert.Equal(cn * dn, slope, 1.0E-8)
            Next
        End Sub

        <Fact>
        Public Sub Jacobi_NearModulusOne_TendsToTanhAndSech()
            ' sn(u, k) = tanh u + O(k′²) for bounded u; at k′ = 1e-9 that is 1e-18.
            Dim jacobi As New JacobiElliptic(0.000000001)
            For Each u In {-3.0, -0.5, 0.0, 0.25, 1.0, 4.0, 10.0}
                Assert.Equal(Math.Tanh(u), jacobi.Sn(u), 1.0E-14)
                Assert.Equal(1 / Math.Cosh(u), jacobi.Cn(u), 1.0E-14)
                Assert.Equal(1 / Math.Cosh(u), jacobi.Dn(u), 1.0E-14)
            Next
            Dim exact As New JacobiElliptic(0)
            Assert.Equal(Math.Tanh(2.0), exact.Sn(2.0), 1.0E-15)
        End Sub

        <Fact>
        Public Sub CarlsonRF_MatchesItsElementaryCases()
            ' R_F(x, y, y) = arccos(√(x/y))/√(y − x) for x < y; R_F(0, 1, 2) = 1.3110287771461 (Carlson 1995, table).
            Assert.Equal(Math.Acos(0.5) / Math.Sqrt(3.0), EllipticIntegral.CarlsonRF(1, 4, 4), 1.0E-14)
            Assert.Equal(1.3110287771461, EllipticIntegral.CarlsonRF(0, 1, 2), 1.0E-12)
            Assert.Equal(1.0, EllipticIntegral.CarlsonRF(1, 1, 1), 1.0E-15)
        End Sub
    End Class
End Namespace
