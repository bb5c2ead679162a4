Option Strict On

Namespace Scenes
    ''' <summary>One body as read and checked from a scene file, before any world is built.</summary>
    Friend NotInheritable Class BodySpec
        ''' <summary>0-based position in the file's "bodies" array.</summary>
        Friend Property Index As Integer
        Friend Property Kind As ShapeKind
        Friend Property Id As String
        ''' <summary>A circle's centre, a rectangle's lower-left corner, a segment's first end, m (a polygon: unused).</summary>
        Friend Property X As Double
        Friend Property Y As Double
        ''' <summary>A segment's second end, m.</summary>
        Friend Property X2 As Double
        Friend Property Y2 As Double
        ''' <summary>m (circles).</summary>
        Friend Property Radius As Double
        ''' <summary>m (rectangles).</summary>
        Friend Property Width As Double
        Friend Property Height As Double
        ''' <summary>A polygon's corners, m, as given.</summary>
        Friend Property Vertices As IReadOnlyList(Of Vector)
        ''' <summary>kg (movable bodies).</summary>
        Friend Property Mass As Double
        ''' <summary>m/s (movable bodies).</summary>
        Friend Property Vx As Double
        Friend Property Vy As Double
        Friend Property IsFixed As Boolean
        ''' <summary>"#rrggbb" or Nothing.</summary>
        Friend Property Color As String
        ''' <summary>The body's own μk and μs, or Nothing for the world's.</summary>
        Friend Property Friction As Double?
        Friend Property StaticFriction As Double?
        ''' <summary>C_d and b (N·s/m) of a movable body; 0 for none.</summary>
        Friend Property DragCoefficient As Double
        Friend Property LinearDrag As Double
        ''' <summary>The body's shape as offsets from <see cref="Position"/>.</summary>
        Friend Property Outline As Outline
        ''' <summary>Its reference point, m (a polygon's centroid).</summary>
        Friend Property Position As Vector

        ''' <summary>
        ''' Where a link joins it, m: its centre of mass, computed as the built body computes it (so a
        ''' distance measured here is the one the world sees): a circle's centre, a rectangle's centre, a
        ''' polygon's centroid.
        ''' </summary>
        Friend ReadOnly Property ReferencePoint As Vector
            Get
                Return Position + Outline.Centroid
            End Get
        End Property

        ''' <summary>Where error messages point: "bodies[3]".</summary>
        Friend ReadOnly Property Place As String
            Get
                Return SceneReader.BodyPlace(Index)
            End Get
        End Property

        ''' <summary>Bounding box, m.</summary>
        Friend ReadOnly Property MinX As Double
            Get
                Return Position.X + Outline.MinX
            End Get
        End Property

        Friend ReadOnly Property MaxX As Double
            Get
                Return Position.X + Outline.MaxX
            End Get
        End Property

        Friend ReadOnly Property MinY As Double
            Get
                Return Position.Y + Outline.MinY
            End Get
        End Property

        Friend ReadOnly Property MaxY As Double
            Get
                Return Position.Y + Outline.MaxY
            End Get
        End Property

        ''' <summary>Builds the model body this spec describes.</summary>
        Friend Function ToShape() As Shape
            Dim p = New Vector(X, Y)
            Dim v = New Vector(Vx, Vy)
            Dim body As Shape
            Select Case Kind
                Case ShapeKind.Circle
                    body = If(IsFixed, Circle.CreateFixed(p, Radius, Id), New Circle(p, Radius, Mass, v, Id))
                Case ShapeKind.Rectangle
                    body = If(IsFixed, New Rectangle(p, Width, Height, Id), Rectangle.CreateMovable(p, Width, Height, Mass, v, Id))
                Case ShapeKind.Segment
                    body = New Segment(p, New Vector(X2, Y2), Id)
                Case Else
                    body = If(IsFixed, Polygon.CreateFixed(Vertices, Id), New Polygon(Vertices, Mass, v, Id))
            End Select
            body.Color = Color
            body.Friction = Friction
            body.StaticFriction = StaticFriction
            body.DragCoefficient = DragCoefficient
            body.LinearDrag = LinearDrag
            Return body
        End Function
    End Class
End Namespace
