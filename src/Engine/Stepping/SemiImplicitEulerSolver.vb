Option Strict On

''' <summary>
''' The textbook game-engine algorithm, kept as the baseline: semi-implicit (symplectic) Euler (v += a dt, then x += v dt with the
''' new v) in fixed sub-steps, then static resolution (push overlapping bodies apart) and dynamic
''' resolution (an impulse along the normal), for bodies of every shape. Collisions are found after the
''' fact, so a ball that moves more than its diameter in one step can pass through another movable body
''' unseen (never through a fixed one: a body whose path crossed into one is sent back out the side it
''' came in by). First order: position and
''' velocity errors shrink in proportion to dt; in free flight it loses ½ g² dt² of energy per unit mass
''' per step, so it never gains energy.
''' </summary>
Public NotInheritable Class SemiImplicitEulerSolver
    Implements ISolver

    ''' <summary>The default sub-step, s.</summary>
    Public Const DefaultTimeStep As Double = 1.0 / 1000

    Private ReadOnly _dt As Double
    Private ReadOnly _contacts As New StepContacts()
    Private ReadOnly _links As New LinkStep()
    ' Each movable body's acceleration in the current step, m/s² (used only when the world has links).
    Private _acceleration As Vector() = Array.Empty(Of Vector)()
    ' Each movable body's new velocity in the current step, m/s (used only when the world has links).
    Private _velocity As Vector() = Array.Empty(Of Vector)()
    ' Drag and buoyancy, read from the world once per advance; Nothing when there are none.
    Private _forces As ForceField
    Private _world As World

    ''' <param name="timeStep">sub-step, s, &gt; 0</param>
    Public Sub New(Optional timeStep As Double = DefaultTimeStep)
        If Not (timeStep > 0) OrElse Double.IsInfinity(timeStep) Then Throw New ArgumentOutOfRangeException(NameOf(timeStep), "time step must be a finite number greater than 0")
        _dt = timeStep
    End Sub

    ''' <summary>"euler".</summary>
    Public ReadOnly Property Name As String Implements ISolver.Name
        Get
            Return "euler"
        End Get
    End Property

    ''' <summary>The longest sub-step, s.</summary>
    Public ReadOnly Property TimeStep As Double? Implements ISolver.TimeStep
        Get
            Return _dt
        End Get
    End Property

    ''' <summary>Called by <see cref="World.Solver"/>.</summary>
    Public Sub Attach(world As World) Implements ISolver.Attach
        _world = world
    End Sub

    ''' <summary>Nothing to do: the state is the bodies' own positions and velocities, and nothing is predicted.</summary>
    Public Sub Invalidate(body As Shape) Implements ISolver.Invalidate
    End Sub

    ''' <summary>Advances by exactly <paramref name="duration"/> s in steps of at most <see cref="TimeStep"/>.</summary>
    Public Sub Advance(duration As Double) Implements ISolver.Advance
        AdvanceWithin(duration, Long.MaxValue)
    End Sub

    ''' <summary>As <see cref="Advance"/>, stopping after the first whole sub-step that ends past <paramref name="deadline"/> (Stopwatch ticks).</summary>
    Public Function AdvanceWithin(duration As Double, deadline As Long) As Double Implements ISolver.AdvanceWithin
        If _world Is Nothing Then Throw New InvalidOperationException("the solver is not attached to a world")
        Dim t0 = _world.Time
        If Not (duration > 0) Then Return t0
        _links.Prepare(_world)
        _forces = If(_world.HasDragOrLiquids, New ForceField(_world), Nothing)
        _contacts.Prepare(_world)
        Dim n = SubSteps.Count(duration, _dt)
        For k = 1L To n
            Dim h = SubSteps.Length(k, n, duration, _dt)
            Dim offset = SubSteps.EndOffset(k, n, duration, _dt)
            If _links.HasLinks OrElse _forces IsNot Nothing Then
                IntegrateLinked(h, duration - offset + h)
                _links.Constrain(h, _world.Restitution, _world.Movables, Nothing)
                _world.Dissipate(_links.SnapLoss)
            Else
                Integrate(h, duration - offset + h)
            End If
            _contacts.Resolve(_world, t0 + offset, h, Nothing)
            If k < n AndAlso Diagnostics.Stopwatch.GetTimestamp() > deadline Then Return t0 + offset
        Next
        Return t0 + duration
    End Function

    ''' <summary>One step of h s for every movable body: v += a h, then x += v h (the new v, which is what makes it semi-implicit and stable).</summary>
    Private Sub Integrate(h As Double, remaining As Double)
        Dim g = _world.Gravity
        Dim dragged = _world.DraggedBody
        For Each b In _world.Movables
            If b Is dragged Then
                DragStep.Move(_world, b, h, remaining)
                Continue For
            End If
            Dim v = New Vector(b.Velocity.X, b.Velocity.Y - g * h)
            b.Velocity = v
            b.Position += v * h
        Next
    End Sub

    ''' <summary>
    ''' As <see cref="Integrate"/>, with each spring's elastic pull (from the positions at the start of the step)
    ''' and buoyancy added to gravity: v += (g + F/m) h, then x += v h. Drag, −c v, is taken at the new velocity
    ''' (v' = (v + a h)/(1 + c h/m)), so that even a drag far too strong for the step (c h/m ≫ 1: a small ball in
    ''' syrup) only slows the body, as it should, instead of reversing it a little more every step; the energy it
    ''' takes, c |v'|² h, is added to <see cref="World.Dissipated"/>. The springs' damping is taken at the new
    ''' velocities the same way (<see cref="LinkStep.Damp"/>), before the bodies move, for the same reason: a light
    ''' body on a strongly damped spring (c h (1/m_A + 1/m_B) ≫ 1) creeps as it should instead of oscillating ever
    ''' faster, to infinity. What it takes is booked from the stretch rates at the step's start
    ''' (<see cref="LinkStep.DampingLoss"/>).
    ''' </summary>
    Private Sub IntegrateLinked(h As Double, remaining As Double)
        Dim bodies = _world.Movables
        If _acceleration.Length < bodies.Count Then
            _acceleration = New Vector(bodies.Count - 1) {}
            _velocity = New Vector(bodies.Count - 1) {}
        End If
        Dim gravity = New Vector(0, -_world.Gravity)
        For i = 0 To bodies.Count - 1
            _acceleration(i) = gravity
        Next
        _links.AddAccelerations(_acceleration)
        ' What the springs' damping takes over the step, from the stretch rates at its start.
        _world.Dissipate(_links.DampingLoss(h))
        Dim dragged = _world.DraggedBody
        For i = 0 To bodies.Count - 1
            Dim b = bodies(i)
            If b Is dragged Then Continue For
            Dim v = b.Velocity + _acceleration(i) * h
            If _forces IsNot Nothing AndAlso _forces.Acts(b) Then
                Dim resistance As Double, lift As Double
                _forces.Evaluate(b, b.Position, b.Velocity, resistance, lift)
                v = New Vector(v.X, v.Y + lift * b.InverseMass * h) / (1 + resistance * b.InverseMass * h)
                _world.Dissipate(resistance * v.LengthSquared * h)
            End If
            _velocity(i) = v
        Next
        _links.Damp(h, _velocity)
        For i = 0 To bodies.Count - 1
            Dim b = bodies(i)
            If b Is dragged Then
                DragStep.Move(_world, b, h, remaining)
                Continue For
            End If
            b.Velocity = _velocity(i)
            b.Position += _velocity(i) * h
        Next
    End Sub
End Class
