Option Strict On

Namespace Generation
    ''' <summary>
    ''' Two balls touching exactly (centres r₁ + r₂ apart) in a random direction: at rest, moving at
    ''' random, or pressing into each other (a collision at t = 0). Now and then one of them is fixed.
    ''' </summary>
    Friend NotInheritable Class TouchingPairIngredient
        Inherits Ingredient

        Friend Overrides ReadOnly Property Name As String = "touching-pair"
        Friend Overrides ReadOnly Property Needs As BodyKinds = BodyKinds.Circle

        Friend Overrides Sub Apply(scene As SceneBuilder)
            Dim rng = scene.Rng
            For attempt = 1 To Attempts
                Dim r1 = scene.Radius(), r2 = scene.Radius()
                Dim d = rng.Direction()
                Dim p1 = scene.PointInside(r1)
                Dim p2 = p1 + d * (r1 + r2)
                Dim mode = rng.NextDouble()
                Dim v1, v2 As Vector
                If mode < 0.3 Then
                    v1 = Vector.Zero
                    v2 = Vector.Zero
                ElseIf mode < 0.6 Then
                    Dim s = If(scene.SpeedTop > 0, rng.LogUniform(scene.SpeedTop * 0.001, scene.SpeedTop), 1.0)
                    v1 = d * s
                    v2 = d * -s * rng.NextDouble()
                Else
                    v1 = scene.Velocity()
                    v2 = scene.Velocity()
                End If
                Dim first = BodyDraft.MovableCircle(scene.NewId("c"), p1, r1, scene.Mass(), v1)
                Dim second = If(rng.Chance(0.25),
                    BodyDraft.FixedCircle(scene.NewId("f"), p2, r2),
                    BodyDraft.MovableCircle(scene.NewId("c"), p2, r2, scene.Mass(), v2))
                If scene.TryAddAll({first, second}) Then Exit For
            Next
        End Sub
    End Class
End Namespace
