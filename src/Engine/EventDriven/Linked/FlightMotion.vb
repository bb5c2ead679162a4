Option Strict On

''' <summary>
''' One body on its parabola, p = p₀ + v₀τ + ½aτ² with a = (0, −g): a free body, or a body on a slack string
''' (then <see cref="LinkedMotion.TransitionTime"/> is when the string snaps taut, a quartic solved by
''' <see cref="StringTaut"/>). A body resting on a support slides along it: on a level face with a = 0, down
''' a slope with gravity's part along it (<see cref="RestingFaces.SlideAcceleration"/>), until it leaves the
''' face's end (<see cref="LinkedMotion.TransitionTime"/>).
''' </summary>
Friend NotInheritable Class FlightMotion
    Inherits LinkedMotion

    ' Below this radial speed after a string snaps taut (a fraction of √(gL)), the string stays taut: the
    ' snaps of an inelastic string form a geometric series whose end would otherwise take endless events.
    Private Const SettleFraction As Double = 0.000001

    Private ReadOnly _p0 As Vector
    Private ReadOnly _v0 As Vector
    Private ReadOnly _acceleration As Vector
    Private ReadOnly _string As Link
    Private ReadOnly _taut As Double = Double.PositiveInfinity
    Private ReadOnly _leaves As Double = Double.PositiveInfinity

    ''' <summary>A body flying (or sliding on a level face, with <paramref name="gravity"/> 0) from its state now; tied by a slack <paramref name="slack"/> string when given.</summary>
    Friend Sub New(body As Shape, startTime As Double, gravity As Double, Optional slack As Link = Nothing, Optional slop As Double = 0)
        Me.New(body, startTime, New Vector(0, -gravity), Double.PositiveInfinity, slack, slop)
    End Sub

    ''' <summary>
    ''' A body sliding from its state now with the constant <paramref name="acceleration"/> (m/s²) until
    ''' <paramref name="leaves"/> (s, absolute; +∞ for never). A slack string it is tied by must see a vertical
    ''' acceleration (the quartic of <see cref="StringTaut"/> knows no other).
    ''' </summary>
    Friend Sub New(body As Shape, startTime As Double, acceleration As Vector, leaves As Double, Optional slack As Link = Nothing, Optional slop As Double = 0)
        MyBase.New({body}, startTime)
        _p0 = body.CentreOfMass
        _v0 = body.Velocity
        _acceleration = acceleration
        _string = slack
        _leaves = leaves
        If slack IsNot Nothing Then _taut = startTime + StringTaut.AnchoredTautTime(slack.EndB, slack.Length, _p0, _v0, -acceleration.Y, slop)
    End Sub

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        Dim tau = time - StartTime
        position = New Vector(_p0.X + (_v0.X + 0.5 * _acceleration.X * tau) * tau, _p0.Y + (_v0.Y + 0.5 * _acceleration.Y * tau) * tau)
        velocity = New Vector(_v0.X + _acceleration.X * tau, _v0.Y + _acceleration.Y * tau)
    End Sub

    Friend Overrides Function Parabola(k As Integer, time As Double, ByRef position As Vector, ByRef velocity As Vector, ByRef acceleration As Vector) As Boolean
        StateAt(time, 0, position, velocity)
        acceleration = _acceleration
        Return True
    End Function

    ''' <summary>Its acceleration, m/s²: (0, −g) in flight, zero resting on a level face, g's part along a slope sliding down it.</summary>
    Friend ReadOnly Property Acceleration As Vector
        Get
            Return _acceleration
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
        acceleration = (a._acceleration - b._acceleration).Length
    End Sub

    ''' <summary>Its velocity at t0 is the frame's; in the frame it accelerates by its acceleration less gravity's (none in flight).</summary>
    Friend Overrides Function FallingBounds(k As Integer, t0 As Double, t1 As Double, gravity As Double,
                                            ByRef frame As Vector, ByRef speed As Double, ByRef acceleration As Double) As Boolean
        Dim p As Vector
        StateAt(t0, 0, p, frame)
        acceleration = New Vector(_acceleration.X, _acceleration.Y + gravity).Length
        speed = acceleration * (t1 - t0) * (1 + 0.000000001)
        Return True
    End Function

    Friend Overrides Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double
        ' |v| is convex in time on a parabola: its largest value is at an end.
        Dim p As Vector, a As Vector, b As Vector
        StateAt(t0, 0, p, a)
        StateAt(t1, 0, p, b)
        Return Math.Max(a.Length, b.Length)
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return _acceleration.Length
    End Function

    Friend Overrides ReadOnly Property TransitionTime As Double
        Get
            Return Math.Min(_taut, _leaves)
        End Get
    End Property

    ''' <summary>
    ''' The string snaps taut: like a collision with the anchor along the string, the speed outwards
    ''' becomes e times as much inwards; the speed across the string is kept.
    ''' </summary>
    Friend Overrides Function Transition(world As World) As Boolean
        ' Leaving the end of the face it slid on changes nothing at that instant: it flies on from there.
        If _string Is Nothing OrElse _leaves < _taut Then Return False
        Dim body = Bodies(0)
        Dim n = (body.CentreOfMass - _string.EndB).Normalized(Vector.Zero)
        Dim outwards = Vector.Dot(body.Velocity, n)
        If outwards <= 0 Then Return False
        Dim after = BounceOffAnchor(body.Velocity, n, outwards, _string.Length, world)
        body.Velocity -= n * (outwards + after)
        Snapped = _string
        If after > 0 Then _released = _string
        Return after > 0
    End Function

    ''' <summary>
    ''' The speed (m/s) at which a body moving <paramref name="outwards"/> (m/s) along unit <paramref name="n"/> comes back
    ''' off a string of <paramref name="length"/> (m) to a fixed point snapping taut: e times as much, or nothing below
    ''' <see cref="SettleFraction"/> of √(pressing × L), where the string stays taut.
    ''' </summary>
    Friend Shared Function BounceOffAnchor(velocity As Vector, n As Vector, outwards As Double, length As Double, world As World) As Double
        Dim after = world.Restitution * outwards
        ' What presses the body out along the string: gravity, or the turning of the string's line as it swings round.
        Dim across = velocity - n * outwards
        Dim pressing = Math.Max(Math.Max(world.Gravity, 0.000001), across.LengthSquared / length)
        Return If(after < SettleFraction * Math.Sqrt(pressing * length), 0, after)
    End Function

    Private _released As Link

    ''' <summary>After the transition: the string, when it snapped taut and the body bounced back off it (slack again).</summary>
    Friend Overrides ReadOnly Property Released As Object
        Get
            Return _released
        End Get
    End Property

    Friend Overrides Sub UpdateTensions(time As Double)
        _string?.SetTension(0)
    End Sub
End Class
