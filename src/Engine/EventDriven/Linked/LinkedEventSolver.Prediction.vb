Option Strict On

' When each body next touches something (docs/links.md, "Links in the event solver"): every pair, wall and fixed
' body is searched by conservative advancement on the motions, up to a horizon, except the contacts a group's
' motion holds (they end by that motion's own events) and pairs that can never meet.
Partial Friend NotInheritable Class LinkedEventSolver
    ' How many times the contact searches have measured a gap, over the solver's life.
    Private _gapEvaluations As Long
    ' How many integrator steps the motions replaced so far had taken.
    Private _retiredSteps As Long
    ' How far (s, absolute) the searches under way need look (see Reach): +∞ but while a body just changed is predicted.
    Private _reach As Double = Double.PositiveInfinity
    ' Whether the last search found a contact (rather than stopping where it was told to, to be taken up again there).
    Private _found As Boolean

    ''' <summary>
    ''' How many times the contact searches have measured a gap since the solver was made: the work of finding
    ''' contacts, counted exactly, so that a search that crawls can be caught without timing it.
    ''' </summary>
    Friend ReadOnly Property GapEvaluations As Long
        Get
            Return _gapEvaluations
        End Get
    End Property

    ''' <summary>
    ''' How many integrator steps the groups' motions have taken since the solver was made, those it has replaced and
    ''' those it moves by now: the work of integrating them, counted exactly (see <see cref="GapEvaluations"/>).
    ''' </summary>
    Friend ReadOnly Property IntegratorSteps As Long
        Get
            Return _retiredSteps + _groups.Sum(Function(g) CLng(If(g.Motion Is Nothing, 0, g.Motion.StepsTaken)))
        End Get
    End Property

    ''' <summary>Counts the steps of a motion about to be replaced.</summary>
    Private Sub Retire(motion As LinkedMotion)
        If motion IsNot Nothing Then _retiredSteps += motion.StepsTaken
    End Sub

    Private Sub PredictAll(tEnd As Double)
        For i = 0 To _bodies.Length - 1
            PredictBody(i, tEnd, Nothing)
        Next
    End Sub

    ''' <summary>
    ''' Predicts every contact of body i: with the bodies after it when <paramref name="done"/> is Nothing, else with
    ''' every body not in <paramref name="done"/> (those whose pairs have just been predicted). After an event that
    ''' changed it (<paramref name="done"/> given), the nearest walls and bodies are searched first, and each search
    ''' looks only a little past the soonest contact found so far for it or, given in <paramref name="soonest"/> and
    ''' kept there, for the other bodies of its group (see <see cref="Reach"/>).
    ''' </summary>
    Private Sub PredictBody(i As Integer, tEnd As Double, done As HashSet(Of Integer), Optional ByRef soonest As Double = Double.PositiveInfinity)
        If done Is Nothing Then
            For j = i + 1 To _bodies.Length - 1
                PredictPairOf(i, j, tEnd)
            Next
            For s = 1 To 4
                PredictWallOf(i, s, tEnd)
            Next
            For f = 0 To _fixed.Length - 1
                PredictFixedOf(i, f, tEnd)
            Next
            Return
        End If
        soonest = Math.Min(soonest, MotionOf(i).TransitionTime)
        For Each target In NearestFirst(i, done)
            _reach = Reach(soonest)
            Dim t As Double
            Select Case target.Kind
                Case LinkedEventKind.Pair : t = PredictPairOf(i, target.Index, tEnd)
                Case LinkedEventKind.Wall : t = PredictWallOf(i, target.Index, tEnd)
                Case Else : t = PredictFixedOf(i, target.Index, tEnd)
            End Select
            If _found Then soonest = Math.Min(soonest, t)
        Next
        _reach = Double.PositiveInfinity
    End Sub

    ''' <summary>
    ''' How far (s, absolute) a search for a body just changed need look, given the soonest contact (or end of its
    ''' group's motion) found for it so far: twice as far ahead. All its searches are made again when that comes, so
    ''' what a search found past it would be thrown away; a search cut short here is taken up again where it stopped,
    ''' should they not be. A light ball rattling between the floor and a heavy ball every 30 ns had its searches
    ''' against a heap of balls and the side walls carried to the horizon, 20 ms ahead, after every bounce.
    ''' </summary>
    Private Function Reach(soonest As Double) As Double
        If Not (soonest > _now) OrElse Double.IsPositiveInfinity(soonest) Then Return Double.PositiveInfinity
        Return _now + 2 * (soonest - _now)
    End Function

    ''' <summary>
    ''' What body i may touch (the walls, the fixed bodies, the other bodies not in <paramref name="done"/>), nearest
    ''' first: by the distance from its centre, less its extent, to a wall, a fixed body's bounding box or another
    ''' body's centre less that body's extent.
    ''' </summary>
    Private Function NearestFirst(i As Integer, done As HashSet(Of Integer)) As List(Of (Kind As LinkedEventKind, Index As Integer))
        Dim targets As New List(Of (Kind As LinkedEventKind, Index As Integer))
        Dim keys As New List(Of Double)
        Dim p As Vector, v As Vector
        MotionOf(i).StateAt(_now, _slotOf(i), p, v)
        Dim size = Extent(i)
        For s = 1 To 4
            targets.Add((LinkedEventKind.Wall, s))
            Select Case CType(s, WallSide)
                Case WallSide.Left : keys.Add(p.X - size)
                Case WallSide.Right : keys.Add(_world.Width - p.X - size)
                Case WallSide.Bottom : keys.Add(p.Y - size)
                Case Else : keys.Add(_world.Height - p.Y - size)
            End Select
        Next
        For f = 0 To _fixed.Length - 1
            Dim low = _fixed(f).BoundsMin, high = _fixed(f).BoundsMax
            Dim outside As New Vector(Math.Max(0, Math.Max(low.X - p.X, p.X - high.X)), Math.Max(0, Math.Max(low.Y - p.Y, p.Y - high.Y)))
            targets.Add((LinkedEventKind.Fixed, f))
            keys.Add(outside.Length - size)
        Next
        For j = 0 To _bodies.Length - 1
            If j = i OrElse done.Contains(j) Then Continue For
            Dim q As Vector, w As Vector
            MotionOf(j).StateAt(_now, _slotOf(j), q, w)
            targets.Add((LinkedEventKind.Pair, j))
            keys.Add((q - p).Length - size - Extent(j))
        Next
        Return Enumerable.Range(0, targets.Count).OrderBy(Function(k) keys(k)).Select(Function(k) targets(k)).ToList()
    End Function

    ''' <summary>How far body i's outline reaches from its centre at most, m.</summary>
    Private Function Extent(i As Integer) As Double
        Dim x = Math.Max(Math.Abs(_low(i).X), Math.Abs(_high(i).X)), y = Math.Max(Math.Abs(_low(i).Y), Math.Abs(_high(i).Y))
        Return Math.Sqrt(x * x + y * y)
    End Function

    Private Function PredictPairOf(i As Integer, j As Integer, tEnd As Double) As Double
        Dim a = Math.Min(i, j), b = Math.Max(i, j)
        _found = False
        ' A contact held by a group's motion is kept by it exactly (it ends by that motion's own events), and
        ' two balls on a rod can never meet: neither is searched.
        Dim skip = IsHeld(ContactKey.PairValue(a, b)) OrElse _neverMeet.Contains(PairKey(a, b))
        _pairTime(a, b) = If(skip, Double.PositiveInfinity, PredictPair(a, b, tEnd))
        Return _pairTime(a, b)
    End Function

    Private Function PredictWallOf(i As Integer, s As Integer, tEnd As Double) As Double
        _found = False
        _wallTime(i, s) = If(_world.Walls AndAlso Not IsHeld(ContactKey.WallValue(i, CType(s, WallSide))), PredictObstacle(i, CType(s, WallSide), -1, tEnd), Double.PositiveInfinity)
        Return _wallTime(i, s)
    End Function

    Private Function PredictFixedOf(i As Integer, f As Integer, tEnd As Double) As Double
        _found = False
        _fixedTime(i, f) = If(IsHeld(ContactKey.FixedValue(i, f)), Double.PositiveInfinity, PredictObstacle(i, WallSide.None, f, tEnd))
        Return _fixedTime(i, f)
    End Function


    Private Function WallGap(i As Integer, side As WallSide) As LinkedGap
        Return LinkedGap.Wall(MotionOf(i), _slotOf(i), _low(i), _high(i), side, _world.Width, _world.Height)
    End Function

    Private Function FixedGap(i As Integer, f As Integer) As LinkedGap
        Return LinkedGap.Obstacle(MotionOf(i), _slotOf(i), _differences(i, f), _fixed(f).Position + _offset(i))
    End Function

    ''' <summary>The gap between bodies a &lt; b: centre distance less the radii for two balls, else the distance to their Minkowski difference.</summary>
    Private Function PairGap(a As Integer, b As Integer) As LinkedGap
        If BothBalls(a, b) Then
            Return LinkedGap.Pair(MotionOf(a), _slotOf(a), MotionOf(b), _slotOf(b), DirectCast(_bodies(a), Circle).Radius + DirectCast(_bodies(b), Circle).Radius)
        End If
        Return LinkedGap.Shapes(MotionOf(a), _slotOf(a), MotionOf(b), _slotOf(b), _pairDifferences(a, b), _offset(a) - _offset(b))
    End Function

    ''' <summary>
    ''' Bodies a &lt; b. The gap is a 1-Lipschitz function of their relative position, so it closes no faster
    ''' than V, the sum of their speed bounds (or, for two bodies each on its parabola, the bound on their
    ''' relative speed). Two balls: its second derivative is at most the relative acceleration plus V²/(r₁ + r₂)
    ''' for the turning of the line of centres. A box or polygon in the pair: the gap is also convex in the
    ''' relative position, which bounds it from below with the relative acceleration alone
    ''' (<see cref="OneSidedAdvancement"/>); from above, the turning of the normal is at most V²/R about a pair
    ''' shape rounded by R (a ball is involved) and unbounded about a sharp one (boxes and polygons).
    ''' </summary>
    Private Function PredictPair(a As Integer, b As Integer, tEnd As Double) As Double
        Dim pa As Vector, va As Vector, qa As Vector, pb As Vector, vb As Vector, qb As Vector
        If Not IsQuiet(ContactKey.Pair(a, b)) AndAlso MotionOf(a).Parabola(_slotOf(a), _now, pa, va, qa) AndAlso MotionOf(b).Parabola(_slotOf(b), _now, pb, vb, qb) Then
            ' Both on parabolas: their difference is one, and the contact time is solved for, not searched.
            Dim k = _pairDifferences(a, b)
            Return Exact(k, pa - pb - (_offset(a) - _offset(b)), va - vb, qa - qb, va.Length + vb.Length)
        End If
        Dim gap = PairGap(a, b)
        Dim t0 = _now
        Dim ma = MotionOf(a), mb = MotionOf(b)
        Dim until = SearchEnd(tEnd, ma, mb)
        Dim speed As Double, accel As Double
        Dim flightA = TryCast(ma, FlightMotion), flightB = TryCast(mb, FlightMotion)
        Dim together = TryCast(ma, ConstrainedMotion)
        If Not BothBalls(a, b) AndAlso flightA IsNot Nothing AndAlso flightB IsNot Nothing Then
            FlightMotion.RelativeBounds(flightA, flightB, t0, until, speed, accel)
        ElseIf together IsNot Nothing AndAlso ma Is mb Then
            together.RelativeBounds(_slotOf(a), _slotOf(b), t0, until, speed, accel)
        Else
            speed = ma.SpeedBound(_slotOf(a), t0, until) + mb.SpeedBound(_slotOf(b), t0, until)
            accel = ma.AccelerationBound(_slotOf(a), t0, until) + mb.AccelerationBound(_slotOf(b), t0, until)
            ' Seen from a frame falling with gravity, both may be far slower: their relative bounds, when tighter.
            Dim frameA As Vector, speedA As Double, accelA As Double, frameB As Vector, speedB As Double, accelB As Double
            If ma.FallingBounds(_slotOf(a), t0, until, _world.Gravity, frameA, speedA, accelA) AndAlso
               mb.FallingBounds(_slotOf(b), t0, until, _world.Gravity, frameB, speedB, accelB) Then
                speed = Math.Min(speed, ((frameA - frameB).Length + speedA + speedB) * (1 + 0.000000001))
                accel = Math.Min(accel, accelA + accelB)
            End If
        End If
        ' Whether they approach now is judged as a collision judges it, against the sum of their speeds: the relative
        ' bound may be far smaller, and a touch the collision leaves alone would be found "now" again and again.
        Dim p As Vector, v As Vector, speeds = 0.0
        ma.StateAt(t0, _slotOf(a), p, v)
        speeds += v.Length
        mb.StateAt(t0, _slotOf(b), p, v)
        speeds += v.Length
        If BothBalls(a, b) Then
            Dim curved = accel + speed * speed / (DirectCast(_bodies(a), Circle).Radius + DirectCast(_bodies(b), Circle).Radius)
            Return Recheck(FirstContact(gap, t0, until, speed, curved, curved, False, speeds), until, tEnd)
        End If
        Return Recheck(FirstContact(gap, t0, until, speed, accel, UpperCurvature(accel, speed, _pairDifferences(a, b).Radius), True, speeds), until, tEnd)
    End Function

    ''' <summary>
    ''' How far ahead (s, absolute) a search of bodies moved by <paramref name="a"/> and <paramref name="b"/> looks: to
    ''' the horizon, and never past either motion's <see cref="LinkedMotion.TransitionTime"/> (its own event, or the end
    ''' of what an integrated group has looked at so far), where the bodies are predicted again. An integrated group would
    ''' otherwise be carried on past its event, on constraints that no longer hold there, or integrated a whole
    ''' horizon ahead after every collision, for a stretch the next collision throws away.
    ''' </summary>
    Private Function SearchEnd(tEnd As Double, a As LinkedMotion, b As LinkedMotion) As Double
        Return Math.Max(_now, Math.Min(Math.Min(Math.Min(tEnd, _reach), _now + Horizon), Math.Min(a.TransitionTime, b.TransitionTime)))
    End Function

    ''' <summary>A bound on the gap's second derivative (m/s²) from above: the acceleration's, plus V²/R for the turning of the normal about a pair shape rounded by R; +∞ (none) for a sharp one.</summary>
    Private Shared Function UpperCurvature(accel As Double, speed As Double, radius As Double) As Double
        If radius > 0 Then Return accel + speed * speed / radius
        Return If(speed > 0, Double.PositiveInfinity, accel)
    End Function

    ''' <summary>
    ''' The first time (s, absolute) at which d(τ) = <paramref name="d"/> + <paramref name="w"/> τ + ½ <paramref name="q"/> τ²
    ''' enters pair shape <paramref name="k"/> while closing, from now; +∞ for never.
    ''' </summary>
    Private Function Exact(k As Outline, d As Vector, w As Vector, q As Vector, speeds As Double) As Double
        Dim feature As Integer
        Dim t = _now + OutlineContact.EarliestEntry(k, d, w, q, Slop, speeds, Double.PositiveInfinity, feature)
        _found = t < Double.PositiveInfinity
        Return t
    End Function

    ''' <summary>Body i's next contact with wall <paramref name="side"/>, or with fixed body f (f ≥ 0).</summary>
    Private Function PredictObstacle(i As Integer, side As WallSide, f As Integer, tEnd As Double) As Double
        Dim p As Vector, v As Vector, a As Vector
        Dim key = If(f >= 0, ContactKey.Fixed(i, f), ContactKey.Wall(i, side))
        If Not IsQuiet(key) AndAlso MotionOf(i).Parabola(_slotOf(i), _now, p, v, a) Then
            If f >= 0 Then Return Exact(_differences(i, f), p - (_fixed(f).Position + _offset(i)), v, a, v.Length)
            ' A wall: its gap is a quadratic in time.
            Dim gap As Double, rate As Double, accel As Double
            Select Case side
                Case WallSide.Left : gap = p.X + _low(i).X : rate = v.X : accel = a.X
                Case WallSide.Right : gap = _world.Width - _high(i).X - p.X : rate = -v.X : accel = -a.X
                Case WallSide.Bottom : gap = p.Y + _low(i).Y : rate = v.Y : accel = a.Y
                Case Else : gap = _world.Height - _high(i).Y - p.Y : rate = -v.Y : accel = -a.Y
            End Select
            ' Further into the wall than the slop and still going in (carried there by a group that did not hold the wall):
            ' struck now. A wall has no end to be past, as a face's plane has, and left to the quadratic it was never
            ' struck at all: a 1.3 mg triangle 3 nm into the floor fell through it.
            If gap < -Slop AndAlso (rate < 0 OrElse (rate = 0 AndAlso accel < 0)) Then
                _found = True
                Return _now
            End If
            Dim t = _now + TimeOfImpact.GapCloses(gap, rate, accel, Slop)
            _found = t < Double.PositiveInfinity
            Return t
        End If
        Return PredictGap(i, If(f >= 0, FixedGap(i, f), WallGap(i, side)), tEnd, KeptOpenNow(key))
    End Function

    ''' <summary>
    ''' Body i's next contact across <paramref name="gap"/>, searched up to <paramref name="tEnd"/>. A contact
    ''' <paramref name="quiet"/> (found within this instant approaching only as a tie in line lets its body graze it: see
    ''' Collide) is not found closing now again: the search goes on from its opening.
    ''' </summary>
    Private Function PredictGap(i As Integer, gap As LinkedGap, tEnd As Double, quiet As Boolean) As Double
        Dim m = MotionOf(i)
        Dim until = SearchEnd(tEnd, m, m)
        Dim speed = m.SpeedBound(_slotOf(i), _now, until)
        Dim accel = m.AccelerationBound(_slotOf(i), _now, until)
        ' A wall is flat: its gap's second derivative is the acceleration across it.
        If gap.Difference Is Nothing Then Return Recheck(FirstContact(gap, _now, until, speed, accel, accel, False, quiet:=quiet), until, tEnd)
        Dim curved = UpperCurvature(accel, speed, gap.Difference.Radius)
        If _bodies(i).Kind = ShapeKind.Circle Then Return Recheck(FirstContact(gap, _now, until, speed, curved, curved, False, quiet:=quiet), until, tEnd)
        Return Recheck(FirstContact(gap, _now, until, speed, accel, curved, True, quiet:=quiet), until, tEnd)
    End Function

    ''' <summary>A search that found nothing before the horizon is taken up again there (an event that is not a contact).</summary>
    Private Function Recheck(found As Double, until As Double, tEnd As Double) As Double
        If Double.IsPositiveInfinity(found) AndAlso until < tEnd Then Return until
        _found = found < Double.PositiveInfinity
        Return found
    End Function

    ''' <summary>
    ''' The first contact of a gap in [t0, tEnd] (s): now when touching and closing (unless <paramref name="quiet"/>). When touching and not
    ''' closing (just after a bounce), first the time the gap has opened to twice the slop, and from there
    ''' when it closes; if it cannot be shown to open that far, when the overlap grows by the slop. Otherwise
    ''' when the gap closes. <paramref name="below"/> (m/s²) bounds the gap's second derivative from below
    ''' (its fall): the relative acceleration for a box or polygon, whose gap is convex, else the same as
    ''' <paramref name="above"/>, the two-sided bound (+∞ for two sharp shapes, where none exists). The closing
    ''' is searched with the bound from below alone (<see cref="OneSidedAdvancement"/>) when
    ''' <paramref name="oneSided"/>, else with <see cref="ConservativeAdvancement"/>. +∞ for none; a search that
    ''' ran out of its budget returns where it stopped, to be taken up again from there. <paramref name="speeds"/> (m/s),
    ''' for a pair, the sum of the two bodies' speeds now, against which Collide judges an approach too.
    ''' An opening searched for step by step counts only before the overlap could have grown by the slop:
    ''' a body pressed into another (a ball pulled onto a peg it sits on) would otherwise be "opened" on the
    ''' far side, after passing right through it, and the contact between never looked for.
    ''' </summary>
    Private Function FirstContact(gap As LinkedGap, t0 As Double, tEnd As Double, speed As Double, below As Double, above As Double, oneSided As Boolean,
                                  Optional speeds As Double = 0, Optional quiet As Boolean = False) As Double
        Dim n As Vector, rate As Double
        Dim d = gap.GapAndNormal(t0, n, rate)
        _gapEvaluations += 1
        If d <= Slop Then
            If rate < -ClosingSpeed(Math.Max(speed, speeds)) AndAlso Not quiet Then Return t0
            ' Leaving at rate ḋ, the gap is at least d + ḋ s − ½ A s² (A the bound from below): where that
            ' parabola first reaches twice the slop, the gap has opened that far, and it did not close before.
            Dim opens = OpeningTime(d, rate, below, 2 * Slop)
            If opens < Double.PositiveInfinity Then
                If t0 + opens > tEnd Then Return Double.PositiveInfinity
                t0 += opens
            Else
                ' Too slow to show it opening from the bound below (a body sliding along a face, or resting):
                ' look for the opening step by step, with the bound from above, until the overlap could have
                ' grown by the slop; two sharp shapes have no such bound, so briefly, with the speed alone.
                ' (A hair short of the slop, as the search lands within rounding of its target either side, and no contact
                ' may end deeper than the slop.)
                Dim sinks = Closing(gap, t0, tEnd, Math.Min(d, 0) - 0.999 * Slop, speed, below, above, oneSided)
                Dim limit = If(sinks.Found, sinks.Time, sinks.ClearUntil)
                Dim sharp = Double.IsPositiveInfinity(above)
                Dim opened = ConservativeAdvancement.FirstContact(New Opening(gap, 2 * Slop), t0, limit, 0, speed, above, If(sharp, SharpOpeningBudget, 100000))
                _gapEvaluations += opened.Evaluations
                If Not opened.Found Then Return If(opened.ClearUntil < limit AndAlso Not sharp, opened.ClearUntil, Finding(sinks, tEnd))
                t0 = opened.Time
            End If
        End If
        Return Finding(Closing(gap, t0, tEnd, 0, speed, below, above, oneSided), tEnd)
    End Function

    ''' <summary>The search for the gap closing to −<paramref name="tolerance"/> (m), one- or two-sided (see <see cref="FirstContact"/>).</summary>
    Private Function Closing(gap As LinkedGap, t0 As Double, tEnd As Double, tolerance As Double, speed As Double,
                             below As Double, above As Double, oneSided As Boolean) As AdvancementResult
        Dim result = If(oneSided,
                        OneSidedAdvancement.FirstContact(gap, t0, tEnd, tolerance, speed, below),
                        ConservativeAdvancement.FirstContact(gap, t0, tEnd, tolerance, speed, above))
        _gapEvaluations += result.Evaluations
        Return result
    End Function

    ''' <summary>A search's answer as a time: when it found the contact, where it stopped short of <paramref name="tEnd"/> (to be taken up again), or +∞.</summary>
    Private Shared Function Finding(result As AdvancementResult, tEnd As Double) As Double
        If result.Found Then Return result.Time
        If result.ClearUntil < tEnd Then Return result.ClearUntil
        Return Double.PositiveInfinity
    End Function

    ''' <summary>
    ''' The first s &gt; 0 (s) at which d + ḋ s − ½ A s² reaches <paramref name="target"/> (m), for a gap d (m)
    ''' opening at ḋ (m/s) with its second derivative at least −A (m/s²); +∞ when that parabola never does.
    ''' </summary>
    Private Shared Function OpeningTime(d As Double, rate As Double, accel As Double, target As Double) As Double
        If rate <= 0 OrElse Double.IsInfinity(accel) OrElse Double.IsNaN(accel) Then Return Double.PositiveInfinity
        Dim rise = target - d
        If rise <= 0 Then Return 0
        If accel <= 0 Then Return rise / rate
        Dim disc = rate * rate - 2 * accel * rise
        If disc < 0 Then Return Double.PositiveInfinity
        ' The smaller root of ½ A s² − ḋ s + rise = 0, written without cancellation.
        Return 2 * rise / (rate + Math.Sqrt(disc))
    End Function

    ''' <summary>How far a gap is from opening to <c>target</c> (m): target − gap, zero once it has opened that far.</summary>
    Private NotInheritable Class Opening
        Implements IDistanceFunction

        Private ReadOnly _gap As LinkedGap
        Private ReadOnly _target As Double

        Public Sub New(gap As LinkedGap, target As Double)
            _gap = gap
            _target = target
        End Sub

        Public Function Distance(time As Double) As Double Implements IDistanceFunction.Distance
            Return _target - _gap.Distance(time)
        End Function

        Public Function Rate(time As Double) As Double Implements IDistanceFunction.Rate
            Return -_gap.Rate(time)
        End Function
    End Class

    ''' <summary>Predicts again from now the one contact of body i with body j, wall <paramref name="side"/> or fixed body f.</summary>
    Private Sub PredictAgain(i As Integer, j As Integer, side As WallSide, f As Integer, tEnd As Double)
        If j >= 0 Then
            _pairTime(Math.Min(i, j), Math.Max(i, j)) = PredictPair(Math.Min(i, j), Math.Max(i, j), tEnd)
        Else
            If f >= 0 Then _fixedTime(i, f) = PredictObstacle(i, WallSide.None, f, tEnd) Else _wallTime(i, side) = PredictObstacle(i, side, -1, tEnd)
        End If
    End Sub

    ''' <summary>Predicts again every contact of the given bodies, with everything.</summary>
    Private Sub Repredict(bodies As List(Of Integer), tEnd As Double)
        ' A pair of two of them is predicted once, with the first.
        Dim done As New HashSet(Of Integer)
        ' The soonest contact found so far for a body of each group: any of them ends the group's motion, and all
        ' its bodies are predicted again then.
        Dim soonest As New Dictionary(Of Integer, Double)
        For Each i In bodies
            Dim g = _groupOf(i)
            Dim t As Double
            If Not soonest.TryGetValue(g, t) Then t = Double.PositiveInfinity
            PredictBody(i, tEnd, done, t)
            soonest(g) = t
            done.Add(i)
        Next
    End Sub
End Class
