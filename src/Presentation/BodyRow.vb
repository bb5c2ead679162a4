Option Strict On

''' <summary>
''' One body's numbers at one moment, as the tables show them: copied when the presenter takes a
''' snapshot, so the rows, the totals and the arrows of that moment agree however late the window
''' draws them.
''' </summary>
Public Structure BodyRow
    ''' <summary>The body's id.</summary>
    Public Property Id As String
    ''' <summary>"#rrggbb" or "".</summary>
    Public Property Colour As String
    ''' <summary>The point the body is placed by (a circle's centre, a rectangle's lower-left corner), m.</summary>
    Public Property Position As Vector
    ''' <summary>m/s</summary>
    Public Property Velocity As Vector
    ''' <summary>kg; +∞ for a fixed body.</summary>
    Public Property Mass As Double
    ''' <summary>A fixed body never moves.</summary>
    Public Property IsFixed As Boolean
    ''' <summary>The body's size, m: (radius, 0) for a circle, (width, height) for a rectangle.</summary>
    Public Property Size As Vector
    ''' <summary>m²</summary>
    Public Property Area As Double
    ''' <summary>The body's sizes by the names a scene file gives them, m: ("radius", r) for a circle; ("width", w), ("height", h) for a rectangle.</summary>
    Public Property SizeFields As IReadOnlyList(Of (Name As String, Metres As Double))

    ''' <summary>The row of a body now. The one place that reads each kind of body for the tables.</summary>
    Public Shared Function Capture(body As Shape) As BodyRow
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        Dim row As New BodyRow With {.Id = body.Id, .Colour = If(body.Color, ""), .IsFixed = body.IsFixed, .Area = body.Area, .Mass = Double.PositiveInfinity}
        Dim c = TryCast(body, Circle)
        If c IsNot Nothing Then
            row.Position = c.Position
            row.Velocity = c.Velocity
            row.Mass = c.Mass
            row.Size = New Vector(c.Radius, 0)
            row.SizeFields = {("radius", c.Radius)}
            Return row
        End If
        Dim r = TryCast(body, Rectangle)
        If r IsNot Nothing Then
            row.Position = r.Position
            row.Size = New Vector(r.Width, r.Height)
            row.SizeFields = {("width", r.Width), ("height", r.Height)}
        End If
        If row.SizeFields Is Nothing Then row.SizeFields = Array.Empty(Of (Name As String, Metres As Double))()
        Return row
    End Function
End Structure
