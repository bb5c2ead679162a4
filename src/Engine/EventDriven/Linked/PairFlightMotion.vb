Option Strict On

''' <summary>
''' Two bodies joined by a slack string and nothing else: each flies its own parabola until the string snaps
''' taut. Gravity cancels in their difference, so that time is a quadratic (<see cref="StringTaut.PairTautTime"/>).
''' </summary>
Friend NotInheritable Class PairFlightMotion
    Inherits LinkedMotion

    Private Const SettleFraction As Double = 0.000001

    Private ReadOnly _link As Link
    Private ReadOnly _flights As FlightMotion()
    Private ReadOnly _taut As Double

    Friend Sub New(a As Shape, b As Shape, link As Link, startTime As Double, gravity As Double, slop As Double)
        MyBase.New({a, b}, startTime)
        _link = link
        _flights = {New FlightMotion(a, startTime, gravity), New FlightMotion(b, startTime, gravity)}
        _taut = startTime + StringTaut.PairTautTime(a.CentreOfMass, a.Velocity, b.CentreOfMass, b.Velocity, link.Length, slop)
    End Sub

    Friend Overrides Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)
        _flights(k).StateAt(time, 0, position, velocity)
    End Sub

    Friend Overrides Function Parabola(k As Integer, time As Double, ByRef position As Vector, ByRef velocity As Vector, ByRef acceleration As Vector) As Boolean
        Return _flights(k).Parabola(0, time, position, velocity, acceleration)
    End Function

    Friend Overrides Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return _flights(k).SpeedBound(0, t0, t1)
    End Function

    Friend Overrides Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double
        Return _flights(k).AccelerationBound(0, t0, t1)
    End Function

    Friend Overrides ReadOnly Property TransitionTime As Double
        Get
            Return _taut
        End Get
    End Property

    ''' <summary>The string snaps taut: an impulse along it, equal and opposite, so the ends separate at −e times the speed they arrived.</summary>
    Friend Overrides Function Transition(world As World) As Boolean
        Dim a = Bodies(0), b = Bodies(1)
        Dim n = (b.CentreOfMass - a.CentreOfMass).Normalized(Vector.Zero)
        Dim apart = Vector.Dot(b.Velocity - a.Velocity, n)
        If apart <= 0 Then Return False
        Dim after = world.Restitution * apart
        If after < SettleFraction * (a.Velocity.Length + b.Velocity.Length) Then after = 0
        Dim impulse = (apart + after) / (a.InverseMass + b.InverseMass)
        a.Velocity += n * (impulse * a.InverseMass)
        b.Velocity -= n * (impulse * b.InverseMass)
        Snapped = _link
        If after > 0 Then _released = _link
        Return after > 0
    End Function

    Private _released As Link

    ''' <summary>After the transition: the string, when it snapped taut and its ends bounced back (slack again).</summary>
    Friend Overrides ReadOnly Property Released As Object
        Get
            Return _released
        End Get
    End Property

    Friend Overrides Sub UpdateTensions(time As Double)
        _link.SetTension(0)
    End Sub
End Class
