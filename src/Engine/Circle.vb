Option Strict On

''' <summary>A circle: movable (it has a mass) or fixed (an obstacle of infinite mass).</summary>
Public NotInheritable Class Circle
    Inherits Shape

    ''' <summary>A movable circle.</summary>
    ''' <param name="position">centre, m</param>
    ''' <param name="radius">m, &gt; 0</param>
    ''' <param name="mass">kg, &gt; 0</param>
    ''' <param name="velocity">m/s</param>
    Public Sub New(position As Vector, radius As Double, mass As Double, Optional velocity As Vector = Nothing, Optional id As String = Nothing)
        MyBase.New(position, Ring(radius), mass, False, velocity, id)
        Me.Radius = radius
    End Sub

    Private Sub New(position As Vector, radius As Double, id As String)
        MyBase.New(position, Ring(radius), Double.PositiveInfinity, True, Vector.Zero, id)
        Me.Radius = radius
    End Sub

    Private Shared Function Ring(radius As Double) As Outline
        If Not (radius > 0) OrElse Double.IsInfinity(radius) Then Throw New ArgumentOutOfRangeException(NameOf(radius), "radius must be a finite number greater than 0")
        Return Outline.Point(radius)
    End Function

    ''' <summary>A fixed circle: it never moves and acts as an obstacle of infinite mass.</summary>
    Public Shared Function CreateFixed(position As Vector, radius As Double, Optional id As String = Nothing) As Circle
        Return New Circle(position, radius, id)
    End Function

    Public Overrides ReadOnly Property Kind As ShapeKind
        Get
            Return ShapeKind.Circle
        End Get
    End Property

    ''' <summary>m.</summary>
    Public ReadOnly Property Radius As Double

    ''' <summary>Mass ÷ area, kg/m². Derived: it is shown, never set.</summary>
    Public ReadOnly Property Density As Double
        Get
            Return Mass / Area
        End Get
    End Property
End Class
