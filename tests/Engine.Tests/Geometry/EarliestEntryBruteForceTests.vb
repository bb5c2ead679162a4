Option Strict On
Imports PhysicsEngine
Imports Xunit
Imports Xunit.Abstractions

Namespace Geometry
    ''' <summary>
    ''' <see cref="OutlineContact.EarliestEntry"/> against a brute-force scan (conservative advancement and
    ''' bisection on an independent distance function) on random outlines of every kind and random straight
    ''' and parabolic paths: the same first entry, never an entry before it, and the horizon changes nothing
    ''' but what lies beyond it.
    ''' </summary>
    Public Class EarliestEntryBruteForceTests
        Private Const Slop As Double = 1.0E-12
        Private Const TMax As Double = 6.0
        Private ReadOnly _output As ITestOutputHelper

        Public Sub New(output As ITestOutputHelper)
            _output = output
        End Sub

        ''' <summary>A path that, without the outline in the way, would pass through target at time t0.</summary>
        Private Shared Sub AimAt(rng As Random, k As Outline, ByRef d0 As Vector, ByRef dv As Vector, ByRef da As Vector)
            Select Case rng.Next(6)
                Case 0, 1 : da = Vector.Zero
                Case 2, 3 : da = New Vector(0, -9.81)
                Case 4 : da = New Vector(0, 9.81) ' the moving body is the fixed one's partner: B falls, A is held
                Case Else
                    Dim angle = rng.NextDouble() * 2 * Math.PI
                    da = New Vector(5 * Math.Cos(angle), 5 * Math.Sin(angle))
            End Select
            Dim centre = k.Centroid
            Do
                d0 = centre + GeometryTestKit.RandomPoint(rng, 2.5)
            Loop Until GeometryTestKit.Gap(k, d0) > 0.01
            ' Targets: near a corner (where edges and rounded corners meet), or anywhere inside the core.
            Dim corner = k.Vertices(rng.Next(k.VertexCount))
            Dim target As Vector
            Select Case rng.Next(3)
                Case 0 : target = corner + GeometryTestKit.RandomPoint(rng, 0.02 + k.Radius)
                Case 1 : target = corner
                Case Else : target = corner + rng.NextDouble() * (centre - corner)
            End Select
            Dim t0 = 0.2 + 1.3 * rng.NextDouble()
            dv = (target - d0 - (0.5 * t0 * t0) * da) / t0
        End Sub

        <Fact>
        Public Sub RandomPaths_FirstEntry_MatchesABruteForceScan()
            Dim rng As New Random(20240611)
            Dim hits = 0, misses = 0, cornerHits = 0, grazes = 0, tipCrossings = 0, worst = 0.0
            For trial = 0 To 2999
                Dim k = GeometryTestKit.RandomOutline(rng)
                Dim d0 As Vector, dv As Vector, da As Vector
                AimAt(rng, k, d0, dv, da)
                Dim feature As Integer
                Dim found = OutlineContact.EarliestEntry(k, d0, dv, da, Slop, 0, Double.PositiveInfinity, feature)
                Dim brute = GeometryTestKit.BruteEntry(k, d0, dv, da, TMax)
                Dim what = $"trial {trial}: {k.VertexCount} corners, R = {k.Radius}, d0 = {d0}, dv = {dv}, da = {da}: found {found} (feature {feature}), brute force {brute}"
                If found <= TMax Then
                    ' Never early: the point has not entered at the returned time, and it touches there.
                    Dim gapThere = GeometryTestKit.Gap(k, GeometryTestKit.PathAt(d0, dv, da, found))
                    Assert.True(gapThere >= -Slop, $"{what}: gap at the returned time {gapThere}")
                    Assert.True(gapThere <= 1.0E-9, $"{what}: not touching at the returned time, gap {gapThere}")
                    Assert.InRange(feature, 0, 2 * k.VertexCount - 1)
                End If
                If brute < Double.PositiveInfinity Then
                    Dim err = Math.Abs(found - brute)
                    If err > 1.0E-12 * (1 + brute) Then
                        ' Only a graze may differ: the path dips in by less than the scan can resolve.
                        Assert.True(IsGraze(k, d0, dv, da, brute), $"{what}: entry differs by {err}")
                        If IsFlat(k) Then tipCrossings += 1 Else grazes += 1
                    Else
                        worst = Math.Max(worst, err / (1 + brute))
                        hits += 1
                        If feature >= k.VertexCount Then cornerHits += 1
                    End If
                ElseIf found <= TMax Then
                    ' The scan missed it: it must be a touch too shallow for the scan's smallest step.
                    Assert.True(IsGraze(k, d0, dv, da, found), $"{what}: found an entry the scan does not see")
                    If IsFlat(k) Then tipCrossings += 1 Else grazes += 1
                Else
                    misses += 1
                End If
            Next
            _output.WriteLine($"hits {hits} (rounded corners {cornerHits}), misses {misses}, grazes {grazes}, crossings at a segment's tip {tipCrossings}, worst relative time error {worst:E2}")
            Assert.True(hits > 1500 AndAlso misses > 100 AndAlso cornerHits > 100, $"too few cases of a kind: hits {hits}, corners {cornerHits}, misses {misses}")
            Assert.True(grazes <= 30, $"{grazes} grazes")
        End Sub

        ''' <summary>A zero-thickness segment, whose entry is a crossing.</summary>
        Private Shared Function IsFlat(k As Outline) As Boolean
            Return k.VertexCount = 2 AndAlso k.Radius = 0
        End Function

        ''' <summary>
        ''' Whether the path only touches the shape around t: it goes in by less than 1 nm, or, for a
        ''' zero-thickness segment, it crosses within 1 µm of one of its ends.
        ''' </summary>
        Private Shared Function IsGraze(k As Outline, d0 As Vector, dv As Vector, da As Vector, t As Double) As Boolean
            If IsFlat(k) Then
                Dim p = GeometryTestKit.PathAt(d0, dv, da, t)
                Return (p - k.Vertices(0)).Length <= 0.000001 OrElse (p - k.Vertices(1)).Length <= 0.000001
            End If
            Return MaxDepthNear(k, d0, dv, da, t) <= 1.0E-9
        End Function

        ''' <summary>The deepest the path goes into the shape within a short window around t (m, ≥ 0).</summary>
        Private Shared Function MaxDepthNear(k As Outline, d0 As Vector, dv As Vector, da As Vector, t As Double) As Double
            Dim deepest = 0.0
            For s = -1000 To 1000
                Dim time = t + s * 0.000001
                If time < 0 Then Continue For
                deepest = Math.Max(deepest, -GeometryTestKit.Gap(k, GeometryTestKit.PathAt(d0, dv, da, time)))
            Next
            Return deepest
        End Function

        <Fact>
        Public Sub RandomPaths_Horizon_CutsOffOnlyWhatLiesBeyondIt()
            Dim rng As New Random(77)
            Dim pruned = 0, kept = 0
            For trial = 0 To 4999
                Dim k = GeometryTestKit.RandomOutline(rng)
                Dim d0 As Vector, dv As Vector, da As Vector
                AimAt(rng, k, d0, dv, da)
                If rng.Next(3) = 0 Then dv = -dv ' many paths that miss, which the box around the path can rule out
                Dim f As Integer, fh As Integer
                Dim free = OutlineContact.EarliestEntry(k, d0, dv, da, Slop, 0, Double.PositiveInfinity, f)
                Dim horizon = If(free < Double.PositiveInfinity AndAlso rng.Next(2) = 0, free * (0.5 + rng.NextDouble()), 3 * rng.NextDouble())
                Dim cut = OutlineContact.EarliestEntry(k, d0, dv, da, Slop, 0, horizon, fh)
                If free <= horizon Then
                    Assert.Equal(free, cut)
                    Assert.Equal(f, fh)
                    kept += 1
                Else
                    Assert.Equal(Double.PositiveInfinity, cut)
                    Assert.Equal(-1, fh)
                    pruned += 1
                End If
            Next
            Assert.True(kept > 500 AndAlso pruned > 500)
        End Sub
    End Class
End Namespace
