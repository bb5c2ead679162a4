Option Strict On

''' <summary>
''' Where a body may go: pure queries over a world's bodies, for placing a new body, carrying one
''' and checking a scene. A body is free at a place when it overlaps, by more than
''' <see cref="Tolerance"/>, no body it may not overlap (<see cref="MayNotOverlap"/>) and, when it
''' is movable in a container with walls, lies inside the container. These are the rules a scene
''' file is read with, so a world kept free always saves to a file that opens again.
''' A body is asked about at an offset from where it is (a body not yet in the world is asked about
''' where it was built). Body kinds are told apart in one place, <see cref="FootprintOf"/>, and
''' their pairs in <see cref="Depth"/>, <see cref="ContactNormal"/> and <see cref="EntryFraction"/>;
''' a new kind of body adds its footprint and its pairs there.
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

    ''' <summary>The geometry a body takes up: a disc, or an axis-aligned box.</summary>
    Private Structure Footprint
        Public IsDisc As Boolean
        Public Centre As Vector
        Public Radius As Double
        ''' <summary>Lower-left corner of the bounding box, m.</summary>
        Public Min As Vector
        ''' <summary>Upper-right corner of the bounding box, m.</summary>
        Public Max As Vector
    End Structure

    ''' <summary>Whether two bodies collide at all: fixed bodies never collide with each other.</summary>
    Public Function Collide(a As Shape, b As Shape) As Boolean
        If a Is Nothing Then Throw New ArgumentNullException(NameOf(a))
        If b Is Nothing Then Throw New ArgumentNullException(NameOf(b))
        Return Not (a.IsFixed AndAlso b.IsFixed)
    End Function

    ''' <summary>
    ''' Whether two bodies may not overlap: those that collide, and two circles even when both are
    ''' fixed, because the scene reader refuses overlapping circles of any kind (a fixed ball may
    ''' still sit on a rectangle). Every query here keeps to this, so what it calls free saves.
    ''' </summary>
    Public Function MayNotOverlap(a As Shape, b As Shape) As Boolean
        Return Collide(a, b) OrElse (TypeOf a Is Circle AndAlso TypeOf b Is Circle)
    End Function

    ''' <summary>How deep <paramref name="body"/>, moved by <paramref name="offset"/> (m), overlaps <paramref name="other"/>, m (≤ 0 when apart).</summary>
    Public Function OverlapDepth(body As Shape, offset As Vector, other As Shape) As Double
        Return Depth(FootprintOf(body, offset), FootprintOf(other, Vector.Zero))
    End Function

    ''' <summary>
    ''' Whether <paramref name="body"/>, moved by <paramref name="offset"/>, keeps to the container:
    ''' always for a fixed body or a container without walls; otherwise wholly inside it.
    ''' </summary>
    Public Function IsInside(world As World, body As Shape, offset As Vector) As Boolean
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        If body.IsFixed OrElse Not world.Walls Then Return True
        Dim f = FootprintOf(body, offset)
        Return f.Min.X >= -Tolerance AndAlso f.Min.Y >= -Tolerance AndAlso f.Max.X <= world.Width + Tolerance AndAlso f.Max.Y <= world.Height + Tolerance
    End Function

    ''' <summary>
    ''' The first body of the world (in the world's order; never <paramref name="body"/> itself) that
    ''' <paramref name="body"/>, moved by <paramref name="offset"/>, would overlap by more than
    ''' <see cref="Tolerance"/> among those it collides with; Nothing when there is none.
    ''' </summary>
    Public Function FirstOverlap(world As World, body As Shape, offset As Vector) As Shape
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        Dim f = FootprintOf(body, offset)
        For Each other In world.Bodies
            If other Is body OrElse Not MayNotOverlap(body, other) Then Continue For
            If Depth(f, FootprintOf(other, Vector.Zero)) > Tolerance Then Return other
        Next
        Return Nothing
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
        If Not displacement.IsFinite OrElse Not from.IsFinite Then Throw New ArgumentException("the move must be finite", NameOf(displacement))
        Dim start = FootprintOf(body, from)
        Dim best = 1.0
        Dim blocker As Shape = Nothing
        Dim byWall = False
        Dim normal = Vector.Zero
        If displacement.LengthSquared = 0 Then Return New Sweep(1.0, Nothing, False, Vector.Zero)
        For Each other In world.Bodies
            If other Is body OrElse Not MayNotOverlap(body, other) Then Continue For
            If blocks IsNot Nothing AndAlso Not blocks(other) Then Continue For
            Dim o = Grown(FootprintOf(other, Vector.Zero), If(clearance Is Nothing, 0.0, Math.Max(0.0, clearance(other))))
            Dim s As Double
            Dim n As Vector
            If Depth(start, o) > -Tolerance Then
                ' Touching (or already inside): away or along is allowed, further in is not.
                n = ContactNormal(start, o)
                If Vector.Dot(displacement, n) >= 0 Then Continue For
                s = 0
            Else
                s = EntryFraction(start, displacement, o)
                If s > best Then Continue For
                n = ContactNormal(Shifted(start, displacement * s), o)
            End If
            If s < best OrElse (s = best AndAlso blocker Is Nothing AndAlso Not byWall) Then
                best = s
                blocker = other
                byWall = False
                normal = n
            End If
        Next
        If Not body.IsFixed AndAlso world.Walls Then
            Dim w = WallFraction(start, displacement, world.Width, world.Height)
            If w.Fraction < best Then
                best = w.Fraction
                blocker = Nothing
                byWall = True
                normal = w.Normal
            End If
        End If
        Return New Sweep(Math.Max(0.0, Math.Min(1.0, best)), blocker, byWall, normal)
    End Function

    ''' <summary>
    ''' Moves as far towards <paramref name="displacement"/> as the body can go, sliding along what
    ''' stops it (the part of the move into the obstacle is dropped, the part along it kept), a few
    ''' times over; returns the offset (m) it reaches.
    ''' </summary>
    Public Function SlideTo(world As World, body As Shape, displacement As Vector, Optional blocks As Func(Of Shape, Boolean) = Nothing,
                            Optional clearance As Func(Of Shape, Double) = Nothing) As Vector
        Dim reached = Vector.Zero
        Dim remaining = displacement
        For attempt = 1 To 4
            If remaining.LengthSquared <= 1.0E-24 Then Exit For
            Dim sweep = SweepTo(world, body, reached, remaining, blocks, clearance)
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
        Dim f = FootprintOf(body, Vector.Zero)
        Dim size = Math.Min(f.Max.X - f.Min.X, f.Max.Y - f.Min.Y)
        Dim centre = KeepInside(world, body, f, desired)
        If IsFree(world, body, centre) Then Return centre
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
                If IsFree(world, body, OnRing(world, body, f, centre, k * stepLength, 2 * Math.PI * i / count)) Then
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
                Dim best = OnRing(world, body, f, centre, hi, angle)
                If Not IsFree(world, body, best) Then Continue For
                For halving = 1 To 10
                    Dim mid = (lo + hi) / 2
                    Dim p = OnRing(world, body, f, centre, mid, angle)
                    If IsFree(world, body, p) Then
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
    ''' container; Nothing when it is sound. Checks every pair: meant for tests and checks, not frames.
    ''' </summary>
    Public Function FindProblem(world As World) As String
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim bodies = world.Bodies
        For i = 0 To bodies.Count - 1
            Dim a = bodies(i)
            If Not IsInside(world, a, Vector.Zero) Then Return "'" & a.Id & "' is outside the container"
            Dim fa = FootprintOf(a, Vector.Zero)
            If Not fa.Min.IsFinite OrElse Not fa.Max.IsFinite Then Return "'" & a.Id & "' is not at a finite place"
            For j = i + 1 To bodies.Count - 1
                Dim b = bodies(j)
                If Not MayNotOverlap(a, b) Then Continue For
                Dim d = Depth(fa, FootprintOf(b, Vector.Zero))
                If d > Tolerance Then
                    Return "'" & b.Id & "' overlaps '" & a.Id & "' by " & d.ToString("G3", Globalization.CultureInfo.InvariantCulture) & " m"
                End If
            Next
        Next
        Return Nothing
    End Function

    ' ---- body kinds -------------------------------------------------------------------------

    ''' <summary>A body's footprint moved by offset, m. The one place that tells body kinds apart.</summary>
    Private Function FootprintOf(body As Shape, offset As Vector) As Footprint
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        Dim c = TryCast(body, Circle)
        If c IsNot Nothing Then
            Dim centre = c.Position + offset
            Dim r = New Vector(c.Radius, c.Radius)
            Return New Footprint With {.IsDisc = True, .Centre = centre, .Radius = c.Radius, .Min = centre - r, .Max = centre + r}
        End If
        Dim box = TryCast(body, Rectangle)
        If box IsNot Nothing Then
            Dim min = box.Min + offset, max = box.Max + offset
            Return New Footprint With {.IsDisc = False, .Centre = (min + max) / 2, .Min = min, .Max = max}
        End If
        Throw New NotSupportedException("placement knows circles and rectangles, not " & body.GetType().Name)
    End Function

    ''' <summary>A footprint grown by a margin (m) all round: a disc's radius, a box's sides (its corners stay square, which only keeps it further away).</summary>
    Private Function Grown(f As Footprint, margin As Double) As Footprint
        If margin <= 0 Then Return f
        Dim m = New Vector(margin, margin)
        f.Min -= m
        f.Max += m
        If f.IsDisc Then f.Radius += margin
        Return f
    End Function

    Private Function Shifted(f As Footprint, by As Vector) As Footprint
        f.Centre += by
        f.Min += by
        f.Max += by
        Return f
    End Function

    ' ---- pairs ------------------------------------------------------------------------------

    ''' <summary>Overlap depth of two footprints, m (≤ 0 when apart).</summary>
    Private Function Depth(a As Footprint, b As Footprint) As Double
        If a.IsDisc AndAlso b.IsDisc Then Return a.Radius + b.Radius - (a.Centre - b.Centre).Length
        If a.IsDisc Then Return DiscBoxDepth(a, b)
        If b.IsDisc Then Return DiscBoxDepth(b, a)
        Return Math.Min(Math.Min(a.Max.X - b.Min.X, b.Max.X - a.Min.X), Math.Min(a.Max.Y - b.Min.Y, b.Max.Y - a.Min.Y))
    End Function

    Private Function DiscBoxDepth(disc As Footprint, box As Footprint) As Double
        Dim p = disc.Centre
        If p.X > box.Min.X AndAlso p.X < box.Max.X AndAlso p.Y > box.Min.Y AndAlso p.Y < box.Max.Y Then
            ' Centre inside: it must travel to the nearest side and a radius more to get out.
            Return disc.Radius + Math.Min(Math.Min(p.X - box.Min.X, box.Max.X - p.X), Math.Min(p.Y - box.Min.Y, box.Max.Y - p.Y))
        End If
        Dim qx = Math.Min(Math.Max(p.X, box.Min.X), box.Max.X)
        Dim qy = Math.Min(Math.Max(p.Y, box.Min.Y), box.Max.Y)
        Return disc.Radius - Vector.Hypot(p.X - qx, p.Y - qy)
    End Function

    ''' <summary>Unit normal of the contact of a with b, pointing from b towards a.</summary>
    Private Function ContactNormal(a As Footprint, b As Footprint) As Vector
        If a.IsDisc AndAlso b.IsDisc Then Return (a.Centre - b.Centre).Normalized(New Vector(0, 1))
        If a.IsDisc Then Return Collider.CircleRectangle(a.Centre, a.Radius, b.Min, b.Max).Normal
        If b.IsDisc Then Return -Collider.CircleRectangle(b.Centre, b.Radius, a.Min, a.Max).Normal
        ' Two boxes: along the axis of least overlap.
        Dim right = a.Max.X - b.Min.X, left = b.Max.X - a.Min.X, up = a.Max.Y - b.Min.Y, down = b.Max.Y - a.Min.Y
        Dim least = Math.Min(Math.Min(right, left), Math.Min(up, down))
        If least = left Then Return New Vector(1, 0)
        If least = right Then Return New Vector(-1, 0)
        If least = down Then Return New Vector(0, 1)
        Return New Vector(0, -1)
    End Function

    ''' <summary>
    ''' The share s of d (0 to 1) at which a, moving by s·d from apart, first touches b; above 1 when
    ''' it does not. Discs: the time of impact of two circles. A disc and a box: the disc's centre
    ''' against the box grown by the radius with rounded corners. Two boxes: a box grown by the other.
    ''' </summary>
    Private Function EntryFraction(a As Footprint, d As Vector, b As Footprint) As Double
        If a.IsDisc AndAlso b.IsDisc Then Return RayDisc(a.Centre, d, b.Centre, a.Radius + b.Radius)
        If a.IsDisc Then Return RayRoundedBox(a.Centre, d, b.Min, b.Max, a.Radius)
        If b.IsDisc Then Return RayRoundedBox(b.Centre, -d, a.Min, a.Max, b.Radius)
        Dim half = (a.Max - a.Min) / 2
        Return RayBox(a.Centre, d, b.Min - half, b.Max + half)
    End Function

    Private Const Never As Double = 2.0

    ''' <summary>First s in [0, 1] with |p + s d − centre| = r, for p outside; <see cref="Never"/> when none.</summary>
    Private Function RayDisc(p As Vector, d As Vector, centre As Vector, r As Double) As Double
        Dim rel = p - centre
        Dim a = d.LengthSquared
        If a = 0 Then Return Never
        Dim b = Vector.Dot(rel, d)
        If b >= 0 Then Return Never ' moving away
        Dim c = rel.LengthSquared - r * r
        Dim disc = b * b - a * c
        If disc < 0 Then Return Never
        ' The smaller root, in the form that does not cancel when c is small.
        Dim s = c / (-b + Math.Sqrt(disc))
        If s < 0 Then s = 0
        Return If(s <= 1, s, Never)
    End Function

    ''' <summary>First s in [0, 1] at which p + s d enters the box [min, max]; <see cref="Never"/> when none.</summary>
    Private Function RayBox(p As Vector, d As Vector, min As Vector, max As Vector) As Double
        Dim enter = Double.NegativeInfinity, leave = Double.PositiveInfinity
        If Not Slab(p.X, d.X, min.X, max.X, enter, leave) OrElse Not Slab(p.Y, d.Y, min.Y, max.Y, enter, leave) Then Return Never
        If enter > leave OrElse leave < 0 OrElse enter > 1 Then Return Never
        Return Math.Max(0.0, enter)
    End Function

    Private Function Slab(p As Double, d As Double, lo As Double, hi As Double, ByRef enter As Double, ByRef leave As Double) As Boolean
        If d = 0 Then Return p > lo AndAlso p < hi
        Dim t1 = (lo - p) / d, t2 = (hi - p) / d
        If t1 > t2 Then
            Dim t = t1
            t1 = t2
            t2 = t
        End If
        enter = Math.Max(enter, t1)
        leave = Math.Min(leave, t2)
        Return True
    End Function

    ''' <summary>First s at which a disc of radius r centred at p + s d touches the box [min, max].</summary>
    Private Function RayRoundedBox(p As Vector, d As Vector, min As Vector, max As Vector, r As Double) As Double
        Dim best = Math.Min(RayBox(p, d, New Vector(min.X - r, min.Y), New Vector(max.X + r, max.Y)),
                            RayBox(p, d, New Vector(min.X, min.Y - r), New Vector(max.X, max.Y + r)))
        For Each corner In {min, max, New Vector(min.X, max.Y), New Vector(max.X, min.Y)}
            best = Math.Min(best, RayDisc(p, d, corner, r))
        Next
        Return best
    End Function

    ''' <summary>Where a movable body's bounding box, moving by s·d, first meets a wall (s from 0 to 1, above 1 for none), and the wall's inward normal.</summary>
    Private Function WallFraction(f As Footprint, d As Vector, width As Double, height As Double) As (Fraction As Double, Normal As Vector)
        Dim best = Never
        Dim normal = Vector.Zero
        Consider(d.X > 0, (width - f.Max.X) / d.X, New Vector(-1, 0), best, normal)
        Consider(d.X < 0, (0 - f.Min.X) / d.X, New Vector(1, 0), best, normal)
        Consider(d.Y > 0, (height - f.Max.Y) / d.Y, New Vector(0, -1), best, normal)
        Consider(d.Y < 0, (0 - f.Min.Y) / d.Y, New Vector(0, 1), best, normal)
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
    Private Function OnRing(world As World, body As Shape, f As Footprint, centre As Vector, radius As Double, angle As Double) As Vector
        Return KeepInside(world, body, f, centre + New Vector(radius * Math.Cos(angle), radius * Math.Sin(angle)))
    End Function

    ''' <summary>desired moved so that a movable body in a walled container lies inside it.</summary>
    Private Function KeepInside(world As World, body As Shape, f As Footprint, desired As Vector) As Vector
        If body.IsFixed OrElse Not world.Walls Then Return desired
        Return New Vector(Clamp(desired.X, -f.Min.X, world.Width - f.Max.X), Clamp(desired.Y, -f.Min.Y, world.Height - f.Max.Y))
    End Function

    Private Function Clamp(v As Double, lo As Double, hi As Double) As Double
        If lo > hi Then Return (lo + hi) / 2 ' larger than the container: centred
        Return Math.Min(Math.Max(v, lo), hi)
    End Function

End Module
