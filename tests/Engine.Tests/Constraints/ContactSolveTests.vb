Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Constraints
    ''' <summary>
    ''' The complementarity solve of frictionless contact forces (docs/contact.md), against closed forms: what holds a
    ''' body in a V, a stack, a box on two supports, a bob on a rod against a wall; contacts that do not press; mass
    ''' ratios of 10¹²; and the same solve for the impulses of a blow.
    ''' </summary>
    Public Class ContactSolveTests
        Private Const G As Double = 9.81

        ''' <summary>Solves for accelerations under gravity alone: free (0, −g) for every body.</summary>
        Private Shared Function Accelerations(masses As Double(), rows As ContactRow(), ByRef forces As Double()) As Vector()
            Dim n = masses.Length
            Dim free = Enumerable.Repeat(New Vector(0, -G), n).ToArray()
            Dim result(n - 1) As Vector
            forces = New Double(rows.Length - 1) {}
            Dim solve As New ContactSolve()
            Assert.True(solve.Solve(masses.Select(Function(m) 1 / m).ToArray(), free, rows, ContactSolve.ApproachTolerance * G, result, forces))
            Return result
        End Function

        <Theory>
        <InlineData(0.1)>
        <InlineData(0.7)>
        <InlineData(1.3)>
        Public Sub BallInAV_EachFacePushesWithMgOverTwoCosAlpha_AndItStaysStill(alpha As Double)
            ' Faces at ±α from the vertical: their normals lean in by α, and the two pushes' vertical parts carry the
            ' weight: 2 N cos α = m g.
            Const M As Double = 2.5
            Dim rows = {New ContactRow(0, ContactRow.None, New Vector(Math.Sin(alpha), Math.Cos(alpha)), 0, False),
                        New ContactRow(0, ContactRow.None, New Vector(-Math.Sin(alpha), Math.Cos(alpha)), 0, False)}
            Dim forces As Double() = Nothing
            Dim masses = {M}
            Dim a = Accelerations(masses, rows, forces)
            Dim expected = M * G / (2 * Math.Cos(alpha))
            Assert.Equal(expected, forces(0), 12 - CInt(Math.Ceiling(Math.Log10(expected))))
            Assert.Equal(expected, forces(1), 12 - CInt(Math.Ceiling(Math.Log10(expected))))
            Assert.True(a(0).Length <= 0.000000000001 * G, $"a = {a(0)}")
        End Sub

        <Fact>
        Public Sub StackOfBoxes_EachFaceCarriesTheWeightAboveIt()
            ' Floor under box 0, box 0 under box 1, box 1 under box 2: the push on each face is the weight above it.
            Dim masses = {3.0, 1.5, 0.25}
            Dim up = New Vector(0, 1)
            Dim rows = {New ContactRow(0, ContactRow.None, up, 0, False),
                        New ContactRow(1, 0, up, 0, False),
                        New ContactRow(2, 1, up, 0, False)}
            Dim forces As Double() = Nothing
            Dim a = Accelerations(masses, rows, forces)
            Assert.Equal((3.0 + 1.5 + 0.25) * G, forces(0), 12)
            Assert.Equal((1.5 + 0.25) * G, forces(1), 12)
            Assert.Equal(0.25 * G, forces(2), 12)
            For Each v In a
                Assert.True(v.Length <= 0.000000000001 * G, $"a = {v}")
            Next
        End Sub

        <Fact>
        Public Sub BoxOnTwoSupportsSideBySide_TheyCarryItsWeightTogether_HoweverShared()
            ' Two faces with one normal under one body: which carries what is not decided by frictionless contact, but
            ' the body's acceleration is, and the pushes add up to the weight.
            Dim rows = {New ContactRow(0, ContactRow.None, New Vector(0, 1), 0, False),
                        New ContactRow(0, ContactRow.None, New Vector(0, 1), 0, False)}
            Dim forces As Double() = Nothing
            Dim masses = {4.0}
            Dim a = Accelerations(masses, rows, forces)
            Assert.Equal(4 * G, forces(0) + forces(1), 12)
            Assert.True(forces(0) >= 0 AndAlso forces(1) >= 0)
            Assert.True(a(0).Length <= 0.000000000001 * G, $"a = {a(0)}")
        End Sub

        <Fact>
        Public Sub ContactThatDoesNotPress_PushesNothing_AndTheBodyFalls()
            ' A wall beside a ball and a ceiling above it: gravity presses on neither.
            Dim rows = {New ContactRow(0, ContactRow.None, New Vector(1, 0), 0, False),
                        New ContactRow(0, ContactRow.None, New Vector(0, -1), 0, False)}
            Dim forces As Double() = Nothing
            Dim masses = {1.0}
            Dim a = Accelerations(masses, rows, forces)
            Assert.Equal(0.0, forces(0))
            Assert.Equal(0.0, forces(1))
            Assert.Equal(New Vector(0, -G), a(0))
        End Sub

        <Theory>
        <InlineData(0.3)>
        <InlineData(1.0)>
        Public Sub BobOnARodAgainstAWall_RodPullsMgOverCosTheta_WallPushesMgTanTheta(theta As Double)
            ' A bob on a rod at θ from the vertical, leaning on a wall on the side it would swing towards: the rod's
            ' pull along it and the wall's push across balance the weight, T cos θ = m g, N = T sin θ.
            Const M As Double = 0.8
            ' The rod from the bob up to its anchor, up and to the right: the bob hangs left of the anchor and would
            ' swing back right, so the wall is on its right and pushes left.
            Dim rod = New Vector(Math.Sin(theta), Math.Cos(theta))
            Dim rows = {New ContactRow(0, ContactRow.None, rod, 0, True),
                        New ContactRow(0, ContactRow.None, New Vector(-1, 0), 0, False)}
            Dim forces As Double() = Nothing
            Dim masses = {M}
            Dim a = Accelerations(masses, rows, forces)
            Assert.Equal(M * G / Math.Cos(theta), forces(0), 12)
            Assert.Equal(M * G * Math.Tan(theta), forces(1), 12)
            Assert.True(a(0).Length <= 0.000000000001 * G, $"a = {a(0)}")
        End Sub

        <Fact>
        Public Sub RodNeedingToPush_Pushes_ForItHoldsBothWays()
            ' A bob on a rod standing straight up from its anchor below: the rod pushes (a negative pull) m g.
            Dim rows = {New ContactRow(0, ContactRow.None, New Vector(0, -1), 0, True)}
            Dim forces As Double() = Nothing
            Dim masses = {2.0}
            Dim a = Accelerations(masses, rows, forces)
            Assert.Equal(-2 * G, forces(0), 12)
            Assert.True(a(0).Length <= 0.000000000001 * G)
        End Sub

        <Fact>
        Public Sub LightBallUnderAHeavyOne_AtAMassRatioOf1e12_NeitherMoves()
            ' 1 kg resting on a 10⁻¹² kg ball on the floor: the light ball's pushes, 10¹² times its weight, cancel to
            ' its weight exactly enough that neither accelerates.
            Dim up = New Vector(0, 1)
            Dim rows = {New ContactRow(0, ContactRow.None, up, 0, False),
                        New ContactRow(1, 0, up, 0, False)}
            Dim forces As Double() = Nothing
            Dim masses = {0.000000000001, 1.0}
            Dim a = Accelerations(masses, rows, forces)
            Assert.Equal(G * (1 + 0.000000000001), forces(0), 12)
            Assert.Equal(G, forces(1), 12)
            Assert.True(a(0).Length <= 0.000000001 * G, $"light a = {a(0)}")
            Assert.True(a(1).Length <= 0.000000000001 * G, $"heavy a = {a(1)}")
        End Sub

        <Fact>
        Public Sub HeadOnBlow_AsTheVelocityProblem_StopsTheApproach_MomentumKept()
            ' The same solve for impulses: two balls closing head on, one contact asked only to stop closing (e = 0):
            ' they leave together at the velocity of their centre of mass.
            Dim rows = {New ContactRow(1, 0, New Vector(1, 0), 0, False)}
            Dim result(1) As Vector, impulses(0) As Double
            Dim solve As New ContactSolve()
            Dim inverse = {1 / 2.0, 1 / 3.0}
            Dim before = {New Vector(4, 0), New Vector(-1, 0)}
            Assert.True(solve.Solve(inverse, before, rows, 0.000000000001, result, impulses))
            Assert.Equal(1.0, result(0).X, 12)
            Assert.Equal(1.0, result(1).X, 12)
            Assert.Equal(6.0, impulses(0), 12)
        End Sub

        <Fact>
        Public Sub KineticEnergy_NeverRises_OnRandomClusters()
            ' The velocities are the nearest to the old ones in the kinetic-energy metric that meet every row: with
            ' the immovable bodies at rest the energy never rises, and no row is left approaching.
            Dim rng As New Random(20261128)
            Dim solve As New ContactSolve()
            For trial = 1 To 300
                Dim n = rng.Next(1, 6)
                Dim inverse = Enumerable.Range(0, n).Select(Function(k) 1 / Math.Pow(10, rng.NextDouble() * 6 - 3)).ToArray()
                Dim v = Enumerable.Range(0, n).Select(Function(k) New Vector(rng.NextDouble() * 4 - 2, rng.NextDouble() * 4 - 2)).ToArray()
                Dim m = rng.Next(1, 8)
                Dim rows(m - 1) As ContactRow
                For r = 0 To m - 1
                    Dim angle = rng.NextDouble() * 2 * Math.PI
                    Dim a = rng.Next(n)
                    Dim b = If(rng.NextDouble() < 0.4 OrElse n = 1, ContactRow.None, (a + 1 + rng.Next(n - 1)) Mod n)
                    rows(r) = New ContactRow(a, b, New Vector(Math.Cos(angle), Math.Sin(angle)), 0, rng.NextDouble() < 0.2)
                Next
                Dim result(n - 1) As Vector, forces(m - 1) As Double
                solve.Solve(inverse, v, rows, 0.000000000001 * 4, result, forces)
                Dim before = 0.0, after = 0.0
                For k = 0 To n - 1
                    before += 0.5 * v(k).LengthSquared / inverse(k)
                    after += 0.5 * result(k).LengthSquared / inverse(k)
                Next
                Assert.True(after <= before * (1 + 0.000000000001) + 0.000000000001, $"trial {trial}: {before} J to {after} J")
                For r = 0 To m - 1
                    Dim row = rows(r)
                    Dim value = Vector.Dot(row.Direction, result(row.A) - If(row.B = ContactRow.None, Vector.Zero, result(row.B)))
                    If row.Holds Then Continue For
                    Assert.True(value >= -0.000001, $"trial {trial}: row {r} approaches at {value} m/s")
                    Assert.True(forces(r) >= 0, $"trial {trial}: row {r} pulls, {forces(r)} N·s")
                Next
            Next
        End Sub
    End Class
End Namespace
