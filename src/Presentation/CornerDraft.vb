Option Strict On

''' <summary>
''' A polygon the teacher is drawing by clicking its corners one after another: the corners so far
''' (m, in the order clicked), and the mass, Fixed box and colour it will have. The polygon it makes
''' is the convex hull of the corners (<see cref="ConvexHull"/>), so corners clicked in either
''' turning order, or not quite convex, still make a valid polygon; the presenter says when the
''' hull differs from what was clicked.
''' </summary>
Public NotInheritable Class CornerDraft
    Private ReadOnly _corners As New List(Of Vector)

    ''' <param name="mass">kg (ignored when fixed)</param>
    ''' <param name="isFixed">whether the polygon will be fixed</param>
    ''' <param name="colour">"#rrggbb"</param>
    Public Sub New(mass As Double, isFixed As Boolean, colour As String)
        Me.Mass = mass
        Me.IsFixed = isFixed
        Me.Colour = colour
    End Sub

    ''' <summary>kg (movable polygons).</summary>
    Public ReadOnly Property Mass As Double
    ''' <summary>Whether it will be fixed.</summary>
    Public ReadOnly Property IsFixed As Boolean
    ''' <summary>"#rrggbb".</summary>
    Public ReadOnly Property Colour As String

    ''' <summary>The corners clicked so far, m, in the order clicked.</summary>
    Public ReadOnly Property Corners As IReadOnlyList(Of Vector)
        Get
            Return _corners
        End Get
    End Property

    ''' <summary>How many corners have been clicked.</summary>
    Public ReadOnly Property Count As Integer
        Get
            Return _corners.Count
        End Get
    End Property

    ''' <summary>Adds a corner, m.</summary>
    Public Sub Add(corner As Vector)
        If Not corner.IsFinite Then Throw New ArgumentException("a corner must be finite", NameOf(corner))
        _corners.Add(corner)
    End Sub

    ''' <summary>Forgets every corner (to start the outline again).</summary>
    Public Sub Clear()
        _corners.Clear()
    End Sub

    ''' <summary>
    ''' The polygon's corners, anticlockwise: the convex hull of the corners clicked, with
    ''' <paramref name="extra"/> (the cursor, for the preview) when given. Empty when they enclose no area.
    ''' </summary>
    Public Function Outline(Optional extra As Vector? = Nothing) As Vector()
        Dim points As New List(Of Vector)(_corners)
        If extra.HasValue Then points.Add(extra.Value)
        Return ConvexHull.Corners(points).Select(Function(i) points(i)).ToArray()
    End Function

    ''' <summary>The numbers (1-based, in the order clicked) of the corners the polygon leaves out: inside its outline or on one of its sides.</summary>
    Public Function LeftOut() As Integer()
        Dim kept = New HashSet(Of Integer)(ConvexHull.Corners(_corners))
        Return Enumerable.Range(0, _corners.Count).Where(Function(i) Not kept.Contains(i)).Select(Function(i) i + 1).ToArray()
    End Function

    ''' <summary>Whether the corners, in the order clicked, already go round a convex polygon (either way round).</summary>
    Public ReadOnly Property IsConvexAsClicked As Boolean
        Get
            Return ConvexHull.IsConvexInOrder(_corners)
        End Get
    End Property

    ''' <summary>The polygon with these corners (m, from <see cref="Outline"/>): fixed, or movable with the mass.</summary>
    Public Function Build(outline As IReadOnlyList(Of Vector)) As Polygon
        If outline Is Nothing Then Throw New ArgumentNullException(NameOf(outline))
        Dim body = If(IsFixed, Polygon.CreateFixed(outline), New Polygon(outline, Mass))
        body.Color = Colour
        Return body
    End Function
End Class
