Option Strict On

''' <summary>
''' A body the teacher has asked for that follows the cursor until a click places it: a circle
''' (radius, mass, fixed or not) or a fixed rectangle (width, height), centred on the cursor.
''' </summary>
Public NotInheritable Class BodyDraft
    Private Sub New(isCircle As Boolean, radius As Double, mass As Double, isFixed As Boolean,
                    width As Double, height As Double, colour As String)
        Me.IsCircle = isCircle
        Me.Radius = radius
        Me.Mass = mass
        Me.IsFixed = isFixed
        Me.Width = width
        Me.Height = height
        Me.Colour = colour
    End Sub

    ''' <summary>A circle of radius (m) and mass (kg; ignored when fixed).</summary>
    Public Shared Function ForCircle(radius As Double, mass As Double, isFixed As Boolean, colour As String) As BodyDraft
        Return New BodyDraft(True, radius, mass, isFixed, 2 * radius, 2 * radius, colour)
    End Function

    ''' <summary>A fixed rectangle of width × height, m.</summary>
    Public Shared Function ForRectangle(width As Double, height As Double, colour As String) As BodyDraft
        Return New BodyDraft(False, 0, 0, True, width, height, colour)
    End Function

    ''' <summary>True for a circle, False for a rectangle.</summary>
    Public ReadOnly Property IsCircle As Boolean
    ''' <summary>m (circles).</summary>
    Public ReadOnly Property Radius As Double
    ''' <summary>kg (movable circles).</summary>
    Public ReadOnly Property Mass As Double
    ''' <summary>Fixed circles and every rectangle.</summary>
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

    ''' <summary>"circle" or "rectangle", for messages and the trace.</summary>
    Public ReadOnly Property KindName As String
        Get
            Return If(IsCircle, "circle", "rectangle")
        End Get
    End Property

    ''' <summary>The body to add, centred at <paramref name="centre"/> (m).</summary>
    Public Function Build(centre As Vector) As Shape
        Dim body As Shape
        If Not IsCircle Then
            body = New Rectangle(New Vector(centre.X - Width / 2, centre.Y - Height / 2), Width, Height)
        ElseIf IsFixed Then
            body = Circle.CreateFixed(centre, Radius)
        Else
            body = New Circle(centre, Radius, Mass)
        End If
        body.Color = Colour
        Return body
    End Function
End Class
