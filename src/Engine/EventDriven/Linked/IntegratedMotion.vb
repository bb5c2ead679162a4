Option Strict On

''' <summary>
''' A group of bodies joined by springs that no closed form fits (a spring swinging at an angle, two bodies
''' on a spring, a chain of springs): integrated by the Dormand–Prince 5(4) pair, whose embedded fourth-order
''' result estimates each step's error, so the step is chosen to keep it below 10⁻¹¹ of the state. Between
''' steps the motion is the quintic through each step's ends that matches position, velocity and
''' acceleration there (error of order h⁶), and that quintic is the motion: contacts are found on it, and
''' the bounds on speed and acceleration that conservative advancement needs come from its coefficients.
''' Steps are taken lazily, as far as anything asks.
''' </summary>
Friend NotInheritable Class IntegratedMotion
    Inherits LinkedMotion

    Private Const RelativeTolerance As Double = 0.000000000003
    Private Const AbsoluteTolerance As Double = 0.0000000000003
    ' Steps kept from one start at most: far more than any advance needs, far less than the memory holds.
    Private Const MaxSteps As Integer = 2000000

    Private ReadOnly _links As Link()
    Private ReadOnly _gravity As Double
    Private ReadOnly _n As Integer
    ' The state at each step's start: per body x, y, vx, vy; and the accelerations there.
    Private ReadOnly _times As New List(Of Double)
    Private ReadOnly _states As New List(Of Double())
    Private ReadOnly _accelerations As New List(Of Double())
    Private _step As Double
    ' Drag and buoyancy on the bodies (docs/forces.md), or Nothing.
    Private ReadOnly _forces As ForceField

    Friend Sub New(bodies As Shape(), links As List(Of Link), startTime As Double, gravity As Double, Optional forces As ForceField = Nothing)
        MyBase.New(bodies, startTime)
        _forces = forces
        _links = links.ToArray()
        _gravity = gravity
        _n = bodies.Length
        Dim y(4 * _n - 1) As Double
        For k = 0 To _n - 1
            y(4 * k) = bodies(k).CentreOfMass.X
            y(4 * k + 1) = bodies(k).CentreOfMass.Y
            y(4 * k + 2) = bodies(k).Velocity.X
            y(4 * k + 3) = bodies(k).Velocity.Y
        Next
        _times.Add(startTime)
        _states.Add(y)
        _accelerations.Add(Derivative(y))
        ' A first step of a hundredth of the fastest spring's period; the error control corrects it at once.
        Dim fastest = 0.0
        For Each l In links
            For Each b In bodies
                If l.A Is b OrElse l.B Is b Then fastest = Math.Max(fastest, Math.Sqrt(l.Stiffness / b.Mass))
            Next
        Next
        _step = If(fastest > 0, 0.06 / fastest, 0.001)
    End Sub

    ''' <summary>dy/dt: velocities, and gravity plus every spring's pull ÷ mass.</summary>
    Private Function Derivative(y As Double()) As Double()
        Dim d(4 * _n - 1) As Double
        For k = 0 To _n - 1
            d(4 * k) = y(4 * k + 2)
            d(4 * k + 1) = y(4 * k + 3)
            d(4 * k + 3) = -_gravity
        Next
        For Each l In _links
            Dim a = Array.IndexOf(Bodies, l.A)
            Dim b = If(l.B Is Nothing, -1, Array.IndexOf(Bodies, l.B))
            Dim pa As New Vector(y(4 * a), y(4 * a + 1)), va As New Vector(y(4 * a + 2), y(4 * a + 3))
            Dim pb = If(b >= 0, New Vector(y(4 * b), y(4 * b + 1)), l.EndB)
            Dim vb = If(b >= 0, New Vector(y(4 * b + 2), y(4 * b + 3)), Vector.Zero)
            Dim r = pb - pa
            Dim dist = r.Length
            If dist = 0 Then Continue For
            ' (k(d − L) + c ḋ)/d along r pulls A towards B.
            Dim force = r * ((l.Stiffness * (dist - l.Length) + l.Damping * Vector.Dot(vb - va, r) / dist) / dist)
            Dim fa = force * Bodies(a).InverseMass
            d(4 * a + 2) += fa.X
            d(4 * a + 3) += fa.Y
            If b >= 0 Then
                Dim fb = force * Bodies(b).InverseMass
                d(4 * b + 2) -= fb.X
                d(4 * b + 3) -= fb.Y
            End If
        Next
        If _forces IsNot Nothing Then BodyForceTerm.Add(_forces, Bodies, y, d)
        Return d
    End Function

    ''' <summary>Takes Dormand–Prince steps until the last step ends at or after <paramref name="time"/>.</summary>
    Private Sub ExtendTo(time As Double)
        If Double.IsInfinity(time) Then Throw New ArgumentOutOfRangeException(NameOf(time), "the springs' motion is integrated only to a finite time")
        Do While _times(_times.Count - 1) < time
            If _times.Count > MaxSteps Then Throw New InvalidOperationException($"the spring integrator took more than {MaxSteps} steps from t = {StartTime} s to t = {_times(_times.Count - 1)} s without reaching t = {time} s")
            Dim t = _times(_times.Count - 1)
            Dim y = _states(_states.Count - 1)
            Dim k1 = _accelerations(_accelerations.Count - 1)
            Do
                Dim h = _step
                Dim next5 As Double() = Nothing, k7 As Double() = Nothing
                Dim worst = DormandPrince.TryStep(AddressOf Derivative, y, k1, h, RelativeTolerance, AbsoluteTolerance, next5, k7)
                _step = h * DormandPrince.StepFactor(worst)
                If worst <= 1 Then
                    _times.Add(t + h)
                    _states.Add(next5)
                    _accelerations.Add(k7)
                    Exit Do
                End If
                If Not (_step > 0.000000000000001 * Math.Max(1, Math.Abs(t))) Then Throw New InvalidOperationException($"the spring integrator could not keep its error down at t = {t} s")
            Loop
        Loop
    End Sub

    ''' <summary>The step holding <paramref name="time"/> (the last whose start is at or before it).</summary>
    Private Function StepAt(time As Double) As Integer
        ExtendTo(time)
        Return QuinticSteps.StepHolding(_times, time)
    End Function

    ''' <summary>The quintic's coefficients c₀…c₅ in s = (t − tₖ)/h for body k's coordinate (0: x, 1: y) on step j.</summary>
    Private Function Coefficients(j As Integer, k As Integer, axis As Integer) As Double()
        Dim h = _times(j + 1) - _times(j)
        Dim p0 = _states(j)(4 * k + axis), v0 = _states(j)(4 * k + 2 + axis) * h, a0 = _accelerations(j)(4 * k + 2 + axis) * h * h
        Dim p1 = _states(j + 1)(4 * k + axis), v1 = _states(j + 1)(4 * k + 2 + axis) * h, a1 = _accelerations(j + 1)(4 * k + 2 + axis) * h * h
        Return QuinticSteps.Coefficients(p0, v0, a0, p1, v1, a1)
    End Function

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
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

    ''' <summary>|p'| and |p''| bounded on a step by Σ j|cⱼ| and Σ j(j − 1)|cⱼ| (s in [0, 1]), over every step that meets [t0, t1].</summary>
    Private Function Bound(k As Integer, t0 As Double, t1 As Double, order As Integer) As Double
        Dim first = StepAt(t0), last = StepAt(t1)
        Dim worst = 0.0
        For j = first To last
            Dim h = _times(j + 1) - _times(j)
            Dim bx = 0.0, by = 0.0
            Dim cx = Coefficients(j, k, 0), cy = Coefficients(j, k, 1)
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
        Return Bound(k, t0, t1, 1)
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return Bound(k, t0, t1, 2)
    End Function
End Class
