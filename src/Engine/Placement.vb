Option Strict On

''' <summary>
''' Where a body may go: pure queries over a world's bodies, for placing a new body, carrying one
''' and checking a scene. A body is free at a place when it overlaps, by more than
''' <see cref="Tolerance"/>, no body it collides with (two fixed bodies never collide) and, when it
''' is movable in a container with walls, lies inside the container. These are the rules a scene
''' file is read with, so a world kept free always saves to a file that opens again.
''' A body is asked about at an offset from where it is (a body not yet in the world is asked about
''' where it was built). Every kind of body is handled alike through its outline: body A touches
''' body B exactly when p_A − p_B lies in their Minkowski difference, so each pair is a point against
''' one fixed outline (<see cref="OutlineContact"/>).
''' </summary>
Public Module Placement
    ''' <summary>Overlap accepted as touching, m (the same as a scene file's).</summary>
    Public Const Tolerance As Double = 0.000000001

    ''' <summary>How far a carried body may go, and what stopped it.</summary>
    Public Structure Sweep
        ''' <summary>The share of the asked displacement it can travel, 0 to 1.</summary>
        Public ReadOnly Property Fraction As Double
        ''' <summary>The body it would enter next, or Nothing (nothing in the way, or a wall).</summary>
        Public ReadOnly Property Blocker As Shape
        ''' <summary>True when a wall of the container stopped it.</summary>
        Public ReadOnly Property ByWall As Boolean
        ''' <summary>Unit normal of the contact, pointing towards the moving body (zero when nothing stopped it).</summary>
        Public ReadOnly Property Normal As Vector

        Friend Sub New(fraction As Double, blocker As Shape, byWall As Boolean, normal As Vector)
            Me.Fraction = fraction
            Me.Blocker = blocker
            Me.ByWall = byWall
            Me.Normal = normal
        End Sub

        ''' <summary>True when something is in the way before the end of the displacement.</summary>
        Public ReadOnly Property IsBlocked As Boolean
            Get
                Return Blocker IsNot Nothing OrElse ByWall
            End Get
        End Property
    End Structure

    ''' <summary>
    ''' The moving body against one other body: the other's reference point and the Minkowski
    ''' difference of their outlines (grown by a clearance, when one is kept), so that the moving body
    ''' with its reference point at p overlaps the other by Penetration(K, p − Anchor).Depth.
    ''' </summary>
    Private Structure Pair
        Public Other As Shape
        Public Anchor As Vector
        Public K As Outline

        ''' <summary>How deep the moving body, with its reference point at p, is in the other (≤ 0 when apart); quick when far.</summary>
        Public Function Depth(p As Vector) As Double
            Dim d = p - Anchor
            ' Outside the difference's box: apart by at least that much (enough to say "apart").
            Dim outside = Math.Max(Math.Max(K.MinX - d.X, d.X - K.MaxX), Math.Max(K.MinY - d.Y, d.Y - K.MaxY))
            If outside > 0 Then Return -outside
            Return OutlineContact.Penetration(K, d).Depth
        End Function
    End Structure

    ''' <summary>Whether two bodies collide at all: fixed bodies never collide with each other.</summary>
    Public Function Collide(a As Shape, b As Shape) As Boolean
        If a Is Nothing Then Throw New ArgumentNullException(NameOf(a))
        If b Is Nothing Then Throw New ArgumentNullException(NameOf(b))
        Return Not (a.IsFixed AndAlso b.IsFixed)
    End Function

    ''' <summary>How deep <paramref name="body"/>, moved by <paramref name="offset"/> (m), overlaps <paramref name="other"/>, m (≤ 0 when apart).</summary>
    Public Function OverlapDepth(body As Shape, offset As Vector, other As Shape) As Double
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        If other Is Nothing Then Throw New ArgumentNullException(NameOf(other))
        Return PairOf(body, other, 0).Depth(body.Position + offset)
    End Function

    ''' <summary>
    ''' Whether <paramref name="body"/>, moved by <paramref name="offset"/>, keeps to the container:
    ''' always for a fixed body or a container without walls; otherwise wholly inside it.
    ''' </summary>
    Public Function IsInside(world As World, body As Shape, offset As Vector) As Boolean
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        If body.IsFixed OrElse Not world.Walls Then Return True
        Dim min = body.BoundsMin + offset, max = body.BoundsMax + offset
        Return min.X >= -Tolerance AndAlso min.Y >= -Tolerance AndAlso max.X <= world.Width + Tolerance AndAlso max.Y <= world.Height + Tolerance
    End Function

    ''' <summary>
    ''' The first body of the world (in the world's order; never <paramref name="body"/> itself) that
    ''' <paramref name="body"/>, moved by <paramref name="offset"/>, would overlap by more than
    ''' <see cref="Tolerance"/> among those it collides with; Nothing when there is none.
    ''' </summary>
    Public Function FirstOverlap(world As World, body As Shape, offset As Vector) As Shape
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        Return FirstOverlapIn(PairsFor(world, body, Nothing, Nothing), body.Position + offset)
    End Function

    ''' <summary>True when <paramref name="body"/>, moved by <paramref name="offset"/>, overlaps nothing it collides with and keeps to the container.</summary>
    Public Function IsFree(world As World, body As Shape, offset As Vector) As Boolean
        Return IsInside(world, body, offset) AndAlso FirstOverlap(world, body, offset) Is Nothing
    End Function

    ''' <summary>
    ''' How far along <paramref name="displacement"/> (m) <paramref name="body"/> can move in a straight
    ''' line before it enters a body that <paramref name="blocks"/> selects (among those it collides
    ''' with) or, when it must keep to the container, leaves it. Contact times are solved for, not
    ''' sampled, so nothing is jumped over however long the move. A body already touching or
    ''' overlapping another may move away from it or along it, never further into it.
    ''' </summary>
    ''' <param name="blocks">which bodies stop it; Nothing for every body it collides with</param>
    ''' <param name="clearance">how far (m) to keep from each body, beyond touching; Nothing for none</param>
    Public Function SweepTo(world As World, body As Shape, displacement As Vector, Optional blocks As Func(Of Shape, Boolean) = Nothing,
                            Optional clearance As Func(Of Shape, Double) = Nothing) As Sweep
        Return SweepTo(world, body, Vector.Zero, displacement, blocks, clearance)
    End Function

    ''' <summary>As <see cref="SweepTo(World, Shape, Vector, Func(Of Shape, Boolean), Func(Of Shape, Double))"/>, from the body moved by <paramref name="from"/> (m).</summary>
    Public Function SweepTo(world As World, body As Shape, from As Vector, displacement As Vector, Optional blocks As Func(Of Shape, Boolean) = Nothing,
                            Optional clearance As Func(Of Shape, Double) = Nothing) As Sweep
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        Return SweepIn(world, body, PairsFor(world, body, blocks, clearance), from, displacement)
    End Function

    ''' <summary>
    ''' Moves as far towards <paramref name="displacement"/> as the body can go, sliding along what
    ''' stops it (the part of the move into the obstacle is dropped, the part along it kept), a few
    ''' times over; returns the offset (m) it reaches.
    ''' </summary>
    Public Function SlideTo(world As World, body As Shape, displacement As Vector, Optional blocks As Func(Of Shape, Boolean) = Nothing,
                            Optional clearance As Func(Of Shape, Double) = Nothing) As Vector
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        Dim pairs = PairsFor(world, body, blocks, clearance)
        Dim reached = Vector.Zero
        Dim remaining = displacement
        For attempt = 1 To 4
            If remaining.LengthSquared <= 1.0E-24 Then Exit For
            Dim sweep = SweepIn(world, body, pairs, reached, remaining)
            reached += remaining * sweep.Fraction
            If Not sweep.IsBlocked Then Exit For
            remaining = remaining * (1 - sweep.Fraction)
            Dim into = Vector.Dot(remaining, sweep.Normal)
            If into < 0 Then remaining -= sweep.Normal * into
        Next
        Return reached
    End Function

    ''' <summary>
    ''' The offset nearest to <paramref name="desired"/> (m) at which the body is free, searched on
    ''' rings out to <paramref name="reach"/> metres (a movable body in a walled container is first
    ''' brought inside); Nothing when there is no free place that near.
    ''' </summary>
    Public Function NearestFree(world As World, body As Shape, desired As Vector, reach As Double) As Vector?
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        If Not desired.IsFinite Then Throw New ArgumentException("the place must be finite", NameOf(desired))
        Dim pairs = PairsFor(world, body, Nothing, Nothing)
        Dim free = Function(offset As Vector) IsInside(world, body, offset) AndAlso FirstOverlapIn(pairs, body.Position + offset) Is Nothing
        Dim size = Math.Min(body.BoundsMax.X - body.BoundsMin.X, body.BoundsMax.Y - body.BoundsMin.Y)
        Dim centre = KeepInside(world, body, desired)
        If free(centre) Then Return centre
        ' At most 60 coarse rings: the search stays well under a tenth of a second among 1000 bodies.
        Dim stepLength = Math.Max(size / 8, reach / 60)
        If Not (stepLength > 0) Then Return Nothing
        Dim rings = CInt(Math.Min(60, Math.Ceiling(reach / stepLength)))
        For k = 1 To rings
            ' Coarse: the first ring with a free place on it; then, ray by ray (one degree apart), the
            ' least distance out to a free place between this ring and the one before.
            Dim count = Math.Max(8, CInt(Math.Ceiling(2 * Math.PI * k)))
            Dim anyFree = False
            For i = 0 To count - 1
                If free(OnRing(world, body, centre, k * stepLength, 2 * Math.PI * i / count)) Then
                    anyFree = True
                    Exit For
                End If
            Next
            If Not anyFree Then Continue For
            Dim found As Vector? = Nothing
            Dim foundDistance = Double.PositiveInfinity
            For degree = 0 To 359
                Dim angle = degree * Math.PI / 180
                Dim hi = k * stepLength, lo = (k - 1) * stepLength
                Dim best = OnRing(world, body, centre, hi, angle)
                If Not free(best) Then Continue For
                For halving = 1 To 10
                    Dim mid = (lo + hi) / 2
                    Dim p = OnRing(world, body, centre, mid, angle)
                    If free(p) Then
                        hi = mid
                        best = p
                    Else
                        lo = mid
                    End If
                Next
                Dim distance = (best - desired).Length
                If distance < foundDistance Then
                    found = best
                    foundDistance = distance
                End If
            Next
            If found.HasValue Then Return found
        Next
        Return Nothing
    End Function

    ''' <summary>
    ''' The first thing wrong with a world as a scene file would see it: two bodies that collide
    ''' overlapping by more than <see cref="Tolerance"/>, or a movable body outside a walled
    ''' container; Nothing when it is sound. Checks every pair whose boxes meet: meant for tests and
    ''' checks, not frames.
    ''' </summary>
    Public Function FindProblem(world As World) As String
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim bodies = world.Bodies
        For i = 0 To bodies.Count - 1
            Dim a = bodies(i)
            If Not a.Position.IsFinite Then Return "'" & a.Id & "' is not at a finite place"
            If Not IsInside(world, a, Vector.Zero) Then Return "'" & a.Id & "' is outside the container"
            Dim amin = a.BoundsMin, amax = a.BoundsMax
            For j = i + 1 To bodies.Count - 1
                Dim b = bodies(j)
                If Not Collide(a, b) Then Continue For
                Dim bmin = b.BoundsMin, bmax = b.BoundsMax
                If amax.X < bmin.X OrElse bmax.X < amin.X OrElse amax.Y < bmin.Y OrElse bmax.Y < amin.Y Then Continue For
                Dim d = PairOf(b, a, 0).Depth(b.Position)
                If d > Tolerance Then
                    Return "'" & b.Id & "' overlaps '" & a.Id & "' by " & d.ToString("G3", Globalization.CultureInfo.InvariantCulture) & " m"
                End If
            Next
        Next
        Return Nothing
    End Function

    ' ---- pairs --------------------------------------------------------------------------------

    ''' <summary>The moving body against <paramref name="other"/>, kept <paramref name="clearance"/> m away.</summary>
    Private Function PairOf(body As Shape, other As Shape, clearance As Double) As Pair
        Dim k = Outline.MinkowskiDifference(other.Outline, body.Outline)
        ' Growing the difference by a point's radius keeps that much more distance.
        If clearance > 0 Then k = Outline.MinkowskiDifference(k, Outline.Point(clearance))
        Return New Pair With {.Other = other, .Anchor = other.Position, .K = k}
    End Function

    ''' <summary>The pairs a query looks at: every other body the moving one collides with (and <paramref name="blocks"/> selects).</summary>
    Private Function PairsFor(world As World, body As Shape, blocks As Func(Of Shape, Boolean), clearance As Func(Of Shape, Double)) As List(Of Pair)
        Dim pairs As New List(Of Pair)(world.Bodies.Count)
        For Each other In world.Bodies
            If other Is body OrElse Not Collide(body, other) Then Continue For
            If blocks IsNot Nothing AndAlso Not blocks(other) Then Continue For
            pairs.Add(PairOf(body, other, If(clearance Is Nothing, 0.0, Math.Max(0.0, clearance(other)))))
        Next
        Return pairs
    End Function

    Private Function FirstOverlapIn(pairs As List(Of Pair), p As Vector) As Shape
        For Each pair In pairs
            If pair.Depth(p) > Tolerance Then Return pair.Other
        Next
        Return Nothing
    End Function

    Private Function SweepIn(world As World, body As Shape, pairs As List(Of Pair), from As Vector, displacement As Vector) As Sweep
        If Not displacement.IsFinite OrElse Not from.IsFinite Then Throw New ArgumentException("the move must be finite", NameOf(displacement))
        If displacement.LengthSquared = 0 Then Return New Sweep(1.0, Nothing, False, Vector.Zero)
        Dim start = body.Position + from
        Dim best = 1.0
        Dim blocker As Shape = Nothing
        Dim byWall = False
        Dim normal = Vector.Zero
        For Each pair In pairs
            Dim d0 = start - pair.Anchor
            ' Nowhere near: the whole move stays outside the difference's box.
            Dim k = pair.K
            Dim d1 = d0 + displacement
            If Math.Max(d0.X, d1.X) < k.MinX - Tolerance OrElse Math.Min(d0.X, d1.X) > k.MaxX + Tolerance OrElse
               Math.Max(d0.Y, d1.Y) < k.MinY - Tolerance OrElse Math.Min(d0.Y, d1.Y) > k.MaxY + Tolerance Then Continue For
            Dim now = OutlineContact.Penetration(k, d0)
            Dim s As Double
            Dim n As Vector
            If now.Depth > -Tolerance Then
                ' Touching (or already inside): away or along is allowed, further in is not.
                n = now.Normal
                If Vector.Dot(displacement, n) >= 0 Then Continue For
                s = 0
            Else
                Dim feature As Integer
                s = OutlineContact.EarliestEntry(k, d0, displacement, Vector.Zero, Tolerance, 0, 1.0, feature)
                If Not (s <= best) Then Continue For
                n = OutlineContact.ContactNormal(k, d0 + displacement * s, feature, Tolerance)
            End If
            If s < best OrElse (s = best AndAlso blocker Is Nothing AndAlso Not byWall) Then
                best = s
                blocker = pair.Other
                byWall = False
                normal = n
            End If
        Next
        If Not body.IsFixed AndAlso world.Walls Then
            Dim w = WallFraction(body.BoundsMin + from, body.BoundsMax + from, displacement, world.Width, world.Height)
            If w.Fraction < best Then
                best = w.Fraction
                blocker = Nothing
                byWall = True
                normal = w.Normal
            End If
        End If
        Return New Sweep(Math.Max(0.0, Math.Min(1.0, best)), blocker, byWall, normal)
    End Function

    ''' <summary>Where a movable body's bounding box, moving by s·d, first meets a wall (s from 0 to 1, above 1 for none), and the wall's inward normal.</summary>
    Private Function WallFraction(min As Vector, max As Vector, d As Vector, width As Double, height As Double) As (Fraction As Double, Normal As Vector)
        Dim best = 2.0
        Dim normal = Vector.Zero
        Consider(d.X > 0, (width - max.X) / d.X, New Vector(-1, 0), best, normal)
        Consider(d.X < 0, (0 - min.X) / d.X, New Vector(1, 0), best, normal)
        Consider(d.Y > 0, (height - max.Y) / d.Y, New Vector(0, -1), best, normal)
        Consider(d.Y < 0, (0 - min.Y) / d.Y, New Vector(0, 1), best, normal)
        Return (best, normal)
    End Function

    Private Sub Consider(moving As Boolean, s As Double, n As Vector, ByRef best As Double, ByRef normal As Vector)
        If Not moving Then Return
        s = Math.Max(0.0, s) ' already at (or past) the wall: no further that way
        If s < best Then
            best = s
            normal = n
        End If
    End Sub

    ''' <summary>The offset at distance radius (m) and angle (rad) from centre, kept inside when it must be.</summary>
    Private Function OnRing(world As World, body As Shape, centre As Vector, radius As Double, angle As Double) As Vector
        Return KeepInside(world, body, centre + New Vector(radius * Math.Cos(angle), radius * Math.Sin(angle)))
    End Function

    ''' <summary>An offset moved so that a movable body in a walled container lies inside it.</summary>
    Private Function KeepInside(world As World, body As Shape, offset As Vector) As Vector
        If body.IsFixed OrElse Not world.Walls Then Return offset
        Return world.InsideFor(body, body.Position + offset) - body.Position
    End Function
End Module
