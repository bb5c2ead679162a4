Option Strict On

Namespace Generation
    ''' <summary>One to three fixed circles (pegs), up to twice the largest ball; a third of them partly outside the container.</summary>
    Friend NotInheritable Class FixedCirclesIngredient
        Inherits Ingredient

        Friend Overrides ReadOnly Property Name As String = "fixed-circles"
        Friend Overrides ReadOnly Property Needs As BodyKinds = BodyKinds.Circle

        Friend Overrides Sub Apply(scene As SceneBuilder)
            Dim rng = scene.Rng
            Dim count = rng.Between(1, 3)
            For i = 1 To count
                For attempt = 1 To Attempts
                    Dim r = rng.LogUniform(scene.RadiusMin, scene.RadiusCeiling * 2)
                    Dim centre = If(rng.Chance(0.33),
                        New Vector(rng.Uniform(-r, scene.World.Width + r), rng.Uniform(-r, scene.World.Height + r)),
                        scene.PointInside(Math.Min(r, Math.Min(scene.World.Width, scene.World.Height) / 2)))
                    If scene.TryAdd(BodyDraft.FixedCircle(scene.NewId("f"), centre, r)) Then Exit For
                Next
            Next
        End Sub
    End Class
End Namespace
