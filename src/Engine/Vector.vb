Option Strict On

''' <summary>An immutable 2D vector of doubles. Positions in m, velocities in m/s, and so on.</summary>
Public Structure Vector
    Implements IEquatable(Of Vector)

    ''' <summary>Horizontal component.</summary>
    Public ReadOnly Property X As Double
    ''' <summary>Vertical component; y points up.</summary>
    Public ReadOnly Property Y As Double

    ''' <summary>Makes a vector from its components.</summary>
    Public Sub New(x As Double, y As Double)
        Me.X = x
        Me.Y = y
    End Sub

    ''' <summary>The zero vector.</summary>
    Public Shared ReadOnly Property Zero As Vector
        Get
            Return New Vector(0, 0)
        End Get
    End Property

    ''' <summary>|v|²: cheaper than <see cref="Length"/> and exact for comparisons.</summary>
    Public ReadOnly Property LengthSquared As Double
        Get
            Return X * X + Y * Y
        End Get
    End Property

    ''' <summary>|v|, computed without overflow or underflow.</summary>
    Public ReadOnly Property Length As Double
        Get
            Return Hypot(X, Y)
        End Get
    End Property

    ''' <summary>True when both components are finite (not NaN, not infinite).</summary>
    Public ReadOnly Property IsFinite As Boolean
        Get
            Return Not (Double.IsNaN(X) OrElse Double.IsInfinity(X) OrElse Double.IsNaN(Y) OrElse Double.IsInfinity(Y))
        End Get
    End Property

    ''' <summary>The unit vector along this one, or <paramref name="fallback"/> when this one is zero.</summary>
    Public Function Normalized(fallback As Vector) As Vector
        Dim len = Length
        If len = 0 OrElse Double.IsNaN(len) Then Return fallback
        Return New Vector(X / len, Y / len)
    End Function

    ''' <summary>Dot product.</summary>
    Public Shared Function Dot(a As Vector, b As Vector) As Double
        Return a.X * b.X + a.Y * b.Y
    End Function

    ''' <summary>z component of the 3D cross product a × b.</summary>
    Public Shared Function Cross(a As Vector, b As Vector) As Double
        Return a.X * b.Y - a.Y * b.X
    End Function

    ''' <summary>The vector turned a quarter turn anticlockwise.</summary>
    Public Function Perpendicular() As Vector
        Return New Vector(-Y, X)
    End Function

    ''' <summary>
    ''' The distance (m) from <paramref name="p"/> to the nearest point of the segment from <paramref name="a"/> to
    ''' <paramref name="b"/>: along the perpendicular where its foot lies between them, else to the nearer end.
    ''' </summary>
    Public Shared Function DistanceToSegment(p As Vector, a As Vector, b As Vector) As Double
        Dim ab = b - a
        Dim lengthSquared = ab.LengthSquared
        Dim t = If(lengthSquared > 0, Math.Max(0.0, Math.Min(1.0, Dot(p - a, ab) / lengthSquared)), 0.0)
        Return (p - (a + ab * t)).Length
    End Function

    ''' <summary>sqrt(x² + y²) with scaling, so huge or tiny components do not overflow.</summary>
    Public Shared Function Hypot(x As Double, y As Double) As Double
        Dim ax = Math.Abs(x)
        Dim ay = Math.Abs(y)
        Dim big = Math.Max(ax, ay)
        If big = 0 OrElse Double.IsInfinity(big) OrElse Double.IsNaN(big) Then Return big + Math.Min(ax, ay)
        Dim small = Math.Min(ax, ay) / big
        Return big * Math.Sqrt(1 + small * small)
    End Function

    Public Shared Operator +(a As Vector, b As Vector) As Vector
        Return New Vector(a.X + b.X, a.Y + b.Y)
    End Operator

    Public Shared Operator -(a As Vector, b As Vector) As Vector
        Return New Vector(a.X - b.X, a.Y - b.Y)
    End Operator

    Public Shared Operator -(a As Vector) As Vector
        Return New Vector(-a.X, -a.Y)
    End Operator

    Public Shared Operator *(a As Vector, s As Double) As Vector
        Return New Vector(a.X * s, a.Y * s)
    End Operator

    Public Shared Operator *(s As Double, a As Vector) As Vector
        Return New Vector(a.X * s, a.Y * s)
    End Operator

    Public Shared Operator /(a As Vector, s As Double) As Vector
        Return New Vector(a.X / s, a.Y / s)
    End Operator

    Public Shared Operator =(a As Vector, b As Vector) As Boolean
        Return a.Equals(b)
    End Operator

    Public Shared Operator <>(a As Vector, b As Vector) As Boolean
        Return Not a.Equals(b)
    End Operator

    ''' <summary>Exact, component-wise equality.</summary>
    Public Overloads Function Equals(other As Vector) As Boolean Implements IEquatable(Of Vector).Equals
        Return X.Equals(other.X) AndAlso Y.Equals(other.Y)
    End Function

    Public Overrides Function Equals(obj As Object) As Boolean
        Return TypeOf obj Is Vector AndAlso Equals(DirectCast(obj, Vector))
    End Function

    Public Overrides Function GetHashCode() As Integer
        Return X.GetHashCode() * 397 Xor Y.GetHashCode()
    End Function

    Public Overrides Function ToString() As String
        Return "(" & X.ToString("R", Globalization.CultureInfo.InvariantCulture) & ", " &
            Y.ToString("R", Globalization.CultureInfo.InvariantCulture) & ")"
    End Function
End Structure
