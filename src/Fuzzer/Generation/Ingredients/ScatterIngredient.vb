Option Strict On

Namespace Generation
    ''' <summary>Movable balls anywhere in the container, of the scene's sizes, masses and speeds, until the budget is spent.</summary>
    Friend NotInheritable Class ScatterIngredient
        Inherits Ingredient

        Friend Overrides ReadOnly Property Name As String = "scatter"
        Friend Overrides ReadOnly Property Needs As BodyKinds = BodyKinds.Circle

        Friend Overrides Sub Apply(scene As SceneBuilder)
            Dim misses = 0
            Do While scene.Budget > 0 AndAlso misses < Attempts
                Dim r = scene.Radius()
                If scene.TryAdd(scene.Ball(scene.PointInside(r), r)) Then misses = 0 Else misses += 1
            Loop
        End Sub
    End Class
End Namespace
