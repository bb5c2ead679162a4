Option Strict On

Namespace Generation
    ''' <summary>
    ''' A row of 2–7 equal balls placed exactly touching (centres 2r apart), on the floor, on a rectangle's
    ''' top or in mid-air: Newton's cradle. The first ball presses into the row, or a striker comes at it
    ''' from a gap, or nothing moves. A quarter of the rows stand upright as a tower.
    ''' </summary>
    Friend NotInheritable Class CradleIngredient
        Inherits Ingredient

        Friend Overrides ReadOnly Property Name As String = "cradle"
        Friend Overrides ReadOnly Property Needs As BodyKinds = BodyKinds.Circle

        Friend Overrides Sub Apply(scene As SceneBuilder)
            Dim rng = scene.Rng
            For attempt = 1 To Attempts
                Dim n = Math.Min(rng.Between(2, 7), scene.Budget)
                If n < 2 Then Return
                Dim r = scene.Radius()
                Dim equal = rng.Chance(0.7)
                Dim mass = scene.Mass()
                Dim upright = rng.Chance(0.25)
                Dim span = If(upright, 2 * r, 2 * r * n)
                Dim supports = scene.Supports(span)
                Dim start As Vector
                If supports.Count > 0 AndAlso rng.Chance(0.7) Then
                    Dim s = rng.Pick(supports)
                    start = New Vector(rng.Uniform(s.Left + r, s.Right - span + r), s.Top + r)
                Else
                    start = scene.PointInside(r)
                End If
                Dim stepVector = If(upright, New Vector(0, 2 * r), New Vector(2 * r, 0))
                Dim speed = If(scene.SpeedTop > 0, rng.LogUniform(scene.SpeedTop * 0.001, scene.SpeedTop), 0.0)
                Dim mode = rng.NextDouble()
                Dim group As New List(Of BodyDraft)
                For i = 0 To n - 1
                    Dim v = Vector.Zero
                    If i = 0 AndAlso mode < 0.5 Then v = stepVector / (2 * r) * speed ' the first ball presses into the row
                    group.Add(BodyDraft.MovableCircle(scene.NewId("c"), start + stepVector * i, r, If(equal, mass, scene.Mass()), v))
                Next
                If mode >= 0.5 AndAlso mode < 0.8 AndAlso n + 1 <= scene.Budget Then
                    ' a striker a gap away, coming at the row
                    Dim gap = r * rng.LogUniform(0.01, 4)
                    group.Add(BodyDraft.MovableCircle(scene.NewId("c"), start - stepVector / (2 * r) * (2 * r + gap), r, If(equal, mass, scene.Mass()), stepVector / (2 * r) * speed))
                End If
                If scene.TryAddAll(group) Then Exit For
            Next
        End Sub
    End Class
End Namespace
