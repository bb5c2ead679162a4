Option Strict On
Imports PhysicsEngine
Imports Xunit
Imports Xunit.Abstractions

Namespace Response
    ''' <summary>
    ''' The guarantees of <see cref="ContactCluster.Resolve"/> on thousands of seeded random clusters with
    ''' masses spread over 10¹², each checked against its definition or an independent formula.
    ''' </summary>
    Public Class ContactClusterPropertyTests
        Private Const Clusters As Integer = 3000
        Private ReadOnly _output As ITestOutputHelper

        ''' <summary>xunit passes the output sink the worst margins are written to.</summary>
        Public Sub New(output As ITestOutputHelper)
            _output = output
        End Sub

        <Fact>
        Public Sub SingleContact_EqualsImpulseResolve()
            ' Newton's rule and Poisson's agree for one contact. Random pairs, masses over 10¹², immovable
            ' bodies that move (a dragged body), the world, and pairs already separating.
            Dim rng As New Random(11)
            Dim worst = 0.0
            Dim worstImpulse = 0.0
            For trial = 1 To Clusters
                Dim invA = If(rng.NextDouble() < 0.1, 0.0, 1 / ClusterTestKit.RandomMass(rng))
                Dim invB = If(rng.NextDouble() < 0.3, 0.0, 1 / ClusterTestKit.RandomMass(rng))
                Dim world = rng.NextDouble() < 0.2
                Dim va = New Vector(rng.NextDouble() * 2 - 1, rng.NextDouble() * 2 - 1) * 3
                Dim vb = If(world, Vector.Zero, New Vector(rng.NextDouble() * 2 - 1, rng.NextDouble() * 2 - 1) * 3)
                Dim normal = ClusterTestKit.RandomUnit(rng)
                Dim e = If(trial Mod 4 = 0, 1.0, If(trial Mod 4 = 1, 0.0, rng.NextDouble()))
                Dim contact = New ClusterContact(0, If(world, ClusterContact.World, 1), normal)
                Dim result = If(world,
                    ContactCluster.Resolve({invA}, {va}, {contact}, e),
                    ContactCluster.Resolve({invA, invB}, {va, vb}, {contact}, e))

                Dim expected = Impulse.Resolve(va, invA, vb, If(world, 0.0, invB), normal, e)
                Dim scale = Math.Max(va.Length, vb.Length)
                worst = Math.Max(worst, (result.Velocities(0) - expected.A).Length / scale)
                If Not world Then worst = Math.Max(worst, (result.Velocities(1) - expected.B).Length / scale)
                ' The impulse of the textbook formula, j = −(1 + e) v_rel·n / (1/m_A + 1/m_B), or 0 if separating.
                Dim approach = Vector.Dot(va - vb, normal)
                Dim sumInv = invA + If(world, 0.0, invB)
                Dim j = If(approach >= 0 OrElse sumInv = 0, 0.0, -(1 + e) * approach / sumInv)
                worstImpulse = Math.Max(worstImpulse, Math.Abs(result.Impulses(0) - j) / Math.Max(j, Double.Epsilon))
                ' Two immovable bodies that approach cannot be parted; the result says so.
                Assert.Equal(approach >= 0 OrElse sumInv > 0, result.Separated)
            Next
            _output.WriteLine($"worst velocity difference / speed {worst:E2}, worst impulse relative difference {worstImpulse:E2}")
            Assert.True(worst <= 0.000000000001, $"velocities differ by {worst:E2} of the speed")
            Assert.True(worstImpulse <= 0.000000000001, $"impulses differ by {worstImpulse:E2}")
        End Sub

        <Fact>
        Public Sub RandomClusters_NeverGainEnergy_AndEndWithNoContactApproaching()
            Dim rng As New Random(12)
            Dim worstGain = 0.0
            Dim worstElasticChange = 0.0
            Dim worstApproach = 0.0
            Dim elasticChecked = 0
            Dim reprojected = 0
            For trial = 1 To Clusters
                Dim e = If(trial Mod 3 = 0, 1.0, If(trial Mod 3 = 1, 0.0, rng.NextDouble()))
                Dim c = ClusterTestKit.RandomCluster(rng, immovables:=True, world:=True, restitution:=e)
                Dim result = c.Resolve()
                Assert.All(result.Velocities, Sub(v) Assert.True(v.IsFinite))
                Assert.All(result.Impulses, Sub(j) Assert.True(j >= 0 AndAlso Not Double.IsInfinity(j)))
                ' Immovable bodies (all at rest here) keep their velocities.
                For i = 0 To c.InverseMasses.Length - 1
                    If c.InverseMasses(i) = 0 Then Assert.Equal(c.Velocities(i), result.Velocities(i))
                Next

                Dim before = ClusterTestKit.KineticEnergy(c.InverseMasses, c.Velocities)
                Dim after = ClusterTestKit.KineticEnergy(c.InverseMasses, result.Velocities)
                ' Every body immovable and at rest: nothing moves, nothing to compare.
                If before = 0 Then
                    Assert.Equal(0.0, after)
                    Continue For
                End If
                worstGain = Math.Max(worstGain, (after - before) / before)
                If e = 1 AndAlso Not result.Reprojected Then
                    worstElasticChange = Math.Max(worstElasticChange, Math.Abs(after - before) / before)
                    elasticChecked += 1
                End If
                If result.Reprojected Then reprojected += 1

                ' With the immovable bodies at rest, standing still satisfies every contact, so a solution exists.
                Assert.True(result.Separated)
                Dim scale = c.SpeedScale()
                For Each contact In c.Contacts
                    worstApproach = Math.Max(worstApproach, -ClusterTestKit.NormalVelocity(contact, result.Velocities) / scale)
                Next
            Next
            _output.WriteLine($"worst KE gain {worstGain:E2}, worst elastic KE change {worstElasticChange:E2} over {elasticChecked} clusters, " &
                              $"worst approach / speed {worstApproach:E2}, reprojected {reprojected} of {Clusters}")
            Assert.True(worstGain <= 0.000000000001, $"kinetic energy grew by {worstGain:E2} of itself")
            Assert.True(worstElasticChange <= 0.000000000001, $"e = 1 changed kinetic energy by {worstElasticChange:E2}")
            ' Random normals make many contacts that a rebound drives into approach; enough clusters remain.
            Assert.True(elasticChecked >= 100, $"only {elasticChecked} e = 1 clusters without a second projection to show equality")
            Assert.True(worstApproach <= ContactCluster.ApproachTolerance, $"a contact still approaches at {worstApproach:E2} of the speed")
        End Sub

        <Fact>
        Public Sub RandomClusters_WithoutTheWorld_ConserveMomentum_AndEveryBodysImpulses()
            Dim rng As New Random(13)
            Dim worstTotal = 0.0
            Dim worstBody = 0.0
            For trial = 1 To Clusters
                Dim c = ClusterTestKit.RandomCluster(rng, immovables:=False, world:=False, restitution:=rng.NextDouble())
                Dim result = c.Resolve()
                Dim scale = ClusterTestKit.MomentumScale(c.InverseMasses, c.Velocities)
                Dim change = ClusterTestKit.Momentum(c.InverseMasses, result.Velocities) - ClusterTestKit.Momentum(c.InverseMasses, c.Velocities)
                worstTotal = Math.Max(worstTotal, change.Length / scale)

                ' The reported impulses account for each body's change of momentum, m Δv = Σ ±J n, to rounding
                ' of the largest impulse in the cluster (a light body beside a squeezed one shares its rounding).
                Dim largest = result.Impulses.Max()
                For i = 0 To c.InverseMasses.Length - 1
                    Dim sum = Vector.Zero
                    Dim size = c.Velocities(i).Length / c.InverseMasses(i) + largest
                    For k = 0 To c.Contacts.Length - 1
                        Dim contact = c.Contacts(k)
                        If contact.BodyA = i Then sum += contact.Normal * result.Impulses(k)
                        If contact.BodyB = i Then sum -= contact.Normal * result.Impulses(k)
                    Next
                    Dim ownChange = (result.Velocities(i) - c.Velocities(i)) / c.InverseMasses(i)
                    If size > 0 Then worstBody = Math.Max(worstBody, (ownChange - sum).Length / size)
                Next
            Next
            _output.WriteLine($"worst momentum change / Σm|v| {worstTotal:E2}, worst body impulse mismatch {worstBody:E2}")
            Assert.True(worstTotal <= 0.000000000001, $"momentum changed by {worstTotal:E2} of Σ m|v|")
            Assert.True(worstBody <= 0.000000000001, $"a body's momentum change and its impulses differ by {worstBody:E2}")
        End Sub

        <Fact>
        Public Sub RandomClusters_InelasticResult_IsTheEnergyProjection()
            ' For e = 0 the result is the compression u₁ itself. It is the closest point to u₋ in the kinetic-energy
            ' metric with no contact approaching exactly when the Karush–Kuhn–Tucker conditions hold: no contact
            ' approaches, m Δv is made of impulses J ≥ 0 along the normals, and only contacts that end at rest
            ' relative to each other push (J g = 0). The first two are checked above; here the third.
            Dim rng As New Random(14)
            Dim worst = 0.0
            For trial = 1 To Clusters
                Dim c = ClusterTestKit.RandomCluster(rng, immovables:=True, world:=True, restitution:=0)
                Dim result = c.Resolve()
                Assert.False(result.Reprojected)
                Dim scale = c.SpeedScale()
                For k = 0 To c.Contacts.Length - 1
                    Dim g = ClusterTestKit.NormalVelocity(c.Contacts(k), result.Velocities)
                    If result.Impulses(k) > 0 Then worst = Math.Max(worst, Math.Abs(g) / scale)
                Next
            Next
            _output.WriteLine($"worst |g| / speed on a pushing contact {worst:E2}")
            Assert.True(worst <= 0.000000000001, $"a pushing contact separates at {worst:E2} of the speed")
        End Sub

        <Fact>
        Public Sub SameInput_GivesBitIdenticalOutput_WithAFreshOrAUsedWorkspace()
            Dim rng As New Random(15)
            Dim reused As New ContactClusterWorkspace()
            For trial = 1 To 300
                Dim c = ClusterTestKit.RandomCluster(rng, immovables:=True, world:=True, restitution:=rng.NextDouble())
                Dim first = c.Resolve()
                ' Use the shared workspace on another cluster first, so it holds that one's leftovers.
                ClusterTestKit.RandomCluster(rng, immovables:=True, world:=True, restitution:=0.5).Resolve(reused)
                Dim second = c.Resolve(reused)
                For i = 0 To first.Velocities.Count - 1
                    Assert.Equal(BitConverter.DoubleToInt64Bits(first.Velocities(i).X), BitConverter.DoubleToInt64Bits(second.Velocities(i).X))
                    Assert.Equal(BitConverter.DoubleToInt64Bits(first.Velocities(i).Y), BitConverter.DoubleToInt64Bits(second.Velocities(i).Y))
                Next
                For k = 0 To first.Impulses.Count - 1
                    Assert.Equal(BitConverter.DoubleToInt64Bits(first.Impulses(k)), BitConverter.DoubleToInt64Bits(second.Impulses(k)))
                Next
            Next
        End Sub

        <Fact>
        Public Sub MirrorImage_GivesTheMirrorImageResult()
            Dim rng As New Random(16)
            Dim worst = 0.0
            For trial = 1 To Clusters
                Dim c = ClusterTestKit.RandomCluster(rng, immovables:=True, world:=True, restitution:=rng.NextDouble())
                Dim mirrored = New ClusterCase With {
                    .InverseMasses = c.InverseMasses,
                    .Velocities = c.Velocities.Select(AddressOf Mirror).ToArray(),
                    .Contacts = c.Contacts.Select(Function(k) New ClusterContact(k.BodyA, k.BodyB, Mirror(k.Normal))).ToArray(),
                    .Restitution = c.Restitution}
                Dim plain = c.Resolve()
                Dim image = mirrored.Resolve()
                Dim scale = Math.Max(c.SpeedScale(), Double.Epsilon)
                For i = 0 To c.Velocities.Length - 1
                    worst = Math.Max(worst, (Mirror(plain.Velocities(i)) - image.Velocities(i)).Length / scale)
                Next
            Next
            _output.WriteLine($"worst mirror mismatch / speed {worst:E2}")
            Assert.True(worst <= 0.000000000001, $"the mirror image differs by {worst:E2} of the speed")
        End Sub

        Private Shared Function Mirror(v As Vector) As Vector
            Return New Vector(-v.X, v.Y)
        End Function
    End Class
End Namespace
