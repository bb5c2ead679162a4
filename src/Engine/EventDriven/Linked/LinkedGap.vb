Option Strict On

''' <summary>
''' The gap (m) between a moving ball and something it can hit, as a function of time, for
''' <see cref="ConservativeAdvancement"/>: another moving ball (centre distance − r₁ − r₂), a wall of the
''' container, or a fixed body (the signed distance to the Minkowski difference of the two outlines, from
''' <see cref="OutlineContact.Penetration"/>). Its rate is the speed of approach along the normal, negated.
''' </summary>
Friend NotInheritable Class LinkedGap
    Implements IDistanceFunction

    Private ReadOnly _motion As LinkedMotion
    Private ReadOnly _k As Integer
    Private ReadOnly _otherMotion As LinkedMotion
    Private ReadOnly _otherK As Integer
    Private ReadOnly _radius As Double
    Private ReadOnly _wall As WallSide
    Private ReadOnly _width As Double
    Private ReadOnly _height As Double
    Private ReadOnly _obstacle As Outline
    Private ReadOnly _obstaclePosition As Vector

    Private Sub New(motion As LinkedMotion, k As Integer, otherMotion As LinkedMotion, otherK As Integer, radius As Double,
                    wall As WallSide, width As Double, height As Double, obstacle As Outline, obstaclePosition As Vector)
        _motion = motion
        _k = k
        _otherMotion = otherMotion
        _otherK = otherK
        _radius = radius
        _wall = wall
        _width = width
        _height = height
        _obstacle = obstacle
        _obstaclePosition = obstaclePosition
    End Sub

    ''' <summary>Between body k of one motion and body otherK of another (or the same): centre distance − <paramref name="radii"/>.</summary>
    Friend Shared Function Pair(motion As LinkedMotion, k As Integer, otherMotion As LinkedMotion, otherK As Integer, radii As Double) As LinkedGap
        Return New LinkedGap(motion, k, otherMotion, otherK, radii, WallSide.None, 0, 0, Nothing, Vector.Zero)
    End Function

    ''' <summary>Between a ball of <paramref name="radius"/> and a wall of a container of the given size.</summary>
    Friend Shared Function Wall(motion As LinkedMotion, k As Integer, radius As Double, side As WallSide, width As Double, height As Double) As LinkedGap
        Return New LinkedGap(motion, k, Nothing, 0, radius, side, width, height, Nothing, Vector.Zero)
    End Function

    ''' <summary>Between a ball and a fixed body: <paramref name="difference"/> is the Minkowski difference of the fixed outline and the ball's.</summary>
    Friend Shared Function Obstacle(motion As LinkedMotion, k As Integer, difference As Outline, position As Vector) As LinkedGap
        Return New LinkedGap(motion, k, Nothing, 0, 0, WallSide.None, 0, 0, difference, position)
    End Function

    ''' <summary>The gap at <paramref name="time"/>, m (negative when overlapping), and the unit normal from the ball towards what it would hit.</summary>
    Friend Function GapAndNormal(time As Double, ByRef normal As Vector, ByRef rate As Double) As Double
        Dim p As Vector, v As Vector
        _motion.StateAt(time, _k, p, v)
        If _otherMotion IsNot Nothing Then
            Dim q As Vector, w As Vector
            _otherMotion.StateAt(time, _otherK, q, w)
            Dim r = q - p
            Dim d = r.Length
            normal = r.Normalized(New Vector(1, 0))
            rate = Vector.Dot(w - v, normal)
            Return d - _radius
        End If
        If _obstacle IsNot Nothing Then
            Dim c = OutlineContact.Penetration(_obstacle, p - _obstaclePosition)
            ' Its normal points from the obstacle to the ball.
            normal = -c.Normal
            rate = Vector.Dot(v, c.Normal)
            Return -c.Depth
        End If
        Select Case _wall
            Case WallSide.Left
                normal = New Vector(-1, 0)
                rate = v.X
                Return p.X - _radius
            Case WallSide.Right
                normal = New Vector(1, 0)
                rate = -v.X
                Return _width - _radius - p.X
            Case WallSide.Bottom
                normal = New Vector(0, -1)
                rate = v.Y
                Return p.Y - _radius
            Case Else
                normal = New Vector(0, 1)
                rate = -v.Y
                Return _height - _radius - p.Y
        End Select
    End Function

    ''' <summary>The gap at <paramref name="time"/>, m.</summary>
    Public Function Distance(time As Double) As Double Implements IDistanceFunction.Distance
        Dim n As Vector, rate As Double
        Return GapAndNormal(time, n, rate)
    End Function

    ''' <summary>Its rate at <paramref name="time"/>, m/s (negative when closing).</summary>
    Public Function Rate(time As Double) As Double Implements IDistanceFunction.Rate
        Dim n As Vector, r As Double
        GapAndNormal(time, n, r)
        Return r
    End Function
End Class
