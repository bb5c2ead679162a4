Option Strict On

''' <summary>
''' Bodies sliding round a corner (<see cref="BodyMode.Rounding"/>): this owns where each one's arc
''' is and how it started, and answers where the body is on it, when the slide ends, and when a
''' neighbour comes within reach. The maths is <see cref="CornerSlide"/>'s.
''' </summary>
Friend NotInheritable Class CornerSlides
    Private ReadOnly _s As SolverState
    ' Per body: the corner (centre of the arc, m), the direction (±1: which way round), the speed at
    ' the start (m/s), the angle at which it will leave (rad, from the upward vertical) and when it started (s).
    Private _cx As Double() = Array.Empty(Of Double)()
    Private _cy As Double() = Array.Empty(Of Double)()
    Private _dir As Double() = Array.Empty(Of Double)()
    Private _v0 As Double() = Array.Empty(Of Double)()
    Private _leaveAngle As Double() = Array.Empty(Of Double)()
    Private _start As Double() = Array.Empty(Of Double)()
    ''' <summary>Scratch list of a body's neighbours (no allocation per event).</summary>
    Private _neighbours As Integer() = Array.Empty(Of Integer)()

    Friend Sub New(state As SolverState)
        _s = state
    End Sub

    Friend Sub Reset(n As Integer)
        If _cx.Length >= n Then Return
        _cx = New Double(n - 1) {}
        _cy = New Double(n - 1) {}
        _dir = New Double(n - 1) {}
        _v0 = New Double(n - 1) {}
        _leaveAngle = New Double(n - 1) {}
        _start = New Double(n - 1) {}
        _neighbours = New Integer(n - 1) {}
    End Sub

    ''' <summary>
    ''' Body i (on the clock, its centre exactly above the corner (cx, cy)) starts sliding round it at
    ''' horizontal speed vx (m/s): it leaves when the normal force vanishes.
    ''' </summary>
    Friend Sub Start(i As Integer, cx As Double, cy As Double, vx As Double)
        Dim b = _s.Bodies
        b.SetMode(i, BodyMode.Rounding)
        b.Motion(i).Ay = Double.NaN ' not a parabola: no prediction may read it as one
        b.Motion(i).Ax = 0
        _cx(i) = cx
        _cy(i) = cy
        _dir(i) = Math.Sign(vx)
        _v0(i) = Math.Abs(vx)
        _leaveAngle(i) = CornerSlide.LeaveAngle(Math.Abs(vx), _s.G, b.Motion(i).R, 0)
        _start(i) = _s.Now
    End Sub

    ''' <summary>Time (s, from now) until sliding body i leaves its corner.</summary>
    Friend Function TimeToEnd(i As Integer) As Double
        Return Math.Max(0, CornerSlide.Duration(_v0(i), _s.G, _s.Bodies.Motion(i).R, 0, _leaveAngle(i)) - (_s.Now - _start(i)))
    End Function

    ''' <summary>
    ''' When body k first comes within reach of sliding body j: j's centre stays within r_j of its
    ''' corner, so k can touch it only inside the disc of radius r_k + 2 r_j about the corner. Reaching
    ''' that disc ends the exact slide early (see <see cref="Interrupt"/>); +∞ if k never gets there.
    ''' </summary>
    Friend Function TimeToReach(j As Integer, k As Integer) As Double
        Dim b = _s.Bodies
        Dim mk = b.Slot(k).Mode
        If mk = BodyMode.Rounding OrElse mk = BodyMode.Sleeping Then Return Double.PositiveInfinity
        Dim xk, yk, vxk, vyk As Double
        b.Motion(k).StateAt(_s.Now, xk, yk, vxk, vyk)
        Return TimeOfImpact.CircleCircle(xk - _cx(j), yk - _cy(j), vxk, vyk, b.Motion(k).Ax, b.Motion(k).Ay,
                                         b.Motion(k).R + 2 * b.Motion(j).R, SolverState.SlopAt(xk, yk))
    End Function

    ''' <summary>Fills the scratch list with body i's grid neighbours (see <see cref="Neighbour"/>); returns how many.</summary>
    Friend Function Neighbours(i As Integer) As Integer
        Return GridNeighbours.Collect(_s, i, _neighbours)
    End Function

    Friend Function Neighbour(q As Integer) As Integer
        Return _neighbours(q)
    End Function

    ''' <summary>Sliding body i's position (m) and velocity (m/s) at time t (s), exactly on its arc.</summary>
    Friend Sub StateAt(i As Integer, t As Double, ByRef position As Vector, ByRef velocity As Vector)
        Dim r = _s.Bodies.Motion(i).R, s = _dir(i)
        Dim theta = CornerSlide.AngleAfter(_v0(i), _s.G, r, 0, _leaveAngle(i), t - _start(i))
        Dim speed = CornerSlide.SpeedAt(_v0(i), _s.G, r, 0, theta)
        position = New Vector(_cx(i) + s * r * Math.Sin(theta), _cy(i) + r * Math.Cos(theta))
        velocity = New Vector(s * speed * Math.Cos(theta), -speed * Math.Sin(theta))
    End Sub

    ''' <summary>
    ''' Ends a slide early (a neighbour came within reach): the body becomes free at its exact place
    ''' and velocity on the arc. If it is still pressed against the corner, the contact rules take
    ''' over (it hops round the rest of the corner).
    ''' </summary>
    Friend Sub Interrupt(i As Integer)
        Dim theta = CornerSlide.AngleAfter(_v0(i), _s.G, _s.Bodies.Motion(i).R, 0, _leaveAngle(i), _s.Now - _start(i))
        Launch(i, theta, _s.Bodies.Motion(i).R)
    End Sub

    ''' <summary>
    ''' The slide is over: it leaves tangentially, touching the corner with zero normal speed; it
    ''' starts a hair (far below any physical scale) outside, so rounding cannot turn the tangent into
    ''' a collision.
    ''' </summary>
    Friend Sub Finish(i As Integer)
        Dim r = _s.Bodies.Motion(i).R
        Launch(i, _leaveAngle(i), r + 10 * SolverState.SlopAt(_cx(i), _cy(i)) + 1.0E-9 * r)
    End Sub

    ''' <summary>
    ''' Turns body i into a free body at angle θ from the vertical, its centre <paramref name="arc"/> m
    ''' from the corner, moving along the tangent at the slide's speed there.
    ''' </summary>
    Private Sub Launch(i As Integer, theta As Double, arc As Double)
        Dim b = _s.Bodies
        Dim s = _dir(i)
        Dim speed = CornerSlide.SpeedAt(_v0(i), _s.G, b.Motion(i).R, 0, theta)
        b.Motion(i).Px = _cx(i) + s * arc * Math.Sin(theta)
        b.Motion(i).Py = _cy(i) + arc * Math.Cos(theta)
        b.Motion(i).Vx = s * speed * Math.Cos(theta)
        b.Motion(i).Vy = -speed * Math.Sin(theta)
        b.Motion(i).T0 = _s.Now
        b.SetMode(i, BodyMode.Free)
        b.Motion(i).Ay = -_s.G
        b.Support(i) = BodyTable.SupportNone
        _s.Changed(i)
        _s.MoveToCellOfPosition(i)
    End Sub
End Class
