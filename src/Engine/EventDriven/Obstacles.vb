Option Strict On

''' <summary>
''' The fixed bodies as the event-driven solver sees them, numbered 0 … Count − 1 (fixed circles
''' first, then rectangles, each in the world's order): what kind each is, where it is, and its
''' bounding box, which the grid uses to list it in the cells it can be touched from. Fixed bodies
''' never move, so this is read once per rebuild.
''' </summary>
Friend NotInheritable Class Obstacles
    Friend Count As Integer
    Friend Shapes As Shape() = Array.Empty(Of Shape)()
    Friend Kind As ObstacleKind() = Array.Empty(Of ObstacleKind)()
    ''' <summary>A fixed circle's centre and radius (m); a rectangle's lower-left (X0, Y0) and upper-right (X1, Y1) corners (m).</summary>
    Friend X0 As Double() = Array.Empty(Of Double)()
    Friend Y0 As Double() = Array.Empty(Of Double)()
    Friend X1 As Double() = Array.Empty(Of Double)()
    Friend Y1 As Double() = Array.Empty(Of Double)()
    Friend Radius As Double() = Array.Empty(Of Double)()

    Friend Sub Load(world As World)
        Dim n = world.Rectangles.Count
        For Each c In world.Circles
            If c.IsFixed Then n += 1
        Next
        Count = n
        Shapes = New Shape(n - 1) {}
        Kind = New ObstacleKind(n - 1) {}
        X0 = New Double(n - 1) {}
        Y0 = New Double(n - 1) {}
        X1 = New Double(n - 1) {}
        Y1 = New Double(n - 1) {}
        Radius = New Double(n - 1) {}
        Dim k = 0
        For Each c In world.Circles
            If Not c.IsFixed Then Continue For
            Shapes(k) = c
            Kind(k) = ObstacleKind.Circle
            X0(k) = c.Position.X
            Y0(k) = c.Position.Y
            X1(k) = c.Position.X
            Y1(k) = c.Position.Y
            Radius(k) = c.Radius
            k += 1
        Next
        For Each r In world.Rectangles
            Shapes(k) = r
            Kind(k) = ObstacleKind.Rectangle
            X0(k) = r.Min.X
            Y0(k) = r.Min.Y
            X1(k) = r.Max.X
            Y1(k) = r.Max.Y
            k += 1
        Next
    End Sub

    ''' <summary>Obstacle k's bounding box, m.</summary>
    Friend Sub Bounds(k As Integer, ByRef xmin As Double, ByRef ymin As Double, ByRef xmax As Double, ByRef ymax As Double)
        xmin = X0(k) - Radius(k)
        ymin = Y0(k) - Radius(k)
        xmax = X1(k) + Radius(k)
        ymax = Y1(k) + Radius(k)
    End Sub
End Class

''' <summary>The kinds of fixed body.</summary>
Friend Enum ObstacleKind As Byte
    Circle
    Rectangle
End Enum
