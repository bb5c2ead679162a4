Option Strict On
Imports PhysicsEngine

''' <summary>
''' Seeded random scenes with every kind of body: fixed segments (ramps), fixed polygons, rectangles and
''' circles, and movable circles, boxes and polygons placed where they overlap nothing. The same seed
''' gives the same scene.
''' </summary>
Public NotInheritable Class MixedScenes
    Private Sub New()
    End Sub

    ''' <summary>A walled 3 m × 2 m container with g and e as given and about <paramref name="movables"/> movable bodies.</summary>
    Public Shared Function Build(seed As Integer, movables As Integer, gravity As Double, restitution As Double) As World
        Dim rng As New Random(seed)
        Dim w As New World(3.0, 2.0, gravity, restitution)
        ' Obstacles: two ramps, a triangle, a table, a peg.
        w.Add(New Segment(New Vector(0.1, 1.2), New Vector(1.2, 0.7 + 0.3 * rng.NextDouble()), "ramp1"))
        w.Add(New Segment(New Vector(2.9, 1.0), New Vector(1.9, 0.5 + 0.3 * rng.NextDouble()), "ramp2"))
        w.Add(Polygon.CreateFixed({New Vector(1.3, 0), New Vector(1.8, 0), New Vector(1.55, 0.3 + 0.2 * rng.NextDouble())}, "wedge"))
        w.Add(New Rectangle(New Vector(2.4, 0), 0.6, 0.25, "table"))
        w.Add(Circle.CreateFixed(New Vector(0.7, 0.35), 0.08, "peg"))
        Dim placed = 0, tries = 0
        While placed < movables AndAlso tries < 20000
            tries += 1
            Dim p = New Vector(0.1 + 2.8 * rng.NextDouble(), 0.1 + 1.8 * rng.NextDouble())
            Dim v = New Vector(4 * rng.NextDouble() - 2, 4 * rng.NextDouble() - 2)
            Dim mass = Math.Pow(10, 4 * rng.NextDouble() - 2)
            Dim body As Shape
            Dim size = 0.02 + 0.08 * rng.NextDouble()
            Select Case rng.Next(3)
                Case 0
                    body = New Circle(p, size, mass, v)
                Case 1
                    body = Rectangle.CreateMovable(p, size * (0.5 + rng.NextDouble()), size * (0.5 + rng.NextDouble()), mass, v)
                Case Else
                    Dim corners = 3 + rng.Next(4)
                    Dim turn = 2 * Math.PI * rng.NextDouble()
                    Dim vertices As New List(Of Vector)
                    For k = 0 To corners - 1
                        Dim angle = turn + 2 * Math.PI * k / corners
                        vertices.Add(p + size * New Vector(Math.Cos(angle), Math.Sin(angle)))
                    Next
                    body = New Polygon(vertices, mass, v)
            End Select
            If body.BoundsMin.X < 0 OrElse body.BoundsMin.Y < 0 OrElse body.BoundsMax.X > w.Width OrElse body.BoundsMax.Y > w.Height Then Continue While
            Dim clear = True
            For Each other In w.Bodies
                If Collider.OutlineOutline(body.Outline, body.Position, other.Outline, other.Position).Depth > -0.001 Then
                    clear = False
                    Exit For
                End If
            Next
            If Not clear Then Continue While
            w.Add(body)
            placed += 1
        End While
        Return w
    End Function

    ''' <summary>The fixed body whose shape holds movable body b's centre of mass by more than a rounding error, or Nothing.</summary>
    Public Shared Function FixedHoldingCentre(w As World, b As Shape) As Shape
        Dim c = b.CentreOfMass
        For Each f In w.Bodies
            If Not f.IsFixed Then Continue For
            Dim depth = OutlineContact.Penetration(f.Outline, c - f.Position).Depth
            If f.Kind <> ShapeKind.Segment AndAlso depth > 0.000000001 Then Return f
        Next
        Return Nothing
    End Function
End Class
