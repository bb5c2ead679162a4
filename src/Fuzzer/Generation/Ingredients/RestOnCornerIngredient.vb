Option Strict On

Namespace Generation
    ''' <summary>
    ''' A ball exactly on a fixed rectangle's corner: balanced right above a top corner (the hardest case
    ''' for a contact rule), or touching a corner from outside along a random diagonal, mostly at rest.
    ''' </summary>
    Friend NotInheritable Class RestOnCornerIngredient
        Inherits Ingredient

        Friend Overrides ReadOnly Property Name As String = "rest-on-corner"
        Friend Overrides ReadOnly Property Needs As BodyKinds = BodyKinds.Circle Or BodyKinds.Rectangle

        Friend Overrides Sub Apply(scene As SceneBuilder)
            Dim rng = scene.Rng
            Dim rect = RestOnRectangleIngredient.PickOrMakeRectangle(scene)
            If rect Is Nothing Then Return
            For attempt = 1 To Attempts
                Dim r = scene.Radius()
                Dim right = rng.Chance(0.5)
                Dim top = rng.Chance(0.8)
                Dim corner = New Vector(If(right, rect.Corner.X, rect.Position.X), If(top, rect.Corner.Y, rect.Position.Y))
                Dim centre As Vector
                If top AndAlso rng.Chance(0.5) Then
                    centre = New Vector(corner.X, corner.Y + r) ' balanced on the corner's point
                Else
                    ' touching the corner from its outer quadrant
                    Dim d = New Vector(rng.Uniform(0.05, 1), rng.Uniform(0.05, 1))
                    d = d / d.Length
                    centre = corner + New Vector(If(right, d.X, -d.X), If(top, d.Y, -d.Y)) * r
                End If
                Dim v = If(rng.Chance(0.7), Vector.Zero, scene.Sliding())
                If scene.TryAdd(scene.Ball(centre, r, v)) Then Exit For
            Next
        End Sub
    End Class
End Namespace
