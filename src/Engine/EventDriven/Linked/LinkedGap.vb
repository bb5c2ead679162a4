Option Strict On

''' <summary>
''' The gap (m) between a moving body and something it can hit, as a function of time, for
''' <see cref="ConservativeAdvancement"/>: another moving ball (centre distance − r₁ − r₂), a wall of the
''' container (the body's extents), or a fixed body or a moving body of any other shape (the signed distance
''' of d = p_A − p_B, the difference of the reference points, to the Minkowski difference K of the two
''' outlines, from <see cref="OutlineContact.Penetration"/>). Bodies never rotate, so that distance is a
''' 1-Lipschitz function of the two centres' relative position: the gap can close no faster than the
''' bodies' relative speed. The motions give centres (centres of mass); a body's reference point is its
''' centre less its outline's centroid. Its rate is the speed of approach along the normal, negated.
''' </summary>
Friend NotInheritable Class LinkedGap
    Implements IDistanceFunction

    ''' <summary>
    ''' How near a sharp corner of K (m) d counts as on it: far below the slop, so that the rate the corner rule
    ''' gives differs from the gap's own slope only where that cannot matter, and far above the rounding of a
    ''' contact's position.
    ''' </summary>
    Friend Const CornerReach As Double = 0.00000000001

    Private ReadOnly _motion As LinkedMotion
    Private ReadOnly _k As Integer
    Private ReadOnly _otherMotion As LinkedMotion
    Private ReadOnly _otherK As Integer
    Private ReadOnly _radius As Double
    Private ReadOnly _wall As WallSide
    Private ReadOnly _width As Double
    Private ReadOnly _height As Double
    Private ReadOnly _low As Vector
    Private ReadOnly _high As Vector
    Private ReadOnly _obstacle As Outline
    Private ReadOnly _shift As Vector

    Private Sub New(motion As LinkedMotion, k As Integer, otherMotion As LinkedMotion, otherK As Integer, radius As Double,
                    wall As WallSide, width As Double, height As Double, low As Vector, high As Vector, obstacle As Outline, shift As Vector)
        _motion = motion
        _k = k
        _otherMotion = otherMotion
        _otherK = otherK
        _radius = radius
        _wall = wall
        _width = width
        _height = height
        _low = low
        _high = high
        _obstacle = obstacle
        _shift = shift
    End Sub

    ''' <summary>Between ball k of one motion and ball otherK of another (or the same): centre distance − <paramref name="radii"/>.</summary>
    Friend Shared Function Pair(motion As LinkedMotion, k As Integer, otherMotion As LinkedMotion, otherK As Integer, radii As Double) As LinkedGap
        Return New LinkedGap(motion, k, otherMotion, otherK, radii, WallSide.None, 0, 0, Vector.Zero, Vector.Zero, Nothing, Vector.Zero)
    End Function

    ''' <summary>
    ''' Between body k of one motion (A) and body otherK of another or the same (B), of any shapes:
    ''' <paramref name="difference"/> is the Minkowski difference of B's outline and A's, and
    ''' <paramref name="shift"/> A's centroid offset less B's (m), so that d = c_A − c_B − shift = p_A − p_B.
    ''' </summary>
    Friend Shared Function Shapes(motion As LinkedMotion, k As Integer, otherMotion As LinkedMotion, otherK As Integer, difference As Outline, shift As Vector) As LinkedGap
        Return New LinkedGap(motion, k, otherMotion, otherK, 0, WallSide.None, 0, 0, Vector.Zero, Vector.Zero, difference, shift)
    End Function

    ''' <summary>
    ''' Between a body and a wall of a container of the given size: <paramref name="low"/> and <paramref name="high"/>
    ''' are the body's extents from its centre (m): (MinX, MinY) and (MaxX, MaxY) less its centroid offset.
    ''' </summary>
    Friend Shared Function Wall(motion As LinkedMotion, k As Integer, low As Vector, high As Vector, side As WallSide, width As Double, height As Double) As LinkedGap
        Return New LinkedGap(motion, k, Nothing, 0, 0, side, width, height, low, high, Nothing, Vector.Zero)
    End Function

    ''' <summary>
    ''' Between a body and a fixed body: <paramref name="difference"/> is the Minkowski difference of the fixed
    ''' outline and the body's, <paramref name="position"/> the fixed body's reference point plus the body's
    ''' centroid offset (m), so that d = c − position = p − p_fixed.
    ''' </summary>
    Friend Shared Function Obstacle(motion As LinkedMotion, k As Integer, difference As Outline, position As Vector) As LinkedGap
        Return New LinkedGap(motion, k, Nothing, 0, 0, WallSide.None, 0, 0, Vector.Zero, Vector.Zero, difference, position)
    End Function

    ''' <summary>The Minkowski difference the gap is measured to (Nothing for two balls or a wall).</summary>
    Friend ReadOnly Property Difference As Outline
        Get
            Return _obstacle
        End Get
    End Property

    ''' <summary>The gap at <paramref name="time"/>, m (negative when overlapping), and the unit normal from the body towards what it would hit.</summary>
    Friend Function GapAndNormal(time As Double, ByRef normal As Vector, ByRef rate As Double) As Double
        Dim d As Vector
        Return GapAt(time, normal, rate, d)
    End Function

    ''' <summary>
    ''' The normal of a contact at <paramref name="time"/> (unit, from the body towards what it hits) by the
    ''' contact rules of docs/shapes.md: a corner on a face takes the face's normal (d on an edge of K), a
    ''' corner on a corner (d within <see cref="CornerReach"/> of a sharp corner of K) the bisector of K's two
    ''' faces there, which does not depend on which face was reached first.
    ''' </summary>
    Friend Function ContactNormal(time As Double) As Vector
        Dim normal As Vector, rate As Double, d As Vector
        GapAt(time, normal, rate, d)
        If _obstacle Is Nothing Then Return normal
        Dim k = SharpCornerAt(d)
        Return If(k >= 0, -_obstacle.CornerBisector(k), normal)
    End Function

    ''' <summary>
    ''' Whether d is on a sharp corner of K at <paramref name="time"/> (a corner of one box or polygon on a corner of
    ''' another), and then the unit normals, from the body towards what it hits, of K's two faces that meet there.
    ''' </summary>
    Friend Function SharpCorner(time As Double, ByRef first As Vector, ByRef second As Vector) As Boolean
        If _obstacle Is Nothing Then Return False
        Dim normal As Vector, rate As Double, d As Vector
        GapAt(time, normal, rate, d)
        Dim k = SharpCornerAt(d)
        If k < 0 Then Return False
        Dim m = _obstacle.VertexCount
        first = -_obstacle.Normals((k + m - 1) Mod m)
        second = -_obstacle.Normals(k)
        Return True
    End Function

    ''' <summary>The sharp corner of K within <see cref="CornerReach"/> of d (a box's or polygon's corner on another's), or −1.</summary>
    Private Function SharpCornerAt(d As Vector) As Integer
        If _obstacle.Radius > 0 OrElse _obstacle.VertexCount < 3 Then Return -1
        For k = 0 To _obstacle.VertexCount - 1
            If (d - _obstacle.Vertices(k)).Length <= CornerReach Then Return k
        Next
        Return -1
    End Function

    ''' <summary>
    ''' The gap's rate (m/s) at K's sharp corner k for d moving at <paramref name="u"/>: the larger of its rates
    ''' across the two faces that meet there (the gap's derivative in that direction; the gap is convex, and
    ''' both normals are its slopes there). It closes only if d closes on both faces, going into the corner; one
    ''' sliding along a face or passing the corner does not collide (docs/shapes.md, "A sharp corner").
    ''' </summary>
    Private Function CornerRate(k As Integer, u As Vector) As Double
        Dim m = _obstacle.VertexCount
        Dim before = _obstacle.Normals((k + m - 1) Mod m), after = _obstacle.Normals(k)
        Return Math.Max(Vector.Dot(u, before), Vector.Dot(u, after))
    End Function

    Private Function GapAt(time As Double, ByRef normal As Vector, ByRef rate As Double, ByRef d As Vector) As Double
        Dim p As Vector, v As Vector
        _motion.StateAt(time, _k, p, v)
        If _otherMotion IsNot Nothing AndAlso _obstacle Is Nothing Then
            Dim q As Vector, w As Vector
            _otherMotion.StateAt(time, _otherK, q, w)
            Dim r = q - p
            normal = r.Normalized(New Vector(1, 0))
            rate = Vector.Dot(w - v, normal)
            Return r.Length - _radius
        End If
        If _obstacle IsNot Nothing Then
            Dim w = Vector.Zero
            If _otherMotion IsNot Nothing Then
                Dim q As Vector
                _otherMotion.StateAt(time, _otherK, q, w)
                d = p - q - _shift
            Else
                d = p - _shift
            End If
            Dim c = OutlineContact.Penetration(_obstacle, d)
            ' Its normal points from K (the other body) to d (this one).
            normal = -c.Normal
            rate = Vector.Dot(v - w, c.Normal)
            Dim k = SharpCornerAt(d)
            If k >= 0 Then rate = CornerRate(k, v - w)
            Return -c.Depth
        End If
        Select Case _wall
            Case WallSide.Left
                normal = New Vector(-1, 0)
                rate = v.X
                Return p.X + _low.X
            Case WallSide.Right
                normal = New Vector(1, 0)
                rate = -v.X
                Return _width - _high.X - p.X
            Case WallSide.Bottom
                normal = New Vector(0, -1)
                rate = v.Y
                Return p.Y + _low.Y
            Case Else
                normal = New Vector(0, 1)
                rate = -v.Y
                Return _height - _high.Y - p.Y
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
