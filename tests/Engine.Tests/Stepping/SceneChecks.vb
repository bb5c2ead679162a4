Option Strict On
Imports PhysicsEngine

''' <summary>Measurements the stepping tests share.</summary>
Public NotInheritable Class SceneChecks
    Private Sub New()
    End Sub

    ''' <summary>The deepest overlap, m, between any two circles (not both fixed), or between a movable circle and a rectangle; ≤ 0 when nothing overlaps.</summary>
    Public Shared Function MaxOverlap(w As World) As Double
        Dim worst = Double.NegativeInfinity
        Dim circles = w.Circles
        For i = 0 To circles.Count - 1
            Dim a = circles(i)
            For j = i + 1 To circles.Count - 1
                Dim b = circles(j)
                If a.IsFixed AndAlso b.IsFixed Then Continue For
                worst = Math.Max(worst, Collider.CircleCircle(a.Position, a.Radius, b.Position, b.Radius).Depth)
            Next
            If a.IsFixed Then Continue For
            For Each r In w.Rectangles
                worst = Math.Max(worst, Collider.CircleRectangle(a.Position, a.Radius, r.Min, r.Max).Depth)
            Next
        Next
        Return worst
    End Function

    ''' <summary>True when every circle's position and velocity are finite numbers.</summary>
    Public Shared Function AllFinite(w As World) As Boolean
        For Each c In w.Circles
            If Not (c.Position.IsFinite AndAlso c.Velocity.IsFinite) Then Return False
        Next
        Return True
    End Function
End Class
