Option Strict On

''' <summary>
''' The seed's algorithm, kept as the baseline: semi-implicit Euler (v += a dt, then x += v dt) in
''' fixed sub-steps, then static resolution (push overlapping bodies apart) and dynamic resolution
''' (an impulse along the normal). Collisions are detected after the fact, so a fast ball can tunnel.
''' </summary>
Public NotInheritable Class SemiImplicitEulerSolver
    Implements ISolver

    ''' <summary>The default sub-step, s.</summary>
    Public Const DefaultTimeStep As Double = 1.0 / 1000

    Private ReadOnly _dt As Double
    Private _world As World

    ''' <param name="timeStep">sub-step, s, &gt; 0</param>
    Public Sub New(Optional timeStep As Double = DefaultTimeStep)
        If Not (timeStep > 0) OrElse Double.IsInfinity(timeStep) Then Throw New ArgumentOutOfRangeException(NameOf(timeStep), "time step must be a finite number greater than 0")
        _dt = timeStep
    End Sub

    Public ReadOnly Property Name As String Implements ISolver.Name
        Get
            Return "euler"
        End Get
    End Property

    Public ReadOnly Property TimeStep As Double? Implements ISolver.TimeStep
        Get
            Return _dt
        End Get
    End Property

    Public Sub Attach(world As World) Implements ISolver.Attach
        _world = world
    End Sub

    Public Sub Invalidate(body As Shape) Implements ISolver.Invalidate
        ' Nothing is predicted, so nothing goes stale.
    End Sub

    Public Sub Advance(duration As Double) Implements ISolver.Advance
        Dim done = 0.0
        Dim t0 = _world.Time
        Do While done < duration
            Dim h = Math.Min(_dt, duration - done)
            If duration - (done + h) < _dt * 1.0E-9 Then h = duration - done
            StepOnce(h, t0 + done + h)
            done += h
        Loop
    End Sub

    Private Sub StepOnce(h As Double, tEnd As Double)
        Integrate(h)
        StepContacts.Resolve(_world, tEnd)
    End Sub

    Private Sub Integrate(h As Double)
        Dim g = _world.Gravity
        Dim dragged = _world.DraggedCircle
        For Each c In _world.Circles
            If c.IsFixed Then Continue For
            If c Is dragged Then
                DragStep.Move(_world, c, h)
                Continue For
            End If
            c.Velocity = New Vector(c.Velocity.X, c.Velocity.Y - g * h)
            c.Position += c.Velocity * h
        Next
    End Sub
End Class
