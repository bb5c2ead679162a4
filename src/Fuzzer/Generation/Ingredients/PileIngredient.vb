Option Strict On

Namespace Generation
    ''' <summary>
    ''' A heap about to happen: 3–20 balls of similar size at rest in a loose cluster just above the floor or
    ''' a rectangle's top (or in mid-air), so that gravity drops them onto each other.
    ''' </summary>
    Friend NotInheritable Class PileIngredient
        Inherits Ingredient

        Friend Overrides ReadOnly Property Name As String = "pile"
        Friend Overrides ReadOnly Property Needs As BodyKinds = BodyKinds.Circle

        Friend Overrides Sub Apply(scene As SceneBuilder)
            Dim rng = scene.Rng
            Dim n = Math.Min(rng.Between(3, 20), scene.Budget)
            Dim r = scene.Radius()
            Dim side = 2.5 * r * Math.Sqrt(n) * 2
            Dim supports = scene.Supports(2 * r)
            Dim left, right, bottom As Double
            If supports.Count > 0 AndAlso rng.Chance(0.8) Then
                Dim s = rng.Pick(supports)
                Dim x0 = rng.Uniform(s.Left, Math.Max(s.Left, s.Right - side))
                left = x0
                right = Math.Min(s.Right, x0 + side)
                bottom = s.Top
            Else
                Dim p = scene.PointInside(r)
                left = p.X - side / 2
                right = p.X + side / 2
                bottom = p.Y
            End If
            Dim mass = scene.Mass()
            Dim sameMass = rng.Chance(0.5)
            Dim placed = 0, misses = 0
            Do While placed < n AndAlso misses < Attempts * 3
                Dim ri = r * rng.Uniform(0.7, 1.3)
                Dim centre = New Vector(rng.Uniform(left + ri, Math.Max(left + ri, right - ri)), bottom + ri + rng.Uniform(0, side))
                Dim ball = BodyDraft.MovableCircle(scene.NewId("c"), centre, ri, If(sameMass, mass, scene.Mass()), Vector.Zero)
                If scene.TryAdd(ball) Then
                    placed += 1
                Else
                    misses += 1
                End If
            Loop
        End Sub
    End Class
End Namespace
