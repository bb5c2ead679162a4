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

    Private ReadOnly _links As Link()
    Private ReadOnly _gravity As Double
    Private ReadOnly _n As Integer
    ' Drag and buoyancy on the bodies (docs/forces.md), or Nothing.
    Private ReadOnly _forces As ForceField
    ' Per body x, y, vx, vy (m, m/s), integrated.
    Private ReadOnly _path As QuinticTrajectory
    ' The stretch looked at so far: the contact searches stop at its end, so that a stiff spring's group, made anew
    ' at each collision, is integrated only as far as the next one needs.
    Private ReadOnly _lookahead As Lookahead

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
        ' The fastest spring's angular frequency (rad/s), for the first step.
        Dim fastest = 0.0
        For Each l In links
            For Each b In bodies
                If l.A Is b OrElse l.B Is b Then fastest = Math.Max(fastest, Math.Sqrt(l.Stiffness / b.Mass))
            Next
        Next
        Dim firstStepSeconds = Lookahead.FirstStepSeconds(fastest)
        _lookahead = New Lookahead(startTime, firstStepSeconds)
        _path = New QuinticTrajectory("the spring integrator", AddressOf Derivative, y, startTime, firstStepSeconds, RelativeTolerance, AbsoluteTolerance,
                                      rounding:=AddressOf Rounding)
    End Sub

    ''' <summary>The end of the stretch looked at so far: nothing happens there but looking further.</summary>
    Friend Overrides ReadOnly Property TransitionTime As Double
        Get
            Return _lookahead.EndTimeSeconds
        End Get
    End Property

    ''' <summary>Looks twice as far from the start (<see cref="Lookahead.LookFurther"/>) and goes on as it was.</summary>
    Friend Overrides Function LookFurther(time As Double) As Boolean
        _lookahead.LookFurther(time)
        Return True
    End Function

    ''' <summary>How far each component of dy/dt may be off by rounding alone at state <paramref name="y"/>: the springs' (<see cref="SpringTerm.AddRounding"/>).</summary>
    Private Function Rounding(y As Double()) As Double()
        Dim r(4 * _n - 1) As Double
        SpringTerm.AddRounding(_links, Bodies, y, r)
        Return r
    End Function

    ''' <summary>dy/dt: velocities, and gravity plus every spring's pull ÷ mass.</summary>
    Private Function Derivative(y As Double()) As Double()
        Dim d(4 * _n - 1) As Double
        For k = 0 To _n - 1
            d(4 * k) = y(4 * k + 2)
            d(4 * k + 1) = y(4 * k + 3)
            d(4 * k + 3) = -_gravity
        Next
        SpringTerm.Add(_links, Bodies, y, d)
        If _forces IsNot Nothing Then BodyForceTerm.Add(_forces, Bodies, y, d)
        Return d
    End Function

    Friend Overrides ReadOnly Property StepsTaken As Integer
        Get
            Return _path.StepCount
        End Get
    End Property

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        _path.StateAt(time, k, position, velocity)
    End Sub

    Friend Overrides Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return _path.Bound(k, t0, t1, 1)
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return _path.Bound(k, t0, t1, 2)
    End Function
End Class
