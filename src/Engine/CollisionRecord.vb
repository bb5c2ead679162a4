Option Strict On

''' <summary>One collision as it happened: who, when, and the velocities just before and just after.</summary>
Public Structure CollisionRecord
    ''' <summary>Simulated time of the collision, s.</summary>
    Public ReadOnly Property Time As Double
    ''' <summary>The movable body (a circle, a box or a polygon).</summary>
    Public ReadOnly Property A As Shape
    ''' <summary>The other body, or Nothing for a wall.</summary>
    Public ReadOnly Property B As Shape
    ''' <summary>Which wall, when <see cref="B"/> is Nothing.</summary>
    Public ReadOnly Property Wall As WallSide
    Public ReadOnly Property Kind As CollisionKind
    ''' <summary>m/s</summary>
    Public ReadOnly Property AVelocityBefore As Vector
    ''' <summary>m/s</summary>
    Public ReadOnly Property AVelocityAfter As Vector
    ''' <summary>m/s; zero for a fixed body or a wall.</summary>
    Public ReadOnly Property BVelocityBefore As Vector
    ''' <summary>m/s; zero for a fixed body or a wall.</summary>
    Public ReadOnly Property BVelocityAfter As Vector

    ''' <summary>The string that snapped taut, for a <see cref="CollisionKind.StringTaut"/> record; Nothing otherwise.</summary>
    Public ReadOnly Property Link As Link

    ''' <summary>
    ''' A string <paramref name="link"/> snapping taut: its body A, and its body B (Nothing for a string to a fixed
    ''' point or a fixed body), with their velocities (m/s) just before and after the jerk.
    ''' </summary>
    Public Sub New(time As Double, link As Link, aBefore As Vector, aAfter As Vector, bBefore As Vector, bAfter As Vector)
        Me.New(time, link.A, If(link.B Is Nothing OrElse link.B.IsFixed, Nothing, link.B), WallSide.None, CollisionKind.StringTaut, aBefore, aAfter, bBefore, bAfter)
        Me.Link = link
    End Sub

    Public Sub New(time As Double, a As Shape, b As Shape, wall As WallSide, kind As CollisionKind,
                   aBefore As Vector, aAfter As Vector, bBefore As Vector, bAfter As Vector)
        Me.Time = time
        Me.A = a
        Me.B = b
        Me.Wall = wall
        Me.Kind = kind
        AVelocityBefore = aBefore
        AVelocityAfter = aAfter
        BVelocityBefore = bBefore
        BVelocityAfter = bAfter
    End Sub

    ''' <summary>The other body's name in outputs: its id, or wall:left, wall:right, wall:bottom, wall:top.</summary>
    Public ReadOnly Property BName As String
        Get
            If Link IsNot Nothing Then Return Link.Id
            If B IsNot Nothing Then Return B.Id
            Return "wall:" & Wall.ToString().ToLowerInvariant()
        End Get
    End Property

    ''' <summary>
    ''' The kind as the outputs spell it: A-B with A the kind of <see cref="A"/> and B of <see cref="B"/>,
    ''' each one of circle, fixed (a fixed circle), rectangle, segment, polygon or wall: circle-circle,
    ''' circle-fixed, circle-rectangle, circle-wall, polygon-segment, rectangle-rectangle, …
    ''' </summary>
    Public ReadOnly Property KindName As String
        Get
            If Kind = CollisionKind.StringTaut Then Return "string-taut"
            Return If(A Is Nothing, "circle", A.KindName) & "-" & If(B Is Nothing, "wall", B.KindName)
        End Get
    End Property
End Structure
