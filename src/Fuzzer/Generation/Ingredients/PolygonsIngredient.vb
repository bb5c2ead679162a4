Option Strict On

Namespace Generation
    ''' <summary>
    ''' One to three convex polygons of 3–7 corners, fixed or movable: corners at random directions on a
    ''' circle, in turning order, so the polygon is convex; corners too close together are redrawn.
    ''' </summary>
    Friend NotInheritable Class PolygonsIngredient
        Inherits Ingredient

        Friend Overrides ReadOnly Property Name As String = "polygons"
        Friend Overrides ReadOnly Property Needs As BodyKinds = BodyKinds.Polygon

        Friend Overrides Sub Apply(scene As SceneBuilder)
            Dim rng = scene.Rng
            Dim count = rng.Between(1, 3)
            For i = 1 To count
                For attempt = 1 To Attempts
                    Dim isFixed = rng.Chance(0.5)
                    Dim size = rng.LogUniform(scene.RadiusMin, scene.RadiusMax) * rng.Uniform(1, 3)
                    Dim centre = If(isFixed AndAlso rng.Chance(0.3),
                        New Vector(rng.Uniform(-size, scene.World.Width + size), rng.Uniform(-size, scene.World.Height + size)),
                        scene.PointInside(Math.Min(size, Math.Min(scene.World.Width, scene.World.Height) / 2)))
                    Dim directions = Corners(rng, rng.Between(3, 7))
                    If directions Is Nothing Then Continue For
                    Dim vertices = directions.Select(Function(d) centre + d * size).ToArray()
                    If Not Geometry.IsStrictlyConvex(vertices) Then Continue For
                    Dim body = BodyDraft.Polygon(scene.NewId("p"), vertices, isFixed, scene.Mass(), scene.Velocity())
                    If scene.TryAdd(body) Then Exit For
                Next
            Next
        End Sub

        ''' <summary>Unit vectors in turning order, no two closer than 0.3 apart; Nothing when the draw bunched up.</summary>
        Friend Shared Function Corners(rng As SplitMix, count As Integer) As Vector()
            Dim list As New List(Of Vector)
            For i = 1 To count
                list.Add(rng.Direction())
            Next
            list.Sort(AddressOf ByTurn)
            For i = 0 To list.Count - 1
                If (list(i) - list((i + 1) Mod list.Count)).Length < 0.3 Then Return Nothing
            Next
            Return list.ToArray()
        End Function

        ' Anticlockwise from +x without atan2: first the upper half-plane, then by the sign of the cross product.
        Private Shared Function ByTurn(a As Vector, b As Vector) As Integer
            Dim ha = If(a.Y > 0 OrElse (a.Y = 0 AndAlso a.X > 0), 0, 1)
            Dim hb = If(b.Y > 0 OrElse (b.Y = 0 AndAlso b.X > 0), 0, 1)
            If ha <> hb Then Return ha.CompareTo(hb)
            Return -Math.Sign(Vector.Cross(a, b))
        End Function
    End Class
End Namespace
