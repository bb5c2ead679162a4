Option Strict On

''' <summary>
''' A group of bodies joined by rods or strings that no closed form fits (a double pendulum, a rope of
''' balls joined by rods, a chain hanging from a point; springs may be among its links): integrated by the
''' Dormand–Prince 5(4) pair with error control (docs/links.md, "Chains"). Rods and taut strings are exact
''' distance constraints whose tensions come from one small linear solve per evaluation
''' (<see cref="ChainConstraints"/>); after each step the state is put back on the lengths if rounding has
''' moved it off. Between steps the motion is the quintic that matches position, velocity and acceleration
''' at both ends, and that quintic is the motion: contacts are found on it by conservative advancement with
''' the speed and acceleration bounds read from its coefficients, as for springs (<see cref="IntegratedMotion"/>).
''' A taut string goes slack where its tension would turn negative (a root of the tension along the quintic,
''' by Brent's method), and a slack one snaps taut where its ends reach its length (conservative advancement
''' on L² − d²); both end this motion, and the next starts from the state there.
''' Steps are taken lazily, as far as anything asks.
''' </summary>
Friend NotInheritable Class ChainMotion
    Inherits LinkedMotion

    Private Const RelativeTolerance As Double = 0.00000000001
    Private Const AbsoluteTolerance As Double = 0.000000000001
    ' Steps kept from one start at most: far more than any advance needs, far less than the memory holds.
    Private Const MaxSteps As Integer = 2000000
    ' A chain with strings is integrated this far ahead (s) to look for a string's change; where none is
    ' found, the motion hands over to a new one there, which looks further.
    Private Const Lookahead As Double = 0.1
    ' The state is projected back onto the lengths when it has drifted off by more than this fraction.
    Private Const DriftFraction As Double = 0.000000000001
    ' A string at full length snaps taut only once it is over-long by this fraction of its length, so that
    ' one that has just snapped (or just gone slack) is not caught again at once by rounding.
    Private Const OverLength As Double = 0.000000000001
    ' A string snapping taut so gently that its ends would come back less than this fraction of its length
    ' apart (v² < 2 g × fraction × L) stays taut: a bob riding the circle with the string just pulling would
    ' otherwise bounce off its full length for ever (with e = 1 the bounces never shrink), as a ball resting on
    ' the floor would (LinkedEventSolver.Rest.vb).
    Private Const SettleFraction As Double = 0.000000001

    Private ReadOnly _gravity As Double
    ' Drag and buoyancy on the bodies (docs/forces.md), or Nothing.
    Private ReadOnly _forces As ForceField
    Private ReadOnly _n As Integer
    Private ReadOnly _inverseMass As Double()
    Private ReadOnly _springs As Link()
    ' The rods and taut strings, and their ties.
    Private ReadOnly _held As Link()
    Private ReadOnly _ties As ChainTie()
    Private ReadOnly _constraints As ChainConstraints
    ' The slack strings, their ties, and how little spare length counts as reaching full length, m.
    Private ReadOnly _slack As Link()
    Private ReadOnly _slackTies As ChainTie()
    Private ReadOnly _snapAt As Double()
    Private ReadOnly _hasStrings As Boolean
    ' Per step start: the state (per body x, y, vx, vy), its derivative, and the ties' tensions.
    Private ReadOnly _times As New List(Of Double)
    Private ReadOnly _states As New List(Of Double())
    Private ReadOnly _derivatives As New List(Of Double())
    Private ReadOnly _tensions As New List(Of Double())
    ' Per step: the quintics' coefficients, once asked for.
    Private ReadOnly _quintics As New List(Of Double())
    ' Per step: each body's speed bound (m/s) and acceleration bound (m/s²), once asked for.
    Private ReadOnly _bounds As New List(Of Double())
    Private _step As Double
    ' The tensions (N) at the last evaluation.
    Private _lastTensions As Double()
    ' The first string event found on the steps scanned so far.
    Private _scanned As Integer
    Private _eventTime As Double = Double.PositiveInfinity
    Private _eventLink As Link
    Private _eventSnaps As Boolean

    ''' <summary>
    ''' The chain of <paramref name="bodies"/> and <paramref name="links"/> from their states now. A string
    ''' counts as taut when it is at full length, its ends not moving apart or together, and its tension,
    ''' worked out with the others, is not negative; <paramref name="slackened"/> (a string whose tension has
    ''' just fallen to zero) is slack whatever the rounding says.
    ''' </summary>
    Friend Sub New(bodies As Shape(), links As List(Of Link), startTime As Double, gravity As Double, slackened As Link, Optional forces As ForceField = Nothing)
        MyBase.New(bodies, startTime)
        _forces = forces
        _gravity = gravity
        _n = bodies.Length
        _inverseMass = bodies.Select(Function(b) b.InverseMass).ToArray()
        _springs = links.Where(Function(l) l.Kind = LinkKind.Spring).ToArray()
        _hasStrings = links.Any(Function(l) l.Kind = LinkKind.String)
        Dim y(4 * _n - 1) As Double
        For k = 0 To _n - 1
            y(4 * k) = bodies(k).CentreOfMass.X
            y(4 * k + 1) = bodies(k).CentreOfMass.Y
            y(4 * k + 2) = bodies(k).Velocity.X
            y(4 * k + 3) = bodies(k).Velocity.Y
        Next
        Dim held As New List(Of Link), slack As New List(Of Link)
        Dim snapNow As Link = Nothing
        For Each l In links
            If l.Kind = LinkKind.Rod Then
                held.Add(l)
            ElseIf l.Kind = LinkKind.String Then
                Dim state = StringState(l, slackened)
                If state > 0 Then snapNow = l
                If state = 0 Then held.Add(l) Else slack.Add(l)
            End If
        Next
        ' A string whose tension would be negative with the others holding is slack: let the most negative go, and look again.
        Do
            Dim ties = held.Select(Function(l) TieOf(l)).ToArray()
            Dim d = FreeDerivative(y)
            Dim lambda = New ChainConstraints(ties, _inverseMass).Tensions(y, d)
            Dim worst = -1, least = 0.0
            For i = 0 To held.Count - 1
                If held(i).Kind <> LinkKind.String Then Continue For
                Dim w = _inverseMass(ties(i).A) + If(ties(i).B >= 0, _inverseMass(ties(i).B), 0)
                ' λw is the pull's share of the ends' relative acceleration, m/s²; rounding of g's size is not a push.
                Dim pull = lambda(i) * w
                If pull < least AndAlso pull < -0.000000001 * (gravity + 1) Then least = pull : worst = i
            Next
            If worst < 0 Then Exit Do
            slack.Add(held(worst))
            held.RemoveAt(worst)
        Loop
        _held = held.ToArray()
        _ties = _held.Select(Function(l) TieOf(l)).ToArray()
        _constraints = New ChainConstraints(_ties, _inverseMass)
        _slack = slack.ToArray()
        _slackTies = _slack.Select(Function(l) TieOf(l)).ToArray()
        _snapAt = New Double(_slack.Length - 1) {}
        For i = 0 To _slack.Length - 1
            Dim spare = SpareLength(y, _slackTies(i))
            _snapAt(i) = If(spare > OverLength * _slack(i).Length, 0, Math.Min(spare, 0) - OverLength * _slack(i).Length)
        Next
        Dim tensions As Double() = Nothing
        _times.Add(startTime)
        _states.Add(y)
        _derivatives.Add(Derivative(y, tensions))
        _tensions.Add(tensions)
        If snapNow IsNot Nothing Then
            _eventTime = startTime
            _eventLink = snapNow
            _eventSnaps = True
        End If
        ' A first step of a hundredth of the shortest link's pendulum period; the error control corrects it at once.
        Dim shortest = links.Where(Function(l) l.Kind <> LinkKind.Spring).Min(Function(l) l.Length)
        _step = 0.06 * Math.Sqrt(shortest / Math.Max(gravity, 1))
    End Sub

    ''' <summary>
    ''' Whether every rod and every string at full length could hold at once where its bodies are now: false when
    ''' some are redundant (two rods between the same two balls, a ball held by rods to two points in line
    ''' with it), which the tension solve cannot take.
    ''' </summary>
    Friend Shared Function CanHoldAll(bodies As Shape(), links As List(Of Link)) As Boolean
        Dim inverseMass = bodies.Select(Function(b) b.InverseMass).ToArray()
        Dim ties = links.Where(Function(l) l.Kind = LinkKind.Rod OrElse (l.Kind = LinkKind.String AndAlso l.Distance >= l.Length * (1 - LinkedMotions.FullFraction))).
                         Select(Function(l) New ChainTie(Array.IndexOf(bodies, l.A), If(l.IsAnchored, -1, Array.IndexOf(bodies, l.B)), If(l.IsAnchored, l.EndB, Vector.Zero), l.Length)).ToArray()
        Dim y(4 * bodies.Length - 1) As Double
        For k = 0 To bodies.Length - 1
            y(4 * k) = bodies(k).CentreOfMass.X
            y(4 * k + 1) = bodies(k).CentreOfMass.Y
        Next
        Dim accelerations(y.Length - 1) As Double
        Try
            Call New ChainConstraints(ties, inverseMass).Tensions(y, accelerations)
            Return True
        Catch ex As InvalidOperationException
            Return False
        End Try
    End Function

    ''' <summary>−1 slack, 0 taut (at full length, not moving along itself), +1 over-long and stretching (it must snap now).</summary>
    Private Function StringState(l As Link, slackened As Link) As Integer
        If l Is slackened Then Return -1
        Dim d = l.Distance
        If d < l.Length * (1 - LinkedMotions.FullFraction) Then Return -1
        Dim rate = l.StretchRate
        Dim vb = If(l.IsAnchored, Vector.Zero, l.B.Velocity)
        Dim scale = l.A.Velocity.Length + vb.Length + Math.Sqrt(Math.Max(_gravity, 1) * l.Length)
        If Math.Abs(rate) <= LinkedMotions.FullFraction * scale Then Return 0
        Return If(rate > 0 AndAlso d >= l.Length, 1, -1)
    End Function

    Private Function TieOf(l As Link) As ChainTie
        Dim a = Array.IndexOf(Bodies, l.A)
        Dim b = If(l.IsAnchored, -1, Array.IndexOf(Bodies, l.B))
        Return New ChainTie(a, b, If(l.IsAnchored, l.EndB, Vector.Zero), l.Length)
    End Function

    ''' <summary>dy/dt without the ties: velocities, and gravity plus every spring's pull ÷ mass.</summary>
    Private Function FreeDerivative(y As Double()) As Double()
        Dim d(4 * _n - 1) As Double
        For k = 0 To _n - 1
            d(4 * k) = y(4 * k + 2)
            d(4 * k + 1) = y(4 * k + 3)
            d(4 * k + 3) = -_gravity
        Next
        For Each l In _springs
            Dim a = Array.IndexOf(Bodies, l.A)
            Dim b = If(l.IsAnchored, -1, Array.IndexOf(Bodies, l.B))
            Dim pa As New Vector(y(4 * a), y(4 * a + 1)), va As New Vector(y(4 * a + 2), y(4 * a + 3))
            Dim pb = If(b >= 0, New Vector(y(4 * b), y(4 * b + 1)), l.EndB)
            Dim vb = If(b >= 0, New Vector(y(4 * b + 2), y(4 * b + 3)), Vector.Zero)
            Dim r = pb - pa
            Dim dist = r.Length
            If dist = 0 Then Continue For
            ' (k(d − L) + c ḋ)/d along r pulls A towards B.
            Dim force = r * ((l.Stiffness * (dist - l.Length) + l.Damping * Vector.Dot(vb - va, r) / dist) / dist)
            d(4 * a + 2) += force.X * _inverseMass(a)
            d(4 * a + 3) += force.Y * _inverseMass(a)
            If b >= 0 Then
                d(4 * b + 2) -= force.X * _inverseMass(b)
                d(4 * b + 3) -= force.Y * _inverseMass(b)
            End If
        Next
        If _forces IsNot Nothing Then BodyForceTerm.Add(_forces, Bodies, y, d)
        Return d
    End Function

    ''' <summary>dy/dt with the ties holding, and their tensions (N).</summary>
    Private Function Derivative(y As Double(), ByRef tensions As Double()) As Double()
        Dim d = FreeDerivative(y)
        tensions = _constraints.Tensions(y, d)
        _lastTensions = tensions
        Return d
    End Function

    Private Function Derivative(y As Double()) As Double()
        Dim unused As Double() = Nothing
        Return Derivative(y, unused)
    End Function

    ''' <summary>Takes steps until the last one ends at or after <paramref name="time"/>, looking at each for a string's change.</summary>
    Private Sub ExtendTo(time As Double)
        If Double.IsInfinity(time) Then Throw New ArgumentOutOfRangeException(NameOf(time), "a chain's motion is integrated only to a finite time")
        Do While _times(_times.Count - 1) < time
            If _times.Count > MaxSteps Then Throw New InvalidOperationException($"the chain integrator took more than {MaxSteps} steps from t = {StartTime} s to t = {_times(_times.Count - 1)} s without reaching t = {time} s")
            Dim t = _times(_times.Count - 1)
            Dim y = _states(_states.Count - 1)
            Dim k1 = _derivatives(_derivatives.Count - 1)
            Do
                Dim h = _step
                Dim result As Double() = Nothing, slope As Double() = Nothing
                Dim worst = DormandPrince.TryStep(AddressOf Derivative, y, k1, h, RelativeTolerance, AbsoluteTolerance, result, slope)
                _step = h * DormandPrince.StepFactor(worst)
                If worst <= 1 Then
                    Dim lengthError As Double, rateError As Double
                    _constraints.Drift(result, lengthError, rateError)
                    ' The step's last evaluation was at its result: its tensions are those there, unless the result is moved back onto the lengths.
                    Dim tensions = _lastTensions
                    If lengthError > DriftFraction OrElse rateError > DriftFraction * SpeedScale(result) Then
                        _constraints.Project(result)
                        slope = Derivative(result, tensions)
                    End If
                    _times.Add(t + h)
                    _states.Add(result)
                    _derivatives.Add(slope)
                    _tensions.Add(tensions)
                    Exit Do
                End If
                If Not (_step > 0.000000000000001 * Math.Max(1, Math.Abs(t))) Then Throw New InvalidOperationException($"the chain integrator could not keep its error down at t = {t} s")
            Loop
            If _hasStrings AndAlso Double.IsPositiveInfinity(_eventTime) Then ScanStep(_times.Count - 2)
        Loop
    End Sub

    ''' <summary>A speed of the chain's size, m/s: the fastest body's, or √(gL) for a chain at rest.</summary>
    Private Function SpeedScale(y As Double()) As Double
        Dim s = Math.Sqrt(Math.Max(_gravity, 1))
        For k = 0 To _n - 1
            s = Math.Max(s, Math.Abs(y(4 * k + 2)) + Math.Abs(y(4 * k + 3)))
        Next
        Return s
    End Function

    ''' <summary>Looks on step j for a taut string whose tension turns negative and a slack one that reaches its length; keeps the first.</summary>
    Private Sub ScanStep(j As Integer)
        Dim t0 = _times(j), t1 = _times(j + 1)
        For i = 0 To _held.Length - 1
            If _held(i).Kind <> LinkKind.String Then Continue For
            Dim before = _tensions(j)(i), after = _tensions(j + 1)(i)
            If after >= 0 Then Continue For
            Dim index = i
            Dim root = If(before <= 0, t0, ScalarRoot.Brent(Function(t) TensionAt(t, index), t0, t1, before, after))
            Keep(root, _held(i), False)
        Next
        For i = 0 To _slack.Length - 1
            Dim tie = _slackTies(i)
            Dim target = _snapAt(i)
            Dim f0 = SpareLength(_states(j), tie), f1 = SpareLength(_states(j + 1), tie)
            Dim h = t1 - t0
            Dim speed = StepBound(j, tie.A, 1) + If(tie.B >= 0, StepBound(j, tie.B, 1), 0)
            ' The spare length falls no faster than the ends' speeds together: from both ends of the step it cannot reach the target in between.
            If f0 > target AndAlso f1 > target AndAlso (f0 + f1 - speed * h) / 2 > target Then Continue For
            ' On L² − d²: |d| ≤ d(t0) + speed × h over the step bounds |(d²)'| = 2|r·w| and |(d²)''| = 2| |w|² + r·a |.
            Dim accel = StepBound(j, tie.A, 2) + If(tie.B >= 0, StepBound(j, tie.B, 2), 0)
            Dim reach = tie.Length - f0 + speed * h
            Dim reached = tie.Length - target
            Dim found = ConservativeAdvancement.FirstContact(New SquaredSpareGap(Me, tie), t0, t1, tie.Length * tie.Length - reached * reached,
                                                             2 * reach * speed, 2 * (speed * speed + reach * accel))
            If found.Found Then
                Keep(found.Time, _slack(i), True)
            ElseIf found.ClearUntil < t1 Then
                Throw New InvalidOperationException($"the chain integrator could not tell whether a string snaps taut between t = {found.ClearUntil} s and {t1} s")
            End If
        Next
    End Sub

    Private Sub Keep(time As Double, link As Link, snaps As Boolean)
        If time >= _eventTime Then Return
        _eventTime = time
        _eventLink = link
        _eventSnaps = snaps
    End Sub

    ''' <summary>L − d for a tie, m: how much length a slack string has to spare.</summary>
    Private Shared Function SpareLength(y As Double(), t As ChainTie) As Double
        Dim pa As New Vector(y(4 * t.A), y(4 * t.A + 1))
        Dim pb = If(t.B >= 0, New Vector(y(4 * t.B), y(4 * t.B + 1)), t.Anchor)
        Return t.Length - (pb - pa).Length
    End Function

    ''' <summary>The state at <paramref name="time"/> on the quintics, as one array.</summary>
    Private Function StateArray(time As Double) As Double()
        Dim y(4 * _n - 1) As Double
        For k = 0 To _n - 1
            Dim p As Vector, v As Vector
            StateAt(time, k, p, v)
            y(4 * k) = p.X
            y(4 * k + 1) = p.Y
            y(4 * k + 2) = v.X
            y(4 * k + 3) = v.Y
        Next
        Return y
    End Function

    Private Function TensionAt(time As Double, i As Integer) As Double
        Dim tensions As Double() = Nothing
        Derivative(StateArray(time), tensions)
        Return tensions(i)
    End Function

    ''' <summary>The step holding <paramref name="time"/> (the last whose start is at or before it).</summary>
    Private Function StepAt(time As Double) As Integer
        ExtendTo(time)
        Dim lo = 0, hi = _times.Count - 2
        Do While lo < hi
            Dim mid = (lo + hi + 1) \ 2
            If _times(mid) <= time Then lo = mid Else hi = mid - 1
        Loop
        Return Math.Max(lo, 0)
    End Function

    ''' <summary>
    ''' Step j's quintics, worked out once: for body k and coordinate a (0: x, 1: y), the coefficients c₀…c₅ in
    ''' s = (t − tⱼ)/h are at 6(2k + a) onwards.
    ''' </summary>
    Private Function Quintics(j As Integer) As Double()
        Do While _quintics.Count <= j
            Dim i = _quintics.Count
            Dim h = _times(i + 1) - _times(i)
            Dim c(12 * _n - 1) As Double
            For k = 0 To _n - 1
                For axis = 0 To 1
                    Dim p0 = _states(i)(4 * k + axis), v0 = _states(i)(4 * k + 2 + axis) * h, a0 = _derivatives(i)(4 * k + 2 + axis) * h * h
                    Dim p1 = _states(i + 1)(4 * k + axis), v1 = _states(i + 1)(4 * k + 2 + axis) * h, a1 = _derivatives(i + 1)(4 * k + 2 + axis) * h * h
                    Dim o = 6 * (2 * k + axis)
                    c(o) = p0
                    c(o + 1) = v0
                    c(o + 2) = 0.5 * a0
                    c(o + 3) = -10 * p0 - 6 * v0 - 1.5 * a0 + 10 * p1 - 4 * v1 + 0.5 * a1
                    c(o + 4) = 15 * p0 + 8 * v0 + 1.5 * a0 - 15 * p1 + 7 * v1 - a1
                    c(o + 5) = -6 * p0 - 3 * v0 - 0.5 * a0 + 6 * p1 - 3 * v1 + 0.5 * a1
                Next
            Next
            _quintics.Add(c)
        Loop
        Return _quintics(j)
    End Function

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        Dim j = If(time = StartTime, 0, StepAt(time))
        Dim y0 = _states(j)
        If time = _times(j) Then
            position = New Vector(y0(4 * k), y0(4 * k + 1))
            velocity = New Vector(y0(4 * k + 2), y0(4 * k + 3))
            Return
        End If
        Dim h = _times(j + 1) - _times(j)
        Dim s = (time - _times(j)) / h
        Dim c = Quintics(j)
        Dim ox = 12 * k, oy = 12 * k + 6
        position = New Vector(Poly(c, ox, s), Poly(c, oy, s))
        velocity = New Vector(Slope(c, ox, s) / h, Slope(c, oy, s) / h)
    End Sub

    Private Shared Function Poly(c As Double(), o As Integer, s As Double) As Double
        Return c(o) + s * (c(o + 1) + s * (c(o + 2) + s * (c(o + 3) + s * (c(o + 4) + s * c(o + 5)))))
    End Function

    Private Shared Function Slope(c As Double(), o As Integer, s As Double) As Double
        Return c(o + 1) + s * (2 * c(o + 2) + s * (3 * c(o + 3) + s * (4 * c(o + 4) + s * 5 * c(o + 5))))
    End Function

    ''' <summary>|p'| (order 1) or |p''| (order 2) of body k on step j, bounded by Σ j|cⱼ| and Σ j(j − 1)|cⱼ| (s in [0, 1]).</summary>
    Private Function StepBound(j As Integer, k As Integer, order As Integer) As Double
        Dim h = _times(j + 1) - _times(j)
        Dim bx = 0.0, by = 0.0
        Dim c = Quintics(j)
        Dim ox = 12 * k, oy = 12 * k + 6
        For p = order To 5
            Dim w = If(order = 1, p, p * (p - 1))
            bx += w * Math.Abs(c(ox + p))
            by += w * Math.Abs(c(oy + p))
        Next
        Return Math.Sqrt(bx * bx + by * by) / Math.Pow(h, order) * (1 + 0.000000001)
    End Function

    ''' <summary>The largest of body k's per-step bounds over the steps that meet [t0, t1]; each step's bounds are worked out once.</summary>
    Private Function Bound(k As Integer, t0 As Double, t1 As Double, order As Integer) As Double
        Dim first = StepAt(t0), last = StepAt(t1)
        Dim worst = 0.0
        For j = first To last
            Do While _bounds.Count <= j
                Dim b(2 * _n - 1) As Double
                For body = 0 To _n - 1
                    b(2 * body) = StepBound(_bounds.Count, body, 1)
                    b(2 * body + 1) = StepBound(_bounds.Count, body, 2)
                Next
                _bounds.Add(b)
            Loop
            worst = Math.Max(worst, _bounds(j)(2 * k + order - 1))
        Next
        Return worst
    End Function

    Friend Overrides Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return Bound(k, t0, t1, 1)
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return Bound(k, t0, t1, 2)
    End Function

    ''' <summary>
    ''' The first string change on the steps looked at; a chain with strings looks <see cref="Lookahead"/>
    ''' ahead and, finding none, hands over to a new motion at the end of what it looked at. +∞ with no strings.
    ''' </summary>
    Friend Overrides ReadOnly Property TransitionTime As Double
        Get
            If Not _hasStrings Then Return Double.PositiveInfinity
            If Double.IsPositiveInfinity(_eventTime) Then ExtendTo(StartTime + Lookahead)
            If Not Double.IsPositiveInfinity(_eventTime) Then Return _eventTime
            ' The end of the first step at or after the look-ahead: a node, so the next motion starts from an integrated state.
            Return _times(StepAt(StartTime + Lookahead) + 1)
        End Get
    End Property

    ''' <summary>The string that has just gone slack (for the next motion), or Nothing.</summary>
    Friend Property Slackened As Link

    ''' <summary>
    ''' A string goes slack (its tension fell to zero), or snaps taut: like a collision along the string,
    ''' its ends' speed apart becomes e times as much together, solved with the rods and taut strings of
    ''' the chain so that they keep their lengths through the jerk (<see cref="LinkedImpulse"/>). Returns
    ''' true when a string has gone slack.
    ''' </summary>
    Friend Overrides Function Transition(world As World) As Boolean
        If _eventLink Is Nothing Then Return False
        If Not _eventSnaps Then
            Slackened = _eventLink
            Return True
        End If
        Dim l = _eventLink
        Dim apart = l.StretchRate
        If apart <= 0 Then Return False
        Dim restitution = world.Restitution
        If restitution * apart < Math.Sqrt(2 * Math.Max(world.Gravity, 0.000001) * SettleFraction * l.Length) Then restitution = 0
        Dim impulse As New LinkedImpulse()
        ' A contact whose normal points from B to A: "approaching" along it is the ends moving apart, and its push pulls them together.
        impulse.AddContact(l.A, If(l.IsAnchored, Nothing, l.B), -(l.EndB - l.EndA).Normalized(Vector.Zero), restitution)
        For Each other In _held
            impulse.AddLink(other)
        Next
        impulse.Resolve()
        Return False
    End Function

    Friend Overrides ReadOnly Property HeldLinks As Link()
        Get
            Return _held
        End Get
    End Property

    Friend Overrides Sub UpdateTensions(time As Double)
        If _held.Length > 0 Then
            Dim tensions As Double() = Nothing
            Derivative(StateArray(time), tensions)
            For i = 0 To _held.Length - 1
                _held(i).SetTension(tensions(i))
            Next
        End If
        For Each l In _slack
            l.SetTension(0)
        Next
    End Sub

    ''' <summary>
    ''' A slack string's L² − d² along the quintics (m²), for conservative advancement: unlike the spare length
    ''' L − d, its second derivative, −2(|w|² + r·(a_B − a_A)), is bounded however close the ends come.
    ''' </summary>
    Private NotInheritable Class SquaredSpareGap
        Implements IDistanceFunction

        Private ReadOnly _motion As ChainMotion
        Private ReadOnly _tie As ChainTie

        Public Sub New(motion As ChainMotion, tie As ChainTie)
            _motion = motion
            _tie = tie
        End Sub

        Private Sub Ends(time As Double, ByRef r As Vector, ByRef w As Vector)
            Dim pa As Vector, va As Vector, pb = _tie.Anchor, vb = Vector.Zero
            _motion.StateAt(time, _tie.A, pa, va)
            If _tie.B >= 0 Then _motion.StateAt(time, _tie.B, pb, vb)
            r = pb - pa
            w = vb - va
        End Sub

        Public Function Distance(time As Double) As Double Implements IDistanceFunction.Distance
            Dim r As Vector, w As Vector
            Ends(time, r, w)
            Return _tie.Length * _tie.Length - r.LengthSquared
        End Function

        Public Function Rate(time As Double) As Double Implements IDistanceFunction.Rate
            Dim r As Vector, w As Vector
            Ends(time, r, w)
            Return -2 * Vector.Dot(r, w)
        End Function
    End Class
End Class
