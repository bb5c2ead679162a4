Option Strict On

''' <summary>
''' A body the teacher has asked for that follows the cursor until a click places it: a circle
''' (radius, mass, fixed or not), a rectangle (a fixed obstacle or a movable box with a mass) or a
''' regular polygon (fixed or movable), centred on the cursor.
''' </summary>
Public NotInheritable Class BodyDraft
    Private ReadOnly _corners As Vector() ' polygon corners around its centre, m

    Private Sub New(kind As ShapeKind, radius As Double, mass As Double, isFixed As Boolean,
                    width As Double, height As Double, colour As String, Optional corners As Vector() = Nothing)
        Me.Kind = kind
        Me.Radius = radius
        Me.Mass = mass
        Me.IsFixed = isFixed
        Me.Width = width
        Me.Height = height
        Me.Colour = colour
        _corners = corners
    End Sub

    ''' <summary>A circle of radius (m) and mass (kg; ignored when fixed).</summary>
    Public Shared Function ForCircle(radius As Double, mass As Double, isFixed As Boolean, colour As String) As BodyDraft
        Return New BodyDraft(ShapeKind.Circle, radius, mass, isFixed, 2 * radius, 2 * radius, colour)
    End Function

    ''' <summary>A fixed rectangle of width × height, m.</summary>
    Public Shared Function ForRectangle(width As Double, height As Double, colour As String) As BodyDraft
        Return New BodyDraft(ShapeKind.Rectangle, 0, 0, True, width, height, colour)
    End Function

    ''' <summary>A movable box of width × height, m, and mass, kg.</summary>
    Public Shared Function ForBox(width As Double, height As Double, mass As Double, colour As String) As BodyDraft
        Return New BodyDraft(ShapeKind.Rectangle, 0, mass, False, width, height, colour)
    End Function

    ''' <summary>A polygon with these corners around its centre (m) and mass (kg; ignored when fixed).</summary>
    Public Shared Function ForPolygon(corners As IReadOnlyList(Of Vector), mass As Double, isFixed As Boolean, colour As String) As BodyDraft
        If corners Is Nothing Then Throw New ArgumentNullException(NameOf(corners))
        Dim c = corners.ToArray()
        Dim w = c.Max(Function(v) v.X) - c.Min(Function(v) v.X)
        Dim h = c.Max(Function(v) v.Y) - c.Min(Function(v) v.Y)
        Return New BodyDraft(ShapeKind.Polygon, 0, mass, isFixed, w, h, colour, c)
    End Function

    ''' <summary>Which kind of body it will be.</summary>
    Public ReadOnly Property Kind As ShapeKind
    ''' <summary>True for a circle.</summary>
    Public ReadOnly Property IsCircle As Boolean
        Get
            Return Kind = ShapeKind.Circle
        End Get
    End Property
    ''' <summary>m (circles).</summary>
    Public ReadOnly Property Radius As Double
    ''' <summary>kg (movable bodies).</summary>
    Public ReadOnly Property Mass As Double
    ''' <summary>Whether it will be fixed.</summary>
    Public ReadOnly Property IsFixed As Boolean
    ''' <summary>Bounding width, m.</summary>
    Public ReadOnly Property Width As Double
    ''' <summary>Bounding height, m.</summary>
    Public ReadOnly Property Height As Double
    ''' <summary>"#rrggbb".</summary>
    Public ReadOnly Property Colour As String
    ''' <summary>Where the centre is now (follows the cursor), m.</summary>
    Public Property Centre As Vector
    ''' <summary>False until the cursor has entered the canvas (nothing to draw before).</summary>
    Public Property HasCentre As Boolean

    ''' <summary>"circle", "rectangle", "box" or "polygon", for messages and the trace.</summary>
    Public ReadOnly Property KindName As String
        Get
            Select Case Kind
                Case ShapeKind.Circle : Return "circle"
                Case ShapeKind.Rectangle : Return If(IsFixed, "rectangle", "box")
                Case Else : Return "polygon"
            End Select
        End Get
    End Property

    ''' <summary>The body to add, centred at <paramref name="centre"/> (m).</summary>
    Public Function Build(centre As Vector) As Shape
        Dim body As Shape
        Select Case Kind
            Case ShapeKind.Rectangle
                Dim corner = New Vector(centre.X - Width / 2, centre.Y - Height / 2)
                body = If(IsFixed, New Rectangle(corner, Width, Height), Rectangle.CreateMovable(corner, Width, Height, Mass))
            Case ShapeKind.Polygon
                Dim at = _corners.Select(Function(v) v + centre).ToArray()
                body = If(IsFixed, Polygon.CreateFixed(at), New Polygon(at, Mass))
            Case Else
                body = If(IsFixed, Circle.CreateFixed(centre, Radius), New Circle(centre, Radius, Mass))
        End Select
        body.Color = Colour
        Return body
    End Function
End Class
