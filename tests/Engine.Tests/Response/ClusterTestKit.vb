Option Strict On
Imports PhysicsEngine

Namespace Response
    ''' <summary>
    ''' A cluster as the tests build it, and the quantities they check, computed here from the definitions
    ''' (not with the code under test).
    ''' </summary>
    Public NotInheritable Class ClusterCase
        ''' <summary>1/kg per body; 0 = immovable.</summary>
        Public Property InverseMasses As Double()
        ''' <summary>m/s per body.</summary>
        Public Property Velocities As Vector()
        ''' <summary>The contacts.</summary>
        Public Property Contacts As ClusterContact()
        ''' <summary>e.</summary>
        Public Property Restitution As Double

        ''' <summary>Runs <see cref="ContactCluster.Resolve"/> on this case.</summary>
        Public Function Resolve(Optional workspace As ContactClusterWorkspace = Nothing) As ClusterResolution
            Return ContactCluster.Resolve(InverseMasses, Velocities, Contacts, Restitution, workspace)
        End Function

        ''' <summary>The largest speed among the bodies, m/s.</summary>
        Public Function SpeedScale() As Double
            Return Velocities.Max(Function(v) v.Length)
        End Function
    End Class

    ''' <summary>Independent formulas and random clusters for the contact-cluster tests.</summary>
    Public NotInheritable Class ClusterTestKit
        Private Sub New()
        End Sub

        ''' <summary>Normal relative velocity n·(v_A − v_B) of a contact, m/s (negative = approaching).</summary>
        Public Shared Function NormalVelocity(c As ClusterContact, v As IReadOnlyList(Of Vector)) As Double
            Dim vb = If(c.BodyB = ClusterContact.World, Vector.Zero, v(c.BodyB))
            Return Vector.Dot(c.Normal, v(c.BodyA) - vb)
        End Function

        ''' <summary>Kinetic energy of the movable bodies, J.</summary>
        Public Shared Function KineticEnergy(inverseMasses As IReadOnlyList(Of Double), v As IReadOnlyList(Of Vector)) As Double
            Dim sum = 0.0
            For i = 0 To v.Count - 1
                If inverseMasses(i) > 0 Then sum += 0.5 * v(i).LengthSquared / inverseMasses(i)
            Next
            Return sum
        End Function

        ''' <summary>Total momentum of the movable bodies, kg·m/s.</summary>
        Public Shared Function Momentum(inverseMasses As IReadOnlyList(Of Double), v As IReadOnlyList(Of Vector)) As Vector
            Dim sum = Vector.Zero
            For i = 0 To v.Count - 1
                If inverseMasses(i) > 0 Then sum += v(i) / inverseMasses(i)
            Next
            Return sum
        End Function

        ''' <summary>Σ m |v| over the movable bodies: the scale momentum errors are measured against, kg·m/s.</summary>
        Public Shared Function MomentumScale(inverseMasses As IReadOnlyList(Of Double), v As IReadOnlyList(Of Vector)) As Double
            Dim sum = 0.0
            For i = 0 To v.Count - 1
                If inverseMasses(i) > 0 Then sum += v(i).Length / inverseMasses(i)
            Next
            Return sum
        End Function

        ''' <summary>A random unit vector.</summary>
        Public Shared Function RandomUnit(rng As Random) As Vector
            Dim angle = rng.NextDouble() * 2 * Math.PI
            Return New Vector(Math.Cos(angle), Math.Sin(angle))
        End Function

        ''' <summary>A mass log-uniform in [10⁻⁶, 10⁶] kg: ratios up to 10¹² within one cluster.</summary>
        Public Shared Function RandomMass(rng As Random) As Double
            Return Math.Pow(10, rng.NextDouble() * 12 - 6)
        End Function

        ''' <summary>
        ''' A random cluster: 2–12 bodies with masses spread over 10¹², some immovable (at rest) when
        ''' <paramref name="immovables"/>, velocities up to a random scale, 1–30 contacts with random unit
        ''' normals (so duplicates, opposite pairs and more contacts than freedoms occur), some against the
        ''' world when <paramref name="world"/>. Random normals make no claim of a drawable geometry, which
        ''' the algebra does not need: every property tested holds for any normals.
        ''' </summary>
        Public Shared Function RandomCluster(rng As Random, immovables As Boolean, world As Boolean, restitution As Double) As ClusterCase
            Dim n = rng.Next(2, 13)
            Dim inverse = New Double(n - 1) {}
            Dim velocities = New Vector(n - 1) {}
            Dim speed = Math.Pow(10, rng.NextDouble() * 4 - 2)
            For i = 0 To n - 1
                If immovables AndAlso rng.NextDouble() < 0.2 Then
                    inverse(i) = 0
                    velocities(i) = Vector.Zero
                Else
                    inverse(i) = 1 / RandomMass(rng)
                    velocities(i) = New Vector(rng.NextDouble() * 2 - 1, rng.NextDouble() * 2 - 1) * speed
                End If
            Next
            Dim m = rng.Next(1, 31)
            Dim contacts = New ClusterContact(m - 1) {}
            For k = 0 To m - 1
                Dim a = rng.Next(n)
                Dim b As Integer
                If world AndAlso rng.NextDouble() < 0.25 Then
                    b = ClusterContact.World
                Else
                    b = rng.Next(n - 1)
                    If b >= a Then b += 1
                End If
                Dim normal = RandomUnit(rng)
                ' A third of the contacts repeat an earlier pair's normal or its opposite: redundancy and squeezes.
                If k > 0 AndAlso rng.NextDouble() < 0.33 Then
                    Dim earlier = contacts(rng.Next(k))
                    normal = If(rng.NextDouble() < 0.5, earlier.Normal, -earlier.Normal)
                End If
                contacts(k) = New ClusterContact(a, b, normal)
            Next
            Return New ClusterCase With {.InverseMasses = inverse, .Velocities = velocities, .Contacts = contacts, .Restitution = restitution}
        End Function
    End Class
End Namespace
