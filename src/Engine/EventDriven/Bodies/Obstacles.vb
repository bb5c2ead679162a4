Option Strict On

''' <summary>
''' The fixed bodies as the event-driven solver sees them, numbered 0 … Count − 1 (fixed circles
''' first, then rectangles, segments and polygons, each in the world's order): what kind each is,
''' where it is, its outline and its bounding box, which the grid uses to list it in the cells it can
''' be touched from. Fixed bodies never move, so this is read once per rebuild.
''' </summary>
Friend NotInheritable Class Obstacles
    Friend Count As Integer
    Friend Shapes As Shape() = Array.Empty(Of Shape)()
    Friend Kind As ShapeKind() = Array.Empty(Of ShapeKind)()
    ''' <summary>Reference point, m: a fixed circle's centre, a rectangle's lower-left corner, a segment's first end, a polygon's centroid.</summary>
    Friend X0 As Double() = Array.Empty(Of Double)()
    Friend Y0 As Double() = Array.Empty(Of Double)()
    ''' <summary>A rectangle's upper-right corner, m (a circle: its centre again).</summary>
    Friend X1 As Double() = Array.Empty(Of Double)()
    Friend Y1 As Double() = Array.Empty(Of Double)()
    ''' <summary>A fixed circle's radius, m (0 for the others).</summary>
    Friend Radius As Double() = Array.Empty(Of Double)()
    Friend Outlines As Outline() = Array.Empty(Of Outline)()

    Friend Sub Load(world As World)
        Dim list As New List(Of Shape)
        For Each c In world.Circles
            If c.IsFixed Then list.Add(c)
        Next
        For Each r In world.Rectangles
            If r.IsFixed Then list.Add(r)
        Next
        list.AddRange(world.Segments)
        For Each p In world.Polygons
            If p.IsFixed Then list.Add(p)
        Next
        Dim n = list.Count
        Count = n
        Shapes = list.ToArray()
        Kind = New ShapeKind(n - 1) {}
        X0 = New Double(n - 1) {}
        Y0 = New Double(n - 1) {}
        X1 = New Double(n - 1) {}
        Y1 = New Double(n - 1) {}
        Radius = New Double(n - 1) {}
        Outlines = New Outline(n - 1) {}
        For k = 0 To n - 1
            Dim s = Shapes(k)
            Kind(k) = s.Kind
            Outlines(k) = s.Outline
            X0(k) = s.Position.X
            Y0(k) = s.Position.Y
            Radius(k) = s.Outline.Radius
            If s.Kind = ShapeKind.Rectangle Then
                Dim r = DirectCast(s, Rectangle)
                X1(k) = r.Max.X
                Y1(k) = r.Max.Y
            Else
                X1(k) = X0(k)
                Y1(k) = Y0(k)
            End If
        Next
    End Sub

    ''' <summary>Obstacle k's bounding box, m.</summary>
    Friend Sub Bounds(k As Integer, ByRef xmin As Double, ByRef ymin As Double, ByRef xmax As Double, ByRef ymax As Double)
        Dim o = Outlines(k)
        xmin = X0(k) + o.MinX
        ymin = Y0(k) + o.MinY
        xmax = X0(k) + o.MaxX
        ymax = Y0(k) + o.MaxY
    End Sub
End Class
