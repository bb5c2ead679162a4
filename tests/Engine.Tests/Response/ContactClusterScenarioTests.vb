Option Strict On
Imports PhysicsEngine
Imports Xunit

Namespace Response
    ''' <summary>
    ''' <see cref="ContactCluster.Resolve"/> on clusters whose outcome can be worked out by hand: the squeezed
    ''' light ball that pairwise impulses cannot get past, balls wedged in a V, a row of touching balls.
    ''' </summary>
    Public Class ContactClusterScenarioTests
        Private Shared ReadOnly Up As New Vector(0, 1)
        Private Shared ReadOnly Root2 As Double = Math.Sqrt(2)

        <Theory>
        <InlineData(0.00001, 0.0)>
        <InlineData(0.00001, 0.5)>
        <InlineData(0.00001, 1.0)>
        <InlineData(0.000000000001, 0.0)>
        <InlineData(0.000000000001, 0.5)>
        <InlineData(0.000000000001, 1.0)>
        Public Sub LightBallBetweenFloorAndHeavyBall_HeavyLeavesAtEV_LightStays(ratio As Double, e As Double)
            ' A 0.4 kg ball falls at 2 m/s onto a ball ratio × 0.4 kg that rests on the floor (sliding at
            ' 0.3 m/s), centres in a vertical line. Compression stops both vertically (the floor holds the light
            ' ball, which holds the heavy one); restitution sends the heavy one up at e v and the light one, whose
            ' vertical velocity was 0 before and after compression, stays at 0. Sliding is untouched: the contacts
            ' are frictionless and vertical. Pairwise impulses need about π √(1/ratio) hits here (10⁶ at 10⁻¹²).
            Const heavy = 0.4
            Const v = 2.0
            Dim light = heavy * ratio
            Dim c = New ClusterCase With {
                .InverseMasses = {1 / light, 1 / heavy},
                .Velocities = {New Vector(0.3, 0), New Vector(0, -v)},
                .Contacts = {New ClusterContact(0, ClusterContact.World, Up), New ClusterContact(1, 0, Up)},
                .Restitution = e}
            Dim result = c.Resolve()

            Assert.True(result.Separated)
            Assert.False(result.Reprojected)
            Assert.Equal(e * v, result.Velocities(1).Y, v * 0.000000000001)
            Assert.Equal(0.0, result.Velocities(1).X)
            Assert.Equal(0.3, result.Velocities(0).X)
            Assert.InRange(result.Velocities(0).Y, -v * ContactCluster.ApproachTolerance, v * ContactCluster.ApproachTolerance)
            For Each contact In c.Contacts
                Assert.True(ClusterTestKit.NormalVelocity(contact, result.Velocities) >= -v * ContactCluster.ApproachTolerance)
            Next
            ' Both contacts carry the heavy ball's whole change of momentum, (1 + e) m v.
            Assert.Equal((1 + e) * heavy * v, result.Impulses(0), (1 + e) * heavy * v * 0.000000001)
            Assert.Equal((1 + e) * heavy * v, result.Impulses(1), (1 + e) * heavy * v * 0.000000001)
        End Sub

        <Fact>
        Public Sub BallFallingIntoA90DegreeV_ByHand()
            ' Walls at 45°, normals (1, 1)/√2 and (−1, 1)/√2; a 2 kg ball touching both; e = 0.5.
            Dim left = New Vector(1, 1) / Root2
            Dim right = New Vector(-1, 1) / Root2
            Dim contacts = {New ClusterContact(0, ClusterContact.World, left), New ClusterContact(0, ClusterContact.World, right)}

            ' Straight down at 3 m/s: −(0, 3) lies between the walls' normals, so compression stops the ball,
            ' each wall pushing with m v/√2; restitution returns half: up at 1.5 m/s.
            Dim down = ContactCluster.Resolve(Listed(0.5), Listed(New Vector(0, -3)), contacts, 0.5)
            AssertClose(New Vector(0, 1.5), down.Velocities(0), 0.000000000000001 * 3)
            Assert.Equal(1.5 * 2 * 3 / Root2, down.Impulses(0), 0.000000000001)
            Assert.Equal(1.5 * 2 * 3 / Root2, down.Impulses(1), 0.000000000001)

            ' Down and to the right, (3, −1): it approaches only the right wall (n·v = −4/√2) and leaves the left
            ' one, so this is Newton's rule on the right wall alone: (3, −1) + 1.5 (4/√2)(−1, 1)/√2 = (0, 2).
            Dim glancing = ContactCluster.Resolve(Listed(0.5), Listed(New Vector(3, -1)), contacts, 0.5)
            AssertClose(New Vector(0, 2), glancing.Velocities(0), 0.000000000000001 * 3)
            Assert.Equal(0.0, glancing.Impulses(0))
            Assert.Equal(1.5 * 2 * 4 / Root2, glancing.Impulses(1), 0.000000000001)
            Assert.False(glancing.Reprojected)
        End Sub

        <Theory>
        <InlineData(0.0)>
        <InlineData(0.3)>
        <InlineData(1.0)>
        Public Sub BallFallingIntoANarrowV_StopsOrReboundsAlongTheBisector(e As Double)
            ' A V of 60° (walls 60° from the horizontal): normals (±√3/2, 1/2). Falling straight down, the
            ' ball is wedged: it stops (e = 0) or goes back up the bisector at e v. Pairwise impulses would
            ' bounce it between the walls, each hit shaving off only a little of its speed.
            Dim s3 = Math.Sqrt(3) / 2
            Dim contacts = {New ClusterContact(0, ClusterContact.World, New Vector(s3, 0.5)),
                            New ClusterContact(0, ClusterContact.World, New Vector(-s3, 0.5))}
            Dim result = ContactCluster.Resolve(Listed(1 / 0.05), Listed(New Vector(0, -4)), contacts, e)
            AssertClose(New Vector(0, 4 * e), result.Velocities(0), 0.000000000000001 * 4)
            Assert.True(result.Separated)
        End Sub

        <Fact>
        Public Sub BallEnteringANarrowVObliquely_StopsWhenInelastic()
            ' (0.5, −1) m/s is −(0.711 n₁ + 1.289 n₂) with both coefficients positive: the walls together
            ' can absorb all of it, so with e = 0 the wedged ball stops, whichever way it came in.
            Dim s3 = Math.Sqrt(3) / 2
            Dim contacts = {New ClusterContact(0, ClusterContact.World, New Vector(s3, 0.5)),
                            New ClusterContact(0, ClusterContact.World, New Vector(-s3, 0.5))}
            Dim result = ContactCluster.Resolve(Listed(1 / 0.05), Listed(New Vector(0.5, -1)), contacts, 0)
            AssertClose(Vector.Zero, result.Velocities(0), 0.000000000000001)
        End Sub

        <Theory>
        <InlineData(0.0)>
        <InlineData(0.5)>
        <InlineData(1.0)>
        Public Sub ThreeTouchingBallsHitAtOneEnd_ResolvedTogether(e As Double)
            ' Three equal balls in a row, touching; the left one moves right at v. Resolved simultaneously,
            ' compression brings all three to v/3 and restitution gives ((1 − 2e) v/3, (1 + e) v/3, (1 + e) v/3):
            ' for e = 1, (−v/3, 2v/3, 2v/3). This is NOT Newton's cradle, where the event solver resolves the
            ' hits one pair at a time at the same instant and gets (0, 0, v); that sequential answer is the
            ' right one for the ordinary case, and this module is only the fallback for clusters it cannot
            ' get past.
            Const v = 1.5
            Dim left = New Vector(-1, 0)
            Dim c = New ClusterCase With {
                .InverseMasses = {1 / 0.2, 1 / 0.2, 1 / 0.2},
                .Velocities = {New Vector(v, 0), Vector.Zero, Vector.Zero},
                .Contacts = {New ClusterContact(0, 1, left), New ClusterContact(1, 2, left)},
                .Restitution = e}
            Dim result = c.Resolve()
            AssertClose(New Vector((1 - 2 * e) * v / 3, 0), result.Velocities(0), 0.000000000000001 * v)
            AssertClose(New Vector((1 + e) * v / 3, 0), result.Velocities(1), 0.000000000000001 * v)
            AssertClose(New Vector((1 + e) * v / 3, 0), result.Velocities(2), 0.000000000000001 * v)
            Assert.False(result.Reprojected)
            If e = 1 Then
                Assert.Equal(ClusterTestKit.KineticEnergy(c.InverseMasses, c.Velocities),
                             ClusterTestKit.KineticEnergy(c.InverseMasses, result.Velocities), 0.000000000000001)
            End If
        End Sub

        <Fact>
        Public Sub BallInACornerTouchingThreeThings_IsNotBrokenByTheRedundantOne()
            ' Floor, left wall and a 45° chamfer all touch a 1 kg ball: three contacts, two freedoms. Coming in at
            ' (−2, −1), every direction it could go is blocked, so it stops and returns e of it: (1, 0.5) at e = 0.5.
            Dim contacts = {New ClusterContact(0, ClusterContact.World, Up),
                            New ClusterContact(0, ClusterContact.World, New Vector(1, 0)),
                            New ClusterContact(0, ClusterContact.World, New Vector(1, 1) / Root2)}
            Dim before = New Vector(-2, -1)
            Dim result = ContactCluster.Resolve(Listed(1.0), Listed(before), contacts, 0.5)
            AssertClose(New Vector(1, 0.5), result.Velocities(0), 0.000000000000001 * 2)
            Assert.True(result.Separated)
            ' However the redundant contacts share it, their impulses add up to m Δv.
            Dim total = Vector.Zero
            For k = 0 To contacts.Length - 1
                Assert.True(result.Impulses(k) >= 0)
                total += contacts(k).Normal * result.Impulses(k)
            Next
            AssertClose(result.Velocities(0) - before, total, 0.000000000001)
        End Sub

        <Fact>
        Public Sub DuplicatedContacts_GiveTheSingleContactsAnswer()
            ' The same ball–ball contact listed twice, then five times: same velocities as Impulse.Resolve, and
            ' the copies' impulses add up to its impulse.
            Dim normal = New Vector(0.6, 0.8)
            Dim va = New Vector(-1, -2)
            Dim vb = New Vector(0.5, 1)
            Dim expected = Impulse.Resolve(va, 1 / 0.3, vb, 1 / 0.7, normal, 0.7)
            Dim j = -(1 + 0.7) * Vector.Dot(va - vb, normal) / (1 / 0.3 + 1 / 0.7)
            For Each copies In {2, 5}
                Dim contacts = Enumerable.Repeat(New ClusterContact(0, 1, normal), copies).ToArray()
                Dim result = ContactCluster.Resolve(Listed(1 / 0.3, 1 / 0.7), Listed(va, vb), contacts, 0.7)
                AssertClose(expected.A, result.Velocities(0), 0.000000000000001 * 4)
                AssertClose(expected.B, result.Velocities(1), 0.000000000000001 * 4)
                Assert.Equal(j, result.Impulses.Sum(), j * 0.000000000001)
            Next
        End Sub

        <Fact>
        Public Sub RandomClusters_WithEveryContactListedThrice_GiveTheSameVelocities()
            ' Listing a contact again changes nothing physical, so the velocities (which are unique) must not move.
            Dim rng As New Random(21)
            For trial = 1 To 500
                Dim c = ClusterTestKit.RandomCluster(rng, immovables:=True, world:=True, restitution:=rng.NextDouble())
                Dim tripled = New ClusterCase With {
                    .InverseMasses = c.InverseMasses, .Velocities = c.Velocities,
                    .Contacts = c.Contacts.Concat(c.Contacts).Concat(c.Contacts).ToArray(), .Restitution = c.Restitution}
                Dim once = c.Resolve()
                Dim thrice = tripled.Resolve()
                Dim scale = Math.Max(c.SpeedScale(), Double.Epsilon)
                For i = 0 To c.Velocities.Length - 1
                    Assert.True((once.Velocities(i) - thrice.Velocities(i)).Length <= 0.000000000001 * scale,
                                $"cluster {trial}, body {i}: {once.Velocities(i)} once, {thrice.Velocities(i)} thrice")
                Next
            Next
        End Sub

        <Fact>
        Public Sub BallSqueezedBetweenTheFloorAndADraggedBody_StaysFinite_AndSaysItIsNotSeparated()
            ' The dragged body (immovable) moves down at 1 m/s onto a ball resting on the floor: no velocity of
            ' the ball can keep both contacts from approaching. The answer must still be finite, and say so.
            Dim contacts = {New ClusterContact(0, ClusterContact.World, Up), New ClusterContact(0, 1, New Vector(0, -1))}
            Dim result = ContactCluster.Resolve(Listed(1 / 0.1, 0.0), Listed(Vector.Zero, New Vector(0, -1)), contacts, 0.5)
            Assert.False(result.Separated)
            Assert.True(result.Velocities(0).IsFinite)
            Assert.Equal(New Vector(0, -1), result.Velocities(1))
            Assert.All(result.Impulses, Sub(j) Assert.True(j >= 0 AndAlso Not Double.IsInfinity(j)))
        End Sub

        <Fact>
        Public Sub DraggedBodyPushingARowOfBalls_MovesThemAtLeastAsFastAsItself()
            ' An immovable body moving right at 2 m/s touches the first of two equal touching balls at rest
            ' (e = 0): compression makes both keep pace with it, at exactly 2 m/s.
            Dim push = New Vector(1, 0)
            Dim contacts = {New ClusterContact(1, 0, push), New ClusterContact(2, 1, push)}
            Dim result = ContactCluster.Resolve(Listed(0.0, 1 / 0.5, 1 / 0.5), Listed(New Vector(2, 0), Vector.Zero, Vector.Zero), contacts, 0)
            AssertClose(New Vector(2, 0), result.Velocities(1), 0.000000000000001 * 2)
            AssertClose(New Vector(2, 0), result.Velocities(2), 0.000000000000001 * 2)
            Assert.True(result.Separated)
        End Sub

        Private Shared Sub AssertClose(expected As Vector, actual As Vector, tolerance As Double)
            Assert.True((expected - actual).Length <= tolerance, $"expected {expected}, got {actual}")
        End Sub
    End Class
End Namespace
