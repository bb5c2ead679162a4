Option Strict On

''' <summary>
''' One body on its parabola, p = p₀ + v₀τ + ½aτ² with a = (0, −g): a free body, or a body on a slack string
''' (then <see cref="LinkedMotion.TransitionTime"/> is when the string snaps taut, a quartic solved by
''' <see cref="StringTaut"/>). A body resting on the floor slides with a = 0.
''' </summary>
Friend NotInheritable Class FlightMotion
    Inherits LinkedMotion

    ' Below this radial speed after a string snaps taut (a fraction of √(gL)), the string stays taut: the
    ' snaps of an inelastic string form a geometric series whose end would otherwise take endless events.
    Private Const SettleFraction As Double = 0.000001

    Private ReadOnly _p0 As Vector
    Private ReadOnly _v0 As Vector
    Private ReadOnly _gravity As Double
    Private ReadOnly _string As Link
    Private ReadOnly _taut As Double = Double.PositiveInfinity

    ''' <summary>A body flying (or sliding, with <paramref name="gravity"/> 0) from its state now; tied by a slack <paramref name="slack"/> string when given.</summary>
    Friend Sub New(body As Shape, startTime As Double, gravity As Double, Optional slack As Link = Nothing, Optional slop As Double = 0)
        MyBase.New({body}, startTime)
        _p0 = body.CentreOfMass
        _v0 = body.Velocity
        _gravity = gravity
        _string = slack
        If slack IsNot Nothing Then _taut = startTime + StringTaut.AnchoredTautTime(slack.EndB, slack.Length, _p0, _v0, gravity, slop)
    End Sub

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        Dim tau = time - StartTime
        position = New Vector(_p0.X + _v0.X * tau, _p0.Y + (_v0.Y - 0.5 * _gravity * tau) * tau)
        velocity = New Vector(_v0.X, _v0.Y - _gravity * tau)
    End Sub

    ''' <summary>Its downward acceleration, m/s² (g in flight, 0 resting on the floor).</summary>
    Friend ReadOnly Property Gravity As Double
        Get
            Return _gravity
        End Get
    End Property

    ''' <summary>
    ''' Bounds on the relative motion of two bodies each on its parabola over [<paramref name="t0"/>, <paramref name="t1"/>]:
    ''' their relative velocity changes at the constant rate of the difference of their accelerations, so its
    ''' size (convex in time) is largest at an end, and the relative acceleration is that difference (0 for two
    ''' bodies in flight under the same g). Much tighter than the sum of the two bodies' own bounds.
    ''' </summary>
    Friend Shared Sub RelativeBounds(a As FlightMotion, b As FlightMotion, t0 As Double, t1 As Double, ByRef speed As Double, ByRef acceleration As Double)
        Dim p As Vector, va0 As Vector, va1 As Vector, vb0 As Vector, vb1 As Vector
        a.StateAt(t0, 0, p, va0)
        a.StateAt(t1, 0, p, va1)
        b.StateAt(t0, 0, p, vb0)
        b.StateAt(t1, 0, p, vb1)
        speed = Math.Max((va0 - vb0).Length, (va1 - vb1).Length) * (1 + 0.000000001)
        acceleration = Math.Abs(a._gravity - b._gravity)
    End Sub

    Friend Overrides Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double
        ' |v| is convex in time on a parabola: its largest value is at an end.
        Dim p As Vector, a As Vector, b As Vector
        StateAt(t0, 0, p, a)
        StateAt(t1, 0, p, b)
        Return Math.Max(a.Length, b.Length)
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return _gravity
    End Function

    Friend Overrides ReadOnly Property TransitionTime As Double
        Get
            Return _taut
        End Get
    End Property

    ''' <summary>
    ''' The string snaps taut: like a collision with the anchor along the string, the speed outwards
    ''' becomes e times as much inwards; the speed across the string is kept.
    ''' </summary>
    Friend Overrides Function Transition(world As World) As Boolean
        If _string Is Nothing Then Return False
        Dim body = Bodies(0)
        Dim n = (body.CentreOfMass - _string.EndB).Normalized(Vector.Zero)
        Dim outwards = Vector.Dot(body.Velocity, n)
        If outwards <= 0 Then Return False
        Dim after = world.Restitution * outwards
        If after < SettleFraction * Math.Sqrt(Math.Max(world.Gravity, 0.000001) * _string.Length) Then after = 0
        body.Velocity -= n * (outwards + after)
        Return after > 0
    End Function

    Friend Overrides Sub UpdateTensions(time As Double)
        _string?.SetTension(0)
    End Sub
End Class
