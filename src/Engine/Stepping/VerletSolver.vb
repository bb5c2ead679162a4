Option Strict On

''' <summary>
''' Position Verlet (Störmer–Verlet in its position form): x_{n+1} = x_n + (x_n − x_{n−1}) + a h², keeping each
''' movable body's previous position (of its reference point) instead of integrating its velocity. The velocity shown is
''' v_{n+1} = (x_{n+1} − x_n)/h + ½ a h, which is the central difference (x_{n+2} − x_n)/(2h) with the
''' x_{n+2} that the next step will produce: second order, and known at the end of the step rather than a
''' step late. Under constant gravity it is exact (a projectile follows s = ut + ½at² to rounding) and it
''' conserves energy. When the step changes (the shortened last step of an advance), the Verlet difference
''' is scaled: x_{n+1} = x_n + (x_n − x_{n−1}) h/h' + a h (h + h')/2, where h' is the previous step.
''' Every outside change (velocity set, impulse, drag, add, g, e, size) re-seeds
''' x_{n−1} = x − v h' + ½ a h'² from the body's velocity, so it takes effect exactly; contacts do the same
''' after moving a body, so the implied velocity is the post-collision one.
''' </summary>
Public NotInheritable Class VerletSolver
    Implements ISolver

    ''' <summary>The default sub-step, s.</summary>
    Public Const DefaultTimeStep As Double = 1.0 / 1000

    ' When a step is this many times longer than the one before, the scaled difference would magnify the
    ' rounding error of a tiny previous step, so the previous position is re-seeded from the velocity instead.
    Private Const MaxStepRatio As Double = 100

    Private ReadOnly _dt As Double
    Private ReadOnly _contacts As New StepContacts()
    ' Previous positions between advances, by body; a body missing here is re-seeded from its velocity.
    Private ReadOnly _previous As New Dictionary(Of Shape, Vector)
    Private _world As World
    Private _hPrevious As Double
    ' Working arrays for one advance, indexed like World.Movables.
    Private _prev As Vector() = Array.Empty(Of Vector)()
    Private _touched As Boolean() = Array.Empty(Of Boolean)()
    Private ReadOnly _links As New LinkStep()
    ' Each movable body's acceleration in the current step, m/s² (used only when the world has links).
    Private _acceleration As Vector() = Array.Empty(Of Vector)()
    ' Drag and buoyancy, read from the world once per advance; Nothing when there are none.
    Private _forces As ForceField
    ' Per body, in the step under way: whether drag is split off for it, and the buoyancy (N) at the step's start.
    Private _dragged As Boolean() = Array.Empty(Of Boolean)()
    Private _lift As Double() = Array.Empty(Of Double)()
    ' Per body: seeded from its velocity at this advance's start (its forces besides gravity not yet known then).
    Private _fresh As Boolean() = Array.Empty(Of Boolean)()
    ' Per body, in the step under way with damped springs: its velocity over the step, then at the step's end, m/s.
    Private _stepVelocity As Vector() = Array.Empty(Of Vector)()

    ''' <param name="timeStep">sub-step, s, &gt; 0</param>
    Public Sub New(Optional timeStep As Double = DefaultTimeStep)
        If Not (timeStep > 0) OrElse Double.IsInfinity(timeStep) Then Throw New ArgumentOutOfRangeException(NameOf(timeStep), "time step must be a finite number greater than 0")
        _dt = timeStep
        _hPrevious = timeStep
        ' A friction impulse acting through a step moves a body ½ (Δv) h, as any force does in Verlet's x += v h + ½ a h².
        _contacts.FrictionShare = 0.5
    End Sub

    ''' <summary>"verlet".</summary>
    Public ReadOnly Property Name As String Implements ISolver.Name
        Get
            Return "verlet"
        End Get
    End Property

    ''' <summary>The longest sub-step, s.</summary>
    Public ReadOnly Property TimeStep As Double? Implements ISolver.TimeStep
        Get
            Return _dt
        End Get
    End Property

    ''' <summary>Called by <see cref="World.Solver"/>; every body is seeded from its velocity.</summary>
    Public Sub Attach(world As World) Implements ISolver.Attach
        _world = world
        _previous.Clear()
        _hPrevious = _dt
    End Sub

    ''' <summary>Forgets the previous position of <paramref name="body"/> (of every body when Nothing), so it is re-seeded from the velocity.</summary>
    Public Sub Invalidate(body As Shape) Implements ISolver.Invalidate
        If body Is Nothing Then
            _previous.Clear()
            Return
        End If
        _previous.Remove(body)
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
        LoadPrevious()
        _links.Prepare(_world)
        _forces = If(_world.HasDragOrLiquids, New ForceField(_world), Nothing)
        _contacts.Prepare(_world)
        Dim n = SubSteps.Count(duration, _dt)
        Dim reached = t0 + duration
        For k = 1L To n
            Dim h = SubSteps.Length(k, n, duration, _dt)
            Dim offset = SubSteps.EndOffset(k, n, duration, _dt)
            If h > 0 Then
                If _links.HasLinks OrElse _forces IsNot Nothing Then
                    IntegrateLinked(h, duration - offset + h)
                    _links.Constrain(h, _world.Restitution, _world.Movables, _touched)
                    _world.Dissipate(_links.SnapLoss)
                    _contacts.Resolve(_world, t0 + offset, h, _touched)
                    ReseedTouchedLinked(h)
                Else
                    Integrate(h, duration - offset + h)
                    _contacts.Resolve(_world, t0 + offset, h, _touched)
                    ReseedTouched(h)
                End If
                _hPrevious = h
            End If
            If k < n AndAlso Diagnostics.Stopwatch.GetTimestamp() > deadline Then
                reached = t0 + offset
                Exit For
            End If
        Next
        SavePrevious()
        Return reached
    End Function

    ''' <summary>One Verlet step of h s for every movable body.</summary>
    Private Sub Integrate(h As Double, remaining As Double)
        Dim bodies = _world.Movables
        Dim dragged = _world.DraggedBody
        Dim a = New Vector(0, -_world.Gravity)
        If h > _hPrevious * MaxStepRatio Then
            For i = 0 To bodies.Count - 1
                _prev(i) = Seed(bodies(i), h)
            Next
            _hPrevious = h
        End If
        Dim ratio = h / _hPrevious
        Dim kick = a * (h * (h + _hPrevious) / 2)
        Dim halfAh = a * (h / 2)
        For i = 0 To bodies.Count - 1
            Dim c = bodies(i)
            _touched(i) = False
            If c Is dragged Then
                DragStep.Move(_world, c, h, remaining)
                _touched(i) = True
                Continue For
            End If
            Dim x = c.Position
            Dim xNext = x + (x - _prev(i)) * ratio + kick
            _prev(i) = x
            c.Position = xNext
            c.Velocity = (xNext - x) / h + halfAh
        Next
    End Sub

    ''' <summary>
    ''' As <see cref="Integrate"/>, with each body's own acceleration: gravity plus its springs' elastic pull and
    ''' buoyancy divided by its mass, read from the positions at the start of the step (Störmer–Verlet with
    ''' forces that depend on position, still symplectic for springs and buoyancy). Drag, −c v, is split off
    ''' (Strang splitting): half a step of it alone, v × e^(−c h/(2m)), which is exact for −c v and can only slow
    ''' the body however strong the drag, then the Verlet step, then the other half. Second order, like the rest.
    ''' The kinetic energy each half takes is added to <see cref="World.Dissipated"/>. The springs' damping is taken
    ''' at the new velocities (<see cref="LinkStep.Damp"/>): on the step's velocity (x_{n+1} − x_n)/h, once the
    ''' other forces have kicked it, and on the velocity shown at the step's end, over its half step. So a light
    ''' body on a strongly damped spring (c h (1/m_A + 1/m_B) ≫ 1) creeps as it should instead of oscillating ever
    ''' faster, to infinity. What the damping takes is booked from the stretch rates at the step's start
    ''' (<see cref="LinkStep.DampingLoss"/>).
    ''' </summary>
    Private Sub IntegrateLinked(h As Double, remaining As Double)
        Dim bodies = _world.Movables
        Dim dragged = _world.DraggedBody
        If _acceleration.Length < bodies.Count Then
            _acceleration = New Vector(bodies.Count - 1) {}
            _stepVelocity = New Vector(bodies.Count - 1) {}
        End If
        Dim gravity = New Vector(0, -_world.Gravity)
        For i = 0 To bodies.Count - 1
            _acceleration(i) = gravity
        Next
        _links.AddAccelerations(_acceleration)
        ' What the springs' damping takes over the step, from the stretch rates at its start.
        _world.Dissipate(_links.DampingLoss(h))
        If _dragged.Length < bodies.Count Then
            _dragged = New Boolean(bodies.Count - 1) {}
            _lift = New Double(bodies.Count - 1) {}
        End If
        Array.Clear(_dragged, 0, bodies.Count)
        If _forces IsNot Nothing Then AddForces(h)
        If h > _hPrevious * MaxStepRatio Then
            For i = 0 To bodies.Count - 1
                _prev(i) = SeedWith(bodies(i), h, _acceleration(i))
            Next
            _hPrevious = h
        End If
        Dim ratio = h / _hPrevious
        Dim kickFactor = h * (h + _hPrevious) / 2
        Dim damped = _links.HasDamping
        If damped Then
            ' The step's velocity as the position formula gives it, then damped over the kick's span, (h + h')/2.
            For i = 0 To bodies.Count - 1
                Dim x = bodies(i).Position
                _stepVelocity(i) = ((x - _prev(i)) * ratio + _acceleration(i) * kickFactor) / h
            Next
            _links.Damp(kickFactor / h, _stepVelocity)
        End If
        For i = 0 To bodies.Count - 1
            Dim c = bodies(i)
            _touched(i) = False
            If c Is dragged Then
                DragStep.Move(_world, c, h, remaining)
                _touched(i) = True
                Continue For
            End If
            Dim a = _acceleration(i)
            Dim x = c.Position
            Dim xNext = If(damped, x + _stepVelocity(i) * h, x + (x - _prev(i)) * ratio + a * kickFactor)
            _prev(i) = x
            c.Position = xNext
            c.Velocity = (xNext - x) / h + a * (h / 2)
            If _dragged(i) Then FinishDragStep(c, i, h)
        Next
        If damped Then
            ' The velocity shown at the step's end: the step's, kicked over half a step, damped over the same half.
            For i = 0 To bodies.Count - 1
                _stepVelocity(i) = bodies(i).Velocity
            Next
            _links.Damp(h / 2, _stepVelocity)
            For i = 0 To bodies.Count - 1
                If bodies(i) IsNot dragged Then bodies(i).Velocity = _stepVelocity(i)
            Next
        End If
        Array.Clear(_fresh, 0, bodies.Count)
    End Sub

    ''' <summary>
    ''' The end of a step of a body whose drag is split off: its velocity as velocity Verlet gives it (the average of
    ''' buoyancy at the two ends of the step, which the position formula took at the start only), then the second
    ''' half-step of drag. Its history is re-seeded from the velocity it leaves.
    ''' </summary>
    Private Sub FinishDragStep(c As Shape, i As Integer, h As Double)
        Dim resistance As Double, lift As Double
        _forces.Evaluate(c, c.Position, c.Velocity, resistance, lift)
        c.Velocity += New Vector(0, 0.5 * (lift - _lift(i)) * c.InverseMass * h)
        Slow(c, DragFactor(c, h))
        _touched(i) = True
    End Sub

    ''' <summary>
    ''' The factor by which half a step of drag alone slows a body: e^(−c h/(2m)), with c taken at the middle of that half
    ''' (midpoint rule; c grows with speed for quadratic drag), so each half, and the whole split step, is second order.
    ''' </summary>
    Private Function DragFactor(body As Shape, h As Double) As Double
        Dim resistance As Double, lift As Double
        _forces.Evaluate(body, body.Position, body.Velocity, resistance, lift)
        Dim quarter = Math.Exp(-0.25 * resistance * body.InverseMass * h)
        _forces.Evaluate(body, body.Position, body.Velocity * quarter, resistance, lift)
        Return Math.Exp(-0.5 * resistance * body.InverseMass * h)
    End Function

    ''' <summary>Multiplies a body's velocity by <paramref name="factor"/> (≤ 1), adding the kinetic energy that takes to <see cref="World.Dissipated"/>.</summary>
    Private Sub Slow(body As Shape, factor As Double)
        Dim v = body.Velocity
        body.Velocity = v * factor
        _world.Dissipate(0.5 * body.Mass * v.LengthSquared * (1 - factor * factor))
    End Sub

    ''' <summary>
    ''' Adds buoyancy ÷ mass to each movable body's acceleration of this step (the dragged body aside). A body that
    ''' some drag can act on takes its first half-step of drag, and its previous position is re-seeded to match; a
    ''' body seeded at this advance's start from gravity alone is re-seeded with its whole acceleration.
    ''' </summary>
    Private Sub AddForces(h As Double)
        Dim bodies = _world.Movables
        Dim dragged = _world.DraggedBody
        For i = 0 To bodies.Count - 1
            Dim b = bodies(i)
            If b Is dragged OrElse Not _forces.Acts(b) Then Continue For
            Dim resistance As Double, lift As Double
            _forces.Evaluate(b, b.Position, b.Velocity, resistance, lift)
            _acceleration(i) += New Vector(0, lift * b.InverseMass)
            _lift(i) = lift
            If _forces.CanDrag(b) Then
                _dragged(i) = True
                Slow(b, DragFactor(b, h))
                _prev(i) = SeedWith(b, _hPrevious, _acceleration(i))
            ElseIf _fresh(i) Then
                _prev(i) = SeedWith(b, _hPrevious, _acceleration(i))
            End If
        Next
    End Sub

    ''' <summary>As <see cref="ReseedTouched"/>, with each body's acceleration of this step.</summary>
    Private Sub ReseedTouchedLinked(h As Double)
        Dim bodies = _world.Movables
        For i = 0 To bodies.Count - 1
            If _touched(i) Then _prev(i) = SeedWith(bodies(i), h, _acceleration(i))
        Next
    End Sub

    ''' <summary>The previous position, a step of h s ago, that makes the Verlet velocity equal the body's velocity now under acceleration <paramref name="a"/> (m/s²).</summary>
    Private Shared Function SeedWith(c As Shape, h As Double, a As Vector) As Vector
        Return c.Position - c.Velocity * h + a * (h * h / 2)
    End Function

    ''' <summary>After contacts moved or pushed some bodies: make x_prev imply the velocity they now have.</summary>
    Private Sub ReseedTouched(h As Double)
        Dim bodies = _world.Movables
        For i = 0 To bodies.Count - 1
            If _touched(i) Then _prev(i) = Seed(bodies(i), h)
        Next
    End Sub

    ''' <summary>The previous position, a step of h s ago, that makes the Verlet velocity equal the body's velocity now.</summary>
    Private Function Seed(c As Shape, h As Double) As Vector
        ' From v = (x − x_prev)/h + ½ a h, solved for x_prev; exact for motion under constant gravity.
        Return c.Position - c.Velocity * h + New Vector(0, -_world.Gravity) * (h * h / 2)
    End Function

    Private Sub LoadPrevious()
        Dim bodies = _world.Movables
        If _prev.Length < bodies.Count Then
            _prev = New Vector(bodies.Count - 1) {}
            _touched = New Boolean(bodies.Count - 1) {}
            _fresh = New Boolean(bodies.Count - 1) {}
        End If
        For i = 0 To bodies.Count - 1
            Dim c = bodies(i)
            Dim p As Vector
            _fresh(i) = Not _previous.TryGetValue(c, p)
            _prev(i) = If(_fresh(i), Seed(c, _hPrevious), p)
        Next
    End Sub

    Private Sub SavePrevious()
        _previous.Clear()
        Dim bodies = _world.Movables
        For i = 0 To bodies.Count - 1
            _previous(bodies(i)) = _prev(i)
        Next
    End Sub
End Class
