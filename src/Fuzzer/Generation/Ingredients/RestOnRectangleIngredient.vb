Option Strict On

Namespace Generation
    ''' <summary>
    ''' One to three balls exactly on a fixed rectangle's top (centre r above it, over the face), at rest or
    ''' rolling along it; a rectangle is made when there is none.
    ''' </summary>
    Friend NotInheritable Class RestOnRectangleIngredient
        Inherits Ingredient

        Friend Overrides ReadOnly Property Name As String = "rest-on-rectangle"
        Friend Overrides ReadOnly Property Needs As BodyKinds = BodyKinds.Circle Or BodyKinds.Rectangle

        Friend Overrides Sub Apply(scene As SceneBuilder)
            Dim rng = scene.Rng
            Dim rect = PickOrMakeRectangle(scene)
            If rect Is Nothing Then Return
            Dim count = rng.Between(1, 3)
            For i = 1 To count
                For attempt = 1 To Attempts
                    Dim r = scene.Radius()
                    Dim centre = New Vector(rng.Uniform(rect.Position.X, rect.Corner.X), rect.Corner.Y + r)
                    If scene.TryAdd(scene.Ball(centre, r, scene.Sliding())) Then Exit For
                Next
            Next
        End Sub

        ''' <summary>A fixed rectangle of the scene, or a new one when there is none (Nothing when none fits).</summary>
        Friend Shared Function PickOrMakeRectangle(scene As SceneBuilder) As BodyDraft
            Dim existing = scene.FixedRectangles()
            If existing.Count > 0 Then Return scene.Rng.Pick(existing)
            If scene.Budget < 2 Then Return Nothing
            For attempt = 1 To Attempts
                Dim rect = RectanglesIngredient.Draw(scene)
                If scene.TryAdd(rect) Then Return rect
            Next
            Return Nothing
        End Function
    End Class
End Namespace
