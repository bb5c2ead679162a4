Option Strict On

''' <summary>
''' A group of bodies held together by constraints that no closed form fits (a double pendulum, a rope of
''' balls joined by rods, a chain hanging from a point, a ball sliding on a ball or round a peg, a bob on a
''' string pressed against a wall, a box on a table pushed by a spring; springs may be among its links):
''' integrated by the Dormand–Prince 5(4) pair with error control (docs/links.md, "Chains"; docs/contact.md).
''' Rods, taut strings and lasting contacts are exact constraints ψ = 0 whose forces come from one small linear
''' solve per evaluation (<see cref="ConstraintSet"/>); after each step the state is put back on them if
''' rounding has moved it off. Between steps the motion is the quintic that matches position, velocity and
''' acceleration at both ends, and that quintic is the motion: contacts are found on it by conservative
''' advancement with the speed and acceleration bounds read from its coefficients, as for springs
''' (<see cref="IntegratedMotion"/>). A taut string goes slack, and a contact lifts off, where its force would
''' turn negative (a root of the force along the quintic, by Brent's method); a contact also ends where it
''' leaves its face or corner (a root of its margin); a slack string snaps taut where its ends reach its
''' length (conservative advancement on L² − d²). Each ends this motion, and the next starts from the state
''' there. Steps are taken lazily, as far as anything asks.
''' </summary>
Friend NotInheritable Class ConstrainedMotion
    Inherits LinkedMotion

    Private Const RelativeTolerance As Double = 0.00000000001
    Private Const AbsoluteTolerance As Double = 0.000000000001
    ' The energy is kept (KeepEnergy) only while the kinetic is at least this share of the energy's terms, and by a
    ' velocity factor no further than this from 1.
    Private Const EnergyShare As Double = 0.001
    Private Const EnergyCorrection As Double = 0.00000001
    ' Steps kept from one start at most: far more than any advance needs, far less than the memory holds.
    Private Const MaxSteps As Integer = 2000000
    ' A group looks ahead for its events and its bodies' searches a stretch at a time, doubling it each time it
    ' reaches its end (Lookahead.StretchEnd); after this many steps it hands over to a new motion, which starts its
    ' list of steps anew.
    Private Const RestartSteps As Integer = 20000
    ' Steps taken at most each time it looks further: an event, which the wall-clock deadline of an advance cannot
    ' cut, stays short however short the steps (a 2 µg ball pressed among bodies of up to 755 t took 0.3 µs steps,
    ' and one look of 9000 of them held a window for 2 s). Long steps reach the stretch's end well within them.
    Private Const LookSteps As Integer = 256
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
    ' A watched contact pressed this far in (m) is judged again; one open this fraction of its bodies' size is left
    ' to the contact search.
    Private Const WatchSlop As Double = 0.000000001
    Private Const WatchOpening As Double = 0.000001
    ' A stuck contact stays stuck at a regrouping (LinkedEventSolver.ApplyFriction) while its friction needs no more
    ' than μs times its push plus this share of the two forces: rounding, not a slip.
    Friend Const StickRounding As Double = 0.000000001
    ' Along a motion it slips once past twice that share, so that the new group starts it sliding, not stuck again.
    Private Const SlipMargin As Double = 2 * StickRounding
    ' A constraint is held only if what it adds to the others' span is at least this fraction of it (squared): about
    ' 10⁻⁴ rad away from depending on them.
    Friend Const IndependenceMargin As Double = 0.00000001

    Private ReadOnly _gravity As Double
    ' Drag and buoyancy on the bodies (docs/forces.md), or Nothing.
    Private ReadOnly _forces As ForceField
    Private ReadOnly _n As Integer
    Private ReadOnly _inverseMass As Double()
    Private ReadOnly _springs As Link()
    ' The rods and taut strings held.
    Private ReadOnly _held As Link()
    ' The lasting contacts held (their constraints follow the links' in _rows).
    Private ReadOnly _contacts As Constraint()
    ' Contacts that touch without pressing (or that the held ones already imply): not held, but watched, so that the
    ' contact search need not follow a gap that the motion keeps at nothing.
    Private ReadOnly _watched As Constraint()
    ' The gap (m) at which each watched contact counts as pressed in.
    Private ReadOnly _pressedAt As Double()
    ' Bodies held where they are by two ties in line (TieLock): the row along the tangent each such pair adds.
    Private ReadOnly _locks As Constraint()
    ' Every constraint held: the links' ties, then the contacts, then the locks.
    Private ReadOnly _rows As Constraint()
    Private ReadOnly _constraints As ConstraintSet
    ' The slack strings, their ties, and how little spare length counts as reaching full length, m.
    Private ReadOnly _slack As Link()
    Private ReadOnly _slackTies As Constraint()
    Private ReadOnly _snapAt As Double()
    ' Whether anything can end this motion by itself (a string, a contact), so that its steps must be scanned.
    Private ReadOnly _hasEvents As Boolean
    ' Per step start: the state (per body x, y, vx, vy), its derivative, and the ties' tensions.
    Private ReadOnly _times As New List(Of Double)
    Private ReadOnly _states As New List(Of Double())
    Private ReadOnly _derivatives As New List(Of Double())
    Private ReadOnly _tensions As New List(Of Double())
    ' Per step: the quintics' coefficients, once asked for.
    Private ReadOnly _quintics As New List(Of Double())
    ' Per step: each body's speed bound (m/s) and acceleration bound (m/s²), once asked for.
    Private ReadOnly _bounds As New List(Of Double())
    ' The bounds of every body over the steps _rangeFirst to _rangeLast, the stretch asked about last.
    Private _range As Double() = Array.Empty(Of Double)()
    Private _rangeFirst As Integer = -1
    Private _rangeLast As Integer = -1
    Private _step As Double
    ' The tensions (N) at the last evaluation.
    Private _lastTensions As Double()
    ' The first event found on the steps scanned so far: the constraint (a string's tie, a contact) and what happens.
    Private _eventTime As Double = Double.PositiveInfinity
    Private _eventRow As Constraint
    Private _eventKind As ConstraintEvent
    ' The integration met a state where the constraints are no longer independent: nothing is integrated past it.
    Private _ended As Boolean
    ' Whether nothing in the group does work but gravity and its springs (no damping, no sliding friction, no drag), and
    ' then the energy it was handed at its start, J: each step's velocities are scaled back onto it (KeepEnergy).
    Private ReadOnly _conservative As Boolean
    Private ReadOnly _energy As Double

    ''' <summary>
    ''' The group of <paramref name="bodies"/>, <paramref name="links"/> and lasting <paramref name="contacts"/>
    ''' (constraints on the bodies' slots, chosen pressing by the complementarity solve) from their states now. A
    ''' string counts as taut when it is at full length, its ends not moving apart or together, and its tension,
    ''' worked out with the others, is not negative; <paramref name="released"/> (a string or contact whose force
    ''' has just fallen to zero) is not held whatever the rounding says. A rod that depends on the others here (a
    ''' second rod between the same two balls) is watched as a slack string is, and held again once it is not.
    ''' <paramref name="size"/> (m) is a length of the group's size, for its first step.
    ''' </summary>
    Friend Sub New(bodies As Shape(), links As List(Of Link), contacts As IEnumerable(Of Constraint), startTime As Double, gravity As Double,
                   released As Object, size As Double, Optional touching As IEnumerable(Of Constraint) = Nothing,
                   Optional forces As ForceField = Nothing)
        MyBase.New(bodies, startTime)
        _forces = forces
        _gravity = gravity
        _n = bodies.Length
        _inverseMass = bodies.Select(Function(b) b.InverseMass).ToArray()
        _springs = links.Where(Function(l) l.Kind = LinkKind.Spring).ToArray()
        Dim y(4 * _n - 1) As Double
        For k = 0 To _n - 1
            y(4 * k) = bodies(k).CentreOfMass.X
            y(4 * k + 1) = bodies(k).CentreOfMass.Y
            y(4 * k + 2) = bodies(k).Velocity.X
            y(4 * k + 3) = bodies(k).Velocity.Y
        Next
        Dim held As New List(Of Constraint), slack As New List(Of Constraint), watched As New List(Of Constraint)
        If touching IsNot Nothing Then watched.AddRange(touching)
        Dim snapNow As Constraint = Nothing
        For Each l In links
            If l.Kind = LinkKind.Rod Then
                If LinkedMotions.IsShortRod(l, WatchSlop) Then slack.Add(TieOf(l)) Else held.Add(TieOf(l))
            ElseIf l.Kind = LinkKind.String Then
                Dim state = LinkedMotions.StringState(l, gravity, released)
                If state > 0 Then snapNow = TieOf(l)
                If state = 0 Then held.Add(TieOf(l)) Else slack.Add(TieOf(l))
            End If
        Next
        For Each c In contacts
            If Not Equals(c.Tag, released) Then held.Add(c)
        Next
        ' Two ties in line that hold their body where it is: the row along the tangent that their two rows, one
        ' only independent, cannot give. Last, so that the ties' and contacts' rows keep their places.
        held.AddRange(TieLock.Find(held, y))
        ' A constraint the others already imply is not held (its row would make the solve singular): a rod is
        ' watched as a slack string is, a contact left to the contact search. A string or contact whose force would
        ' be negative with the others holding lets go: the most negative first, then look again, at the implied ones
        ' too: a contact implied by a rod and a string is not once the string has let go (a ball on a rod resting on
        ' a peg, with a string that would have to push), and must hold, or the ball falls into the peg.
        Dim candidates As New List(Of Constraint)(held)
        Do
            Dim independent = IndependentRows(candidates, y)
            Dim d = FreeDerivative(y)
            Dim lambda = New ConstraintSet(independent.ToArray(), _inverseMass).Tensions(y, d)
            Dim worst = -1, least = 0.0
            For i = 0 To independent.Count - 1
                If independent(i).Holds Then Continue For
                Dim w = _inverseMass(independent(i).A) + If(independent(i).B >= 0, _inverseMass(independent(i).B), 0)
                ' λw is the force's share of the ends' relative acceleration, m/s²; rounding of g's size is not a push.
                Dim pull = lambda(i) * w
                If pull < least AndAlso pull < -0.000000001 * (gravity + 1) Then least = pull : worst = i
            Next
            If worst < 0 Then
                For Each c In candidates.Except(independent)
                    ' A lock the others already imply (the body is held by a contact across it too) is simply not needed.
                    If c.IsLock Then Continue For
                    If c.Shape = ConstraintShape.Tie Then slack.Add(c) Else watched.Add(c)
                Next
                held = independent
                Exit Do
            End If
            Dim letGo = independent(worst)
            If letGo.Shape = ConstraintShape.Tie Then slack.Add(letGo) Else watched.Add(letGo)
            candidates.Remove(letGo)
            ' A contact that lets go no longer sticks either.
            candidates.RemoveAll(Function(c) c.StuckTo Is letGo)
        Loop
        _rows = held.ToArray()
        _held = held.Where(Function(c) c.Shape = ConstraintShape.Tie).Select(Function(c) DirectCast(c.Tag, Link)).ToArray()
        _contacts = held.Where(Function(c) c.Shape <> ConstraintShape.Tie AndAlso Not c.IsLock).ToArray()
        _locks = held.Where(Function(c) c.IsLock).ToArray()
        _constraints = New ConstraintSet(_rows, _inverseMass)
        ' Rounding and the slop leave the held rows a little off at the start (a contact held from a gap of 10⁻¹⁰ m): the
        ' start is put on them as each step's end is, or the first step's quintic would bend to take up the jump at its end
        ' (within that step a 486 t ball's speed read 3.6·10⁻⁵ m/s off, 1.3·10⁻⁵ of the scene's energy).
        ' The energy kept (KeepEnergy) is the one handed over, before that: the slop's worth of move against a spring's pull
        ' (a light ball's, 290 N, on a heavy ball that rests among others) is not new energy, at every regrouping.
        _conservative = _forces Is Nothing AndAlso _springs.All(Function(l) l.Damping = 0) AndAlso _rows.All(Function(c) c.Sliding = 0)
        If _conservative Then
            Dim kinetic As Double, scale As Double
            _energy = Energy(y, kinetic, scale)
        End If
        Dim lengthError As Double, rateError As Double
        _constraints.Drift(y, lengthError, rateError)
        If lengthError > DriftFraction OrElse rateError > DriftFraction * SpeedScale(y) Then
            Try
                _constraints.Project(y)
            Catch ex As InvalidOperationException
                ' Rows that cannot all be met at once here are left as they are; the first step's end meets what it can.
            End Try
        End If
        _slackTies = slack.ToArray()
        _slack = slack.Select(Function(c) DirectCast(c.Tag, Link)).ToArray()
        _snapAt = New Double(_slack.Length - 1) {}
        For i = 0 To _slack.Length - 1
            Dim spare = SpareLength(y, _slackTies(i))
            Dim margin = OverLength * _slack(i).Length
            ' A string at its length that the held rows already keep there (beside a contact of the same two balls,
            ' at its length) has its length held to the integrator's accuracy, not to rounding: it counts as taut
            ' once over-long by a watched contact's slop, or the search for it would crawl along a spare length that
            ' stays at nothing.
            If spare <= WatchSlop AndAlso Implied(_slackTies(i), held, y) Then margin = Math.Max(WatchSlop, margin)
            _snapAt(i) = If(spare > margin, 0, Math.Min(spare, 0) - margin)
            ' A rod short of its length (LinkedMotions.IsShortRod) comes back to it where the circle its body rolls
            ' round touches its own, along the row that holds the body there: it reaches its length there only to the
            ' integrator's accuracy and passes on. It snaps taut only once over-long by a watched contact's slop: a blow
            ' there, with two rows all but in line, would stop the body dead across them.
            If _slack(i).Kind = LinkKind.Rod AndAlso spare > margin Then _snapAt(i) = -Math.Max(WatchSlop, margin)
        Next
        _watched = watched.Where(Function(c) Not Equals(c.Tag, released)).ToArray()
        ' A watched contact already pressed in a little at the start (a body put on a level face beside it) is
        ' judged from there: pressed a slop further in, not at once.
        _pressedAt = _watched.Select(Function(c) Math.Min(0, Gap(c, y)) - WatchSlop).ToArray()
        _hasEvents = _slack.Length > 0 OrElse _watched.Length > 0 OrElse _rows.Any(Function(c) Not c.Holds OrElse c.StuckTo IsNot Nothing)
        Dim tensions As Double() = Nothing
        _times.Add(startTime)
        _states.Add(y)
        _derivatives.Add(Derivative(y, tensions))
        _tensions.Add(tensions)
        If snapNow IsNot Nothing Then
            _eventTime = startTime
            _eventRow = snapNow
            _eventKind = ConstraintEvent.Snaps
        End If
        ' A first step of a hundredth of the shortest link's pendulum period (or of a fall through the group's
        ' size); the error control corrects it at once.
        Dim lengths = links.Where(Function(l) l.Kind <> LinkKind.Spring).Select(Function(l) l.Length).ToList()
        Dim shortest = If(lengths.Count > 0, lengths.Min(), size)
        _step = 0.06 * Math.Sqrt(shortest / Math.Max(gravity, 1))
    End Sub

    ''' <summary>
    ''' The constraints of <paramref name="rows"/>, in order, that do not depend on those kept before them at
    ''' <paramref name="y"/>, with room to spare: one within 10⁻⁴ rad of the others' span (two rods in line but for
    ''' rounding) would be lost to rounding a step later.
    ''' </summary>
    Private Function IndependentRows(rows As List(Of Constraint), y As Double()) As List(Of Constraint)
        Dim kept As New List(Of Constraint)
        If rows.Any(Function(c) c.Sliding <> 0) OrElse ConstraintSet.IsSpread(rows, _inverseMass) Then
            ' A sliding row or bodies of very different masses: the solve is not Cholesky's method alone, so each
            ' trial is the solve itself. The free motion at y is the same for every trial (each adds its forces to a copy).
            Dim free = FreeDerivative(y)
            For Each c In rows
                kept.Add(c)
                If Not Admits(kept.ToArray(), y, free) Then kept.RemoveAt(kept.Count - 1)
            Next
            Return kept
        End If
        ' Otherwise the solve refuses a row exactly when its Cholesky pivot is too small, and the rows before it
        ' factor as they did before it came: one factor grown row by row answers each trial (see Admits for the two metrics).
        Dim unit = New GrowingFactor(UnitInverseMass(), IndependenceMargin)
        Dim real = New GrowingFactor(_inverseMass, ConstraintSet.DefaultIndependence)
        For Each c In rows
            Dim u As Vector, value As Double, rate As Double, curvature As Double
            c.Measure(y, u, value, rate, curvature)
            If Not unit.TryAdd(c, u) Then Continue For
            If Not real.TryAdd(c, u) Then
                unit.RemoveLast()
                Continue For
            End If
            kept.Add(c)
        Next
        Return kept
    End Function

    ''' <summary>
    ''' Whether the solve takes <paramref name="trial"/> at state <paramref name="y"/> (free motion
    ''' <paramref name="free"/>, left as it is): every row independent of the others with every movable body weighing
    ''' the same, and the real masses able to take them.
    ''' </summary>
    Private Function Admits(trial As Constraint(), y As Double(), free As Double()) As Boolean
        ' The margin is judged with every movable body weighing the same: in the inverse-mass metric a row between a
        ' very light ball wedged in a corner and a heavy one pressing on it is almost all the light ball's part, which
        ' the corner's faces already span, and would count as depending on them, though it alone holds the heavy
        ' one up. The real masses are asked only whether the solve can take the row at all.
        Try
            Call New ConstraintSet(trial, UnitInverseMass(), IndependenceMargin).Tensions(y, CType(free.Clone(), Double()))
            Call New ConstraintSet(trial, _inverseMass).Tensions(y, CType(free.Clone(), Double()))
            Return True
        Catch ex As InvalidOperationException
            Return False
        End Try
    End Function

    ''' <summary>The inverse masses with every movable body weighing 1 kg (and the others none): the metric rows are judged independent in.</summary>
    Private Function UnitInverseMass() As Double()
        Return _inverseMass.Select(Function(w) If(w > 0, 1.0, 0.0)).ToArray()
    End Function

    ''' <summary>
    ''' Whether <paramref name="row"/> depends on the <paramref name="held"/> rows (already found independent) at state
    ''' <paramref name="y"/>: one trial with it added, as <see cref="IndependentRows"/> would make last.
    ''' </summary>
    Private Function Implied(row As Constraint, held As List(Of Constraint), y As Double()) As Boolean
        Return Not Admits(held.Append(row).ToArray(), y, FreeDerivative(y))
    End Function

    Private Function TieOf(l As Link) As Constraint
        Dim a = Array.IndexOf(Bodies, l.A)
        Dim b = If(l.IsAnchored, -1, Array.IndexOf(Bodies, l.B))
        Dim c = Constraint.Tie(a, b, If(l.IsAnchored, l.EndB, Vector.Zero), l.Length, l.Kind = LinkKind.Rod)
        c.Tag = l
        Return c
    End Function

    ''' <summary>dy/dt without the ties: velocities, and gravity plus every spring's pull ÷ mass.</summary>
    Private Function FreeDerivative(y As Double()) As Double()
        Dim d(4 * _n - 1) As Double
        For k = 0 To _n - 1
            d(4 * k) = y(4 * k + 2)
            d(4 * k + 1) = y(4 * k + 3)
            d(4 * k + 3) = -_gravity
        Next
        SpringTerm.Add(_springs, Bodies, y, d)
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

    ''' <summary>
    ''' Takes steps until the last one ends at or after <paramref name="time"/>, looking at each for a string's change;
    ''' only one when <paramref name="oneStep"/> (the first step, whatever length the error control gives it), and no
    ''' more than <paramref name="stepLimit"/>.
    ''' </summary>
    Private Sub ExtendTo(time As Double, Optional oneStep As Boolean = False, Optional stepLimit As Integer = Integer.MaxValue)
        If Double.IsInfinity(time) Then Throw New ArgumentOutOfRangeException(NameOf(time), "a chain's motion is integrated only to a finite time")
        Dim taken = 0
        ' Nothing is integrated past an event found: the motion ends there, and past it the forces are those of a
        ' group that no longer holds (a contact pulling, harder and harder, on a light body it should have let go).
        Do While IntegratedTo < Math.Min(time, _eventTime) AndAlso Not _ended AndAlso Not (oneStep AndAlso taken > 0) AndAlso taken < stepLimit
            taken += 1
            If _times.Count > MaxSteps Then Throw New InvalidOperationException($"the chain integrator took more than {MaxSteps} steps from t = {StartTime} s to t = {_times(_times.Count - 1)} s without reaching t = {time} s")
            Dim t = _times(_times.Count - 1)
            Dim y = _states(_states.Count - 1)
            Dim k1 = _derivatives(_derivatives.Count - 1)
            Dim rounding As Double() = Nothing
            Do
                Dim h = _step
                Dim result As Double() = Nothing, slope As Double() = Nothing
                Dim worst As Double
                Dim tensions As Double() = Nothing
                Try
                    ' Among masses 10⁶ apart the light bodies' accelerations are the small difference of great forces, all
                    ' rounding where the rows fix their motion: the error is measured in what the rows leave free, and the
                    ' quintic is kept on the rows between the ends (docs/links.md, "Bodies of very different masses").
                    ' And a light body's acceleration among them may be the small sum of great terms, known only to their
                    ' rounding: h times that is noise no shorter step takes away (ConstraintSet.AccelerationRounding).
                    If _constraints.Spread AndAlso rounding Is Nothing Then rounding = _constraints.AccelerationRounding(y, FreeDerivative(y))
                    worst = DormandPrince.TryStep(AddressOf Derivative, y, k1, h, RelativeTolerance, AbsoluteTolerance, result, slope, rounding,
                                                  removeHeld:=If(_constraints.Spread, New Func(Of Double(), Double(), Boolean)(AddressOf _constraints.TryRemoveHeld), Nothing))
                    If worst <= 1 Then
                        Dim lengthError As Double, rateError As Double
                        _constraints.Drift(result, lengthError, rateError)
                        ' The step's last evaluation was at its result: its tensions are those there, unless the result is moved back onto the lengths.
                        tensions = _lastTensions
                        If lengthError > DriftFraction OrElse rateError > DriftFraction * SpeedScale(result) Then
                            _constraints.Project(result)
                            slope = Derivative(result, tensions)
                        End If
                        If _constraints.Spread Then worst = Math.Max(worst, DriftBetween(y, k1, result, slope, h))
                        If worst <= 1 AndAlso _conservative Then KeepEnergy(result, slope)
                    End If
                Catch ex As InvalidOperationException
                    ' The constraints lose their independence within the step (two contacts turning parallel, a group
                    ' carried on past a collision it will meet first): a shorter step, or the motion ends before it.
                    worst = Double.PositiveInfinity
                End Try
                _step = h * DormandPrince.StepFactor(worst)
                If worst <= 1 Then
                    _times.Add(t + h)
                    _states.Add(result)
                    _derivatives.Add(slope)
                    _tensions.Add(tensions)
                    Exit Do
                End If
                If Not (_step > 0.000000000000001 * Math.Max(1, Math.Abs(t))) Then
                    If Not Double.IsPositiveInfinity(worst) Then Throw New InvalidOperationException($"the chain integrator could not keep its error down at t = {t} s")
                    ' Where the constraints stop being independent, this motion ends: the group is formed anew there.
                    _ended = True
                    Keep(t, Nothing, ConstraintEvent.Leaves)
                    Exit Do
                End If
            Loop
            If Not _ended AndAlso _hasEvents AndAlso Double.IsPositiveInfinity(_eventTime) Then ScanStep(_times.Count - 2)
        Loop
    End Sub

    ''' <summary>
    ''' How far the quintic of a step from <paramref name="y"/> (slope <paramref name="k1"/>) to <paramref name="result"/>
    ''' (slope <paramref name="k7"/>) strays off the held rows between its ends, beyond the ends' own |ψ| (a contact may
    ''' start a slop open, and the end is put back on its rows), as a fraction of what the integrator holds a position to (the
    ''' worst of a quarter, half and three quarters of the way): above 1, the step is too long.
    ''' </summary>
    Private Function DriftBetween(y As Double(), k1 As Double(), result As Double(), k7 As Double(), h As Double) As Double
        If _rows.Length = 0 Then Return 0
        Dim inside(4 * _n - 1) As Double
        Dim first(_rows.Length - 1) As Double, last(_rows.Length - 1) As Double
        Dim u As Vector, value As Double, rate As Double, curvature As Double
        For i = 0 To _rows.Length - 1
            _rows(i).Measure(y, u, first(i), rate, curvature)
            _rows(i).Measure(result, u, last(i), rate, curvature)
        Next
        Dim c = StepQuintics(y, k1, result, k7, h)
        Dim worst = 0.0
        For Each s In {0.25, 0.5, 0.75}
            For k = 0 To _n - 1
                For axis = 0 To 1
                    Dim o = 6 * (2 * k + axis)
                    inside(4 * k + axis) = Poly(c, o, s)
                    inside(4 * k + 2 + axis) = Slope(c, o, s) / h
                Next
            Next
            For i = 0 To _rows.Length - 1
                Dim row = _rows(i)
                row.Measure(inside, u, value, rate, curvature)
                Dim stray = Math.Max(0, Math.Abs(value) - Math.Max(Math.Abs(first(i)), Math.Abs(last(i))))
                worst = Math.Max(worst, stray / (AbsoluteTolerance + RelativeTolerance * row.Scale))
            Next
        Next
        Return worst
    End Function

    ''' <summary>
    ''' The group's energy at state <paramref name="y"/>, J: kinetic (<paramref name="kinetic"/>), gravity's m g y and its
    ''' springs' ½ k (d − L)². <paramref name="size"/> is the sum of the sizes of those terms, the scale of their rounding.
    ''' </summary>
    Private Function Energy(y As Double(), ByRef kinetic As Double, ByRef size As Double) As Double
        kinetic = 0
        Dim potential = 0.0
        size = 0
        For k = 0 To _n - 1
            Dim m = Bodies(k).Mass
            kinetic += 0.5 * m * (y(4 * k + 2) * y(4 * k + 2) + y(4 * k + 3) * y(4 * k + 3))
            potential += m * _gravity * y(4 * k + 1)
            size += Math.Abs(m * _gravity * y(4 * k + 1))
        Next
        Dim springs = SpringTerm.Energy(_springs, Bodies, y)
        potential += springs
        size += springs + kinetic
        Return kinetic + potential
    End Function

    ''' <summary>
    ''' Puts a step's <paramref name="result"/> back on the energy the group was handed at its start, where nothing in it
    ''' does work but gravity and its springs: its velocities scaled by √((E₀ − V)/T), a change that keeps every held row's rate at
    ''' nothing (each is a sum of velocities) and moves along the motion. The error control holds each step to 10⁻¹¹ of
    ''' the coordinates; thousands of steps would let the energy wander by 10⁻⁹ of itself and more (a 97 mg ball on a
    ''' spring bouncing round a box at 700 m/s lost 7·10⁻⁸ of its energy in 0.3 s). Only where the bodies move enough
    ''' that the rounding of the energy's terms is not the whole correction, and never by more than a step's error could
    ''' be: anything larger is not drift. <paramref name="slope"/>'s positions' rates, when given, follow the velocities.
    ''' </summary>
    Private Sub KeepEnergy(result As Double(), Optional slope As Double() = Nothing)
        Dim kinetic As Double, size As Double
        Dim potential = Energy(result, kinetic, size) - kinetic
        If kinetic <= EnergyShare * size Then Return
        Dim wanted = _energy - potential
        If wanted <= 0 Then Return
        Dim factor = Math.Sqrt(wanted / kinetic)
        If factor = 1 OrElse Math.Abs(factor - 1) > EnergyCorrection Then Return
        For k = 0 To _n - 1
            result(4 * k + 2) *= factor
            result(4 * k + 3) *= factor
            If slope Is Nothing Then Continue For
            slope(4 * k) = result(4 * k + 2)
            slope(4 * k + 1) = result(4 * k + 3)
        Next
    End Sub

    ''' <summary>A speed of the chain's size, m/s: the fastest body's, or √(gL) for a chain at rest.</summary>
    Private Function SpeedScale(y As Double()) As Double
        Dim s = Math.Sqrt(Math.Max(_gravity, 1))
        For k = 0 To _n - 1
            s = Math.Max(s, Math.Abs(y(4 * k + 2)) + Math.Abs(y(4 * k + 3)))
        Next
        Return s
    End Function

    ''' <summary>
    ''' Looks on step j for a taut string or contact whose force turns negative, a contact that leaves its face or
    ''' corner, and a slack string (or watched rod) that reaches its length; keeps the first.
    ''' </summary>
    Private Sub ScanStep(j As Integer)
        Dim t0 = _times(j), t1 = _times(j + 1)
        For i = 0 To _rows.Length - 1
            Dim row = _rows(i)
            If Not row.Holds Then
                Dim before = _tensions(j)(i), after = _tensions(j + 1)(i)
                If after < 0 Then
                    Dim index = i
                    Dim root = If(before <= 0, t0, ScalarRoot.Brent(Function(t) TensionAt(t, index), t0, t1, before, after))
                    Keep(root, row, ConstraintEvent.Slackens)
                End If
            End If
            If row.Bounded Then
                Dim root = LeavingTime(row, j)
                If root <= t1 Then Keep(root, row, ConstraintEvent.Leaves)
            End If
        Next
        ' Friction: a sliding contact that stops sliding, a sticking one whose pull outgrows μs times its push.
        For i = 0 To _rows.Length - 1
            Dim row = _rows(i)
            If row.Sliding <> 0 Then
                Dim r0 = row.SlidingRate(_states(j)) * row.Sliding, r1 = row.SlidingRate(_states(j + 1)) * row.Sliding
                If r1 <= 0 Then
                    Dim root = If(r0 <= 0, t0, ScalarRoot.Brent(Function(t) row.SlidingRate(StateArray(t)) * row.Sliding, t0, t1, r0, r1))
                    Keep(root, row, ConstraintEvent.Stops)
                End If
            ElseIf row.StuckTo IsNot Nothing Then
                Dim n = Array.IndexOf(_rows, row.StuckTo)
                If n < 0 Then Continue For
                Dim stick = i
                ' Past μs times its push by SlipMargin, twice what the regrouping forgives: the new group starts it sliding.
                Dim spare = Function(tensions As Double()) row.StuckTo.StaticFriction * tensions(n) - Math.Abs(tensions(stick)) +
                                                             SlipMargin * (Math.Abs(tensions(stick)) + Math.Abs(tensions(n)))
                Dim s0 = spare(_tensions(j)), s1 = spare(_tensions(j + 1))
                If s1 < 0 Then
                    Dim root = If(s0 <= 0, t0, ScalarRoot.Brent(Function(t) spare(TensionsAt(t)), t0, t1, s0, s1))
                    Keep(root, row, ConstraintEvent.Slips)
                End If
            End If
        Next
        For w = 0 To _watched.Length - 1
            Dim row = _watched(w)
            Dim v0 = Gap(row, _states(j)), v1 = Gap(row, _states(j + 1))
            Dim pressed = _pressedAt(w)
            If v1 < pressed Then
                ' Pressed a slop in: from here the contact is the one rule's to judge again (a collision, or held).
                Dim root = If(v0 <= pressed, t0, ScalarRoot.Brent(Function(t) Gap(row, StateArray(t)) - pressed, t0, t1, v0 - pressed, v1 - pressed))
                Keep(root, row, ConstraintEvent.Presses)
            ElseIf v1 > WatchOpening * row.Scale AndAlso v0 <= WatchOpening * row.Scale Then
                ' Opened clear: from here the contact search follows it.
                Dim root = ScalarRoot.Brent(Function(t) WatchOpening * row.Scale - Gap(row, StateArray(t)), t0, t1, WatchOpening * row.Scale - v0, WatchOpening * row.Scale - v1)
                Keep(root, row, ConstraintEvent.Opens)
            End If
            If row.Bounded Then
                Dim root = LeavingTime(row, j)
                If root <= t1 Then Keep(root, row, ConstraintEvent.Leaves)
            End If
        Next
        For i = 0 To _slack.Length - 1
            Dim tie = _slackTies(i)
            Dim target = _snapAt(i)
            Dim f0 = SpareLength(_states(j), tie), f1 = SpareLength(_states(j + 1), tie)
            Dim h = t1 - t0
            Dim speed = StepBound(j, tie.A, 1, tie.B)
            ' The spare length falls no faster than the ends' relative speed: from both ends of the step it cannot reach the target in between.
            If f0 > target AndAlso f1 > target AndAlso (f0 + f1 - speed * h) / 2 > target Then Continue For
            ' On L² − d²: |d| ≤ d(t0) + speed × h over the step bounds |(d²)'| = 2|r·w| and |(d²)''| = 2| |w|² + r·a |.
            Dim accel = StepBound(j, tie.A, 2, tie.B)
            Dim reach = tie.Length - f0 + speed * h
            Dim reached = tie.Length - target
            Dim found = ConservativeAdvancement.FirstContact(New SquaredSpareGap(Me, tie), t0, t1, tie.Length * tie.Length - reached * reached,
                                                             2 * reach * speed, 2 * (speed * speed + reach * accel))
            If found.Found Then
                Keep(found.Time, tie, ConstraintEvent.Snaps)
            ElseIf found.ClearUntil < t1 Then
                Throw New InvalidOperationException($"the chain integrator could not tell whether a string snaps taut between t = {found.ClearUntil} s and {t1} s")
            End If
        Next
    End Sub

    ''' <summary>
    ''' When in step j a bounded contact leaves its face or corner (<see cref="Constraint.EndMargins"/>), or +∞ if it
    ''' stays on. Each end is watched apart: a contact that starts exactly at one end, moving onto the face, has a
    ''' margin of 0 there, and judged by the nearer end alone (the least of the two) it would leave at once, be held
    ''' again on the same face, and leave again, for ever; it leaves by the far end, where that end's margin turns
    ''' negative. One that starts at or past an end and is still past it at the step's end leaves at the start. But one
    ''' that starts past an end by no more than a slop leaves only once a slop further past it: rounding put it there (a
    ''' ball balanced on a box's corner, 10⁻¹⁵ m over onto the top face, was held on the corner, left it at once, and
    ''' was held on it again, for ever).
    ''' </summary>
    Private Function LeavingTime(row As Constraint, j As Integer) As Double
        Dim t0 = _times(j), t1 = _times(j + 1)
        Dim first0, second0, first1, second1, firstStart, secondStart As Double
        row.EndMargins(_states(j), first0, second0)
        row.EndMargins(_states(j + 1), first1, second1)
        row.EndMargins(_states(0), firstStart, secondStart)
        Dim firstEnd = EndLimit(firstStart), secondEnd = EndLimit(secondStart)
        Dim best = Double.PositiveInfinity
        If first1 < firstEnd Then
            best = Math.Min(best, If(first0 <= firstEnd, t0, ScalarRoot.Brent(Function(t) EndMargin(row, t, True) - firstEnd, t0, t1, first0 - firstEnd, first1 - firstEnd)))
        End If
        If second1 < secondEnd Then
            best = Math.Min(best, If(second0 <= secondEnd, t0, ScalarRoot.Brent(Function(t) EndMargin(row, t, False) - secondEnd, t0, t1, second0 - secondEnd, second1 - secondEnd)))
        End If
        Return best
    End Function

    ''' <summary>
    ''' The margin (m) below which a contact whose margin at one end was <paramref name="atStart"/> (m) at the motion's
    ''' start has left by that end: 0, or a slop below where it started when that was past the end by a slop at most.
    ''' </summary>
    Private Shared Function EndLimit(atStart As Double) As Double
        Return If(atStart < 0 AndAlso atStart >= -WatchSlop, atStart - WatchSlop, 0)
    End Function

    ''' <summary>One end's part of a bounded contact's margin (m) at <paramref name="time"/>.</summary>
    Private Function EndMargin(row As Constraint, time As Double, first As Boolean) As Double
        Dim a As Double, b As Double
        row.EndMargins(StateArray(time), a, b)
        Return If(first, a, b)
    End Function

    ''' <summary>A contact's ψ (m) at state <paramref name="y"/>: its gap, negative when pressed in.</summary>
    Private Shared Function Gap(row As Constraint, y As Double()) As Double
        Dim u As Vector, value As Double, rate As Double, curvature As Double
        row.Measure(y, u, value, rate, curvature)
        Return value
    End Function

    Private Sub Keep(time As Double, row As Constraint, kind As ConstraintEvent)
        If time >= _eventTime Then Return
        _eventTime = time
        _eventRow = row
        _eventKind = kind
    End Sub

    ''' <summary>L − d for a tie, m: how much length a slack string has to spare.</summary>
    Private Shared Function SpareLength(y As Double(), t As Constraint) As Double
        Dim pa As New Vector(y(4 * t.A), y(4 * t.A + 1))
        Dim pb = If(t.B >= 0, New Vector(y(4 * t.B), y(4 * t.B + 1)), t.Point)
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
        Return TensionsAt(time)(i)
    End Function

    ''' <summary>Every held row's force (N) at <paramref name="time"/>, on the quintics.</summary>
    Private Function TensionsAt(time As Double) As Double()
        Dim tensions As Double() = Nothing
        Derivative(StateArray(time), tensions)
        Return tensions
    End Function

    ''' <summary>The step holding <paramref name="time"/> (the last whose start is at or before it).</summary>
    Private Function StepAt(time As Double) As Integer
        ExtendTo(time)
        Return QuinticSteps.StepHolding(_times, time)
    End Function

    ''' <summary>
    ''' Step j's quintics, worked out once: for body k and coordinate a (0: x, 1: y), the coefficients c₀…c₅ in
    ''' s = (t − tⱼ)/h are at 6(2k + a) onwards.
    ''' </summary>
    Private Function Quintics(j As Integer) As Double()
        Do While _quintics.Count <= j
            Dim i = _quintics.Count
            _quintics.Add(StepQuintics(_states(i), _derivatives(i), _states(i + 1), _derivatives(i + 1), _times(i + 1) - _times(i)))
        Loop
        Return _quintics(j)
    End Function

    ''' <summary>
    ''' The quintics of a step of <paramref name="h"/> s from state <paramref name="y0"/> (derivative <paramref name="d0"/>)
    ''' to <paramref name="y1"/> (<paramref name="d1"/>), laid out as in <see cref="Quintics"/>.
    ''' </summary>
    Private Function StepQuintics(y0 As Double(), d0 As Double(), y1 As Double(), d1 As Double(), h As Double) As Double()
        Dim c(12 * _n - 1) As Double
        For k = 0 To _n - 1
            For axis = 0 To 1
                Dim p0 = y0(4 * k + axis), v0 = y0(4 * k + 2 + axis) * h, a0 = d0(4 * k + 2 + axis) * h * h
                Dim p1 = y1(4 * k + axis), v1 = y1(4 * k + 2 + axis) * h, a1 = d1(4 * k + 2 + axis) * h * h
                QuinticSteps.Fill(c, 6 * (2 * k + axis), p0, v0, a0, p1, v1, a1)
            Next
        Next
        Return c
    End Function

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        Dim j = If(time = StartTime, 0, StepAt(time))
        Dim y0 = _states(j)
        ' A motion that ended where it started (its constraints not independent past it) has only its start.
        If time = _times(j) OrElse _times.Count = 1 Then
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

    ''' <summary>
    ''' Every body's state at <paramref name="time"/>, read from the quintics, and where nothing in the group does work but
    ''' gravity and its springs, its velocities scaled onto the energy it was handed, as each step's end is
    ''' (<see cref="KeepEnergy"/>): between the ends the quintic's own error, of order h⁶, moved the energy read there by
    ''' up to 2.7·10⁻⁹ of itself (a 1.6 mg ball on a 178 N/m spring, snapping a string taut 9 000 times a second).
    ''' </summary>
    Friend Overrides Sub StatesAt(time As Double, positions As Vector(), velocities As Vector())
        MyBase.StatesAt(time, positions, velocities)
        If Not _conservative Then Return
        Dim y(4 * _n - 1) As Double
        For k = 0 To _n - 1
            y(4 * k) = positions(k).X
            y(4 * k + 1) = positions(k).Y
            y(4 * k + 2) = velocities(k).X
            y(4 * k + 3) = velocities(k).Y
        Next
        KeepEnergy(y)
        For k = 0 To _n - 1
            velocities(k) = New Vector(y(4 * k + 2), y(4 * k + 3))
        Next
    End Sub

    Private Shared Function Poly(c As Double(), o As Integer, s As Double) As Double
        Return c(o) + s * (c(o + 1) + s * (c(o + 2) + s * (c(o + 3) + s * (c(o + 4) + s * c(o + 5)))))
    End Function

    Private Shared Function Slope(c As Double(), o As Integer, s As Double) As Double
        Return c(o + 1) + s * (2 * c(o + 2) + s * (3 * c(o + 3) + s * (4 * c(o + 4) + s * 5 * c(o + 5))))
    End Function

    ''' <summary>
    ''' |p'| (order 1) or |p''| (order 2) of body k on step j, or of its motion relative to body
    ''' <paramref name="other"/> when that is not negative: bounded by Σ j|cⱼ| and Σ j(j − 1)|cⱼ| of the (difference
    ''' of the) quintics, s in [0, 1]. Two bodies moving together have small relative bounds, however fast they go.
    ''' </summary>
    Private Function StepBound(j As Integer, k As Integer, order As Integer, Optional other As Integer = -1) As Double
        Dim h = _times(j + 1) - _times(j)
        Dim bx = 0.0, by = 0.0
        Dim c = Quintics(j)
        Dim ox = 12 * k, oy = 12 * k + 6
        Dim qx = 12 * other, qy = 12 * other + 6
        For p = order To 5
            Dim w = If(order = 1, p, p * (p - 1))
            bx += w * Math.Abs(c(ox + p) - If(other >= 0, c(qx + p), 0))
            by += w * Math.Abs(c(oy + p) - If(other >= 0, c(qy + p), 0))
        Next
        Return Math.Sqrt(bx * bx + by * by) / Math.Pow(h, order) * (1 + 0.000000001)
    End Function

    ''' <summary>
    ''' Bounds on the relative motion of bodies <paramref name="k1"/> and <paramref name="k2"/> of this group over
    ''' [<paramref name="t0"/>, <paramref name="t1"/>]: the speed (m/s) and acceleration (m/s²) of their difference,
    ''' read from the differences of their quintics. Two bodies that move together (resting on each other, sliding
    ''' as one) have small ones, however fast they go.
    ''' </summary>
    Friend Sub RelativeBounds(k1 As Integer, k2 As Integer, t0 As Double, t1 As Double, ByRef speed As Double, ByRef acceleration As Double)
        Dim first = StepAt(t0), last = StepAt(t1)
        speed = 0
        acceleration = 0
        If _times.Count = 1 Then
            Dim y = _states(0), d = _derivatives(0)
            speed = New Vector(y(4 * k1 + 2) - y(4 * k2 + 2), y(4 * k1 + 3) - y(4 * k2 + 3)).Length
            acceleration = New Vector(d(4 * k1 + 2) - d(4 * k2 + 2), d(4 * k1 + 3) - d(4 * k2 + 3)).Length
            Return
        End If
        For j = first To last
            speed = Math.Max(speed, StepBound(j, k1, 1, k2))
            acceleration = Math.Max(acceleration, StepBound(j, k1, 2, k2))
        Next
    End Sub

    ''' <summary>
    ''' Its velocity at t0 is the frame's; its acceleration in the frame, bounded on each step from its quintic less
    ''' gravity's parabola, also bounds how fast it leaves the frame's velocity.
    ''' </summary>
    Friend Overrides Function FallingBounds(k As Integer, t0 As Double, t1 As Double, gravity As Double,
                                            ByRef frame As Vector, ByRef speed As Double, ByRef acceleration As Double) As Boolean
        Dim p As Vector
        StateAt(t0, k, p, frame)
        Dim first = StepAt(t0), last = StepAt(t1)
        acceleration = 0
        If _times.Count = 1 Then
            Dim d = _derivatives(0)
            acceleration = New Vector(d(4 * k + 2), d(4 * k + 3) + gravity).Length
        Else
            For j = first To last
                Dim h = _times(j + 1) - _times(j)
                Dim c = Quintics(j)
                ' Gravity's parabola −½ g (h s)² has c₂ = −½ g h² in y, and no other term past the first.
                Dim bx = 0.0, by = 0.0
                For q = 2 To 5
                    Dim w = q * (q - 1)
                    bx += w * Math.Abs(c(12 * k + q))
                    by += w * Math.Abs(c(12 * k + 6 + q) + If(q = 2, 0.5 * gravity * h * h, 0))
                Next
                acceleration = Math.Max(acceleration, Math.Sqrt(bx * bx + by * by) / (h * h) * (1 + 0.000000001))
            Next
        End If
        speed = acceleration * (t1 - t0) * (1 + 0.000000001)
        Return True
    End Function

    ''' <summary>The largest of body k's per-step bounds over the steps that meet [t0, t1]; each step's bounds are worked out once.</summary>
    Private Function Bound(k As Integer, t0 As Double, t1 As Double, order As Integer) As Double
        Dim first = StepAt(t0), last = StepAt(t1)
        If _times.Count = 1 Then
            ' Ended where it started: only the start is known, and the motion is over there.
            Dim y = _states(0), d = _derivatives(0)
            Return If(order = 1, New Vector(y(4 * k + 2), y(4 * k + 3)).Length, New Vector(d(4 * k + 2), d(4 * k + 3)).Length)
        End If
        ' Every body's bounds over these steps at once: the searches of one instant all ask about the same stretch.
        If first <> _rangeFirst OrElse last <> _rangeLast Then
            If _range.Length < 2 * _n Then _range = New Double(2 * _n - 1) {}
            Array.Clear(_range, 0, 2 * _n)
            For j = first To last
                Do While _bounds.Count <= j
                    Dim b(2 * _n - 1) As Double
                    For body = 0 To _n - 1
                        b(2 * body) = StepBound(_bounds.Count, body, 1)
                        b(2 * body + 1) = StepBound(_bounds.Count, body, 2)
                    Next
                    _bounds.Add(b)
                Loop
                Dim stepBounds = _bounds(j)
                For i = 0 To 2 * _n - 1
                    _range(i) = Math.Max(_range(i), stepBounds(i))
                Next
            Next
            _rangeFirst = first
            _rangeLast = last
        End If
        Return _range(2 * k + order - 1)
    End Function

    Friend Overrides Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return Bound(k, t0, t1, 1)
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return Bound(k, t0, t1, 2)
    End Function

    ''' <summary>
    ''' The first event on the steps looked at so far; with none found yet, the end of its last step, where it looks
    ''' further (<see cref="LookFurther"/>). A group that nothing of its own can end (a rod and a spring) is looked at
    ''' so too: its searches, which end here, would otherwise integrate it a whole horizon ahead after every
    ''' collision (a short rod spinning among balls: 1000 collisions in 2 s took 18 s of CPU, now 8).
    ''' </summary>
    Friend Overrides ReadOnly Property TransitionTime As Double
        Get
            If Not Double.IsPositiveInfinity(_eventTime) Then Return _eventTime
            ' One step, not up to the first step's guess: that guess (a hundredth of a pendulum period) can be a
            ' thousand steps of a stiff spring, integrated for a stretch the next collision throws away.
            If _times.Count < 2 Then ExtendTo(StartTime + _step, oneStep:=True)
            If Not Double.IsPositiveInfinity(_eventTime) Then Return _eventTime
            Return _times(_times.Count - 1)
        End Get
    End Property

    Friend Overrides ReadOnly Property StepsTaken As Integer
        Get
            Return _times.Count - 1
        End Get
    End Property

    ''' <summary>The end of the last step taken (s): nothing of the motion is integrated past it.</summary>
    Friend ReadOnly Property IntegratedTo As Double
        Get
            Return _times(_times.Count - 1)
        End Get
    End Property

    ''' <summary>
    ''' At the end of the steps looked at, with no event on them: takes as many steps again (up to
    ''' <see cref="Lookahead.LongestStretchSeconds"/> at once, <see cref="Lookahead.StretchEnd"/>) and returns True,
    ''' so the motion goes on as it was; False once it has taken so many that the group had better start anew from
    ''' where it is.
    ''' </summary>
    Friend Overrides Function LookFurther(time As Double) As Boolean
        If _eventRow IsNot Nothing OrElse _ended OrElse Not Double.IsPositiveInfinity(_eventTime) OrElse time <> _times(_times.Count - 1) Then Return False
        If _times.Count > RestartSteps Then Return False
        ExtendTo(Lookahead.StretchEnd(StartTime, time, _step), stepLimit:=LookSteps)
        Return True
    End Function

    ''' <summary>The string or contact whose force has just fallen to zero (not held in the next motion), or Nothing.</summary>
    Friend Overrides ReadOnly Property Released As Object
        Get
            Return If(_eventKind = ConstraintEvent.Slackens AndAlso _eventRow IsNot Nothing, _eventRow.Tag, Nothing)
        End Get
    End Property

    ''' <summary>After <see cref="Transition"/>: the contact (its tag) that left the end of its face or corner there, or Nothing.</summary>
    Friend ReadOnly Property LeftItsFeature As Object
        Get
            Return If(_eventKind = ConstraintEvent.Leaves AndAlso _eventRow IsNot Nothing, _eventRow.Tag, Nothing)
        End Get
    End Property

    ''' <summary>
    ''' A string goes slack or a contact lifts off (its force fell to zero), or a contact leaves its face or corner:
    ''' nothing changes at that instant. Or a string snaps taut: like a collision along the string, its ends' speed
    ''' apart becomes e times as much together (a rod the others implied: 0), solved with the rods, taut strings and
    ''' lasting contacts of the group so that they hold through the jerk (<see cref="LinkedImpulse"/>). Returns true
    ''' when a string has gone slack or a contact lifted off.
    ''' </summary>
    Friend Overrides Function Transition(world As World) As Boolean
        If _eventRow Is Nothing Then Return False
        If _eventKind <> ConstraintEvent.Snaps Then Return _eventKind = ConstraintEvent.Slackens
        Dim l = DirectCast(_eventRow.Tag, Link)
        Dim apart = l.StretchRate
        If apart <= 0 Then Return False
        Dim restitution = If(l.Kind = LinkKind.Rod, 0, world.Restitution)
        If restitution * apart < Math.Sqrt(2 * Stretching(_eventRow, world.Gravity) * SettleFraction * l.Length) Then restitution = 0
        Dim impulse As New LinkedImpulse()
        ' A contact whose normal points from B to A: "approaching" along it is the ends moving apart, and its push pulls them together.
        impulse.AddContact(l.A, If(l.IsAnchored, Nothing, l.B), -(l.EndB - l.EndA).Normalized(Vector.Zero), restitution)
        impulse.AddHeldRowsOf(Me)
        impulse.Resolve()
        If l.Kind = LinkKind.String Then Snapped = l
        Return False
    End Function

    ''' <summary>
    ''' How hard (m/s²) the motion would stretch <paramref name="tie"/> now, held by nothing: gravity's size at least, or
    ''' what the free forces and the turning of the string's line (a body swinging round on it) add up to along it.
    ''' </summary>
    Private Function Stretching(tie As Constraint, gravity As Double) As Double
        Dim y = Constraint.StateOf(Bodies)
        Dim d = FreeDerivative(y)
        Dim u As Vector, value As Double, rate As Double, curvature As Double
        tie.Measure(y, u, value, rate, curvature)
        Dim relative = New Vector(d(4 * tie.A + 2), d(4 * tie.A + 3)) - If(tie.B >= 0, New Vector(d(4 * tie.B + 2), d(4 * tie.B + 3)), Vector.Zero)
        Return Math.Max(Math.Max(gravity, 0.000001), -(Vector.Dot(u, relative) + curvature))
    End Function

    ''' <summary>
    ''' Whether the group is at rest at its start: every body still, and every acceleration within
    ''' <paramref name="fraction"/> of the forces' own size of zero (rounding of their balance).
    ''' </summary>
    Friend Function IsStill(fraction As Double) As Boolean
        Dim y = _states(0), d = _derivatives(0)
        Dim free = FreeDerivative(y)
        Dim scale = _gravity
        For k = 0 To _n - 1
            If y(4 * k + 2) <> 0 OrElse y(4 * k + 3) <> 0 Then Return False
            scale = Math.Max(scale, Math.Abs(free(4 * k + 2)) + Math.Abs(free(4 * k + 3)))
        Next
        For k = 0 To _n - 1
            If Math.Abs(d(4 * k + 2)) > fraction * scale OrElse Math.Abs(d(4 * k + 3)) > fraction * scale Then Return False
        Next
        Return True
    End Function

    ''' <summary>The held rods' and taut strings' tensions at the start (N), in the order of <see cref="HeldLinks"/>.</summary>
    Friend ReadOnly Property StartTensions As Double()
        Get
            Return _tensions(0).Take(_held.Length).ToArray()
        End Get
    End Property

    ''' <summary>The links this motion does not hold: springs and slack strings.</summary>
    Friend ReadOnly Property SlackLinks As Link()
        Get
            Return _slack.Concat(_springs).ToArray()
        End Get
    End Property

    Friend Overrides ReadOnly Property HeldLinks As Link()
        Get
            Return _held
        End Get
    End Property

    Friend Overrides ReadOnly Property HeldContacts As Constraint()
        Get
            Return _contacts
        End Get
    End Property

    Friend Overrides ReadOnly Property HeldLocks As Constraint()
        Get
            Return _locks
        End Get
    End Property

    Friend Overrides ReadOnly Property WatchedContacts As Constraint()
        Get
            Return _watched
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

        Private ReadOnly _motion As ConstrainedMotion
        Private ReadOnly _tie As Constraint

        Public Sub New(motion As ConstrainedMotion, tie As Constraint)
            _motion = motion
            _tie = tie
        End Sub

        Private Sub Ends(time As Double, ByRef r As Vector, ByRef w As Vector)
            Dim pa As Vector, va As Vector, pb = _tie.Point, vb = Vector.Zero
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
