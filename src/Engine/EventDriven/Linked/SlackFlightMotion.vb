Option Strict On

''' <summary>
''' Bodies joined by slack strings and nothing else (two balls on a slack string, a loose chain in flight, a body on
''' two slack strings): each flies its own parabola until the first string snaps taut. A pair's string is taut where
''' their difference, free of gravity, reaches its length (a quadratic); a string to a fixed point where the body's
''' parabola meets the circle (a quartic), both solved by <see cref="StringTaut"/>. Nothing is integrated: the motion
''' is exact, and a body's velocity stays what it was to the last bit, where an integrated group's would drift by the
''' rounding of its positions.
''' </summary>
Friend NotInheritable Class SlackFlightMotion
    Inherits LinkedMotion

    ' Below these speeds after a snap the string stays taut, as for a body on one string to a point (FlightMotion): the
    ' snaps of an inelastic string form a geometric series whose end would otherwise take endless events.
    Private Const SettleFraction As Double = 0.000001

    Private ReadOnly _flights As FlightMotion()
    Private ReadOnly _strings As Link()
    Private ReadOnly _first As Link
    Private ReadOnly _taut As Double = Double.PositiveInfinity
    Private _released As Link

    ''' <summary>
    ''' <paramref name="bodies"/> flying from their states now under <paramref name="gravity"/> (m/s²), tied by the
    ''' slack <paramref name="strings"/>; <paramref name="slop"/> (m) as for one string (<see cref="StringTaut"/>).
    ''' </summary>
    Friend Sub New(bodies As Shape(), strings As IEnumerable(Of Link), startTime As Double, gravity As Double, slop As Double)
        MyBase.New(bodies, startTime)
        _flights = bodies.Select(Function(b) New FlightMotion(b, startTime, gravity)).ToArray()
        _strings = strings.ToArray()
        For Each l In _strings
            Dim wait = If(l.IsAnchored,
                          StringTaut.AnchoredTautTime(l.EndB, l.Length, l.A.CentreOfMass, l.A.Velocity, gravity, slop),
                          StringTaut.PairTautTime(l.A.CentreOfMass, l.A.Velocity, l.B.CentreOfMass, l.B.Velocity, l.Length, slop))
            If startTime + wait < _taut Then
                _taut = startTime + wait
                _first = l
            End If
        Next
    End Sub

    ''' <summary>
    ''' Whether <paramref name="strings"/> (the links of a group with more than one body or link) are all strings and all
    ''' slack now (<see cref="LinkedMotions.StringState"/>), so that the group flies.
    ''' </summary>
    Friend Shared Function Fits(strings As IEnumerable(Of Link), gravity As Double, released As Object) As Boolean
        Return strings.All(Function(l) l.Kind = LinkKind.String AndAlso LinkedMotions.StringState(l, gravity, released) < 0)
    End Function

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        _flights(k).StateAt(time, 0, position, velocity)
    End Sub

    Friend Overrides Function Parabola(k As Integer, time As Double, ByRef position As Vector, ByRef velocity As Vector, ByRef acceleration As Vector) As Boolean
        Return _flights(k).Parabola(0, time, position, velocity, acceleration)
    End Function

    Friend Overrides Function FallingBounds(k As Integer, t0 As Double, t1 As Double, gravity As Double,
                                            ByRef frame As Vector, ByRef speed As Double, ByRef acceleration As Double) As Boolean
        Return _flights(k).FallingBounds(0, t0, t1, gravity, frame, speed, acceleration)
    End Function

    Friend Overrides Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return _flights(k).SpeedBound(0, t0, t1)
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return _flights(k).AccelerationBound(0, t0, t1)
    End Function

    ''' <summary>When the first string snaps taut, s.</summary>
    Friend Overrides ReadOnly Property TransitionTime As Double
        Get
            Return _taut
        End Get
    End Property

    ''' <summary>
    ''' The first string snaps taut: a collision along it, the speed at which its ends move apart becoming e times as
    ''' much together (their speeds across it kept). Returns true when its ends bounce back (it is slack next); a snap
    ''' too gentle to bounce leaves it taut, for the group formed next to hold.
    ''' </summary>
    Friend Overrides Function Transition(world As World) As Boolean
        If _first Is Nothing Then Return False
        Dim l = _first
        Dim a = l.A
        Dim n = (l.EndB - l.EndA).Normalized(Vector.Zero)
        Dim vb = If(l.IsAnchored, Vector.Zero, l.B.Velocity)
        Dim apart = Vector.Dot(vb - a.Velocity, n)
        If apart <= 0 Then Return False
        Dim after As Double
        If l.IsAnchored Then
            after = FlightMotion.BounceOffAnchor(a.Velocity, -n, apart, l.Length, world)
        Else
            after = world.Restitution * apart
            If after < SettleFraction * (a.Velocity.Length + vb.Length) Then after = 0
        End If
        Dim wb = If(l.IsAnchored, 0, l.B.InverseMass)
        Dim impulse = (apart + after) / (a.InverseMass + wb)
        a.Velocity += n * (impulse * a.InverseMass)
        If Not l.IsAnchored Then l.B.Velocity -= n * (impulse * wb)
        Snapped = l
        If after > 0 Then _released = l
        Return after > 0
    End Function

    ''' <summary>After the transition: the string, when it snapped taut and its ends bounced back (slack again).</summary>
    Friend Overrides ReadOnly Property Released As Object
        Get
            Return _released
        End Get
    End Property

    Friend Overrides Sub UpdateTensions(time As Double)
        For Each l In _strings
            l.SetTension(0)
        Next
    End Sub
End Class
