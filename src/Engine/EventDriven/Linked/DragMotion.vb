Option Strict On

''' <summary>
''' One free body under gravity, drag and buoyancy (<see cref="ForceField"/>) where no closed form fits: quadratic
''' drag, or anything in a world with liquids (a body may fly into one). Integrated as the springs are
''' (<see cref="IntegratedMotion"/>, docs/links.md section 4): the Dormand–Prince 5(4) pair with its error kept
''' below 10⁻¹¹ of the state, and between steps the quintic that matches position, velocity and acceleration at
''' both ends; that quintic is the motion, and its coefficients bound the speed and acceleration that conservative
''' advancement needs, so no contact is ever stepped over. The energy the drag removes, W with dW/dt = c |v|² ≥ 0,
''' is integrated with the motion as a fifth component of the state. Steps are taken lazily, as far as anything asks.
''' </summary>
Friend NotInheritable Class DragMotion
    Inherits LinkedMotion
    Implements IDissipatingMotion

    Private Const RelativeTolerance As Double = 0.00000000001
    Private Const AbsoluteTolerance As Double = 0.000000000001
    ' Steps kept from one start at most: far more than any advance needs, far less than the memory holds.
    Private Const MaxSteps As Integer = 2000000
    ' The longest step, s: about the linked solver's search horizon.
    Private Const MaxStepLength As Double = 0.01

    Private ReadOnly _forces As ForceField
    Private ReadOnly _gravity As Double
    Private ReadOnly _body As Shape
    ' The centre of mass less the reference point, m: the forces are worked out where the outline is.
    Private ReadOnly _offset As Vector
    ' Per step start: the state x, y, vx, vy, W, and its derivative.
    Private ReadOnly _times As New List(Of Double)
    Private ReadOnly _states As New List(Of Double())
    Private ReadOnly _slopes As New List(Of Double())
    Private _step As Double

    Friend Sub New(body As Shape, startTime As Double, gravity As Double, forces As ForceField)
        MyBase.New({body}, startTime)
        _body = body
        _forces = forces
        _gravity = gravity
        _offset = body.Outline.Centroid
        Dim y = {body.CentreOfMass.X, body.CentreOfMass.Y, body.Velocity.X, body.Velocity.Y, 0.0}
        _times.Add(startTime)
        _states.Add(y)
        _slopes.Add(Derivative(y))
        ' A first step of a millisecond; the error control corrects it at once.
        _step = 0.001
    End Sub

    ''' <summary>
    ''' The longest next step from state <paramref name="y"/>, s: 10 ms, and with liquids about, the time to move a fifth
    ''' of the body's smaller extent. A liquid acts on a body only while some of it is inside, over a stretch of the
    ''' path as long as the body at least; steps that short put stages inside that stretch, so the error control
    ''' sees the push begin and end, and a body cannot be stepped through the water unpushed.
    ''' </summary>
    Private Function MaxStep(y As Double()) As Double
        Dim longest = MaxStepLength
        If _forces.HasLiquids Then
            Dim speed = Math.Sqrt(y(2) * y(2) + y(3) * y(3))
            Dim o = _body.Outline
            Dim size = Math.Min(o.MaxX - o.MinX, o.MaxY - o.MinY)
            If speed > 0 Then longest = Math.Min(longest, 0.2 * size / speed)
        End If
        Return longest
    End Function

    ''' <summary>dy/dt: the velocity, gravity plus the forces ÷ mass, and the drag's power.</summary>
    Private Function Derivative(y As Double()) As Double()
        Dim velocity As New Vector(y(2), y(3))
        Dim power As Double
        Dim f = _forces.Force(_body, New Vector(y(0), y(1)) - _offset, velocity, power)
        Dim inverseMass = _body.InverseMass
        Return {y(2), y(3), f.X * inverseMass, f.Y * inverseMass - _gravity, power}
    End Function

    ''' <summary>Takes Dormand–Prince steps until the last step ends at or after <paramref name="time"/>.</summary>
    Private Sub ExtendTo(time As Double)
        If Double.IsInfinity(time) Then Throw New ArgumentOutOfRangeException(NameOf(time), "the motion under drag is integrated only to a finite time")
        Do While _times(_times.Count - 1) < time
            If _times.Count > MaxSteps Then Throw New InvalidOperationException($"the drag integrator took more than {MaxSteps} steps from t = {StartTime} s to t = {_times(_times.Count - 1)} s without reaching t = {time} s")
            Dim t = _times(_times.Count - 1)
            Dim y = _states(_states.Count - 1)
            Dim k1 = _slopes(_slopes.Count - 1)
            Do
                Dim h = _step
                Dim next5 As Double() = Nothing, k7 As Double() = Nothing
                Dim worst = DormandPrince.TryStep(AddressOf Derivative, y, k1, h, RelativeTolerance, AbsoluteTolerance, next5, k7)
                ' Never longer than MaxStep: the bounds are read from a whole step's quintic, and a step grown long
                ' over a smooth stretch (a body in free flight far from any liquid) would bound a search of a few
                ' milliseconds by the motion of seconds.
                _step = Math.Min(h * DormandPrince.StepFactor(worst), MaxStep(next5))
                If worst <= 1 Then
                    _times.Add(t + h)
                    _states.Add(next5)
                    _slopes.Add(k7)
                    Exit Do
                End If
                If Not (_step > 0.000000000000001 * Math.Max(1, Math.Abs(t))) Then Throw New InvalidOperationException($"the drag integrator could not keep its error down at t = {t} s")
            Loop
        Loop
    End Sub

    ''' <summary>The step holding <paramref name="time"/> (the last whose start is at or before it).</summary>
    Private Function StepAt(time As Double) As Integer
        ExtendTo(time)
        Return QuinticSteps.StepHolding(_times, time)
    End Function

    ''' <summary>The quintic's coefficients c₀…c₅ in s = (t − tⱼ)/h for coordinate <paramref name="axis"/> (0: x, 1: y) on step j.</summary>
    Private Function Coefficients(j As Integer, axis As Integer) As Double()
        Dim h = _times(j + 1) - _times(j)
        Dim p0 = _states(j)(axis), v0 = _states(j)(2 + axis) * h, a0 = _slopes(j)(2 + axis) * h * h
        Dim p1 = _states(j + 1)(axis), v1 = _states(j + 1)(2 + axis) * h, a1 = _slopes(j + 1)(2 + axis) * h * h
        Return QuinticSteps.Coefficients(p0, v0, a0, p1, v1, a1)
    End Function

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        If time = StartTime Then
            Dim y0 = _states(0)
            position = New Vector(y0(0), y0(1))
            velocity = New Vector(y0(2), y0(3))
            Return
        End If
        Dim j = StepAt(time)
        Dim h = _times(j + 1) - _times(j)
        Dim s = (time - _times(j)) / h
        Dim cx = Coefficients(j, 0), cy = Coefficients(j, 1)
        position = New Vector(Poly(cx, s), Poly(cy, s))
        velocity = New Vector(Slope(cx, s) / h, Slope(cy, s) / h)
    End Sub

    Private Shared Function Poly(c As Double(), s As Double) As Double
        Return c(0) + s * (c(1) + s * (c(2) + s * (c(3) + s * (c(4) + s * c(5)))))
    End Function

    Private Shared Function Slope(c As Double(), s As Double) As Double
        Return c(1) + s * (2 * c(2) + s * (3 * c(3) + s * (4 * c(4) + s * 5 * c(5))))
    End Function

    ''' <summary>|p'| and |p''| bounded on a step by Σ j|cⱼ| and Σ j(j − 1)|cⱼ| (s in [0, 1]), over every step that meets [t0, t1].</summary>
    Private Function Bound(t0 As Double, t1 As Double, order As Integer) As Double
        Dim first = StepAt(Math.Max(t0, StartTime)), last = StepAt(Math.Max(t1, StartTime))
        Dim worst = 0.0
        For j = first To last
            Dim h = _times(j + 1) - _times(j)
            Dim bx = 0.0, by = 0.0
            Dim cx = Coefficients(j, 0), cy = Coefficients(j, 1)
            For p = order To 5
                Dim w = If(order = 1, p, p * (p - 1))
                bx += w * Math.Abs(cx(p))
                by += w * Math.Abs(cy(p))
            Next
            worst = Math.Max(worst, Math.Sqrt(bx * bx + by * by) / Math.Pow(h, order))
        Next
        Return worst * (1 + 0.000000001)
    End Function

    Friend Overrides Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return Bound(t0, t1, 1)
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return Bound(t0, t1, 2)
    End Function

    ' Five-point Gauss–Legendre nodes on [−1, 1] and their weights.
    Private Shared ReadOnly GaussNodes As Double() = {0, -0.538469310105683, 0.538469310105683, -0.906179845938664, 0.906179845938664}
    Private Shared ReadOnly GaussWeights As Double() = {0.568888888888889, 0.478628670499366, 0.478628670499366, 0.236926885056189, 0.236926885056189}

    ''' <summary>
    ''' The energy the drag has removed since the start, J: W at the start of the step holding <paramref name="time"/>,
    ''' plus the drag's power c |v|² integrated along the motion (the quintic) from there, by Gauss–Legendre
    ''' quadrature. Interpolating W itself between the steps' ends (a cubic in W and its rate) was wrong by
    ''' parts in 10⁸ of the energy within a long step; the quadrature follows the very motion the energies are
    ''' read from.
    ''' </summary>
    Friend Function Dissipated(time As Double) As Double Implements IDissipatingMotion.Dissipated
        If time <= StartTime Then Return 0
        Dim j = StepAt(time)
        Dim t0 = _times(j)
        Dim half = 0.5 * (time - t0)
        If half <= 0 Then Return _states(j)(4)
        Dim sum = 0.0
        For q = 0 To GaussNodes.Length - 1
            Dim p As Vector, v As Vector
            StateAt(t0 + half * (1 + GaussNodes(q)), 0, p, v)
            Dim power As Double
            _forces.Force(_body, p - _offset, v, power)
            sum += GaussWeights(q) * power
        Next
        Return _states(j)(4) + half * sum
    End Function
End Class
