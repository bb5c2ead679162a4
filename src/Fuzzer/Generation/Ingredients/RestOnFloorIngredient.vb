Option Strict On

Namespace Generation
    ''' <summary>A ball exactly on the floor (y = r), at rest or rolling; one in five sits in a corner, touching two walls.</summary>
    Friend NotInheritable Class RestOnFloorIngredient
        Inherits Ingredient

        Friend Overrides ReadOnly Property Name As String = "rest-on-floor"
        Friend Overrides ReadOnly Property Needs As BodyKinds = BodyKinds.Circle

        Friend Overrides Sub Apply(scene As SceneBuilder)
            If Not scene.World.Walls Then Return
            Dim rng = scene.Rng
            For attempt = 1 To Attempts
                Dim r = scene.Radius()
                Dim x As Double
                If rng.Chance(0.2) Then
                    x = If(rng.Chance(0.5), r, scene.World.Width - r)
                Else
                    x = rng.Uniform(r, scene.World.Width - r)
                End If
                If scene.TryAdd(scene.Ball(New Vector(x, r), r, scene.Sliding())) Then Exit For
            Next
        End Sub
    End Class
End Namespace
