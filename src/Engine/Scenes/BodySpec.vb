Option Strict On

Namespace Scenes
    ''' <summary>One body as read and checked from a scene file, before any world is built.</summary>
    Friend NotInheritable Class BodySpec
        ''' <summary>0-based position in the file's "bodies" array.</summary>
        Friend Property Index As Integer
        Friend Property IsRectangle As Boolean
        Friend Property Id As String
        ''' <summary>Centre of a circle, lower-left corner of a rectangle, m.</summary>
        Friend Property X As Double
        Friend Property Y As Double
        ''' <summary>m (circles).</summary>
        Friend Property Radius As Double
        ''' <summary>kg (movable circles).</summary>
        Friend Property Mass As Double
        ''' <summary>m/s (movable circles).</summary>
        Friend Property Vx As Double
        Friend Property Vy As Double
        Friend Property IsFixed As Boolean
        ''' <summary>m (rectangles).</summary>
        Friend Property Width As Double
        Friend Property Height As Double
        ''' <summary>"#rrggbb" or Nothing.</summary>
        Friend Property Color As String

        ''' <summary>Where error messages point: "bodies[3]".</summary>
        Friend ReadOnly Property Place As String
            Get
                Return SceneReader.BodyPlace(Index)
            End Get
        End Property

        Friend ReadOnly Property IsMovableCircle As Boolean
            Get
                Return Not IsRectangle AndAlso Not IsFixed
            End Get
        End Property

        ''' <summary>Bounding box, m.</summary>
        Friend ReadOnly Property MinX As Double
            Get
                Return If(IsRectangle, X, X - Radius)
            End Get
        End Property

        Friend ReadOnly Property MaxX As Double
            Get
                Return If(IsRectangle, X + Width, X + Radius)
            End Get
        End Property

        Friend ReadOnly Property MinY As Double
            Get
                Return If(IsRectangle, Y, Y - Radius)
            End Get
        End Property

        Friend ReadOnly Property MaxY As Double
            Get
                Return If(IsRectangle, Y + Height, Y + Radius)
            End Get
        End Property
    End Class
End Namespace
