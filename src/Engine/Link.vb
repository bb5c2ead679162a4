Option Strict On

''' <summary>
''' A massless link between the reference points of two bodies (a circle's centre, a rectangle's centre, a
''' polygon's centroid: each body's centre of mass), or between a body and a fixed anchor point. End A is
''' always a movable body; end B is another body (a fixed one is an anchor) or, when
''' <see cref="B"/> is Nothing, the point <see cref="Anchor"/>. Links never collide with anything.
''' </summary>
Public NotInheritable Class Link
    Private _tension As Double

    Private Sub New(kind As LinkKind, a As Shape, b As Shape, anchor As Vector, length As Double,
                    stiffness As Double, damping As Double, id As String)
        If a Is Nothing Then Throw New ArgumentNullException(NameOf(a))
        If a.IsFixed Then Throw New ArgumentException("end A must be a movable body", NameOf(a))
        If b Is a Then Throw New ArgumentException("a link joins two different bodies", NameOf(b))
        If b Is Nothing AndAlso Not anchor.IsFinite Then Throw New ArgumentException("the anchor must be a finite point", NameOf(anchor))
        If Not (length >= 0) OrElse Double.IsInfinity(length) Then Throw New ArgumentOutOfRangeException(NameOf(length), "a length must be a finite number ≥ 0")
        If kind <> LinkKind.Spring AndAlso Not (length > 0) Then Throw New ArgumentOutOfRangeException(NameOf(length), "a rod or string must be longer than 0")
        If kind = LinkKind.Spring AndAlso (Not (stiffness > 0) OrElse Double.IsInfinity(stiffness)) Then Throw New ArgumentOutOfRangeException(NameOf(stiffness), "a spring's stiffness must be a finite number > 0")
        If Not (damping >= 0) OrElse Double.IsInfinity(damping) Then Throw New ArgumentOutOfRangeException(NameOf(damping), "damping must be a finite number ≥ 0")
        Me.Kind = kind
        Me.A = a
        Me.B = b
        Me.Anchor = If(b Is Nothing, anchor, Vector.Zero)
        Me.Length = length
        Me.Stiffness = stiffness
        Me.Damping = damping
        Me.Id = If(id, "")
    End Sub

    ''' <summary>A spring of stiffness k (N/m), rest length (m) and damping (N·s/m) from body a to body b.</summary>
    Public Shared Function CreateSpring(a As Shape, b As Shape, stiffness As Double, restLength As Double, Optional damping As Double = 0, Optional id As String = "") As Link
        If b Is Nothing Then Throw New ArgumentNullException(NameOf(b))
        Return New Link(LinkKind.Spring, a, b, Vector.Zero, restLength, stiffness, damping, id)
    End Function

    ''' <summary>A spring of stiffness k (N/m), rest length (m) and damping (N·s/m) from body a to a fixed point (m).</summary>
    Public Shared Function CreateSpring(a As Shape, anchor As Vector, stiffness As Double, restLength As Double, Optional damping As Double = 0, Optional id As String = "") As Link
        Return New Link(LinkKind.Spring, a, Nothing, anchor, restLength, stiffness, damping, id)
    End Function

    ''' <summary>A rod (or, with <paramref name="kind"/> String, a string) of the given length (m) from body a to body b.</summary>
    Public Shared Function CreateTie(kind As LinkKind, a As Shape, b As Shape, length As Double, Optional id As String = "") As Link
        If b Is Nothing Then Throw New ArgumentNullException(NameOf(b))
        If kind = LinkKind.Spring Then Throw New ArgumentException("use CreateSpring for a spring", NameOf(kind))
        Return New Link(kind, a, b, Vector.Zero, length, 0, 0, id)
    End Function

    ''' <summary>A rod (or, with <paramref name="kind"/> String, a string) of the given length (m) from body a to a fixed point (m).</summary>
    Public Shared Function CreateTie(kind As LinkKind, a As Shape, anchor As Vector, length As Double, Optional id As String = "") As Link
        If kind = LinkKind.Spring Then Throw New ArgumentException("use CreateSpring for a spring", NameOf(kind))
        Return New Link(kind, a, Nothing, anchor, length, 0, 0, id)
    End Function

    ''' <summary>Spring, rod or string.</summary>
    Public ReadOnly Property Kind As LinkKind

    ''' <summary>Unique among the world's links; the world numbers links given none.</summary>
    Public Property Id As String

    ''' <summary>End A: a movable body.</summary>
    Public ReadOnly Property A As Shape

    ''' <summary>End B: a body (fixed or movable), or Nothing when end B is the point <see cref="Anchor"/>.</summary>
    Public ReadOnly Property B As Shape

    ''' <summary>End B's fixed point, m, when <see cref="B"/> is Nothing (otherwise zero).</summary>
    Public ReadOnly Property Anchor As Vector

    ''' <summary>A rod's or string's length, or a spring's rest length, m.</summary>
    Public ReadOnly Property Length As Double

    ''' <summary>A spring's stiffness k, N/m (0 for rods and strings).</summary>
    Public ReadOnly Property Stiffness As Double

    ''' <summary>A spring's damping, N·s/m: its pull grows by this times the rate of stretching.</summary>
    Public ReadOnly Property Damping As Double

    ''' <summary>Whether end B holds still: a fixed point, or a fixed body.</summary>
    Public ReadOnly Property IsAnchored As Boolean
        Get
            Return B Is Nothing OrElse B.IsFixed
        End Get
    End Property

    ''' <summary>Where end A is now: body A's centre of mass, m.</summary>
    Public ReadOnly Property EndA As Vector
        Get
            Return A.CentreOfMass
        End Get
    End Property

    ''' <summary>Where end B is now: body B's centre of mass, or the anchor, m.</summary>
    Public ReadOnly Property EndB As Vector
        Get
            Return If(B Is Nothing, Anchor, B.CentreOfMass)
        End Get
    End Property

    ''' <summary>The distance between the ends now, m.</summary>
    Public ReadOnly Property Distance As Double
        Get
            Return (EndB - EndA).Length
        End Get
    End Property

    ''' <summary>Distance − length, m: a spring's stretch (negative when compressed); a string's or rod's is 0 when taut, negative when slack.</summary>
    Public ReadOnly Property Extension As Double
        Get
            Return Distance - Length
        End Get
    End Property

    ''' <summary>The rate the ends move apart, m/s (positive when stretching).</summary>
    Public ReadOnly Property StretchRate As Double
        Get
            Dim d = EndB - EndA
            Dim length = d.Length
            If length = 0 Then Return 0
            Dim vb = If(B Is Nothing OrElse B.IsFixed, Vector.Zero, B.Velocity)
            Return Vector.Dot(vb - A.Velocity, d) / length
        End Get
    End Property

    ''' <summary>
    ''' The pull along the link, N (positive pulls the ends together, negative pushes them apart). A spring's
    ''' is k·extension + damping·stretch rate; a rod's or string's is the force the solver needed to hold the
    ''' length at its last step or event (0 while a string is slack).
    ''' </summary>
    Public ReadOnly Property Tension As Double
        Get
            If Kind = LinkKind.Spring Then Return Stiffness * Extension + Damping * StretchRate
            Return _tension
        End Get
    End Property

    ''' <summary>Set by a solver: a rod's or string's pull, N.</summary>
    Friend Sub SetTension(value As Double)
        _tension = value
    End Sub

    ''' <summary>Energy stored in a spring, ½ k extension², J (0 for rods and strings).</summary>
    Public ReadOnly Property StoredEnergy As Double
        Get
            If Kind <> LinkKind.Spring Then Return 0
            Dim x = Extension
            Return 0.5 * Stiffness * x * x
        End Get
    End Property

    ''' <summary>The same link with body <paramref name="old"/> at either end replaced by <paramref name="replacement"/> (same id, tension kept).</summary>
    Friend Function WithBody(old As Shape, replacement As Shape) As Link
        Dim copy = New Link(Kind, If(A Is old, replacement, A), If(B Is old, replacement, B), Anchor, Length, Stiffness, Damping, Id)
        copy._tension = _tension
        Return copy
    End Function

    ''' <summary>"spring", "rod" or "string": the scene file's name for the kind.</summary>
    Public ReadOnly Property KindName As String
        Get
            Select Case Kind
                Case LinkKind.Spring : Return "spring"
                Case LinkKind.Rod : Return "rod"
                Case Else : Return "string"
            End Select
        End Get
    End Property
End Class
