Option Strict On

''' <summary>
''' Which closed form moves a group of linked bodies that holds no lasting contact, chosen from their state now;
''' a group no closed form fits is integrated.
''' </summary>
Friend Module LinkedMotions
    ''' <summary>A string within this fraction of its length counts as at full length.</summary>
    Friend Const FullFraction As Double = 0.000000001

    ''' <summary>
    ''' Whether <paramref name="l"/> is a rod short of its length (by more than <see cref="FullFraction"/> of it and
    ''' <paramref name="slop"/>, m). Only a rod that a group watched, as the others held implied it, can get there (a
    ''' body held by two rods in line to fixed points cannot: <see cref="TieLock"/> holds it where it is). Such a rod is
    ''' watched as a slack string is until it reaches its length again; held as it is, it would put its ends back at its
    ''' length at once, a jump that makes or takes energy. A rod short by no more than the slop is only the integrator's
    ''' error in a rod that held (a 7.8 mg ball pressed into a corner by a spring's 2·10⁷ N, a 0.16 kg ball on a 1 cm
    ''' rod from it, is a nanometre short after a step): it is held, and put back at its length as a contact within
    ''' the slop is put on its face. Watched instead, nothing would stop its ends coming together.
    ''' </summary>
    Friend Function IsShortRod(l As Link, slop As Double) As Boolean
        Return l.Kind = LinkKind.Rod AndAlso l.Distance < l.Length * (1 - FullFraction) - slop
    End Function

    ''' <summary>
    ''' Whether string <paramref name="l"/> is taut: its ends at its full length (within <see cref="FullFraction"/>
    ''' and <paramref name="slop"/>, m) and neither moving apart nor together (within FullFraction of the speeds
    ''' that matter, or <paramref name="speedSlop"/>, m/s, if larger). <paramref name="gravity"/>: m/s².
    ''' </summary>
    Friend Function IsTaut(l As Link, gravity As Double, Optional slop As Double = 0, Optional speedSlop As Double = 0) As Boolean
        If l.Distance < l.Length * (1 - FullFraction) - slop Then Return False
        Dim vb = If(l.IsAnchored, Vector.Zero, l.B.Velocity)
        Dim scale = l.A.Velocity.Length + vb.Length + Math.Sqrt(Math.Max(gravity, 1) * l.Length)
        Return Math.Abs(l.StretchRate) <= Math.Max(FullFraction * scale, speedSlop)
    End Function

    ''' <summary>
    ''' −1 slack, 0 taut (at full length, not moving along itself), +1 over-long and stretching (it must snap now), for
    ''' string <paramref name="l"/> under <paramref name="gravity"/> (m/s²); <paramref name="released"/> (a string that has
    ''' just gone slack or snapped back) is slack whatever the rounding says.
    ''' </summary>
    Friend Function StringState(l As Link, gravity As Double, released As Object) As Integer
        If l Is released Then Return -1
        Dim d = l.Distance
        If d < l.Length * (1 - FullFraction) Then Return -1
        Dim rate = l.StretchRate
        Dim vb = If(l.IsAnchored, Vector.Zero, l.B.Velocity)
        Dim scale = l.A.Velocity.Length + vb.Length + Math.Sqrt(Math.Max(gravity, 1) * l.Length)
        If Math.Abs(rate) <= FullFraction * scale Then Return 0
        Return If(rate > 0 AndAlso d >= l.Length, 1, -1)
    End Function

    ''' <summary>
    ''' The closed form for <paramref name="group"/> from its bodies' states at <paramref name="time"/> (s).
    ''' <paramref name="released"/>: a string that has just gone slack (its tension fell to zero) or snapped back is
    ''' slack, whatever the rounding says.
    ''' </summary>
    Friend Function Create(group As LinkedGroup, world As World, time As Double, released As Object, slop As Double) As LinkedMotion
        Dim g = world.Gravity
        Dim slack = released IsNot Nothing AndAlso group.Links.Contains(TryCast(released, Link))
        Dim a = group.Bodies(0)
        ' Drag or buoyancy: its closed form (linear drag alone) or its integral (docs/forces.md).
        Dim forced = ForcedMotions.Create(group, world, time, released)
        If forced IsNot Nothing Then Return forced
        ' A group that holds no contact: a free body flies.
        If group.Links.Count = 0 Then Return New FlightMotion(a, time, g)
        Dim l = group.Links(0)
        If OnlySprings(group) Then
            If group.Bodies.Count = 1 AndAlso group.Links.Count = 1 AndAlso SpringMotion.Fits(a, l, g) Then Return New SpringMotion(a, l, time, g)
            If SpringPairMotion.Fits(group) Then Return New SpringPairMotion(l.A, l.B, group.Links, time, g)
            Return New IntegratedMotion(group.Bodies.ToArray(), group.Links, time, g)
        End If
        If IsChain(group) Then
            If SlackFlightMotion.Fits(group.Links, g, released) Then
                Dim flight = New SlackFlightMotion(group.Bodies.ToArray(), group.Links, time, g, slop)
                ' A string at full length that the flight would take past it at once, its ends not moving apart (a body
                ' swung across it, 31 km/s across 0.95 m): it pulls, and the integrated chain holds it; the flight would
                ' snap it, find nothing to stop, and snap it again, for ever.
                If flight.TransitionTime > time Then Return flight
            End If
            Return New ConstrainedMotion(group.Bodies.ToArray(), group.Links, Array.Empty(Of Constraint)(), time, g, released, ForcedMotions.Size(group))
        End If
        If group.Bodies.Count = 1 Then
            Select Case l.Kind
                Case LinkKind.Rod
                    Return New PendulumMotion(a, l, time, g)
                Case Else
                    If Not slack AndAlso AnchoredTaut(a, l, g, slop) Then Return New PendulumMotion(a, l, time, g)
                    Return New FlightMotion(a, time, g, l, slop)
            End Select
        End If
        Dim b = group.Bodies(1)
        If l.Kind = LinkKind.Rod OrElse (Not slack AndAlso PairTaut(a, b, l, slop)) Then
            Dim first = If(l.A Is a, a, b)
            Return New DumbbellMotion(first, If(first Is a, b, a), l, time, g)
        End If
        Return New SlackFlightMotion({a, b}, {l}, time, g, slop)
    End Function

    ''' <summary>Whether the group has a rod or string and is more than one body on one link or two bodies on one link (a double pendulum, a rope, a chain).</summary>
    Private Function IsChain(group As LinkedGroup) As Boolean
        Return group.Bodies.Count > 2 OrElse group.Links.Count > 1
    End Function

    ''' <summary>Whether every link of the group is a spring (and it has one).</summary>
    Private Function OnlySprings(group As LinkedGroup) As Boolean
        Return group.Links.Count > 0 AndAlso group.Links.All(Function(l) l.Kind = LinkKind.Spring)
    End Function

    ''' <summary>
    ''' A body on a string to a fixed point is taut when it is at full length (within <paramref name="slop"/>, m, as the
    ''' flight's search for the string snapping taut allows: a body short of the length by less than that, swung
    ''' round fast, was found snapping taut at once, again and again, and never taut), not moving along the string,
    ''' and the string pulls: T/m = v_across²/L + g cos θ ≥ 0 (θ from straight down). Where the pull is
    ''' within rounding of zero, the free parabola decides: if it would leave the circle at once, the string is taut.
    ''' </summary>
    Private Function AnchoredTaut(body As Shape, l As Link, g As Double, slop As Double) As Boolean
        Dim r = body.CentreOfMass - l.EndB
        Dim d = r.Length
        If d < l.Length * (1 - FullFraction) - slop Then Return False
        Dim v = body.Velocity
        Dim along = Vector.Dot(v, r) / d
        Dim scale = v.Length + Math.Sqrt(g * l.Length)
        If Math.Abs(along) > FullFraction * scale Then Return False
        Dim pull = (v.LengthSquared - along * along) / l.Length - g * r.Y / d
        If pull > FullFraction * (g + v.LengthSquared / l.Length) Then Return True
        If pull < -FullFraction * (g + v.LengthSquared / l.Length) Then Return False
        Return StringTaut.AnchoredTautTime(l.EndB, l.Length, body.CentreOfMass, v, g, slop) = 0
    End Function

    ''' <summary>
    ''' A string between two free bodies is taut at full length (within <paramref name="slop"/>, m, as the flight's search
    ''' for the string snapping taut allows) when they do not move along it (its pull, μω²L, is never negative). Short
    ''' of the length by less than the slop, a pair turning on it was found snapping taut at once, with nothing to stop,
    ''' again and again, and never taut.
    ''' </summary>
    Private Function PairTaut(a As Shape, b As Shape, l As Link, slop As Double) As Boolean
        Dim r = b.CentreOfMass - a.CentreOfMass
        Dim d = r.Length
        If d < l.Length * (1 - FullFraction) - slop Then Return False
        Dim w = b.Velocity - a.Velocity
        Return Math.Abs(Vector.Dot(w, r) / d) <= FullFraction * (w.Length + a.Velocity.Length + b.Velocity.Length)
    End Function

    ''' <summary>
    ''' The speed (m/s) below which a bounce against a support pressed on by <paramref name="gravity"/> (m/s²)
    ''' would rise less than four times <paramref name="slop"/> (m): v² = 2 g h with h = 4 slop.
    ''' </summary>
    Friend Function RestingSpeed(gravity As Double, slop As Double) As Double
        Return Math.Sqrt(8 * Math.Max(gravity, 0) * slop)
    End Function
End Module
