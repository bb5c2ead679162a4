Option Strict On

Namespace Generation
    ''' <summary>
    ''' A pyramid of equal balls at rest, every ball exactly touching its neighbours: a base row of 2–5 on
    ''' the floor or a rectangle's top, each row above sitting in the hollows of the one below (centres
    ''' r apart sideways and r√3 up).
    ''' </summary>
    Friend NotInheritable Class StackIngredient
        Inherits Ingredient

        Friend Overrides ReadOnly Property Name As String = "stack"
        Friend Overrides ReadOnly Property Needs As BodyKinds = BodyKinds.Circle

        Friend Overrides Sub Apply(scene As SceneBuilder)
            Dim rng = scene.Rng
            Dim root3 = Math.Sqrt(3.0)
            For attempt = 1 To Attempts
                Dim baseCount = rng.Between(2, 5)
                Do While baseCount > 1 AndAlso baseCount * (baseCount + 1) \ 2 > scene.Budget
                    baseCount -= 1
                Loop
                If baseCount < 2 Then Return
                Dim r = scene.Radius()
                Dim supports = scene.Supports(2 * r * baseCount)
                If supports.Count = 0 Then Return
                Dim s = rng.Pick(supports)
                Dim x0 = rng.Uniform(s.Left, s.Right - 2 * r * baseCount)
                Dim mass = scene.Mass()
                Dim group As New List(Of BodyDraft)
                For row = 0 To baseCount - 1
                    For i = 0 To baseCount - 1 - row
                        Dim centre = New Vector(x0 + r + row * r + 2 * r * i, s.Top + r + row * r * root3)
                        group.Add(BodyDraft.MovableCircle(scene.NewId("c"), centre, r, mass, Vector.Zero))
                    Next
                Next
                If scene.TryAddAll(group) Then Exit For
            Next
        End Sub
    End Class
End Namespace
