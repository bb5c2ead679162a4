Option Strict On

''' <summary>
''' The bodies of a group as they are, before any motion has been chosen for them: what the rule that chooses one
''' reads (their states now) while it works (LinkedEventSolver.Contacts.vb). It is never advanced.
''' </summary>
Friend NotInheritable Class SnapshotMotion
    Inherits LinkedMotion

    Private ReadOnly _p As Vector()
    Private ReadOnly _v As Vector()
    ' Each body's acceleration now from gravity, springs and the forces (m/s²), or Nothing for none known.
    Private ReadOnly _a As Vector()

    ''' <summary>
    ''' The <paramref name="bodies"/>' centres and velocities now, and their <paramref name="accelerations"/> (m/s²,
    ''' from gravity, springs and the forces): whether a touch may last depends on how hard the body is pressed,
    ''' and a spring can press far harder than gravity.
    ''' </summary>
    Friend Sub New(bodies As Shape(), time As Double, Optional accelerations As Vector() = Nothing)
        MyBase.New(bodies, time)
        _p = bodies.Select(Function(b) b.CentreOfMass).ToArray()
        _v = bodies.Select(Function(b) b.Velocity).ToArray()
        _a = accelerations
    End Sub

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        position = _p(k)
        velocity = _v(k)
    End Sub

    Friend Overrides Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return _v(k).Length
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return If(_a Is Nothing, 0, _a(k).Length)
    End Function
End Class
