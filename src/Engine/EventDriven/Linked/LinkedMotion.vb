Option Strict On

''' <summary>
''' How one group of linked bodies (or one free body) moves between events in the event solver, in closed
''' form: positions and velocities at any later time, when the form stops holding (a string going slack or
''' snapping taut), and bounds on each body's speed and acceleration that conservative advancement needs to
''' find contacts without ever stepping over one. Times are absolute (s, like <see cref="World.Time"/>).
''' </summary>
Friend MustInherit Class LinkedMotion
    Protected Sub New(bodies As Shape(), startTime As Double)
        Me.Bodies = bodies
        Me.StartTime = startTime
    End Sub

    ''' <summary>How many integrator steps this motion has taken so far (0 for a closed form): the work of integrating it, counted exactly.</summary>
    Friend Overridable ReadOnly Property StepsTaken As Integer
        Get
            Return 0
        End Get
    End Property

    ''' <summary>The bodies this motion moves, in its own order (one or two).</summary>
    Friend ReadOnly Property Bodies As Shape()

    ''' <summary>When the motion started, s.</summary>
    Friend ReadOnly Property StartTime As Double

    ''' <summary>Body k's position (m) and velocity (m/s) at <paramref name="time"/> (s, ≥ <see cref="StartTime"/>).</summary>
    Friend MustOverride Sub StateAt(time As Double, k As Integer, ByRef position As Vector, ByRef velocity As Vector)

    ''' <summary>
    ''' Every body's position (m) and velocity (m/s) at <paramref name="time"/> (s), in this motion's order: what is written
    ''' to the bodies. By default each body's <see cref="StateAt"/>.
    ''' </summary>
    Friend Overridable Sub StatesAt(time As Double, positions As Vector(), velocities As Vector())
        For k = 0 To Bodies.Length - 1
            StateAt(time, k, positions(k), velocities(k))
        Next
    End Sub

    ''' <summary>An upper bound on body k's speed (m/s) over [<paramref name="t0"/>, <paramref name="t1"/>].</summary>
    Friend MustOverride Function SpeedBound(k As Integer, t0 As Double, t1 As Double) As Double

    ''' <summary>An upper bound on body k's acceleration (m/s²) over [<paramref name="t0"/>, <paramref name="t1"/>].</summary>
    Friend MustOverride Function AccelerationBound(k As Integer, t0 As Double, t1 As Double) As Double

    ''' <summary>
    ''' Bounds on body k's motion over [<paramref name="t0"/>, <paramref name="t1"/>] as seen from a frame that falls
    ''' freely under <paramref name="gravity"/> (m/s², towards −y): the frame's velocity at t0 (m/s), and bounds on the
    ''' body's speed (m/s) and acceleration (m/s²) in that frame. Seen so, two bodies move apart or together no faster
    ''' than the difference of their frames' velocities (constant, as both frames fall alike) plus their two speeds,
    ''' and gravity drops out of their relative acceleration: a ball flying beside a dumbbell, or touching a group
    ''' that a spring pulls, is searched with its bounds relative to them, not with the sum of all their speeds.
    ''' False when the motion gives none.
    ''' </summary>
    Friend Overridable Function FallingBounds(k As Integer, t0 As Double, t1 As Double, gravity As Double,
                                              ByRef frame As Vector, ByRef speed As Double, ByRef acceleration As Double) As Boolean
        Return False
    End Function

    ''' <summary>
    ''' When this closed form stops holding, s; +∞ when it holds for ever. Its bodies' contacts are searched no
    ''' further, and are predicted again from there: for an integrated group that is its own event or the end of
    ''' what it has looked at so far, so that it is integrated only as far as it is looked at, doubling, not a
    ''' whole horizon ahead for a stretch the next collision throws away.
    ''' </summary>
    Friend Overridable ReadOnly Property TransitionTime As Double
        Get
            Return Double.PositiveInfinity
        End Get
    End Property

    ''' <summary>
    ''' At <see cref="TransitionTime"/>: whether that was only the end of what the motion had looked at, and it has
    ''' now looked further and goes on as it was (nothing to do). False when something happens there.
    ''' </summary>
    Friend Overridable Function LookFurther(time As Double) As Boolean
        Return False
    End Function

    ''' <summary>
    ''' At <see cref="TransitionTime"/>, with the bodies' states written to them: does what happens there
    ''' (a string snapping taut changes their velocities). Returns true when the string is to be slack next.
    ''' </summary>
    Friend Overridable Function Transition(world As World) As Boolean
        Return False
    End Function

    ''' <summary>The links that hold their length now (rods, taut strings): they take part in every collision of these bodies.</summary>
    Friend Overridable ReadOnly Property HeldLinks As Link()
        Get
            Return Array.Empty(Of Link)()
        End Get
    End Property

    ''' <summary>
    ''' Whether body k moves on a parabola (a constant acceleration) from <paramref name="time"/> until this motion's
    ''' transition, and then its position (m), velocity (m/s) and acceleration (m/s²) there: contacts with it can then
    ''' be solved for exactly rather than searched for.
    ''' </summary>
    Friend Overridable Function Parabola(k As Integer, time As Double, ByRef position As Vector, ByRef velocity As Vector, ByRef acceleration As Vector) As Boolean
        Return False
    End Function

    ''' <summary>The lasting contacts this motion holds (constraints on its bodies' slots): their pairs are not searched.</summary>
    Friend Overridable ReadOnly Property HeldContacts As Constraint()
        Get
            Return Array.Empty(Of Constraint)()
        End Get
    End Property

    ''' <summary>The rows by which two ties in line hold a body where it is (<see cref="TieLock"/>), on its bodies' slots.</summary>
    Friend Overridable ReadOnly Property HeldLocks As Constraint()
        Get
            Return Array.Empty(Of Constraint)()
        End Get
    End Property

    ''' <summary>
    ''' Contacts that touch without pressing, which this motion watches until they press in or open clear: their
    ''' pairs are not searched either.
    ''' </summary>
    Friend Overridable ReadOnly Property WatchedContacts As Constraint()
        Get
            Return Array.Empty(Of Constraint)()
        End Get
    End Property

    ''' <summary>After <see cref="Transition"/>: the string or contact whose force has just fallen to zero, not to be held at this instant; or Nothing.</summary>
    Friend Overridable ReadOnly Property Released As Object
        Get
            Return Nothing
        End Get
    End Property

    ''' <summary>After <see cref="Transition"/>: the string that snapped taut there (a collision to report), or Nothing.</summary>
    Friend Property Snapped As Link

    ''' <summary>Sets the tension of rods and strings at <paramref name="time"/> (s), for the tables.</summary>
    Friend Overridable Sub UpdateTensions(time As Double)
    End Sub
End Class
