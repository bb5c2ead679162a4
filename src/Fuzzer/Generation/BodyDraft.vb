Option Strict On

Namespace Generation
    ''' <summary>
    ''' One body of a generated scene: its geometry (for placing the next bodies) and how it is written in
    ''' physics-scene/1. Every number is kept exactly as it is written, so the scene reader sees the same
    ''' doubles the generator checked.
    ''' </summary>
    Friend NotInheritable Class BodyDraft
        Private Sub New()
        End Sub

        ''' <summary>Unique in the scene.</summary>
        Friend Property Id As String
        Friend Property Shape As DraftShape
        Friend Property IsFixed As Boolean
        ''' <summary>A circle's centre, a rectangle's lower-left corner, a segment's first end, m.</summary>
        Friend Property Position As Vector
        ''' <summary>A circle's radius, m.</summary>
        Friend Property Radius As Double
        ''' <summary>A rectangle's size, m.</summary>
        Friend Property Width As Double
        Friend Property Height As Double
        ''' <summary>A segment's second end, m.</summary>
        Friend Property EndPoint As Vector
        ''' <summary>A polygon's corners in order, m.</summary>
        Friend Property Vertices As Vector()
        ''' <summary>kg (movable bodies).</summary>
        Friend Property Mass As Double
        ''' <summary>m/s (movable bodies).</summary>
        Friend Property Velocity As Vector

        ''' <summary>A movable circle.</summary>
        Friend Shared Function MovableCircle(id As String, centre As Vector, radius As Double, mass As Double, velocity As Vector) As BodyDraft
            Return New BodyDraft With {.Id = id, .Shape = DraftShape.Circle, .Position = centre, .Radius = radius, .Mass = mass, .Velocity = velocity}
        End Function

        ''' <summary>A fixed circle.</summary>
        Friend Shared Function FixedCircle(id As String, centre As Vector, radius As Double) As BodyDraft
            Return New BodyDraft With {.Id = id, .Shape = DraftShape.Circle, .IsFixed = True, .Position = centre, .Radius = radius}
        End Function

        ''' <summary>A fixed rectangle from its lower-left corner and size.</summary>
        Friend Shared Function FixedRectangle(id As String, lowerLeft As Vector, width As Double, height As Double) As BodyDraft
            Return New BodyDraft With {.Id = id, .Shape = DraftShape.Rectangle, .IsFixed = True, .Position = lowerLeft, .Width = width, .Height = height}
        End Function

        ''' <summary>A movable box (a rectangle with "fixed": false).</summary>
        Friend Shared Function Box(id As String, lowerLeft As Vector, width As Double, height As Double, mass As Double, velocity As Vector) As BodyDraft
            Return New BodyDraft With {.Id = id, .Shape = DraftShape.Rectangle, .Position = lowerLeft, .Width = width, .Height = height, .Mass = mass, .Velocity = velocity}
        End Function

        ''' <summary>A fixed segment between two different points.</summary>
        Friend Shared Function Segment(id As String, a As Vector, b As Vector) As BodyDraft
            Return New BodyDraft With {.Id = id, .Shape = DraftShape.Segment, .IsFixed = True, .Position = a, .EndPoint = b}
        End Function

        ''' <summary>A convex polygon, fixed (mass ignored) or movable.</summary>
        Friend Shared Function Polygon(id As String, vertices As Vector(), isFixed As Boolean, mass As Double, velocity As Vector) As BodyDraft
            Return New BodyDraft With {.Id = id, .Shape = DraftShape.Polygon, .IsFixed = isFixed, .Vertices = vertices, .Mass = mass, .Velocity = If(isFixed, Vector.Zero, velocity)}
        End Function

        ''' <summary>A rectangle's upper-right corner, m, summed as the reader sums it.</summary>
        Friend ReadOnly Property Corner As Vector
            Get
                Return New Vector(Position.X + Width, Position.Y + Height)
            End Get
        End Property

        ''' <summary>The point links attach to: a circle's centre, a rectangle's centre, a polygon's centroid, m.</summary>
        Friend ReadOnly Property ReferencePoint As Vector
            Get
                Select Case Shape
                    Case DraftShape.Circle : Return Position
                    Case DraftShape.Rectangle : Return New Vector(Position.X + Width / 2, Position.Y + Height / 2)
                    Case DraftShape.Polygon : Return Geometry.Centroid(Vertices)
                    Case Else : Return (Position + EndPoint) * 0.5
                End Select
            End Get
        End Property

        ''' <summary>A circle that holds the whole body: the body itself for a circle, m.</summary>
        Friend Function Bound() As BodyDraft
            Select Case Shape
                Case DraftShape.Circle
                    Return Me
                Case DraftShape.Rectangle
                    Return New BodyDraft With {.Shape = DraftShape.Circle, .IsFixed = IsFixed, .Position = ReferencePoint, .Radius = Vector.Hypot(Width, Height) / 2 * (1 + 0.000001)}
                Case DraftShape.Segment
                    Return New BodyDraft With {.Shape = DraftShape.Circle, .IsFixed = True, .Position = ReferencePoint, .Radius = (EndPoint - Position).Length / 2 * (1 + 0.000001)}
                Case Else
                    Dim c = ReferencePoint
                    Dim r = 0.0
                    For Each v In Vertices
                        r = Math.Max(r, (v - c).Length)
                    Next
                    Return New BodyDraft With {.Shape = DraftShape.Circle, .IsFixed = IsFixed, .Position = c, .Radius = r * (1 + 0.000001)}
            End Select
        End Function

        ''' <summary>The body as one physics-scene/1 object.</summary>
        Friend Function ToJson() As String
            Dim j = New JsonText().Add("id", Id)
            Select Case Shape
                Case DraftShape.Circle
                    j.Add("type", "circle").Add("x", Position.X).Add("y", Position.Y).Add("radius", Radius)
                    If IsFixed Then
                        j.Add("fixed", True)
                    Else
                        j.Add("mass", Mass).Add("vx", Velocity.X).Add("vy", Velocity.Y)
                    End If
                Case DraftShape.Rectangle
                    j.Add("type", "rectangle").Add("x", Position.X).Add("y", Position.Y).Add("width", Width).Add("height", Height)
                    If Not IsFixed Then j.Add("fixed", False).Add("mass", Mass).Add("vx", Velocity.X).Add("vy", Velocity.Y)
                Case DraftShape.Segment
                    j.Add("type", "segment").Add("x1", Position.X).Add("y1", Position.Y).Add("x2", EndPoint.X).Add("y2", EndPoint.Y)
                Case Else
                    j.Add("type", "polygon").Raw("vertices", "[" & String.Join(", ", Vertices.Select(Function(v) JsonText.Point(v))) & "]")
                    If IsFixed Then
                        j.Add("fixed", True)
                    Else
                        j.Add("mass", Mass).Add("vx", Velocity.X).Add("vy", Velocity.Y)
                    End If
            End Select
            Return j.ToString()
        End Function
    End Class
End Namespace
