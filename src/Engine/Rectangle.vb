Option Strict On

''' <summary>A fixed, axis-aligned rectangular obstacle. It never moves or rotates.</summary>
Public NotInheritable Class Rectangle
    Inherits Shape

    ''' <param name="lowerLeft">lower-left corner, m</param>
    ''' <param name="width">m, &gt; 0</param>
    ''' <param name="height">m, &gt; 0</param>
    Public Sub New(lowerLeft As Vector, width As Double, height As Double, Optional id As String = Nothing)
        If Not (width > 0) OrElse Double.IsInfinity(width) Then Throw New ArgumentOutOfRangeException(NameOf(width), "width must be a finite number greater than 0")
        If Not (height > 0) OrElse Double.IsInfinity(height) Then Throw New ArgumentOutOfRangeException(NameOf(height), "height must be a finite number greater than 0")
        Me.Position = lowerLeft
        Me.Width = width
        Me.Height = height
        Me.Id = id
    End Sub

    ''' <summary>Lower-left corner, m.</summary>
    Public ReadOnly Property Position As Vector

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

    Public Overrides ReadOnly Property IsFixed As Boolean
        Get
            Return True
        End Get
    End Property

    ''' <summary>m².</summary>
    Public Overrides ReadOnly Property Area As Double
        Get
            Return Width * Height
        End Get
    End Property
End Class
