Option Strict On

Namespace Generation
    ''' <summary>
    ''' One to three fixed rectangles: some standing on the floor, some floating, and a third reaching
    ''' out through a side of the container (fixed bodies may).
    ''' </summary>
    Friend NotInheritable Class RectanglesIngredient
        Inherits Ingredient

        Friend Overrides ReadOnly Property Name As String = "rectangles"
        Friend Overrides ReadOnly Property Needs As BodyKinds = BodyKinds.Rectangle

        Friend Overrides Sub Apply(scene As SceneBuilder)
            Dim count = scene.Rng.Between(1, 3)
            For i = 1 To count
                For attempt = 1 To Attempts
                    If scene.TryAdd(Draw(scene)) Then Exit For
                Next
            Next
        End Sub

        ''' <summary>A random rectangle for the scene (not yet checked against it).</summary>
        Friend Shared Function Draw(scene As SceneBuilder) As BodyDraft
            Dim rng = scene.Rng
            Dim w = scene.World.Width * rng.LogUniform(0.03, 0.5)
            Dim h = scene.World.Height * rng.LogUniform(0.02, 0.4)
            Dim x, y As Double
            Dim u = rng.NextDouble()
            If u < 0.33 Then
                ' partly outside: at least part of it in the container
                x = rng.Uniform(-w / 2, scene.World.Width - w / 2)
                y = rng.Uniform(-h / 2, scene.World.Height - h / 2)
            ElseIf u < 0.6 Then
                x = rng.Uniform(0, scene.World.Width - w)
                y = 0 ' standing on the floor
            Else
                x = rng.Uniform(0, scene.World.Width - w)
                y = rng.Uniform(0, scene.World.Height - h)
            End If
            Return BodyDraft.FixedRectangle(scene.NewId("r"), New Vector(x, y), w, h)
        End Function
    End Class
End Namespace
