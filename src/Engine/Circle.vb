Option Strict On

''' <summary>A circle: movable (it has a mass) or fixed (an obstacle of infinite mass).</summary>
Public NotInheritable Class Circle
    Inherits Shape

    Private ReadOnly _fixed As Boolean

    ''' <summary>A movable circle.</summary>
    ''' <param name="position">centre, m</param>
    ''' <param name="radius">m, &gt; 0</param>
    ''' <param name="mass">kg, &gt; 0</param>
    ''' <param name="velocity">m/s</param>
    Public Sub New(position As Vector, radius As Double, mass As Double, Optional velocity As Vector = Nothing, Optional id As String = Nothing)
        If Not (radius > 0) OrElse Double.IsInfinity(radius) Then Throw New ArgumentOutOfRangeException(NameOf(radius), "radius must be a finite number greater than 0")
        If Not (mass > 0) OrElse Double.IsInfinity(mass) Then Throw New ArgumentOutOfRangeException(NameOf(mass), "mass must be a finite number greater than 0")
        Me.Position = position
        Me.Radius = radius
        Me.Mass = mass
        Me.Velocity = velocity
        Me.Id = id
    End Sub

    Private Sub New(position As Vector, radius As Double, id As String)
        If Not (radius > 0) OrElse Double.IsInfinity(radius) Then Throw New ArgumentOutOfRangeException(NameOf(radius), "radius must be a finite number greater than 0")
        Me.Position = position
        Me.Radius = radius
        Mass = Double.PositiveInfinity
        _fixed = True
        Me.Id = id
    End Sub

    ''' <summary>A fixed circle: it never moves and acts as an obstacle of infinite mass.</summary>
    Public Shared Function CreateFixed(position As Vector, radius As Double, Optional id As String = Nothing) As Circle
        Return New Circle(position, radius, id)
    End Function

    ''' <summary>Centre, m. Change it through the <see cref="World"/> while the circle is in one.</summary>
    Public Property Position As Vector

    ''' <summary>m/s; always zero for a fixed circle. Change it through the <see cref="World"/> while the circle is in one.</summary>
    Public Property Velocity As Vector

    ''' <summary>m.</summary>
    Public ReadOnly Property Radius As Double

    ''' <summary>kg; +∞ for a fixed circle.</summary>
    Public ReadOnly Property Mass As Double

    ''' <summary>1/kg; 0 for a fixed circle, so impulses never move it.</summary>
    Public ReadOnly Property InverseMass As Double
        Get
            Return If(_fixed, 0.0, 1.0 / Mass)
        End Get
    End Property

    Public Overrides ReadOnly Property IsFixed As Boolean
        Get
            Return _fixed
        End Get
    End Property

    ''' <summary>π r², m².</summary>
    Public Overrides ReadOnly Property Area As Double
        Get
            Return Math.PI * Radius * Radius
        End Get
    End Property

    ''' <summary>Mass ÷ area, kg/m². Derived: it is shown, never set.</summary>
    Public ReadOnly Property Density As Double
        Get
            Return Mass / Area
        End Get
    End Property

    ''' <summary>½ m v², J (0 for a fixed circle).</summary>
    Public ReadOnly Property KineticEnergy As Double
        Get
            Return If(_fixed, 0.0, 0.5 * Mass * Velocity.LengthSquared)
        End Get
    End Property

    ''' <summary>m v, kg·m/s (0 for a fixed circle).</summary>
    Public ReadOnly Property Momentum As Vector
        Get
            Return If(_fixed, Vector.Zero, Velocity * Mass)
        End Get
    End Property
End Class
