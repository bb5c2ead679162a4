Option Strict On

''' <summary>
''' The maths of a body resting on flat faces with no friction (docs/links.md, section 6), as pure functions.
''' A face is an edge of the pair shape K (the Minkowski difference of the support's outline and the body's):
''' the body touches it while d = p_body − p_support lies on that edge, and its outward normal n points from
''' the support to the body. Times in s, distances in m, speeds in m/s, accelerations in m/s². The event
''' solver's rest rules (<see cref="RestRules"/>) use the same level, slide, holding and crossing maths.
''' </summary>
Friend Module RestingFaces
    ''' <summary>A face whose normal is this close to straight up (its cosine from vertical) is level: it takes the whole weight.</summary>
    Friend Const LevelCosine As Double = 1 - 0.000000000001

    ''' <summary>
    ''' A body sliding on a face with normal <paramref name="normal"/> (unit, upwards from the face): the face
    ''' pushes only along n, as hard as it takes to keep the body on it, so what is left of gravity (0, −g) is
    ''' its part along the face, (0, −g) − ((0, −g)·n) n, of size g sin θ, down the slope. Zero on a level face.
    ''' </summary>
    Friend Function SlideAcceleration(normal As Vector, gravity As Double) As Vector
        If normal.Y >= LevelCosine Then Return Vector.Zero
        Dim pressing = gravity * normal.Y
        Return New Vector(pressing * normal.X, pressing * normal.Y - gravity)
    End Function

    ''' <summary>The unit direction along edge e of K, from its vertex e to vertex e + 1 (the outward normal turned a quarter anticlockwise).</summary>
    Friend Function Along(normal As Vector) As Vector
        Return New Vector(-normal.Y, normal.X)
    End Function

    ''' <summary>
    ''' Whether a point at <paramref name="position"/> along a face of <paramref name="length"/> (both m, from the
    ''' face's first vertex), moving along it at <paramref name="rate"/> with <paramref name="acceleration"/>, is
    ''' at an end (within <paramref name="slop"/>) and going off it: then it does not rest there but flies on.
    ''' </summary>
    Friend Function IsLeaving(position As Double, rate As Double, acceleration As Double, length As Double, slop As Double) As Boolean
        Dim outwards = If(rate <> 0, rate, acceleration)
        Return (position >= length - slop AndAlso outwards > 0) OrElse (position <= slop AndAlso outwards < 0)
    End Function

    ''' <summary>
    ''' How long (s) a point at <paramref name="position"/> along a face of <paramref name="length"/>, moving along
    ''' it as s(τ) = s₀ + u τ + ½ a τ², stays on it: the first τ &gt; 0 at which s reaches an end it is not
    ''' already beyond; +∞ when it never does (at rest on a level face, or on a face with no ends: u = a = 0).
    ''' A point starting within rounding outside an end counts the end as where it is.
    ''' </summary>
    Friend Function TimeOnFace(position As Double, rate As Double, acceleration As Double, length As Double) As Double
        Dim lo = Math.Min(0, position), hi = Math.Max(length, position)
        Return Math.Min(FirstReach(position - lo, rate, acceleration), FirstReach(position - hi, rate, acceleration))
    End Function

    ''' <summary>The first τ &gt; 0 with c + u τ + ½ a τ² = 0, +∞ for none (c is the start less the end, m).</summary>
    Private Function FirstReach(c As Double, u As Double, a As Double) As Double
        Dim best = Double.PositiveInfinity
        If a = 0 Then
            If u <> 0 Then
                Dim t = -c / u
                If t > 0 Then best = t
            End If
            Return best
        End If
        Dim half = 0.5 * a
        Dim disc = u * u - 4 * half * c
        If disc < 0 Then Return best
        ' The two roots without cancellation: q = −(u + sign(u)√disc)/2, roots q/half and c/q.
        Dim q = -0.5 * (u + If(u >= 0, 1, -1) * Math.Sqrt(disc))
        For Each t In {If(half <> 0, q / half, Double.NaN), If(q <> 0, c / q, Double.NaN)}
            If t > 0 AndAlso t < best Then best = t
        Next
        Return best
    End Function

    ''' <summary>
    ''' Whether two faces with normals <paramref name="a"/> and <paramref name="b"/> (unit, from each face to the
    ''' body) hold a body up between them: straight up lies between the two, at less than half a turn, so that
    ''' two pushes along them (never pulls) add up to any upward force, the weight's included. The bottom of a V.
    ''' </summary>
    Friend Function HoldsUp(a As Vector, b As Vector) As Boolean
        Dim left = If(a.X >= b.X, a, b), right = If(a.X >= b.X, b, a)
        ' left leans right (x ≥ 0), right leans left (x ≤ 0), and turning from left to right anticlockwise passes up.
        Return left.X >= 0 AndAlso right.X <= 0 AndAlso left.X * right.Y - left.Y * right.X > 0
    End Function

    ''' <summary>
    ''' The point p where two faces, each touched when n·p = h, cross (m): where a body held by both sits.
    ''' Nothing for faces within rounding of parallel.
    ''' </summary>
    Friend Function Crossing(n1 As Vector, h1 As Double, n2 As Vector, h2 As Double) As Vector?
        Dim det = n1.X * n2.Y - n1.Y * n2.X
        If Math.Abs(det) < 0.000001 Then Return Nothing
        Return New Vector((h1 * n2.Y - h2 * n1.Y) / det, (n1.X * h2 - n2.X * h1) / det)
    End Function
End Module
