Option Strict On

Namespace Generation
    ''' <summary>A ball exactly touching a fixed circle from above (straight on top half the time), mostly at rest.</summary>
    Friend NotInheritable Class RestOnFixedCircleIngredient
        Inherits Ingredient

        Friend Overrides ReadOnly Property Name As String = "rest-on-fixed-circle"
        Friend Overrides ReadOnly Property Needs As BodyKinds = BodyKinds.Circle

        Friend Overrides Sub Apply(scene As SceneBuilder)
            Dim rng = scene.Rng
            Dim pegs = scene.Bodies.Where(Function(b) b.Shape = DraftShape.Circle AndAlso b.IsFixed).ToList()
            Dim peg As BodyDraft = Nothing
            If pegs.Count > 0 Then
                peg = rng.Pick(pegs)
            ElseIf scene.Budget >= 2 Then
                Dim r = rng.LogUniform(scene.RadiusMin, scene.RadiusCeiling * 2)
                Dim candidate = BodyDraft.FixedCircle(scene.NewId("f"), scene.PointInside(Math.Min(r, Math.Min(scene.World.Width, scene.World.Height) / 2)), r)
                If scene.TryAdd(candidate) Then peg = candidate
            End If
            If peg Is Nothing Then Return
            For attempt = 1 To Attempts
                Dim r = scene.Radius()
                Dim d = If(rng.Chance(0.5), New Vector(0, 1), rng.Direction())
                If d.Y < 0 Then d = New Vector(d.X, -d.Y)
                Dim centre = peg.Position + d * (peg.Radius + r)
                Dim v = If(rng.Chance(0.7), Vector.Zero, scene.Sliding())
                If scene.TryAdd(scene.Ball(centre, r, v)) Then Exit For
            Next
        End Sub
    End Class
End Namespace
