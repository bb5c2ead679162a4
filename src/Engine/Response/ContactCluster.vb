Option Strict On

Imports System.Globalization

''' <summary>
''' Collision response for a cluster of bodies that all touch at one instant, resolved at once:
''' exact, deterministic, conserving momentum and never adding kinetic energy. A pure function.
''' Used only as a fallback, when pairwise resolution cannot get past an instant, because for ordinary
''' collisions it gives a different answer: it treats touching contacts as one simultaneous collision,
''' so three touching equal balls hit at one end leave at −v/3, 2v/3, 2v/3 (e = 1), not 0, 0, v as in
''' Newton's cradle, which the event solver's one-pair-at-a-time resolution gets right.
''' </summary>
''' <remarks>
''' <para>
''' Why the fallback is needed: a light body squeezed between the floor and a heavy one (mass ratios up
''' to 10¹²) is hit back and forth by pairwise impulses thousands or millions of times at one instant,
''' as in the problem of π from collisions, and a ball wedged in a narrow V loses only a little speed
''' at each hit. When a body has been hit many times at one instant, the caller resolves the whole
''' cluster of touching bodies here instead.
''' </para>
''' <para>
''' The method is Poisson's hypothesis written as a projection. Compression: the velocities u₁ closest
''' to the incoming u₋ in the kinetic-energy metric at which no contact approaches (see
''' <see cref="ContactProjection"/>). Restitution: u₊ = u₁ + e (u₁ − u₋), each contact giving back e times
''' its compression impulse. For a single contact this is Newton's rule and equals
''' <see cref="Impulse.Resolve"/>. Because u₁ is an orthogonal projection onto a cone (when the
''' immovable bodies are at rest), KE(u₊) = KE(u₁) + e² KE(u₋ − u₁) ≤ KE(u₋), with equality for e = 1.
''' The rebound of one contact can drive another, which did not push during compression, into
''' approach; then u₊ is projected once more (compression only), which loses some energy even for e = 1.
''' </para>
''' </remarks>
Public Module ContactCluster
    ''' <summary>
    ''' A contact counts as approaching only when its normal velocity is below −ApproachTolerance times
    ''' the speed scale (the largest speed among the bodies given). The event solver's threshold for
    ''' "approaching" is the same 10⁻¹², measured there against the pair's relative speed: a residual
    ''' approach smaller than this is rounding that no impulse can remove.
    ''' </summary>
    Public Const ApproachTolerance As Double = 0.000000000001

    ''' <summary>
    ''' Resolves every contact of a cluster at once. <paramref name="inverseMasses"/> (1/kg; 0 for an
    ''' immovable body: fixed, a wall, sleeping or dragged) and <paramref name="velocities"/> (m/s) give
    ''' the bodies; <paramref name="contacts"/> join two of them, or one and <see cref="ClusterContact.World"/>,
    ''' with the unit normal from B towards A; <paramref name="restitution"/> e is in [0, 1]. Immovable
    ''' bodies keep their velocities (a dragged body's is taken into account), and so do bodies in no contact.
    ''' Pass a <paramref name="workspace"/> to reuse its memory between calls.
    ''' </summary>
    ''' <exception cref="ArgumentNullException">An argument is Nothing.</exception>
    ''' <exception cref="ArgumentException">The lists differ in length, a number is not finite or out of range,
    ''' a contact names a body that does not exist or joins a body to itself, or a normal is not of unit length.</exception>
    Public Function Resolve(inverseMasses As IReadOnlyList(Of Double), velocities As IReadOnlyList(Of Vector),
                            contacts As IReadOnlyList(Of ClusterContact), restitution As Double,
                            Optional workspace As ContactClusterWorkspace = Nothing) As ClusterResolution
        Validate(inverseMasses, velocities, contacts, restitution)
        Return Solve(inverseMasses, velocities, contacts, restitution, If(workspace, New ContactClusterWorkspace()))
    End Function

    Private Function Solve(inverseMasses As IReadOnlyList(Of Double), velocities As IReadOnlyList(Of Vector),
                           contacts As IReadOnlyList(Of ClusterContact), e As Double,
                           ws As ContactClusterWorkspace) As ClusterResolution
        Dim n = velocities.Count
        Dim m = contacts.Count
        Dim after = New Vector(n - 1) {}
        Dim speedScale = 0.0
        For i = 0 To n - 1
            after(i) = velocities(i)
            speedScale = Math.Max(speedScale, velocities(i).Length)
        Next
        Dim impulses = New Double(m - 1) {}
        ' Nothing moves, so nothing approaches.
        If m = 0 OrElse speedScale = 0 Then Return New ClusterResolution(after, impulses, True, False)
        Dim tolerance = ApproachTolerance * speedScale

        Dim projection = ws.Projection
        projection.Load(inverseMasses, velocities, contacts)
        Dim slots = projection.SlotCount
        ws.Grow(slots, m)
        For s = 0 To slots - 1
            Dim v = velocities(projection.BodyOfSlot(s))
            ws.Before(2 * s) = v.X
            ws.Before(2 * s + 1) = v.Y
        Next

        Dim final = ws.Compressed
        Dim reprojected = False
        Dim converged = projection.Project(ws.Before, tolerance, ws.Compressed, ws.CompressionImpulses)
        If converged Then
            For i = 0 To 2 * slots - 1
                ws.Restituted(i) = ws.Compressed(i) + e * (ws.Compressed(i) - ws.Before(i))
            Next
            For k = 0 To m - 1
                impulses(k) = (1 + e) * ws.CompressionImpulses(k)
            Next
            final = ws.Restituted
            If projection.SlowestSeparation(ws.Restituted) < -tolerance Then
                reprojected = True
                converged = projection.Project(ws.Restituted, tolerance, ws.SecondProjection, ws.SecondImpulses)
                For k = 0 To m - 1
                    impulses(k) += ws.SecondImpulses(k)
                Next
                final = ws.SecondProjection
            End If
        Else
            ' The cap: restitution needs the exact compression (the energy argument rests on it), so the
            ' partial compression is returned as it is.
            Array.Copy(ws.CompressionImpulses, impulses, m)
        End If

        For s = 0 To slots - 1
            after(projection.BodyOfSlot(s)) = New Vector(final(2 * s), final(2 * s + 1))
        Next
        Dim separated = converged AndAlso projection.SlowestSeparation(final) >= -tolerance
        Return New ClusterResolution(after, impulses, separated, reprojected)
    End Function

    Private Sub Validate(inverseMasses As IReadOnlyList(Of Double), velocities As IReadOnlyList(Of Vector),
                         contacts As IReadOnlyList(Of ClusterContact), restitution As Double)
        If inverseMasses Is Nothing Then Throw New ArgumentNullException(NameOf(inverseMasses))
        If velocities Is Nothing Then Throw New ArgumentNullException(NameOf(velocities))
        If contacts Is Nothing Then Throw New ArgumentNullException(NameOf(contacts))
        If inverseMasses.Count <> velocities.Count Then
            Throw New ArgumentException(Message("{0} inverse masses but {1} velocities: one of each per body.",
                                                inverseMasses.Count, velocities.Count), NameOf(velocities))
        End If
        If Not (restitution >= 0 AndAlso restitution <= 1) Then
            Throw New ArgumentException(Message("restitution must be in [0, 1], not {0}.", restitution), NameOf(restitution))
        End If
        Dim n = inverseMasses.Count
        For i = 0 To n - 1
            Dim w = inverseMasses(i)
            If Not (w >= 0 AndAlso Not Double.IsInfinity(w)) Then
                Throw New ArgumentException(Message("inverseMasses({0}) must be finite and ≥ 0 (1/kg), not {1}.", i, w), NameOf(inverseMasses))
            End If
            If Not velocities(i).IsFinite Then
                Throw New ArgumentException(Message("velocities({0}) must be finite, not {1}.", i, velocities(i)), NameOf(velocities))
            End If
        Next
        For k = 0 To contacts.Count - 1
            Dim c = contacts(k)
            If c.BodyA < 0 OrElse c.BodyA >= n Then
                Throw New ArgumentException(Message("contacts({0}).BodyA is {1}; bodies are 0 to {2}.", k, c.BodyA, n - 1), NameOf(contacts))
            End If
            If c.BodyB <> ClusterContact.World AndAlso (c.BodyB < 0 OrElse c.BodyB >= n) Then
                Throw New ArgumentException(Message("contacts({0}).BodyB is {1}; bodies are 0 to {2}, or World (−1).", k, c.BodyB, n - 1), NameOf(contacts))
            End If
            If c.BodyA = c.BodyB Then
                Throw New ArgumentException(Message("contacts({0}) joins body {1} to itself.", k, c.BodyA), NameOf(contacts))
            End If
            ' Unit to well within rounding of a normalised vector; the impulses are reported in N·s along it.
            If Not c.Normal.IsFinite OrElse Math.Abs(c.Normal.Length - 1) > 0.000000001 Then
                Throw New ArgumentException(Message("contacts({0}).Normal must be a unit vector, not {1}.", k, c.Normal), NameOf(contacts))
            End If
        Next
    End Sub

    Private Function Message(format As String, ParamArray args As Object()) As String
        Return String.Format(CultureInfo.InvariantCulture, format, args)
    End Function
End Module
