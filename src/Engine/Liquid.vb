Option Strict On

''' <summary>
''' A fixed, axis-aligned region of liquid. It never moves and never collides: bodies pass into it and
''' feel buoyancy ρ_l g A_sub upwards (A_sub the area of the body inside the region, which lies below its
''' surface, the region's top), and drag from it in proportion to the fraction of them inside. Densities
''' are areal (kg/m²), as every density in this 2D world is (a body's mass ÷ its area).
''' </summary>
Public NotInheritable Class Liquid
    Private _dragCoefficient As Double
    Private _linearDrag As Double

    ''' <param name="lowerLeft">lower-left corner, m</param>
    ''' <param name="width">m, &gt; 0</param>
    ''' <param name="height">m, &gt; 0</param>
    ''' <param name="density">ρ_l, kg/m², &gt; 0</param>
    Public Sub New(lowerLeft As Vector, width As Double, height As Double, density As Double, Optional id As String = Nothing)
        If Not lowerLeft.IsFinite Then Throw New ArgumentException("a liquid's corner must be finite", NameOf(lowerLeft))
        If Not (width > 0) OrElse Double.IsInfinity(width) Then Throw New ArgumentOutOfRangeException(NameOf(width), "width must be a finite number greater than 0")
        If Not (height > 0) OrElse Double.IsInfinity(height) Then Throw New ArgumentOutOfRangeException(NameOf(height), "height must be a finite number greater than 0")
        If Not (density > 0) OrElse Double.IsInfinity(density) Then Throw New ArgumentOutOfRangeException(NameOf(density), "a liquid's density must be a finite number greater than 0")
        Me.Min = lowerLeft
        Me.Width = width
        Me.Height = height
        Me.Density = density
        Me.Id = id
    End Sub

    ''' <summary>Unique in its world among bodies and liquids; assigned by <see cref="World.Add(Liquid)"/> when left empty.</summary>
    Public Property Id As String

    ''' <summary>How the app draws it (translucent), "#rrggbb", or Nothing to let the app choose.</summary>
    Public Property Color As String

    ''' <summary>Lower-left corner, m.</summary>
    Public ReadOnly Property Min As Vector

    ''' <summary>m.</summary>
    Public ReadOnly Property Width As Double

    ''' <summary>m.</summary>
    Public ReadOnly Property Height As Double

    ''' <summary>Upper-right corner, m.</summary>
    Public ReadOnly Property Max As Vector
        Get
            Return New Vector(Min.X + Width, Min.Y + Height)
        End Get
    End Property

    ''' <summary>The height of its surface (its top), m.</summary>
    Public ReadOnly Property Surface As Double
        Get
            Return Min.Y + Height
        End Get
    End Property

    ''' <summary>ρ_l, kg/m² (areal).</summary>
    Public ReadOnly Property Density As Double

    ''' <summary>C_d of bodies moving through it (≥ 0): drag −½ ρ_l C_d L |v| v times the body's submerged fraction.</summary>
    Public Property DragCoefficient As Double
        Get
            Return _dragCoefficient
        End Get
        Set(value As Double)
            Shape.CheckCoefficient(value, NameOf(DragCoefficient))
            _dragCoefficient = value
        End Set
    End Property

    ''' <summary>b_l, N·s/m (≥ 0): drag −b_l v times the body's submerged fraction.</summary>
    Public Property LinearDrag As Double
        Get
            Return _linearDrag
        End Get
        Set(value As Double)
            Shape.CheckCoefficient(value, NameOf(LinearDrag))
            _linearDrag = value
        End Set
    End Property

    ''' <summary>Whether the two regions share any area (touching along an edge is not overlapping).</summary>
    Public Function Overlaps(other As Liquid) As Boolean
        If other Is Nothing Then Throw New ArgumentNullException(NameOf(other))
        Return Math.Min(Max.X, other.Max.X) > Math.Max(Min.X, other.Min.X) AndAlso
               Math.Min(Max.Y, other.Max.Y) > Math.Max(Min.Y, other.Min.Y)
    End Function
End Class
