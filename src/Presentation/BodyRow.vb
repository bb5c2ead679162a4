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
    ''' <summary>What the body is, as the Bodies table names it: "ball", "box", a polygon by its sides ("triangle", "quadrilateral", "dodecagon"; "polygon" past twelve), each led by "fixed" when it is ("fixed ball", "fixed box", "fixed pentagon"); a ramp is always "fixed ramp".</summary>
    Public Property KindLabel As String
    ''' <summary>Where its mass is centred (a ramp's middle), m.</summary>
    Public Property Centre As Vector
    ''' <summary>The body's size in words: "r 0.25", "1 × 0.5", "length 2.83", a polygon's width × height "0.8 × 0.76" (m).</summary>
    Public Property SizeText As String
    ''' <summary>The body's sizes by the names a scene file gives them, m: ("radius", r) for a circle; ("width", w), ("height", h) for a rectangle.</summary>
    Public Property SizeFields As IReadOnlyList(Of (Name As String, Metres As Double))

    ''' <summary>Whether the body's surface takes friction (every kind but a ball).</summary>
    Public Property TakesFriction As Boolean
    ''' <summary>μk of the body's own surface, or Nothing for the world's.</summary>
    Public Property OwnKinetic As Double?
    ''' <summary>μs of the body's own surface, or Nothing (its own μk when set, else the world's μs).</summary>
    Public Property OwnStatic As Double?
    ''' <summary>The μk its surface has in effect (its own or the world's); set when a snapshot is taken with the world.</summary>
    Public Property Kinetic As Double
    ''' <summary>The μs its surface has in effect; set when a snapshot is taken with the world.</summary>
    Public Property [Static] As Double

    ''' <summary>Whether the canvas fills the body with the theme's fixed colour rather than its own (fixed rectangles, polygons and ramps; a fixed ball keeps its colour, with a cross).</summary>
    Public Property DrawnInFixedColour As Boolean

    ''' <summary>The row of a body now, every number exact. Sizes are the one thing read by kind of body.</summary>
    Public Shared Function Capture(body As Shape) As BodyRow
        Return Capture(body, 0, 0)
    End Function

    ''' <summary>
    ''' The row of a body now, with a coordinate at rounding noise beside <paramref name="lengthScale"/>
    ''' (m, the container's size) and a velocity component at noise beside <paramref name="speedScale"/>
    ''' (m/s) shown as 0 (see <see cref="Units.NoiseFraction"/>).
    ''' </summary>
    Public Shared Function Capture(body As Shape, lengthScale As Double, speedScale As Double) As BodyRow
        If body Is Nothing Then Throw New ArgumentNullException(NameOf(body))
        Dim clean = Function(v As Vector, scale As Double) New Vector(Units.AtNoise(v.X, scale), Units.AtNoise(v.Y, scale))
        Dim row As New BodyRow With {
            .Id = body.Id, .Colour = If(body.Color, ""), .IsFixed = body.IsFixed, .Area = body.Area,
            .Position = clean(body.Position, lengthScale), .Velocity = clean(body.Velocity, speedScale), .Mass = body.Mass,
            .Centre = clean(body.CentreOfMass, lengthScale), .DrawnInFixedColour = body.IsFixed AndAlso body.Kind <> ShapeKind.Circle,
            .TakesFriction = body.Kind <> ShapeKind.Circle, .OwnKinetic = body.Friction, .OwnStatic = body.StaticFriction,
            .Kinetic = If(body.Friction, 0.0), .Static = If(body.StaticFriction, If(body.Friction, 0.0))}
        Select Case body.Kind
            Case ShapeKind.Circle
                Dim r = DirectCast(body, Circle).Radius
                row.Size = New Vector(r, 0)
                row.SizeFields = {("radius", r)}
                row.KindLabel = FixedWord(body) & "ball"
                row.SizeText = "r " & Units.Sig(r)
            Case ShapeKind.Rectangle
                Dim box = DirectCast(body, Rectangle)
                row.Size = New Vector(box.Width, box.Height)
                row.SizeFields = {("width", box.Width), ("height", box.Height)}
                row.KindLabel = FixedWord(body) & "box"
                row.SizeText = Units.Sig(box.Width) & " × " & Units.Sig(box.Height)
            Case ShapeKind.Segment
                Dim length = DirectCast(body, Segment).Length
                row.Size = New Vector(length, 0)
                row.SizeFields = {("length", length)}
                row.KindLabel = FixedWord(body) & "ramp"
                row.SizeText = "length " & Units.Sig(length)
            Case Else
                row.Size = body.BoundsMax - body.BoundsMin
                row.SizeFields = Array.Empty(Of (Name As String, Metres As Double))()
                ' Its sides in its name ("pentagon"), its size as a box's: the Size column then needs no more room for a polygon than for a box.
                row.KindLabel = FixedWord(body) & PolygonName(body.Outline.VertexCount)
                row.SizeText = Units.Sig(row.Size.X) & " × " & Units.Sig(row.Size.Y)
        End Select
        Return row
    End Function

    ''' <summary>"fixed " before a fixed body's kind, so that every kind reads alike in the Kind column ("fixed ball", "fixed box", "fixed pentagon"); "" for a movable one.</summary>
    Private Shared Function FixedWord(body As Shape) As String
        Return If(body.IsFixed, "fixed ", "")
    End Function

    ''' <summary>A polygon's name by its number of sides: "triangle" to "dodecagon", "polygon" past twelve.</summary>
    Public Shared Function PolygonName(sides As Integer) As String
        Select Case sides
            Case 3 : Return "triangle"
            Case 4 : Return "quadrilateral"
            Case 5 : Return "pentagon"
            Case 6 : Return "hexagon"
            Case 7 : Return "heptagon"
            Case 8 : Return "octagon"
            Case 9 : Return "nonagon"
            Case 10 : Return "decagon"
            Case 11 : Return "hendecagon"
            Case 12 : Return "dodecagon"
        End Select
        Return "polygon"
    End Function
End Structure
