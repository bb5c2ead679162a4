Option Strict On

''' <summary>
''' One free body under gravity, drag and buoyancy (<see cref="ForceField"/>) where no closed form fits: quadratic
''' drag, or anything in a world with liquids (a body may fly into one). Integrated as the springs are
''' (<see cref="QuinticTrajectory"/>, docs/links.md section 4): the Dormand–Prince 5(4) pair with its error kept
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
    ' The longest step, s: about the linked solver's search horizon.
    Private Const MaxStepLength As Double = 0.01

    Private ReadOnly _forces As ForceField
    Private ReadOnly _gravity As Double
    Private ReadOnly _body As Shape
    ' The centre of mass less the reference point, m: the forces are worked out where the outline is.
    Private ReadOnly _offset As Vector
    ' The state x, y, vx, vy (m, m/s) and W (J), integrated.
    Private ReadOnly _path As QuinticTrajectory

    Friend Sub New(body As Shape, startTime As Double, gravity As Double, forces As ForceField)
        MyBase.New({body}, startTime)
        _body = body
        _forces = forces
        _gravity = gravity
        _offset = body.Outline.Centroid
        Dim y = {body.CentreOfMass.X, body.CentreOfMass.Y, body.Velocity.X, body.Velocity.Y, 0.0}
        ' A first step of a millisecond; the error control corrects it at once.
        _path = New QuinticTrajectory("the drag integrator", AddressOf Derivative, y, startTime, 0.001, RelativeTolerance, AbsoluteTolerance, AddressOf MaxStep)
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

    Friend Overrides ReadOnly Property StepsTaken As Integer
        Get
            Return _path.StepCount
        End Get
    End Property

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        _path.StateAt(time, 0, position, velocity)
    End Sub

    Friend Overrides Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return _path.Bound(0, t0, t1, 1)
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return _path.Bound(0, t0, t1, 2)
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
        Dim j = _path.StepAt(time)
        Dim t0 = _path.TimeOf(j)
        Dim half = 0.5 * (time - t0)
        If half <= 0 Then Return _path.StateOf(j)(4)
        Dim sum = 0.0
        For q = 0 To GaussNodes.Length - 1
            Dim p As Vector, v As Vector
            StateAt(t0 + half * (1 + GaussNodes(q)), 0, p, v)
            Dim power As Double
            _forces.Force(_body, p - _offset, v, power)
            sum += GaussWeights(q) * power
        Next
        Return _path.StateOf(j)(4) + half * sum
    End Function
End Class
