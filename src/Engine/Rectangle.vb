Option Strict On

''' <summary>
''' An axis-aligned rectangle: a fixed obstacle (the default), or a movable box with a mass that never
''' rotates. Its reference point is its lower-left corner.
''' </summary>
Public NotInheritable Class Rectangle
    Inherits Shape

    ''' <summary>A fixed rectangle.</summary>
    ''' <param name="lowerLeft">lower-left corner, m</param>
    ''' <param name="width">m, &gt; 0</param>
    ''' <param name="height">m, &gt; 0</param>
    Public Sub New(lowerLeft As Vector, width As Double, height As Double, Optional id As String = Nothing)
        MyBase.New(lowerLeft, Outline.Box(width, height), Double.PositiveInfinity, True, Vector.Zero, id)
        Me.Width = width
        Me.Height = height
    End Sub

    Private Sub New(lowerLeft As Vector, width As Double, height As Double, mass As Double, velocity As Vector, id As String)
        MyBase.New(lowerLeft, Outline.Box(width, height), mass, False, velocity, id)
        Me.Width = width
        Me.Height = height
    End Sub

    ''' <summary>A movable box of the given mass (kg, &gt; 0): it slides, bounces and is pushed, but never rotates.</summary>
    Public Shared Function CreateMovable(lowerLeft As Vector, width As Double, height As Double, mass As Double,
                                         Optional velocity As Vector = Nothing, Optional id As String = Nothing) As Rectangle
        Return New Rectangle(lowerLeft, width, height, mass, velocity, id)
    End Function

    Public Overrides ReadOnly Property Kind As ShapeKind
        Get
            Return ShapeKind.Rectangle
        End Get
    End Property

    ''' <summary>m.</summary>
    Public ReadOnly Property Width As Double

    ''' <summary>m.</summary>
    Public ReadOnly Property Height As Double

    ''' <summary>Lower-left corner, m.</summary>
    Public ReadOnly Property Min As Vector
        Get
            Return Position
        End Get
    End Property

    ''' <summary>Upper-right corner, m.</summary>
    Public ReadOnly Property Max As Vector
        Get
            Return New Vector(Position.X + Width, Position.Y + Height)
        End Get
    End Property

    ''' <summary>Mass ÷ area, kg/m² (+∞ for a fixed rectangle). Derived: it is shown, never set.</summary>
    Public ReadOnly Property Density As Double
        Get
            Return Mass / Area
        End Get
    End Property
End Class
