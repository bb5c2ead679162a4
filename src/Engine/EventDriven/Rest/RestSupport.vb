Option Strict On

''' <summary>
''' What a body at rest touches, as the set of positions p (m) of the body at which it touches it: a flat face,
''' n · p = h (n the face's outward unit normal, h its level, m), or a round part (a ball's outline, a rounded
''' corner), |p − c| = R (c the centre, R the radius of the pair shape there, m). A pure value; the sums that
''' put a sleeping body exactly on two of them are in <see cref="RestSupport.Touching"/>.
''' </summary>
Friend Structure RestSupport
    ''' <summary>Whether the set is a circle (|p − c| = R) rather than a line (n · p = h).</summary>
    Friend ReadOnly IsRound As Boolean
    ''' <summary>A flat face's outward unit normal.</summary>
    Friend ReadOnly Normal As Vector
    ''' <summary>A flat face's level h (m): touching means n · p = h.</summary>
    Friend ReadOnly Level As Double
    ''' <summary>A round part's centre c (m).</summary>
    Friend ReadOnly Centre As Vector
    ''' <summary>A round part's radius R (m).</summary>
    Friend ReadOnly Radius As Double

    Private Sub New(isRound As Boolean, normal As Vector, level As Double, centre As Vector, radius As Double)
        Me.IsRound = isRound
        Me.Normal = normal
        Me.Level = level
        Me.Centre = centre
        Me.Radius = radius
    End Sub

    ''' <summary>A flat face n · p = h.</summary>
    Friend Shared Function Flat(normal As Vector, level As Double) As RestSupport
        Return New RestSupport(False, normal, level, Vector.Zero, 0)
    End Function

    ''' <summary>A round part |p − c| = R.</summary>
    Friend Shared Function Round(centre As Vector, radius As Double) As RestSupport
        Return New RestSupport(True, Vector.Zero, 0, centre, radius)
    End Function

    ''' <summary>The outward unit normal of the support at the body's position p (m): from the support towards the body.</summary>
    Friend Function NormalAt(p As Vector) As Vector
        If Not IsRound Then Return Normal
        Dim d = p - Centre
        Dim length = d.Length
        Return If(length > 0, d / length, New Vector(0, 1))
    End Function

    ''' <summary>The position on the support nearest p (m): p moved along the normal onto it.</summary>
    Friend Function Nearest(p As Vector) As Vector
        If IsRound Then Return Centre + NormalAt(p) * Radius
        Return p + Normal * (Level - Vector.Dot(Normal, p))
    End Function

    ''' <summary>
    ''' The position nearest <paramref name="p"/> (m) at which the body touches both <paramref name="a"/> and
    ''' <paramref name="b"/>; Nothing when they have no common point, or touch along a whole line or circle (parallel
    ''' faces, one circle twice), or cross at so shallow an angle that a point is not well defined.
    ''' </summary>
    ''' <remarks>
    ''' Two lines cross at one point (<see cref="RestingFaces.Crossing"/>). A line and a circle: with δ = h − n · c the
    ''' circle's centre's distance below the line and t the line's direction, the points are
    ''' c + δ n ± √(R² − δ²) t. Two circles at distance d apart: along the line of centres u at a = (R₁² − R₂² + d²) / 2d
    ''' from c₁, and off it by ±√(R₁² − a²) across. Of two points the one nearer p; a tangency (the root 0) gives one.
    ''' </remarks>
    Friend Shared Function Touching(p As Vector, a As RestSupport, b As RestSupport) As Vector?
        If Not a.IsRound AndAlso Not b.IsRound Then Return RestingFaces.Crossing(a.Normal, a.Level, b.Normal, b.Level)
        If a.IsRound AndAlso b.IsRound Then Return CirclesCrossing(p, a, b)
        Return If(a.IsRound, LineCircleCrossing(p, b, a), LineCircleCrossing(p, a, b))
    End Function

    Private Shared Function LineCircleCrossing(p As Vector, line As RestSupport, circle As RestSupport) As Vector?
        Dim n = line.Normal
        Dim t = New Vector(-n.Y, n.X)
        Dim delta = line.Level - Vector.Dot(n, circle.Centre)
        Dim across2 = circle.Radius * circle.Radius - delta * delta
        ' Closer than about 0.08° between the two normals there (cos = 0.999999) the point slides far along the line
        ' for a tiny change of level: the body rests on one support, not two.
        If across2 <= 0.000002 * circle.Radius * circle.Radius Then Return Nothing
        Dim foot = circle.Centre + n * delta
        Dim across = Math.Sqrt(across2)
        Return Nearer(p, foot + t * across, foot - t * across)
    End Function

    Private Shared Function CirclesCrossing(p As Vector, first As RestSupport, second As RestSupport) As Vector?
        Dim between = second.Centre - first.Centre
        Dim d = between.Length
        If d = 0 Then Return Nothing
        Dim u = between / d
        Dim along = (first.Radius * first.Radius - second.Radius * second.Radius + d * d) / (2 * d)
        Dim across2 = first.Radius * first.Radius - along * along
        If across2 <= 0.000002 * first.Radius * first.Radius Then Return Nothing
        Dim foot = first.Centre + u * along
        Dim across = Math.Sqrt(across2)
        Dim perpendicular = New Vector(-u.Y, u.X)
        Return Nearer(p, foot + perpendicular * across, foot - perpendicular * across)
    End Function

    Private Shared Function Nearer(p As Vector, a As Vector, b As Vector) As Vector
        Return If((a - p).Length <= (b - p).Length, a, b)
    End Function
End Structure
