Option Strict On

''' <summary>
''' A motion integrated by the Dormand–Prince 5(4) pair, whose embedded fourth-order result estimates each
''' step's error so the step keeps it below the given tolerances, and read between steps on the quintic
''' through each step's ends that matches position, velocity and acceleration there (error of order h⁶).
''' That quintic is the motion: contacts are found on it, and the bounds on speed and acceleration that
''' conservative advancement needs come from its coefficients. Steps are taken lazily, as far as anything asks.
''' The state holds x, y, vx, vy (m, m/s) for each body in turn; further components (an energy, say) may follow.
''' </summary>
Friend NotInheritable Class QuinticTrajectory
    ' Steps kept from one start at most: far more than any advance needs, far less than the memory holds.
    Private Const MaxSteps As Integer = 2000000

    Private ReadOnly _what As String
    Private ReadOnly _derivative As Func(Of Double(), Double())
    Private ReadOnly _relativeTolerance As Double
    Private ReadOnly _absoluteTolerance As Double
    Private ReadOnly _maxStep As Func(Of Double(), Double)
    Private ReadOnly _rounding As Func(Of Double(), Double())
    ' Per step start: the time (s), the state and its derivative.
    Private ReadOnly _times As New List(Of Double)
    Private ReadOnly _states As New List(Of Double())
    Private ReadOnly _slopes As New List(Of Double())
    Private _step As Double

    ''' <summary>
    ''' Starts at <paramref name="startTime"/> (s) in state <paramref name="y0"/>, with dy/dt given by
    ''' <paramref name="derivative"/>. <paramref name="firstStep"/>: s, corrected by the error control at once.
    ''' <paramref name="maxStep"/>: the longest next step from a state, s (Nothing: no limit).
    ''' <paramref name="rounding"/>: how far each component of dy/dt at a state may be off by rounding alone, the
    ''' floor of the error control (see <see cref="DormandPrince.TryStep"/>; Nothing: none).
    ''' <paramref name="what"/> names the integrator in messages ("the spring integrator").
    ''' </summary>
    Friend Sub New(what As String, derivative As Func(Of Double(), Double()), y0 As Double(), startTime As Double, firstStep As Double,
                   relativeTolerance As Double, absoluteTolerance As Double, Optional maxStep As Func(Of Double(), Double) = Nothing,
                   Optional rounding As Func(Of Double(), Double()) = Nothing)
        _what = what
        _derivative = derivative
        _relativeTolerance = relativeTolerance
        _absoluteTolerance = absoluteTolerance
        _maxStep = maxStep
        _rounding = rounding
        _times.Add(startTime)
        _states.Add(y0)
        _slopes.Add(derivative(y0))
        _step = firstStep
    End Sub

    ''' <summary>The time the motion starts, s.</summary>
    Friend ReadOnly Property StartTime As Double
        Get
            Return _times(0)
        End Get
    End Property

    ''' <summary>How many steps have been taken so far.</summary>
    Friend ReadOnly Property StepCount As Integer
        Get
            Return _times.Count - 1
        End Get
    End Property

    ''' <summary>Takes steps until the last step ends at or after <paramref name="time"/> (s).</summary>
    Private Sub ExtendTo(time As Double)
        If Double.IsInfinity(time) Then Throw New ArgumentOutOfRangeException(NameOf(time), $"{_what} integrates only to a finite time")
        Do While _times(_times.Count - 1) < time
            If _times.Count > MaxSteps Then Throw New InvalidOperationException($"{_what} took more than {MaxSteps} steps from t = {StartTime} s to t = {_times(_times.Count - 1)} s without reaching t = {time} s")
            Dim t = _times(_times.Count - 1)
            Dim y = _states(_states.Count - 1)
            Dim k1 = _slopes(_slopes.Count - 1)
            Do
                Dim h = _step
                Dim next5 As Double() = Nothing, k7 As Double() = Nothing
                Dim worst = DormandPrince.TryStep(_derivative, y, k1, h, _relativeTolerance, _absoluteTolerance, next5, k7,
                                                  If(_rounding Is Nothing, Nothing, _rounding(y)))
                _step = h * DormandPrince.StepFactor(worst)
                ' Never longer than the caller's limit: the bounds are read from a whole step's quintic, and a step grown
                ' long over a smooth stretch would bound a search of a few milliseconds by the motion of seconds.
                If _maxStep IsNot Nothing Then _step = Math.Min(_step, _maxStep(next5))
                If worst <= 1 Then
                    _times.Add(t + h)
                    _states.Add(next5)
                    _slopes.Add(k7)
                    Exit Do
                End If
                If Not (_step > 0.000000000000001 * Math.Max(1, Math.Abs(t))) Then Throw New InvalidOperationException($"{_what} could not keep its error down at t = {t} s")
            Loop
        Loop
    End Sub

    ''' <summary>The step holding <paramref name="time"/> (the last whose start is at or before it), stepping as far as needed.</summary>
    Friend Function StepAt(time As Double) As Integer
        ExtendTo(time)
        Return QuinticSteps.StepHolding(_times, time)
    End Function

    ''' <summary>The start of step <paramref name="j"/>, s.</summary>
    Friend Function TimeOf(j As Integer) As Double
        Return _times(j)
    End Function

    ''' <summary>The state at the start of step <paramref name="j"/> (do not change it).</summary>
    Friend Function StateOf(j As Integer) As Double()
        Return _states(j)
    End Function

    ''' <summary>The quintic's coefficients c₀…c₅ in s = (t − tⱼ)/h for body <paramref name="k"/>'s coordinate <paramref name="axis"/> (0: x, 1: y) on step j.</summary>
    Private Function Coefficients(j As Integer, k As Integer, axis As Integer) As Double()
        Dim h = _times(j + 1) - _times(j)
        Dim p0 = _states(j)(4 * k + axis), v0 = _states(j)(4 * k + 2 + axis) * h, a0 = _slopes(j)(4 * k + 2 + axis) * h * h
        Dim p1 = _states(j + 1)(4 * k + axis), v1 = _states(j + 1)(4 * k + 2 + axis) * h, a1 = _slopes(j + 1)(4 * k + 2 + axis) * h * h
        Return QuinticSteps.Coefficients(p0, v0, a0, p1, v1, a1)
    End Function

    ''' <summary>Body <paramref name="k"/>'s position (m) and velocity (m/s) at <paramref name="time"/> (s).</summary>
    Friend Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        If time = StartTime Then
            Dim y0 = _states(0)
            position = New Vector(y0(4 * k), y0(4 * k + 1))
            velocity = New Vector(y0(4 * k + 2), y0(4 * k + 3))
            Return
        End If
        Dim j = StepAt(time)
        Dim h = _times(j + 1) - _times(j)
        Dim s = (time - _times(j)) / h
        Dim cx = Coefficients(j, k, 0), cy = Coefficients(j, k, 1)
        position = New Vector(Poly(cx, s), Poly(cy, s))
        velocity = New Vector(Slope(cx, s) / h, Slope(cy, s) / h)
    End Sub

    Private Shared Function Poly(c As Double(), s As Double) As Double
        Return c(0) + s * (c(1) + s * (c(2) + s * (c(3) + s * (c(4) + s * c(5)))))
    End Function

    Private Shared Function Slope(c As Double(), s As Double) As Double
        Return c(1) + s * (2 * c(2) + s * (3 * c(3) + s * (4 * c(4) + s * 5 * c(5))))
    End Function

    ''' <summary>
    ''' Body <paramref name="k"/>'s |p'| (<paramref name="order"/> 1, m/s) or |p''| (order 2, m/s²) bounded on a step by
    ''' Σ j|cⱼ| or Σ j(j − 1)|cⱼ| (s in [0, 1]), over every step that meets [t0, t1] (s).
    ''' </summary>
    Friend Function Bound(k As Integer, t0 As Double, t1 As Double, order As Integer) As Double
        Dim first = StepAt(Math.Max(t0, StartTime)), last = StepAt(Math.Max(t1, StartTime))
        If _times.Count = 1 Then
            ' Asked only about its start (a search that ends where it begins): no step yet, the start state's own.
            Dim y = _states(0), d = _slopes(0)
            Dim source = If(order = 1, y, d)
            Return New Vector(source(4 * k + 2), source(4 * k + 3)).Length * (1 + 0.000000001)
        End If
        ' The searches of one instant all ask about the same stretch, for each body and both orders: each step's
        ' bounds are worked out once, and the last stretch's are kept.
        Dim slot = 2 * k + order - 1
        If first <> _rangeFirst OrElse last <> _rangeLast Then
            _rangeFirst = first
            _rangeLast = last
            _range.Clear()
        End If
        Dim known As Double
        If _range.TryGetValue(slot, known) Then Return known
        Dim worst = 0.0
        For j = first To last
            worst = Math.Max(worst, StepBound(j, k, order))
        Next
        Dim result = worst * (1 + 0.000000001)
        _range(slot) = result
        Return result
    End Function

    ''' <summary>Body k's bound of the given order on step j, worked out once.</summary>
    Private Function StepBound(j As Integer, k As Integer, order As Integer) As Double
        Dim slot = 2 * k + order - 1
        Do While _stepBounds.Count <= j
            _stepBounds.Add(Nothing)
        Loop
        Dim known = _stepBounds(j)
        If known Is Nothing Then
            known = New Dictionary(Of Integer, Double)
            _stepBounds(j) = known
        End If
        Dim value As Double
        If known.TryGetValue(slot, value) Then Return value
        Dim h = _times(j + 1) - _times(j)
        Dim bx = 0.0, by = 0.0
        Dim cx = Coefficients(j, k, 0), cy = Coefficients(j, k, 1)
        For p = order To 5
            Dim w = If(order = 1, p, p * (p - 1))
            bx += w * Math.Abs(cx(p))
            by += w * Math.Abs(cy(p))
        Next
        value = Math.Sqrt(bx * bx + by * by) / Math.Pow(h, order)
        known(slot) = value
        Return value
    End Function

    ' Per step: each body's bounds (keyed 2k + order − 1), once asked for.
    Private ReadOnly _stepBounds As New List(Of Dictionary(Of Integer, Double))
    ' The bounds over the steps _rangeFirst to _rangeLast, the stretch asked about last.
    Private ReadOnly _range As New Dictionary(Of Integer, Double)
    Private _rangeFirst As Integer = -1
    Private _rangeLast As Integer = -1
End Class
