Option Strict On

''' <summary>
''' A fixed straight line of no thickness, solid on both sides, whose two ends act as corners: a ramp,
''' a shelf, a funnel wall. Its reference point is its first end.
''' </summary>
Public NotInheritable Class Segment
    Inherits Shape

    ''' <param name="startPoint">first end, m</param>
    ''' <param name="endPoint">second end, m; must differ from the first</param>
    Public Sub New(startPoint As Vector, endPoint As Vector, Optional id As String = Nothing)
        MyBase.New(startPoint, Line(startPoint, endPoint), Double.PositiveInfinity, True, Vector.Zero, id)
    End Sub

    Private Shared Function Line(a As Vector, b As Vector) As Outline
        If Not a.IsFinite OrElse Not b.IsFinite Then Throw New ArgumentException("a segment's ends must be finite")
        If a = b Then Throw New ArgumentException("a segment's two ends must differ")
        Return Outline.Segment(Vector.Zero, b - a)
    End Function

    Public Overrides ReadOnly Property Kind As ShapeKind
        Get
            Return ShapeKind.Segment
        End Get
    End Property

    ''' <summary>First end, m.</summary>
    Public ReadOnly Property StartPoint As Vector
        Get
            Return Position
        End Get
    End Property

    ''' <summary>Second end, m.</summary>
    Public ReadOnly Property EndPoint As Vector
        Get
            Return Position + Outline.Vertices(1)
        End Get
    End Property

    ''' <summary>Length, m.</summary>
    Public ReadOnly Property Length As Double
        Get
            Return (EndPoint - StartPoint).Length
        End Get
    End Property
End Class
