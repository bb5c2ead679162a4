Option Strict On

''' <summary>
''' Times each pass of a body's centre through a line, in one direction (the direction of the first
''' pass it sees), and the period between successive passes. The instant of a pass between two frames
''' is found on the cubic through both frames' positions and velocities (the body's motion to third
''' order), not on the straight line between them, so a pendulum's period comes out far finer than a frame.
''' </summary>
Public NotInheritable Class PassTimer
    Private ReadOnly _passes As New List(Of Double)
    ''' <summary>The last frame seen: its time (s), the centre's signed distance from the line (m) and its rate (m/s).</summary>
    Private _last As (T As Double, S As Double, Rate As Double)?
    ''' <summary>+1 or −1 once the first pass set the direction counted, 0 before.</summary>
    Private _sense As Integer

    ''' <summary>The longest time between two frames a pass is timed across, s: longer is a jump, not a frame.</summary>
    Public Const MaxGapSeconds As Double = 1.0

    ''' <param name="bodyId">the body timed</param>
    ''' <param name="through">a point of the line, m</param>
    ''' <param name="direction">the line's direction (any length but 0)</param>
    Public Sub New(bodyId As String, through As Vector, direction As Vector)
        Me.BodyId = bodyId
        Me.Through = through
        Me.Direction = direction.Normalized(New Vector(0, 1))
    End Sub

    ''' <summary>The body timed.</summary>
    Public ReadOnly Property BodyId As String
    ''' <summary>A point of the line, m.</summary>
    Public ReadOnly Property Through As Vector
    ''' <summary>The line's direction, a unit vector.</summary>
    Public ReadOnly Property Direction As Vector

    ''' <summary>The simulated times of the passes counted, s, earliest first.</summary>
    Public ReadOnly Property Passes As IReadOnlyList(Of Double)
        Get
            Return _passes
        End Get
    End Property

    ''' <summary>The time between the last two passes, s (NaN before the second).</summary>
    Public ReadOnly Property Period As Double
        Get
            If _passes.Count < 2 Then Return Double.NaN
            Return _passes(_passes.Count - 1) - _passes(_passes.Count - 2)
        End Get
    End Property

    ''' <summary>
    ''' The body's centre was at <paramref name="position"/> (m) moving at <paramref name="velocity"/>
    ''' (m/s) at time <paramref name="t"/> (s). Returns the time of a pass counted since the last frame,
    ''' or Nothing. A frame earlier than the last (the run taken back in time) forgets the passes after it.
    ''' </summary>
    Public Function Observe(t As Double, position As Vector, velocity As Vector) As Double?
        Dim s = Vector.Cross(Direction, position - Through)
        Dim rate = Vector.Cross(Direction, velocity)
        Dim last = _last
        _last = (t, s, rate)
        If Not last.HasValue Then Return Nothing
        If t < last.Value.T Then
            _passes.RemoveAll(Function(x) x > t)
            Return Nothing
        End If
        ' Two frames this far apart are a jump (a scrub forward, a long step): no pass is counted across it.
        If t = last.Value.T OrElse t - last.Value.T > MaxGapSeconds Then Return Nothing
        Dim sense = 0
        If last.Value.S < 0 AndAlso s >= 0 Then sense = 1
        If last.Value.S > 0 AndAlso s <= 0 Then sense = -1
        If sense = 0 Then Return Nothing
        If _sense = 0 Then _sense = sense
        If sense <> _sense Then Return Nothing
        Dim at = CrossingTime(last.Value.T, last.Value.S, last.Value.Rate, t, s, rate)
        _passes.Add(at)
        Return at
    End Function

    ''' <summary>
    ''' The root in [t0, t1] (s) of the cubic Hermite curve through distances s0 and s1 (m) with rates r0
    ''' and r1 (m/s), s0 and s1 of opposite signs (or s1 = 0), by bisection.
    ''' </summary>
    Public Shared Function CrossingTime(t0 As Double, s0 As Double, r0 As Double, t1 As Double, s1 As Double, r1 As Double) As Double
        If s1 = 0 Then Return t1
        Dim h = t1 - t0
        Dim at = Function(u As Double) As Double
                     Dim u2 = u * u, u3 = u2 * u
                     Return (2 * u3 - 3 * u2 + 1) * s0 + (u3 - 2 * u2 + u) * h * r0 + (-2 * u3 + 3 * u2) * s1 + (u3 - u2) * h * r1
                 End Function
        Dim lo = 0.0, hi = 1.0
        Dim sLo = s0
        ' 60 halvings reach the last bit of the fraction of a frame.
        For k = 1 To 60
            Dim mid = 0.5 * (lo + hi)
            Dim sMid = at(mid)
            If (sMid < 0) = (sLo < 0) AndAlso sMid <> 0 Then
                lo = mid
                sLo = sMid
            Else
                hi = mid
            End If
        Next
        Return t0 + 0.5 * (lo + hi) * h
    End Function
End Class
