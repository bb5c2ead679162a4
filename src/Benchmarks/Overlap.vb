Option Strict On

''' <summary>How far bodies have sunk into each other or into the walls: zero for a correct solver.</summary>
Friend Module Overlap
    ''' <summary>The deepest overlap between two circles, a circle and a rectangle or a segment, or a circle and a wall, m (0 when none).</summary>
    Public Function Deepest(world As World) As Double
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim worst = 0.0
        Dim cs = world.Circles
        For i = 0 To cs.Count - 1
            Dim a = cs(i)
            If world.Walls Then
                worst = Math.Max(worst, a.Radius - a.Position.X)
                worst = Math.Max(worst, a.Radius - a.Position.Y)
                worst = Math.Max(worst, a.Position.X + a.Radius - world.Width)
                worst = Math.Max(worst, a.Position.Y + a.Radius - world.Height)
            End If
            For j = i + 1 To cs.Count - 1
                Dim b = cs(j)
                If a.IsFixed AndAlso b.IsFixed Then Continue For ' fixed bodies never collide with each other
                worst = Math.Max(worst, a.Radius + b.Radius - (a.Position - b.Position).Length)
            Next
            If a.IsFixed Then Continue For
            For Each r In world.Rectangles
                worst = Math.Max(worst, Collider.CircleRectangle(a.Position, a.Radius, r.Min, r.Max).Depth)
            Next
            For Each s In world.Segments
                worst = Math.Max(worst, a.Radius - Vector.DistanceToSegment(a.Position, s.StartPoint, s.EndPoint))
            Next
        Next
        Return worst
    End Function

    ''' <summary>
    ''' The deepest overlap between two axis-aligned rectangles (at least one movable) or a movable rectangle and a
    ''' wall, m (0 when none): two boxes overlap by the smaller of their overlaps along x and along y.
    ''' </summary>
    Public Function DeepestBetweenBoxes(world As World) As Double
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim worst = 0.0
        Dim rs = world.Rectangles
        For i = 0 To rs.Count - 1
            Dim a = rs(i)
            If Not a.IsFixed AndAlso world.Walls Then
                worst = Math.Max(worst, -a.Min.X)
                worst = Math.Max(worst, -a.Min.Y)
                worst = Math.Max(worst, a.Max.X - world.Width)
                worst = Math.Max(worst, a.Max.Y - world.Height)
            End If
            For j = i + 1 To rs.Count - 1
                Dim b = rs(j)
                If a.IsFixed AndAlso b.IsFixed Then Continue For
                worst = Math.Max(worst, Collider.BoxBoxDepth(a.Min, a.Max, b.Min, b.Max))
            Next
        Next
        Return worst
    End Function

    ''' <summary>How many movable circles have their centre inside a fixed body (a fixed circle or a rectangle).</summary>
    Public Function CentresInsideFixedBodies(world As World) As Integer
        If world Is Nothing Then Throw New ArgumentNullException(NameOf(world))
        Dim count = 0
        For Each a In world.Circles
            If a.IsFixed Then Continue For
            Dim p = a.Position
            Dim inside = world.Rectangles.Any(Function(r) p.X > r.Min.X AndAlso p.X < r.Max.X AndAlso p.Y > r.Min.Y AndAlso p.Y < r.Max.Y) OrElse
                         world.Circles.Any(Function(f) f.IsFixed AndAlso (p - f.Position).Length < f.Radius)
            If inside Then count += 1
        Next
        Return count
    End Function
End Module
