Option Strict On

''' <summary>
''' A convex polygon, movable (with a mass) or fixed; it never rotates. Its reference point is its
''' centroid (centre of area), which is also where its mass is centred.
''' </summary>
Public NotInheritable Class Polygon
    Inherits Shape

    ''' <summary>A movable polygon.</summary>
    ''' <param name="vertices">its corners, m, in either turning direction: convex, at least 3, area &gt; 0</param>
    ''' <param name="mass">kg, &gt; 0</param>
    ''' <exception cref="ArgumentException">the corners do not make a convex polygon of area &gt; 0</exception>
    Public Sub New(vertices As IReadOnlyList(Of Vector), mass As Double, Optional velocity As Vector = Nothing, Optional id As String = Nothing)
        Me.New(Core(vertices), mass, False, velocity, id)
    End Sub

    Private Sub New(core As Outline, mass As Double, fixed As Boolean, velocity As Vector, id As String)
        MyBase.New(core.Centroid, core.Translated(-core.Centroid), mass, fixed, velocity, id)
    End Sub

    ''' <summary>A fixed polygon: it never moves and acts as an obstacle of infinite mass.</summary>
    Public Shared Function CreateFixed(vertices As IReadOnlyList(Of Vector), Optional id As String = Nothing) As Polygon
        Return New Polygon(Core(vertices), Double.PositiveInfinity, True, Vector.Zero, id)
    End Function

    Private Shared Function Core(vertices As IReadOnlyList(Of Vector)) As Outline
        If vertices Is Nothing Then Throw New ArgumentNullException(NameOf(vertices))
        Return Outline.Polygon(vertices)
    End Function

    Public Overrides ReadOnly Property Kind As ShapeKind
        Get
            Return ShapeKind.Polygon
        End Get
    End Property

    ''' <summary>Its corners where it is now, m, anticlockwise.</summary>
    Public ReadOnly Property Vertices As IReadOnlyList(Of Vector)
        Get
            Dim p = Position
            Return Outline.Vertices.Select(Function(v) p + v).ToList()
        End Get
    End Property

    ''' <summary>Mass ÷ area, kg/m² (+∞ for a fixed polygon). Derived: it is shown, never set.</summary>
    Public ReadOnly Property Density As Double
        Get
            Return Mass / Area
        End Get
    End Property
End Class
