Option Strict On

''' <summary>
''' What every body shares: an id that every output names it by, a colour for the app, whether it is
''' fixed, its mass, its motion, and its outline. Nothing rotates, so a body's outline (a convex core
''' rounded by a radius, as offsets from its reference point) never changes: only the reference point
''' moves. The reference point is the one scene files use: a circle's centre, a rectangle's lower-left
''' corner, a segment's first end, a polygon's centroid.
''' </summary>
Public MustInherit Class Shape
    Private ReadOnly _fixed As Boolean
    Private _friction As Double?
    Private _staticFriction As Double?
    Private _dragCoefficient As Double
    Private _linearDrag As Double

    ''' <param name="position">reference point, m</param>
    ''' <param name="outline">the shape, as offsets from the reference point</param>
    ''' <param name="mass">kg, &gt; 0, for a movable body; ignored for a fixed one (infinite mass)</param>
    ''' <param name="fixed">a fixed body never moves, feels no gravity and has infinite mass</param>
    Protected Sub New(position As Vector, outline As Outline, mass As Double, fixed As Boolean, velocity As Vector, id As String)
        If outline Is Nothing Then Throw New ArgumentNullException(NameOf(outline))
        If Not fixed AndAlso (Not (mass > 0) OrElse Double.IsInfinity(mass)) Then
            Throw New ArgumentOutOfRangeException(NameOf(mass), "mass must be a finite number greater than 0")
        End If
        Me.Position = position
        Me.Outline = outline
        _fixed = fixed
        Me.Mass = If(fixed, Double.PositiveInfinity, mass)
        Me.Velocity = If(fixed, Vector.Zero, velocity)
        Me.Id = id
    End Sub

    ''' <summary>Unique in its world; assigned by <see cref="World.Add"/> when left empty.</summary>
    Public Property Id As String

    ''' <summary>How the app draws the body, "#rrggbb", or Nothing to let the app choose.</summary>
    Public Property Color As String

    ''' <summary>
    ''' μk of this body's own surface, or Nothing for the world's (<see cref="World.Friction"/>). A contact
    ''' uses the geometric mean of its two surfaces' values. Circles keep it but take no friction: they cannot
    ''' spin, and a ball that slid on a rough ramp instead of rolling would teach the wrong physics.
    ''' </summary>
    Public Property Friction As Double?
        Get
            Return _friction
        End Get
        Set(value As Double?)
            If value.HasValue Then CheckCoefficient(value.Value, NameOf(Friction))
            _friction = value
        End Set
    End Property

    ''' <summary>μs of this body's own surface, or Nothing for its <see cref="Friction"/> when that is set, else the world's <see cref="World.StaticFriction"/>.</summary>
    Public Property StaticFriction As Double?
        Get
            Return _staticFriction
        End Get
        Set(value As Double?)
            If value.HasValue Then CheckCoefficient(value.Value, NameOf(StaticFriction))
            _staticFriction = value
        End Set
    End Property

    ''' <summary>C_d, the drag coefficient (≥ 0; 0: none): with the world's air density ρ &gt; 0, drag −½ ρ C_d L |v| v, L the body's width across its motion.</summary>
    Public Property DragCoefficient As Double
        Get
            Return _dragCoefficient
        End Get
        Set(value As Double)
            CheckCoefficient(value, NameOf(DragCoefficient))
            _dragCoefficient = value
        End Set
    End Property

    ''' <summary>b, N·s/m (≥ 0; 0: none): linear (Stokes) drag −b v, in air and in liquids.</summary>
    Public Property LinearDrag As Double
        Get
            Return _linearDrag
        End Get
        Set(value As Double)
            CheckCoefficient(value, NameOf(LinearDrag))
            _linearDrag = value
        End Set
    End Property

    ''' <summary>A coefficient of friction or drag must be a finite number ≥ 0.</summary>
    Friend Shared Sub CheckCoefficient(value As Double, name As String)
        If Not (value >= 0) OrElse Double.IsInfinity(value) Then Throw New ArgumentOutOfRangeException(name, name & " must be a finite number ≥ 0")
    End Sub

    ''' <summary>Which kind of body this is.</summary>
    Public MustOverride ReadOnly Property Kind As ShapeKind

    ''' <summary>A fixed body never moves, feels no gravity and has infinite mass.</summary>
    Public ReadOnly Property IsFixed As Boolean
        Get
            Return _fixed
        End Get
    End Property

    ''' <summary>The reference point, m (see the class). Change it through the <see cref="World"/> while the body is in one.</summary>
    Public Property Position As Vector

    ''' <summary>m/s; always zero for a fixed body. Change it through the <see cref="World"/> while the body is in one.</summary>
    Public Property Velocity As Vector

    ''' <summary>kg; +∞ for a fixed body.</summary>
    Public ReadOnly Property Mass As Double

    ''' <summary>1/kg; 0 for a fixed body, so impulses never move it.</summary>
    Public ReadOnly Property InverseMass As Double
        Get
            Return If(_fixed, 0.0, 1.0 / Mass)
        End Get
    End Property

    ''' <summary>The body's shape as offsets from its reference point: a convex core rounded by a radius.</summary>
    Public ReadOnly Property Outline As Outline

    ''' <summary>Area in m² (0 for a segment).</summary>
    Public ReadOnly Property Area As Double
        Get
            Return Outline.Area
        End Get
    End Property

    ''' <summary>Where its mass is centred, m (the centre of its area: uniform density).</summary>
    Public ReadOnly Property CentreOfMass As Vector
        Get
            Return Position + Outline.Centroid
        End Get
    End Property

    ''' <summary>½ m v², J (0 for a fixed body).</summary>
    Public ReadOnly Property KineticEnergy As Double
        Get
            Return If(_fixed, 0.0, 0.5 * Mass * Velocity.LengthSquared)
        End Get
    End Property

    ''' <summary>m v, kg·m/s (0 for a fixed body).</summary>
    Public ReadOnly Property Momentum As Vector
        Get
            Return If(_fixed, Vector.Zero, Velocity * Mass)
        End Get
    End Property

    ''' <summary>The lowest corner of its bounding box, m.</summary>
    Public ReadOnly Property BoundsMin As Vector
        Get
            Return New Vector(Position.X + Outline.MinX, Position.Y + Outline.MinY)
        End Get
    End Property

    ''' <summary>The highest corner of its bounding box, m.</summary>
    Public ReadOnly Property BoundsMax As Vector
        Get
            Return New Vector(Position.X + Outline.MaxX, Position.Y + Outline.MaxY)
        End Get
    End Property

    ''' <summary>How outputs name the body's kind in a pair: circle, fixed (a fixed circle), rectangle, segment or polygon.</summary>
    Public ReadOnly Property KindName As String
        Get
            Select Case Kind
                Case ShapeKind.Circle : Return If(_fixed, "fixed", "circle")
                Case ShapeKind.Rectangle : Return "rectangle"
                Case ShapeKind.Segment : Return "segment"
                Case Else : Return "polygon"
            End Select
        End Get
    End Property
End Class
