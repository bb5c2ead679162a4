Option Strict On
Imports System.Globalization

Namespace Checking
    ''' <summary>
    ''' What must hold in any state of a world, as pure functions: each returns Nothing when the state is
    ''' fine, or one line saying what is wrong (the deepest case, where there is a measure).
    ''' </summary>
    Friend Module StateChecks
        ''' <summary>
        ''' Overlap and wall slack, m: the scene format's own tolerance, so a run is held to exactly what a
        ''' scene file may contain at its start.
        ''' </summary>
        Friend Const Tolerance As Double = 0.000000001

        ''' <summary>The first movable body (circle, box or polygon) whose position or velocity is NaN or infinite.</summary>
        Friend Function NotFinite(world As World) As String
            For Each c In world.Movables
                If Not c.Position.IsFinite OrElse Not c.Velocity.IsFinite Then Return c.Id & " is at " & c.Position.ToString() & " moving at " & c.Velocity.ToString()
            Next
            Return Nothing
        End Function

        ''' <summary>
        ''' With walls on: the movable body furthest outside the container, when one is out by more than
        ''' <see cref="Tolerance"/> (a circle by its centre and radius, a box or polygon by its bounds).
        ''' </summary>
        Friend Function Outside(world As World) As String
            If Not world.Walls Then Return Nothing
            Dim worst = Tolerance
            Dim found As String = Nothing
            For Each c In world.Movables
                Dim p = c.Position
                Dim lo = c.BoundsMin, hi = c.BoundsMax
                Dim beyond = {-lo.X, hi.X - world.Width, -lo.Y, hi.Y - world.Height}
                Dim sides = {"the left wall", "the right wall", "the floor", "the top"}
                For k = 0 To 3
                    If beyond(k) > worst Then
                        worst = beyond(k)
                        found = c.Id & " " & p.ToString() & " sticks out of " & sides(k) & " by " & Brief(beyond(k)) & " m"
                    End If
                Next
            Next
            Return found
        End Function

        ''' <summary>
        ''' A movable circle whose centre is inside a fixed circle or a rectangle (strictly: a centre on the
        ''' boundary has gone in by a whole radius but no further). The one deepest in, measured from the
        ''' nearest boundary.
        ''' </summary>
        Friend Function CentreInside(world As World) As String
            Dim worst = 0.0
            Dim found As String = Nothing
            For Each c In world.Circles
                If c.IsFixed Then Continue For
                Dim p = c.Position
                For Each f In world.Circles
                    If Not f.IsFixed Then Continue For
                    Dim inside = f.Radius - (p - f.Position).Length
                    If inside > worst Then
                        worst = inside
                        found = "the centre of " & c.Id & " " & p.ToString() & " is inside fixed circle " & f.Id & ", " & Brief(inside) & " m from its edge"
                    End If
                Next
                For Each rect In world.Rectangles
                    Dim lo = rect.Min, hi = rect.Max
                    If p.X > lo.X AndAlso p.X < hi.X AndAlso p.Y > lo.Y AndAlso p.Y < hi.Y Then
                        Dim inside = Math.Min(Math.Min(p.X - lo.X, hi.X - p.X), Math.Min(p.Y - lo.Y, hi.Y - p.Y))
                        If inside > worst Then
                            worst = inside
                            found = "the centre of " & c.Id & " " & p.ToString() & " is inside rectangle " & rect.Id & ", " & Brief(inside) & " m from its nearest face"
                        End If
                    End If
                Next
            Next
            Return found
        End Function

        ''' <summary>
        ''' The deepest overlap, beyond <see cref="Tolerance"/>, between two bodies that collide with each
        ''' other: two circles (not both fixed), or a movable circle and a rectangle. Walls are
        ''' <see cref="Outside"/>'s.
        ''' </summary>
        Friend Function Overlap(world As World) As String
            Dim worst = Tolerance
            Dim found As String = Nothing
            Dim circles = world.Circles
            For i = 0 To circles.Count - 1
                Dim a = circles(i)
                For j = i + 1 To circles.Count - 1
                    Dim b = circles(j)
                    If a.IsFixed AndAlso b.IsFixed Then Continue For
                    Dim depth = a.Radius + b.Radius - Vector.Hypot(a.Position.X - b.Position.X, a.Position.Y - b.Position.Y)
                    If depth > worst Then
                        worst = depth
                        found = a.Id & " and " & b.Id & " overlap by " & Brief(depth) & " m"
                    End If
                Next
                If a.IsFixed Then Continue For
                For Each rect In world.Rectangles
                    Dim depth = Generation.Geometry.CircleBoxDepth(a.Position.X, a.Position.Y, a.Radius, rect.Min.X, rect.Min.Y, rect.Max.X, rect.Max.Y)
                    If depth > worst Then
                        worst = depth
                        found = a.Id & " " & a.Position.ToString() & " and rectangle " & rect.Id & " overlap by " & Brief(depth) & " m"
                    End If
                Next
            Next
            Return found
        End Function

        ''' <summary>A number for a message: six digits, invariant.</summary>
        Friend Function Brief(value As Double) As String
            Return value.ToString("G6", CultureInfo.InvariantCulture)
        End Function
    End Module
End Namespace
